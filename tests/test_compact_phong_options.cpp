// Design options of the compact Phong top against the line deadline, in the cycle model: the top
// as built (shading before the depth test: CompactCycleModel, "built") and compositions of the
// same blocks' cycle twins that no RTL implements yet, each clocked as predict_compact_cycles
// clocks the built top (the front end's twins, the fragment queue, compact_scanline_buffer's
// twin), a frame after the reset clears, edge records back to back, every pixel taken at once:
//  - deferred ("deferred5"): the line buffer keeps the winning fragment's normal and material per
//    pixel; its read-out sends each covered pixel through the normalizer and the shader and lets
//    uncovered pixels pass, in order: an order FIFO beside the two blocks, run-length coded (an
//    entry is a covered pixel or a run of uncovered ones, OrderDepth entries), whose head the
//    output takes (an uncovered run a pixel a clock, a covered pixel with the shader's result).
//    The interpolator feeds the queue and the buffer's writer a beat a clock.
//  - the same at two fragment lanes ("def5-2lane"): the interpolator's beats and the buffer's
//    writer carry up to two fragments (their Lanes = 2 twins), the read-out as above.
//  - the same with 4-clock periods ("deferred4", and at two lanes "def4-2lane"): the two blocks'
//    schedules at 4 clocks a period, their periods and load phases unchanged.
//  - early depth test ("early-z"): each fragment's key is compared with its pixel's key as written
//    so far (the depth RAM of its line's bank) in the clock the interpolator offers it; a
//    fragment that loses is dropped in that clock, one that wins and each marker go on through the
//    normalizer and the shader to the queue and the buffer, whose depth test decides as in the
//    built top (a write only lowers a pixel's key, so a dropped fragment loses there too). A
//    line's fragments wait until its bank is free (the reader has loaded the last pixel of the
//    line two before). The test takes no clock of its own and never waits for a RAM port here:
//    the bound of what it gives.
// Every option shades each pixel with its winning fragment, so the values are the built top's;
// only the clocks differ. Printed for docs/reference/compact.md ("Design options"); the test
// holds that every option takes every pixel and that the deferred read-out shades exactly the
// covered pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "build_options.hpp"
#include "compact_active_edge_list_timing.hpp"
#include "compact_cycle_model.hpp"
#include "compact_normalizer_timing.hpp"
#include "compact_phong_shader_timing.hpp"
#include "compact_scanline_buffer_timing.hpp"
#include "compact_segment_former_timing.hpp"
#include "config_file.hpp"
#include "cycle_model.hpp"
#include "prepare.hpp"
#include "scene.hpp"
#include "watkins_top.hpp"

using namespace watkins;
using namespace watkins::test;

namespace {

constexpr std::size_t OrderDepth = 32;

// CompactScheduleTiming's control with the period a parameter.
class Schedule {
 public:
  Schedule(int periods, int load_phase, int period)
      : period_(period), load_phase_(load_phase), v_(static_cast<std::size_t>(periods), false) {}
  bool ready() const { return ph_ == period_ - 1; }
  bool valid() const { return out_valid_; }
  void clock(bool valid_in, bool ready_in) {
    const bool load = ph_ == load_phase_ && v_.back();
    if (load && out_valid_ && !ready_in) return;
    if (load) out_valid_ = true;
    else if (ready_in) out_valid_ = false;
    if (ph_ == period_ - 1) {
      for (std::size_t k = v_.size() - 1; k > 0; --k) v_[k] = v_[k - 1];
      v_[0] = valid_in;
      ph_ = 0;
    } else {
      ++ph_;
    }
  }

 private:
  int period_, load_phase_, ph_ = 0;
  std::vector<bool> v_;
  bool out_valid_ = false;
};

enum class Option { Deferred, EarlyDepth };

struct Beat {
  bool eol = false;
  int y = 0, x = 0;
  std::uint64_t key = 0;
};

struct OptionRun {
  long long cycles = 0;
  long long shaded = 0;  // beats through the normalizer and the shader (fragments and markers, or pixels)
  std::vector<long long> takes;
};

OptionRun simulate(const PreparedScene& frame, const Config& cfg, Option option, int period, int lanes,
                   const std::vector<Beat>& beats, const std::vector<std::uint8_t>& covered) {
  using Item = CompactSegmentInterpolatorTiming::Item;
  Config lane_cfg = cfg;
  lane_cfg.lanes = lanes;
  const std::vector<Item> items = compact_segment_items(frame, cfg.max_active_edges, lane_cfg);
  const ChannelFormats formats = cfg.channels(frame.shading);
  CompactActiveEdgeListTiming list(cfg.max_active_edges, formats, id_bits(cfg.max_edges));
  CompactSegmentFormerTiming former(id_bits(cfg.max_polygons));
  CompactSegmentInterpolatorTiming interp(formats.bits[fmt::ChanX], formats.bits[fmt::ChanZ],
                                          formats.bits[fmt::ChanR], rtl_timing::CompactQuotientBitsPerClock, lanes);
  CompactScanlineBufferTiming buffer(cfg.max_width, lanes);
  buffer.set_frame(frame.width, frame.height);
  // A frame after the reset clears (CycleOptions::after_reset -1), the schedules at phase 0.
  const long long clears = std::max<long long>(1LL << id_bits(cfg.max_polygons), buffer.clear_clocks());
  for (long long i = 0; i < clears; ++i) {
    former.clock(false, false, 0, false);
    buffer.clock(false, false, false);
  }
  Schedule normalizer(CompactNormalizerTiming::Periods, CompactNormalizerTiming::LoadPhase, period);
  Schedule shader(CompactPhongShaderTiming::Periods, CompactPhongShaderTiming::LoadPhase, period);

  const int w = frame.width, h = frame.height;
  const long long frame_pixels = static_cast<long long>(w) * h;
  std::vector<std::vector<std::uint64_t>> keys(std::size_t(h),
                                               std::vector<std::uint64_t>(std::size_t(w), ~std::uint64_t{0}));
  std::deque<std::size_t> shading;  // early depth: the beats inside the normalizer and the shader
  // deferred: the read-out's order, run-length coded: an entry is a covered pixel (1) or a run
  // of uncovered pixels (its length, negated), OrderDepth entries at most.
  std::deque<int> order;
  std::array<std::size_t, rtl_timing::FragQueueDepth> q{};  // early depth: the queue's beats
  std::array<bool, rtl_timing::FragQueueDepth> q_marker{};   // deferred: the queue's marker flags
  int q_count = 0;
  std::size_t next_record = 0, next_item = 0, next_beat = 0;
  bool eof_taken = false;
  int lines_read = 0;  // lines whose last pixel the reader has loaded
  int markers = 0;     // deferred: the markers the queue has taken
  OptionRun out;
  CompactActiveEdgeListTiming::Inputs in;
  in.height = h;
  long long taken = 0;
  for (long long t = 0;; ++t) {
    // The output side.
    bool px_ready = true, disp = false, disp_cov = false, sh_take = false;
    if (option == Option::Deferred) {
      const bool head = !order.empty();
      sh_take = head && order.front() > 0 && shader.valid();
      const bool out_take = sh_take || (head && order.front() < 0);
      if (out_take) {
        if (order.front() > 0 || ++order.front() == 0) order.pop_front();
        out.takes.push_back(t);
        ++taken;
      }
      if (buffer.pixel_valid()) {
        disp_cov = covered[std::size_t(buffer.pixel_y()) * std::size_t(w) + std::size_t(buffer.pixel_x())] != 0;
        const bool joins = !disp_cov && !order.empty() && order.back() < 0;
        disp = (joins || order.size() < OrderDepth) && (!disp_cov || normalizer.ready());
        px_ready = disp;
      }
    } else if (buffer.pixel_valid()) {
      out.takes.push_back(t);
      ++taken;
    }
    const bool q_valid = q_count > 0;
    const bool q_eol = q_valid && (option == Option::Deferred ? q_marker[0] : beats[q[0]].eol);
    const bool q_pop = q_valid && buffer.frag_ready(q_eol, px_ready);
    const bool q_ready = q_count != rtl_timing::FragQueueDepth;
    const bool seg_valid = former.seg_valid();
    const Item offered = seg_valid ? items[next_item] : Item{};
    const bool nm_ready = normalizer.ready(), nm_valid = normalizer.valid();
    const bool sh_ready = shader.ready(), sh_valid = shader.valid();
    bool frag_ready = q_ready, drop = false;
    if (option == Option::EarlyDepth) {
      CompactSegmentInterpolatorTiming probe = interp;
      const auto p = probe.clock(seg_valid, offered, false);
      frag_ready = false;
      if (p.frag_valid) {
        const Beat& b = beats[next_beat];
        const bool bank_free = b.y < 2 || lines_read >= b.y - 1;
        if (!b.eol && bank_free && b.key >= keys[std::size_t(b.y)][std::size_t(b.x)]) {
          frag_ready = drop = true;
        } else {
          frag_ready = nm_ready && (b.eol || bank_free);
        }
      }
    }
    const auto pins = interp.clock(seg_valid, offered, frag_ready);
    const bool frag_take = pins.frag_valid && frag_ready;
    in.start = t == 0;
    in.edge_valid = !eof_taken;
    in.edge_eof = next_record == frame.edges.size();
    if (!in.edge_eof) in.edge = frame.edges[next_record];
    in.out_ready = former.edge_ready(pins.seg_ready);
    const CompactActiveEdgeListTiming::Outputs ae = list.eval(in);
    const int poly = ae.edge ? ae.edge->rec.poly : 0;

    // The clock edge.
    if (in.edge_valid && ae.edge_ready) {
      if (in.edge_eof) eof_taken = true;
      else ++next_record;
    }
    list.tick(in);
    former.clock(ae.out_valid, ae.out_eol, poly, pins.seg_ready);
    if (seg_valid && pins.seg_ready) ++next_item;
    if (buffer.pixel_valid() && px_ready && buffer.pixel_x() + 1 == w) lines_read = buffer.pixel_y() + 1;
    buffer.clock(q_valid, q_eol, px_ready);
    if (q_pop) {
      if (option == Option::EarlyDepth && !beats[q[0]].eol) {
        const Beat& b = beats[q[0]];
        std::uint64_t& k = keys[std::size_t(b.y)][std::size_t(b.x)];
        k = std::min(k, b.key);
      }
      for (int i = 0; i + 1 < rtl_timing::FragQueueDepth; ++i) {
        q[std::size_t(i)] = q[std::size_t(i) + 1];
        q_marker[std::size_t(i)] = q_marker[std::size_t(i) + 1];
      }
      --q_count;
    }
    if (option == Option::Deferred) {
      if (frag_take) {
        q_marker[std::size_t(q_count++)] = pins.frag_eol;
        markers += pins.frag_eol;
      }
      normalizer.clock(disp && disp_cov, sh_ready);
      shader.clock(nm_valid, sh_take);
      if (disp) {
        if (disp_cov) order.push_back(1);
        else if (!order.empty() && order.back() < 0) --order.back();
        else order.push_back(-1);
        out.shaded += disp_cov;
      }
    } else {
      const bool q_push = sh_valid && q_ready;
      if (q_push) {
        q[std::size_t(q_count++)] = shading.front();
        shading.pop_front();
      }
      if (frag_take) {
        if (!drop) {
          shading.push_back(next_beat);
          ++out.shaded;
        }
        ++next_beat;
      }
      normalizer.clock(frag_take && !drop, sh_ready);
      shader.clock(nm_valid, q_ready);
    }
    if (taken == frame_pixels) {
      out.cycles = t + 1;
      if (option == Option::EarlyDepth ? next_beat != beats.size() : markers != h)
        throw std::logic_error("design options: beats left over");
      return out;
    }
    if (t > 100'000'000) throw std::logic_error("design options: no end");
  }
}

struct LineFigures {
  long long worst = 0, missed = 0;
};
LineFigures lines(const std::vector<long long>& takes, int w, int h) {
  LineFigures f;
  long long before = takes[std::size_t(w) - 1];
  for (int y = 1; y < h; ++y) {
    const long long end = takes[std::size_t(y) * std::size_t(w) + std::size_t(w) - 1];
    f.worst = std::max(f.worst, end - before);
    f.missed += end - before > 1600;
    before = end;
  }
  return f;
}

TEST(CompactPhongOptions, LinesAgainstTheBeam) {
  std::vector<std::string> stems;
  for (const auto& e : std::filesystem::directory_iterator(WATKINS_SOURCE_DIR "/scenes/sized")) {
    const std::string n = e.path().filename().string();
    const std::string suffix = ".phong.json";
    if (n.size() > suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0)
      stems.push_back(n.substr(0, n.size() - suffix.size()));
  }
  std::sort(stems.begin(), stems.end());
  std::printf("  %-16s %-10s %9s %8s %9s %6s %6s\n", "scene", "option", "shaded", "cycles", "clk/cov", "worst",
              ">1600");
  int ran = 0;
  for (const std::string& stem : stems) {
    const std::string scene = WATKINS_SOURCE_DIR "/scenes/" + stem + ".json";
    if (!std::filesystem::exists(scene)) continue;
    Config cfg = load_config(WATKINS_SOURCE_DIR "/scenes/sized/" + stem + ".phong.json");
    cfg.compact = true;
    cfg.smoothing = false;
    cfg.eq2 = false;
    PreparedScene p;
    try {
      p = prepare(load_scene(scene, shading_options(ShadingMode::Phong)), cfg);
    } catch (const std::exception&) {
      continue;
    }
    if (p.width > 320 || p.smoothed()) continue;
    std::vector<Beat> beats;
    PipelineObserver obs;
    const bool submission = p.depth_tie == DepthTie::Submission;
    obs.fragment = [&](int y, const Fragment& f, bool) {
      beats.push_back(Beat{false, y, f.x,
                           (std::uint64_t{f.depth} << 32) | (submission ? std::uint64_t(std::uint32_t(f.poly)) : 0)});
    };
    obs.fragments_end = [&](int y) { beats.push_back(Beat{true, y, 0, 0}); };
    const Image img = WatkinsTop(cfg).render(p, obs);
    std::vector<std::uint8_t> covered(img.covered.begin(), img.covered.end());
    long long n_covered = 0;
    for (const auto v : covered) n_covered += v != 0;
    auto row = [&](const char* name, long long shaded, long long cycles, const std::vector<long long>& takes) {
      ASSERT_EQ(takes.size(), covered.size()) << stem << " " << name;
      const LineFigures f = lines(takes, p.width, p.height);
      std::printf("  %-16s %-10s %9lld %8lld %9.2f %6lld %6lld\n", stem.c_str(), name, shaded, cycles,
                  double(cycles) / double(std::max<long long>(n_covered, 1)), f.worst, f.missed);
    };
    CycleOptions o;
    o.max_active_edges = cfg.max_active_edges;
    std::vector<long long> built_takes;
    o.take_cycles = &built_takes;
    const CyclePrediction built = predict_cycles(p, cfg, o);
    row("built", static_cast<long long>(beats.size()), built.cycles, built_takes);
    const OptionRun d5 = simulate(p, cfg, Option::Deferred, 5, 1, beats, covered);
    row("deferred5", d5.shaded, d5.cycles, d5.takes);
    const OptionRun d4 = simulate(p, cfg, Option::Deferred, 4, 1, beats, covered);
    row("deferred4", d4.shaded, d4.cycles, d4.takes);
    const OptionRun d52 = simulate(p, cfg, Option::Deferred, 5, 2, beats, covered);
    row("def5-2lane", d52.shaded, d52.cycles, d52.takes);
    const OptionRun d42 = simulate(p, cfg, Option::Deferred, 4, 2, beats, covered);
    row("def4-2lane", d42.shaded, d42.cycles, d42.takes);
    const OptionRun e = simulate(p, cfg, Option::EarlyDepth, 5, 1, beats, covered);
    row("early-z", e.shaded, e.cycles, e.takes);
    EXPECT_EQ(d5.shaded, n_covered) << stem;
    EXPECT_LE(e.shaded, static_cast<long long>(beats.size())) << stem;
    ++ran;
  }
  EXPECT_GE(ran, 5);
}

}  // namespace
