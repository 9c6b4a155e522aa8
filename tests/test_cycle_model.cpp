// The cycle model (model/twins/cycle_model.hpp) without the RTL: counts worked by hand from the
// RTL's latencies, and bounds every frame must meet. (tests/cosim/test_cycle_model.cpp holds it
// equal to Verilator's cycles.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "build_options.hpp"
#include "compact_active_edge_list_timing.hpp"
#include "compact_cycle_model.hpp"
#include "config_file.hpp"
#include "cycle_model.hpp"
#include "prepare.hpp"
#include "scene.hpp"
#include "scene_builder.hpp"
#include "twin_error.hpp"
#include "watkins_top.hpp"

using namespace watkins;
using namespace watkins::test;

namespace {

PreparedScene with_shading(PreparedScene p, ShadingMode mode) {
  p.shading = mode;
  if (mode == ShadingMode::Phong && p.materials.empty()) p.materials.resize(1);
  return p;
}

// An empty W x H frame, by hand. The active-edge list: cycle 0 starts the frame, cycle 1 decides
// the swap to line 1 (the stream's head is its EOF beat), cycle 2 swaps, and from cycle 3 each
// line is its end-of-line marker (one cycle), the swap's decision (one) and the swap (one): 3
// cycles per line. The first marker reaches the line buffer at cycle 44: segment former 4 (its
// input register), 5 (its pairing register) and 6 (its output), s0 7, span_reciprocal 8..33,
// sa/sm/sp/sh/sb/sc/sv/sd 34..41, FIFO 42, the stepper's output register 43, the fragment queue
// 44. Full-frame: each line's read-out (W cycles) hides the next marker, so the last pixel is read
// at 44 + H*W and taken one cycle later: H*W + 46 cycles counting cycle 0. Sparse: an empty line
// is one read step (two cycles after its marker: the swap hands the search's registers over in
// between), so the list's 3 cycles per line set the pace: the last line's marker arrives at
// 44 + 3(H-1), is read two cycles later and taken the next: 3H + 45. The Phong top's 58 stages
// (normalizer 16, shader 42) delay it all by 58.
TEST(CycleModel, EmptyFrameByHand) {
  for (const auto& [w, h] : {std::pair{13, 5}, std::pair{320, 240}, std::pair{1, 1}, std::pair{40, 60}}) {
    const PreparedScene g = prepare(screen(w, h, {}, "empty"));
    const PreparedScene p = with_shading(g, ShadingMode::Phong);
    EXPECT_EQ(predict_cycles(g, PixelOutput::FullFrame).cycles, w * h + 46) << w << "x" << h;
    EXPECT_EQ(predict_cycles(p, PixelOutput::FullFrame).cycles, w * h + 46 + 58) << w << "x" << h;
    EXPECT_EQ(predict_cycles(g, PixelOutput::Sparse).cycles, 3 * h + 45) << w << "x" << h;
    EXPECT_EQ(predict_cycles(p, PixelOutput::Sparse).cycles, 3 * h + 45 + 58) << w << "x" << h;
    EXPECT_EQ(predict_cycles(g, PixelOutput::FullFrame).pixels, w * h);
    EXPECT_EQ(predict_cycles(g, PixelOutput::Sparse).pixels, 1);  // the terminating beat
  }
}

// Every shipped scene: full-frame output costs at least a pixel per cycle; sparse output at least
// a cycle per covered pixel and never more than full-frame plus a cycle per line (each swap
// starts the sparse reader a clock later than the full-frame one); as many sparse beats as the model's
// sparse stream; the full-frame Phong top exactly 58 cycles more (its pipeline only delays the
// read-out, which sets the pace).
TEST(CycleModel, ShippedScenesMeetTheBounds) {
  int checked = 0;
  for (const auto& e : std::filesystem::directory_iterator(WATKINS_SOURCE_DIR "/scenes")) {
    if (e.path().extension() != ".json") continue;
    const std::string name = e.path().filename().string();
    PreparedScene g;
    try {
      g = prepare(load_scene(e.path().string(), shading_options(ShadingMode::Gouraud)));
    } catch (const SceneError&) {
      continue;
    }
    const Image img = WatkinsTop().render(g);
    // A smoothed frame (Herman & Liu's smoother on) is emitted in full even in sparse mode.
    const long long beats = g.smooth_w > 0 ? static_cast<long long>(g.width) * g.height
                                           : static_cast<long long>(sparse_stream(img).size());
    const CyclePrediction full = predict_cycles(g, PixelOutput::FullFrame);
    const CyclePrediction sparse = predict_cycles(g, PixelOutput::Sparse);
    EXPECT_GE(full.cycles, static_cast<long long>(g.width) * g.height) << name;
    EXPECT_EQ(full.pixels, static_cast<long long>(g.width) * g.height) << name;
    EXPECT_EQ(sparse.pixels, beats) << name;
    EXPECT_GE(sparse.cycles, beats) << name;
    EXPECT_LE(sparse.cycles, full.cycles + g.height) << name;
    const PreparedScene p = with_shading(g, ShadingMode::Phong);
    EXPECT_EQ(predict_cycles(p, PixelOutput::FullFrame).cycles, full.cycles + 58) << name;
    ++checked;
  }
  EXPECT_GT(checked, 5);
}

TEST(CycleModel, OverflowIsACapacityError) {
  std::vector<ScreenPolygon> many;
  for (int i = 0; i < 6; ++i) many.push_back(poly({vtx(1 + i, 1), vtx(30 - i, 2), vtx(15, 20)}));
  const PreparedScene p = prepare(screen(32, 24, many, "stack"), PrepareOptions{64});
  EXPECT_THROW(predict_cycles(p, PixelOutput::FullFrame, 4), CapacityError);
  EXPECT_NO_THROW(predict_cycles(p, PixelOutput::FullFrame, 64));
}

}  // namespace

namespace {

class AlwaysHigh : public PixelReady {
 public:
  bool ready(long long, long long) override { return true; }
};

// The clocked pixel path with pixel_ready_i held high takes every pixel in the cycle the closed
// count says: same cycles, first pixel and beats, on every shipped scene in both shadings and
// output modes, smoothed (W = 0.8) and not; the takes are strictly increasing, one per beat.
TEST(CycleModel, ClockedPixelPathEqualsTheFastCount) {
  int checked = 0;
  for (const auto& e : std::filesystem::directory_iterator(WATKINS_SOURCE_DIR "/scenes")) {
    if (e.path().extension() != ".json") continue;
    for (const ShadingMode mode : {ShadingMode::Gouraud, ShadingMode::Phong})
      for (const double w : {0.0, 0.8}) {
        BuildOptions bo = shading_options(mode);
        bo.smooth = w;
        PreparedScene p;
        try {
          p = prepare(load_scene(e.path().string(), bo));
        } catch (const SceneError&) {
          continue;
        }
        for (const PixelOutput out : {PixelOutput::FullFrame, PixelOutput::Sparse}) {
          const std::string what = e.path().filename().string() + (mode == ShadingMode::Phong ? " phong" : " gouraud") +
                                   (w > 0 ? " smoothed" : "") + (out == PixelOutput::Sparse ? " sparse" : " full");
          const CyclePrediction fast = predict_cycles(p, out);
          AlwaysHigh high;
          std::vector<long long> takes;
          CycleOptions o;
          o.output = out;
          o.pixel_ready = &high;
          o.take_cycles = &takes;
          const CyclePrediction clocked = predict_cycles(p, Config{}, o);
          EXPECT_EQ(clocked.cycles, fast.cycles) << what;
          EXPECT_EQ(clocked.first_pixel, fast.first_pixel) << what;
          EXPECT_EQ(clocked.pixels, fast.pixels) << what;
          ASSERT_EQ(static_cast<long long>(takes.size()), fast.pixels) << what;
          EXPECT_EQ(takes.front(), fast.first_pixel) << what;
          EXPECT_EQ(takes.back(), fast.cycles - 1) << what;
          for (std::size_t i = 1; i < takes.size(); ++i) ASSERT_LT(takes[i - 1], takes[i]) << what << " pixel " << i;
          ++checked;
        }
      }
  }
  EXPECT_GT(checked, 40);
}

// A consumer that takes one pixel in three: the frame's last pixel leaves no earlier than three
// cycles a pixel after the first, and the clocked model never takes a pixel the consumer refused.
class OneInThree : public PixelReady {
 public:
  bool ready(long long cycle, long long) override {
    asked.push_back(cycle);
    return cycle % 3 == 0;
  }
  std::vector<long long> asked;
};

TEST(CycleModel, ClockedPixelPathHonoursTheConsumer) {
  const PreparedScene p = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/sphere.json", shading_options(ShadingMode::Gouraud)));
  OneInThree third;
  std::vector<long long> takes;
  CycleOptions o;
  o.pixel_ready = &third;
  o.take_cycles = &takes;
  const CyclePrediction c = predict_cycles(p, Config{}, o);
  ASSERT_EQ(static_cast<long long>(takes.size()), static_cast<long long>(p.width) * p.height);
  for (const long long t : takes) ASSERT_EQ(t % 3, 0);
  EXPECT_EQ(c.cycles, takes.back() + 1);
  EXPECT_GE(takes.back() - takes.front(), 3 * (static_cast<long long>(takes.size()) - 1));
  for (std::size_t i = 1; i < third.asked.size(); ++i) ASSERT_LT(third.asked[i - 1], third.asked[i]);
}

// ---------------------------------------------------------------- the compact top

// The compact top at the default scene's sized configuration (the UP5K's): MaxWidth 320,
// PolyIdBits 7.
Config compact_sized() { return load_config(WATKINS_SOURCE_DIR "/tests/configs/compact_default.gouraud.json"); }

CyclePrediction compact_cycles(const PreparedScene& p, const Config& cfg, long long after_reset = -1,
                               std::vector<long long>* takes = nullptr, PixelReady* ready = nullptr) {
  CycleOptions o;
  o.max_active_edges = cfg.max_active_edges;
  o.after_reset = after_reset;
  o.take_cycles = takes;
  o.pixel_ready = ready;
  return predict_cycles(p, cfg, o);
}

// An empty W x H frame on the compact top, by hand, its reset clears over. Cycle 0 starts the
// frame; the list's INS finds the EOF beat past line 0 at cycle 1 and offers the marker at 2;
// the former takes it at 2, decides it at 3 and offers it from 4; the interpolator classifies it
// at 4, takes it at 5 and has it on its output at 6; the fragment queue holds it at 7; the line
// buffer takes it at 8, reads pixel 0 at 9 and loads it at 10; through the pixel skid it is
// taken at 11. The reader then spends W + 1 clocks a line (one to read pixel 0, one a pixel) and
// takes the next marker with the line's last load, while a marker reaches the queue every 3
// clocks (the former's decision, the interpolator's classification and take): for W >= 2 the
// reader sets the pace, the last pixel is taken at 9 + H(W + 1), H(W + 1) + 10 cycles; a
// one-pixel-wide frame is paced by the markers, a pixel every 3 clocks from 11: 3H + 9.
// From reset, as the bench starts a frame (its first beat a clock after reset), the buffer's
// clear of MaxWidth clocks holds the first marker back to frame cycle MaxWidth - 1 (the former's
// 2^PolyIdBits = 128 are over by then): the first pixel is taken at MaxWidth + 2 and the frame
// takes MaxWidth + 1 cycles more than the same frame after the clears, the buffer's figure
// (docs/reference/compact.md).
TEST(CompactCycleModel, EmptyFrameByHand) {
  const Config cfg = compact_sized();
  for (const auto& [w, h] : {std::pair{13, 5}, std::pair{320, 240}, std::pair{2, 1}, std::pair{40, 60}, std::pair{1, 1}}) {
    const PreparedScene p = prepare(screen(w, h, {}, "empty"), cfg);
    const CyclePrediction c = compact_cycles(p, cfg);
    EXPECT_EQ(c.cycles, static_cast<long long>(h) * (w + 1) + 10) << w << "x" << h;
    EXPECT_EQ(c.first_pixel, 11) << w << "x" << h;
    EXPECT_EQ(c.pixels, static_cast<long long>(w) * h);
    const CyclePrediction r = compact_cycles(p, cfg, 1);
    EXPECT_EQ(r.cycles, cfg.max_width + static_cast<long long>(h) * (w + 1) + 1) << w << "x" << h << " from reset";
    EXPECT_EQ(r.first_pixel, cfg.max_width + 2) << w << "x" << h << " from reset";
  }
  for (const int h : {2, 7, 30}) {
    const PreparedScene p = prepare(screen(1, h, {}, "empty column"), cfg);
    EXPECT_EQ(compact_cycles(p, cfg).cycles, 3 * h + 9) << "1x" << h;
  }
}

// The list alone (records back to back, its output always taken) and the interpolator alone (the
// frame's segment stream back to back, fragments always taken): clocks to their last marker.
long long list_alone(const PreparedScene& p, const Config& cfg) {
  CompactActiveEdgeListTiming list(cfg.max_active_edges, cfg.channels(p.shading), id_bits(cfg.max_edges));
  CompactActiveEdgeListTiming::Inputs in;
  in.height = p.height;
  in.out_ready = true;
  std::size_t next = 0;
  bool eof = false;
  int markers = 0;
  for (long long t = 0;; ++t) {
    in.start = t == 0;
    in.edge_valid = !eof;
    in.edge_eof = next == p.edges.size();
    if (!in.edge_eof) in.edge = p.edges[next];
    const CompactActiveEdgeListTiming::Outputs o = list.eval(in);
    if (o.out_valid && o.out_eol && ++markers == p.height) return t + 1;
    if (in.edge_valid && o.edge_ready) in.edge_eof ? void(eof = true) : void(++next);
    list.tick(in);
    if (t > 100'000'000) throw std::logic_error("list alone: no end");
  }
}

long long interpolator_alone(const PreparedScene& p, const Config& cfg, long long& fragments) {
  const std::vector<CompactSegmentInterpolatorTiming::Item> items = compact_segment_items(p, cfg.max_active_edges, cfg);
  const ChannelFormats f = cfg.channels(p.shading);
  CompactSegmentInterpolatorTiming t(f.bits[fmt::ChanX], f.bits[fmt::ChanZ], f.bits[fmt::ChanR],
                                     rtl_timing::CompactQuotientBitsPerClock, cfg.lanes);
  std::size_t next = 0;
  int markers = 0;
  fragments = 0;
  for (long long c = 0;; ++c) {
    const bool valid = next < items.size();
    const auto pins = t.clock(valid, valid ? items[next] : CompactSegmentInterpolatorTiming::Item{}, true);
    if (pins.frag_valid && pins.frag_eol && ++markers == p.height) return c + 1;
    fragments += (pins.frag_valid && !pins.frag_eol) * (1 + pins.frag_pair);
    if (valid && pins.seg_ready) ++next;
    if (c > 100'000'000) throw std::logic_error("interpolator alone: no end");
  }
}

// A consumer ready every other cycle (odd ones).
class EveryOther : public PixelReady {
 public:
  bool ready(long long cycle, long long) override { return cycle % 2 == 1; }
};

// Every shipped scene at its sized Gouraud configuration (scenes/sized/<scene>.gouraud.json) with
// compact true: the frame costs at least the empty frame's H(W + 1) + 10 and at least what the
// list and the interpolator each take alone; every pixel is taken once, in order, the last at
// cycles - 1; a consumer ready every other cycle gets every pixel on an odd cycle. Prints each
// scene's cycles, fragments per clock and slowest line (clocks from the previous line's last
// pixel taken to its own): the table in docs/reference/compact.md.
TEST(CompactCycleModel, SizedScenes) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(WATKINS_SOURCE_DIR "/scenes/sized")) {
    const std::string n = e.path().filename().string();
    const std::string suffix = ".gouraud.json";
    if (n.size() > suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0)
      names.push_back(n.substr(0, n.size() - suffix.size()));
  }
  std::sort(names.begin(), names.end());
  int ran = 0;
  for (const std::string& name : names) {
    const std::string scene = WATKINS_SOURCE_DIR "/scenes/" + name + ".json";
    if (!std::filesystem::exists(scene)) continue;
    Config cfg = load_config(WATKINS_SOURCE_DIR "/scenes/sized/" + name + ".gouraud.json");
    cfg.compact = true;
    cfg.smoothing = false;
    PreparedScene p;
    try {
      p = prepare(load_scene(scene, shading_options(ShadingMode::Gouraud)), cfg);
    } catch (const std::exception& e) {  // a smoothed scene: the compact top has no smoother
      std::printf("  %s: not on the compact top (%s)\n", name.c_str(), e.what());
      continue;
    }
    std::vector<long long> takes;
    const CyclePrediction c = compact_cycles(p, cfg, -1, &takes);
    const long long pixels = static_cast<long long>(p.width) * p.height;
    ASSERT_EQ(static_cast<long long>(takes.size()), pixels) << name;
    for (std::size_t i = 1; i < takes.size(); ++i) ASSERT_LT(takes[i - 1], takes[i]) << name;
    EXPECT_EQ(takes.back() + 1, c.cycles) << name;
    EXPECT_EQ(takes.front(), c.first_pixel) << name;
    EXPECT_GE(c.cycles, static_cast<long long>(p.height) * (p.width + 1) + 10) << name;
    long long fragments = 0;
    EXPECT_GE(c.cycles, interpolator_alone(p, cfg, fragments)) << name;
    EXPECT_GE(c.cycles, list_alone(p, cfg)) << name;
    long long worst = 0, before = -1;
    int worst_y = 0;
    for (int y = 0; y < p.height; ++y) {
      const long long end = takes[std::size_t(y) * std::size_t(p.width) + std::size_t(p.width) - 1];
      if (end - before > worst) worst = end - before, worst_y = y;
      before = end;
    }
    EveryOther odd;
    std::vector<long long> slow;
    const CyclePrediction s = compact_cycles(p, cfg, -1, &slow, &odd);
    ASSERT_EQ(static_cast<long long>(slow.size()), pixels) << name;
    for (const long long t : slow) ASSERT_EQ(t % 2, 1) << name;
    EXPECT_GE(s.cycles, c.cycles) << name;
    std::printf("  %s (%dx%d): %lld cycles, %lld fragments (%.3f per clock), slowest line %d: %lld clocks\n",
                name.c_str(), p.width, p.height, c.cycles, fragments, double(fragments) / double(c.cycles),
                worst_y, worst);
    ++ran;
  }
  EXPECT_GE(ran, 12);
}

// Two fragment lanes on overdraw (eight screen-wide quads: 2,548 fragments a line), the
// fragment-bound scene, at its sized configuration built compact: the interpolator alone emits
// the same fragments in fewer clocks, about half on spans of 319 pixels; the frame takes at least
// a pixel a clock of the reader (H(W + 1) + 10) and no line takes more than the 1,600 clocks a
// line doubled on 640 x 480 gives it, which one lane misses (about 2,570 a line). Line 0 counts
// from the frame's first edge beat, the pipeline's fill included (the board starts a frame lines
// ahead of the beam: `watkins board check` times that), so the bound is on lines 1 onwards.
TEST(CompactCycleModel, TwoLanesOnOverdraw) {
  Config cfg = load_config(WATKINS_SOURCE_DIR "/scenes/sized/overdraw.gouraud.json");
  cfg.compact = true;
  cfg.smoothing = false;
  const PreparedScene p =
      prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/overdraw.json", shading_options(ShadingMode::Gouraud)), cfg);
  auto slowest_line = [&p](const std::vector<long long>& takes) {
    long long worst = 0, before = takes[std::size_t(p.width) - 1];
    for (int y = 1; y < p.height; ++y) {
      const long long end = takes[std::size_t(y) * std::size_t(p.width) + std::size_t(p.width) - 1];
      worst = std::max(worst, end - before);
      before = end;
    }
    return worst;
  };
  Config two = cfg;
  two.lanes = 2;
  std::vector<long long> takes1, takes2;
  const CyclePrediction one_lane = compact_cycles(p, cfg, -1, &takes1);
  const CyclePrediction two_lanes = compact_cycles(p, two, -1, &takes2);
  long long frags1 = 0, frags2 = 0;
  const long long alone1 = interpolator_alone(p, cfg, frags1), alone2 = interpolator_alone(p, two, frags2);
  EXPECT_EQ(frags1, frags2);
  EXPECT_GT(frags1, 2500LL * p.height);
  EXPECT_LT(alone2, alone1 * 55 / 100) << alone1 << " clocks alone with one lane";
  EXPECT_GE(alone2, frags2 / 2);
  EXPECT_GE(two_lanes.cycles, static_cast<long long>(p.height) * (p.width + 1) + 10);
  EXPECT_LT(two_lanes.cycles, one_lane.cycles * 55 / 100);
  ASSERT_EQ(takes2.size(), takes1.size());
  EXPECT_GT(slowest_line(takes1), 1600);
  EXPECT_LE(slowest_line(takes2), 1600);
  std::printf("  overdraw: one lane %lld cycles (slowest line %lld), two lanes %lld (slowest line %lld); "
              "interpolator alone %lld and %lld\n",
              one_lane.cycles, slowest_line(takes1), two_lanes.cycles, slowest_line(takes2), alone1, alone2);
}

// The edge source's pace (CycleOptions::edge_interval, edge_gap), on both micro-architectures:
// 1 and 1 is the source offering back to back; beat k + 1 no sooner than edge_interval cycles
// after beat k, so a frame of N records and the EOF beat takes at least N edge_interval cycles
// before its last pixel; the iCEBreaker's SPRAM frame player's pace (3 and 2 at the sized
// default's 184-bit record) costs the compact top cycles on the default scene (79,417 against
// 79,275) and the pipelined top none (76,846: its list takes a record no faster), the EOF beat
// alone (an empty frame) none on either.
TEST(CycleModel, EdgePace) {
  for (const bool compact : {true, false}) {
    Config cfg = compact_sized();
    cfg.compact = compact;
    const PreparedScene p = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/default.json", shading_options(ShadingMode::Gouraud)), cfg);
    const PreparedScene empty = prepare(screen(p.width, p.height, {}, "empty"), cfg);
    auto cycles = [&](const PreparedScene& f, int interval, int gap) {
      CycleOptions o;
      o.max_active_edges = cfg.max_active_edges;
      o.edge_interval = interval;
      o.edge_gap = gap;
      std::vector<long long> takes;
      o.take_cycles = &takes;
      return predict_cycles(f, cfg, o).cycles;
    };
    const long long full = cycles(p, 1, 1), spram = cycles(p, 3, 2), slow = cycles(p, 1000, 1);
    EXPECT_EQ(full, predict_cycles(p, PixelOutput::FullFrame, cfg.max_active_edges, cfg).cycles);
    EXPECT_GE(spram, full) << (compact ? "compact" : "pipelined");
    if (compact) EXPECT_GT(spram, full);  // the compact list places a record in 2 clocks, skips one in 1
    EXPECT_GE(slow, 1000LL * static_cast<long long>(p.edges.size())) << (compact ? "compact" : "pipelined");
    EXPECT_EQ(cycles(empty, 3, 2), cycles(empty, 1, 1)) << (compact ? "compact" : "pipelined");
    std::printf("  %s top, default scene: %lld cycles back to back, %lld at the SPRAM player's pace\n",
                compact ? "compact" : "pipelined", full, spram);
  }
}

// The pixel path clocked with a consumer that is always ready equals the run without one.
TEST(CompactCycleModel, AlwaysReadyEqualsNoConsumer) {
  class Always : public PixelReady {
   public:
    bool ready(long long, long long) override { return true; }
  } always;
  const Config cfg = compact_sized();
  const PreparedScene p = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/default.json", shading_options(ShadingMode::Gouraud)), cfg);
  std::vector<long long> a, b;
  const CyclePrediction x = compact_cycles(p, cfg, 1, &a);
  const CyclePrediction y = compact_cycles(p, cfg, 1, &b, &always);
  EXPECT_EQ(x.cycles, y.cycles);
  EXPECT_EQ(a, b);
}

// What the compact top does not have: sparse output, Phong at two lanes, the smoother, the divider.
TEST(CompactCycleModel, RefusesWhatTheCompactTopLacks) {
  const Config cfg = compact_sized();
  const PreparedScene g = prepare(screen(8, 4, {}, "empty"), cfg);
  EXPECT_THROW(predict_cycles(g, PixelOutput::Sparse, cfg.max_active_edges, cfg), std::invalid_argument);
  Config two = cfg;
  two.lanes = 2;
  EXPECT_THROW(predict_cycles(with_shading(g, ShadingMode::Phong), PixelOutput::FullFrame, cfg.max_active_edges, two),
               std::invalid_argument);
  EXPECT_NO_THROW(predict_cycles(with_shading(g, ShadingMode::Phong), PixelOutput::FullFrame, cfg.max_active_edges, cfg));
  PreparedScene smoothed = g;
  smoothed.smooth_w = 4;
  EXPECT_THROW(predict_cycles(smoothed, PixelOutput::FullFrame, cfg.max_active_edges, cfg), std::invalid_argument);
  Config divided = cfg;
  divided.eq2 = true;
  EXPECT_THROW(predict_cycles(g, PixelOutput::FullFrame, cfg.max_active_edges, divided), std::invalid_argument);
}

// The compact Phong top: every beat (fragment or marker) holds the normalizer and the shader for
// a 5-clock period each, so a frame takes at least 5 clocks per beat; an empty frame's markers
// add the two blocks' latencies (33 + 65) to the first pixel and, at 5 clocks a marker against
// the reader's W + 1 a line, nothing to the rest for W >= 4.
TEST(CompactCycleModel, PhongEmptyFrameAndFiveClocksAFragment) {
  const Config cfg = load_config(WATKINS_SOURCE_DIR "/tests/configs/compact.phong.json");
  for (const int w : {4, 40}) {
    const PreparedScene g = prepare(screen(w, 6, {}, "empty"), compact_sized());
    const CyclePrediction gouraud = compact_cycles(g, compact_sized());
    const CyclePrediction phong = compact_cycles(with_shading(g, ShadingMode::Phong), cfg);
    EXPECT_GE(phong.first_pixel, gouraud.first_pixel + 33 + 65) << w;
    EXPECT_LE(phong.cycles - phong.first_pixel, gouraud.cycles - gouraud.first_pixel + 5) << w;
  }
  const PreparedScene p =
      prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/default.json", shading_options(ShadingMode::Phong)), cfg);
  long long fragments = 0;
  interpolator_alone(p, cfg, fragments);
  EXPECT_GE(compact_cycles(p, cfg).cycles, 5 * (fragments + p.height));
}

// The shipped scenes of width <= 320 rendered Phong at their sized Phong configurations made
// compact (what the iCEBreaker's UP5K would hold), against the 1,600 clocks a line that a
// 320 x 240 frame doubled on 640 x 480 gives: the frame's clocks per covered pixel and its slowest
// line (lines 1 onwards, each from the previous line's last pixel taken to its own; line 0 holds
// the pipeline's fill, which the board starts lines ahead of the beam). Printed for
// docs/reference/compact.md; the bound itself is the board check's.
TEST(CompactCycleModel, PhongLinesAgainstTheBeam) {
  int ran = 0;
  std::printf("  %-18s %7s %9s %9s %8s %10s %6s %s\n", "scene", "WxH", "fragments", "covered", "cycles",
              "clk/covered", "worst", "lines > 1600");
  std::vector<std::string> stems;
  for (const auto& e : std::filesystem::directory_iterator(WATKINS_SOURCE_DIR "/scenes/sized")) {
    const std::string n = e.path().filename().string();
    const std::string suffix = ".phong.json";
    if (n.size() > suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0)
      stems.push_back(n.substr(0, n.size() - suffix.size()));
  }
  std::sort(stems.begin(), stems.end());
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
    } catch (const std::exception&) {  // a smoothed or curved scene
      continue;
    }
    if (p.width > 320 || p.smoothed()) continue;
    std::vector<long long> takes;
    const CyclePrediction c = compact_cycles(p, cfg, -1, &takes);
    ASSERT_EQ(takes.size(), static_cast<std::size_t>(p.width) * static_cast<std::size_t>(p.height));
    long long fragments = 0;
    interpolator_alone(p, cfg, fragments);
    const Image img = WatkinsTop(cfg).render(p);
    long long covered = 0;
    for (const auto v : img.covered) covered += v != 0;
    long long worst = 0, missed = 0, before = takes[std::size_t(p.width) - 1];
    for (int y = 1; y < p.height; ++y) {
      const long long end = takes[std::size_t(y) * std::size_t(p.width) + std::size_t(p.width) - 1];
      worst = std::max(worst, end - before);
      missed += end - before > 1600;
      before = end;
    }
    EXPECT_GE(c.cycles, 5 * fragments) << stem;
    std::printf("  %-18s %3dx%-3d %9lld %9lld %8lld %10.2f %6lld %lld\n", stem.c_str(), p.width, p.height, fragments,
                covered, c.cycles, covered ? double(c.cycles) / double(covered) : 0.0, worst, missed);
    ++ran;
  }
  EXPECT_GE(ran, 5);
}

}  // namespace
