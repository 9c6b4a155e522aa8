// rtl/compact_segment_interpolator.sv against SegmentInterpolator::setup/fragment/step (every
// fragment's values, in order) and against its cycle twin CompactSegmentInterpolatorTiming (every
// cycle's seg_ready_o, frag_valid_o, and each beat's marker flag and x): the segment streams the
// twins produce for the shipped scenes that prepare at the unit's configuration and for random
// scenes, and random segments (spans narrower than a pixel, clipped at 0 and at the width, empty
// and reversed, full-range channel words), at full rate and under random valid gaps and
// back-pressure; spans of every pixel count from 1 to 9, clipped at 0 and at the width. Each beat is
// split into its fragments (Lanes = 2: lane 0, then lane 1 when frag_pair_o), each checked against
// the next expected fragment, a pair's two from one span, lane 0 at an even pixel of its span.
// Prints each shipped scene's fragment rate and longest line at full rate. Built at the sized
// default scene's parameters, at the overdraw scene's with Lanes = 2, and at the default
// configuration's (tests/rtl/CMakeLists.txt).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "Vcompact_segment_interpolator.h"
#include "build_options.hpp"
#include "compact_segment_interpolator_timing.hpp"
#include "config_file.hpp"
#include "edge_packing.hpp"
#include "prepare.hpp"
#include "random_scene.hpp"
#include "rtl_harness.hpp"
#include "scene.hpp"
#include "segment_interpolator.hpp"
#include "watkins_top.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

constexpr int NC = fmt::NumChannels;
#ifdef WATKINS_RTL_PARAM_QuotientBitsPerClock
constexpr int QuotientBitsPerClock = WATKINS_RTL_PARAM_QuotientBitsPerClock;
#else
constexpr int QuotientBitsPerClock = 2;
#endif
#ifdef WATKINS_RTL_PARAM_Lanes
constexpr int Lanes = WATKINS_RTL_PARAM_Lanes;
#else
constexpr int Lanes = 1;
#endif
#ifdef WATKINS_RTL_PARAM_PolyIdBits
constexpr int PolyIdBits = WATKINS_RTL_PARAM_PolyIdBits;
constexpr int MaterialIdBits = WATKINS_RTL_PARAM_MaterialIdBits;
#else
constexpr int PolyIdBits = fmt::PolyIdBits;
constexpr int MaterialIdBits = fmt::MaterialIdBits;
#endif

// The configuration the unit was built at: when PARAMS set the widths, WATKINS_UNIT_CONFIG's (a
// file under the source folder), the sized default scene's unless the build names another.
#ifndef WATKINS_UNIT_CONFIG
#define WATKINS_UNIT_CONFIG "scenes/sized/default.gouraud.json"
#endif
const Config& unit_config() {
#ifdef WATKINS_RTL_PARAM_XBits
  static const Config c = load_config(WATKINS_SOURCE_DIR "/" WATKINS_UNIT_CONFIG);
#else
  static const Config c;
#endif
  return c;
}
const ChannelFormats& formats() {
  static const ChannelFormats f = unit_config().channels(ShadingMode::Gouraud);
  return f;
}

struct Item {
  bool eol = false;
  Segment seg;
};

struct Frag {
  bool eol;
  int x;
  std::uint32_t depth, rgb;
  std::uint64_t normal;  // {Nz, Ny, Nx}, NormalInBits each
  int material;
  int poly;
  std::uint64_t span;  // the item it comes from
  int k;               // its pixel's index in the span (x - x_start)
};

// 1.0 in slot c's unit; a value wrapped to the slot's word.
i64 one(int c) { return i64{1} << formats().frac[c]; }
i64 word(int c, i128 v) { return wrap_signed(v, formats().bits[c]); }

Segment random_segment(std::mt19937_64& rng, int width) {
  Segment s;
  auto rnd = [&](i64 lo, i64 hi) { return lo + static_cast<i64>(rng() % static_cast<std::uint64_t>(hi - lo + 1)); };
  const i64 One = one(fmt::ChanX);
  const i64 XMax = (i64{1} << (formats().bits[fmt::ChanX] - 1)) - 1;  // the X word's range
  const int kind = static_cast<int>(rng() % 10);
  i64 xe, xf;
  switch (kind) {
    case 0:  // narrower than a pixel, anywhere
      xe = rnd(-2 * One, (width + 2) * One);
      xf = xe + rnd(1, One);
      break;
    case 1:  // clipped at both ends, up to the word's range
      xe = rnd(-XMax, 0);
      xf = rnd(width * One, XMax);
      break;
    case 2:  // reversed or zero width: empty
      xe = rnd(0, width * One);
      xf = xe - rnd(0, 4 * One);
      break;
    case 3:  // full-range words (wrapped accumulations)
      xe = word(fmt::ChanX, static_cast<i128>(rng()));
      xf = word(fmt::ChanX, static_cast<i128>(rng()));
      break;
    case 4:  // tiny widths in X units
      xe = rnd(-One, width * One);
      xf = xe + rnd(1, 64);
      break;
    default:  // ordinary span
      xe = rnd(-4 * One, (width + 4) * One);
      xf = xe + rnd(1, (width / 2 + 2) * One);
      break;
  }
  s.e[fmt::ChanX] = word(fmt::ChanX, xe);
  s.f[fmt::ChanX] = word(fmt::ChanX, xf);
  const int depth_bits = formats().depth_bits;
  for (int c = fmt::ChanZ; c < NC; ++c) {
    const i64 u = one(c);
    if (rng() % 6 == 0) {
      s.e[c] = word(c, static_cast<i128>(rng()));
      s.f[c] = word(c, static_cast<i128>(rng()));
    } else if (c == fmt::ChanZ) {
      const i64 range = (i64{1} << depth_bits) * u;
      s.e[c] = word(c, rnd(-range / 16, range + range / 16));
      s.f[c] = word(c, rnd(-range / 16, range + range / 16));
    } else {
      s.e[c] = word(c, rnd(-40 * u, 300 * u));
      s.f[c] = word(c, rnd(-40 * u, 300 * u));
    }
  }
  s.poly = static_cast<int>(rng() % (1u << PolyIdBits));
  s.material = static_cast<int>(rng() % (1u << MaterialIdBits));
  return s;
}

// A span of n pixels from pixel x0 (before clipping to [0, width)): X_E and X_F each a random
// fraction of a pixel left of a pixel centre, so centres x0 + 1/2 .. x0 + n - 1/2 are covered.
Segment span_of(std::mt19937_64& rng, int x0, int n) {
  Segment s = random_segment(rng, 64);  // its channel words; X set below
  const i64 One = one(fmt::ChanX);
  auto below_centre = [&](int x) { return x * One + 1 + static_cast<i64>(rng() % static_cast<std::uint64_t>(One / 2)); };
  s.e[fmt::ChanX] = word(fmt::ChanX, below_centre(x0));
  s.f[fmt::ChanX] = word(fmt::ChanX, below_centre(x0 + n));
  return s;
}

// Spans of 1 to 9 pixels anywhere on a line of `width` pixels and a little past both ends (so
// clipped at 0 and at the width to every count), a marker every eol_every items on average.
std::vector<Item> short_spans(std::mt19937_64& rng, int n, int width, int eol_every) {
  std::vector<Item> items(static_cast<std::size_t>(n));
  for (Item& it : items) {
    it.eol = rng() % static_cast<std::uint64_t>(eol_every) == 0;
    const int len = 1 + static_cast<int>(rng() % 9);
    const int x0 = -10 + static_cast<int>(rng() % static_cast<std::uint64_t>(width + 20));
    it.seg = span_of(rng, x0, len);
  }
  return items;
}

void expected(const Item& it, std::uint64_t index, int width, std::deque<Frag>& out) {
  if (it.eol) {
    out.push_back({true, 0, 0, 0, 0, 0, 0, index, 0});
    return;
  }
  const SpanSetup span = SegmentInterpolator::setup(it.seg, width, formats());
  ChannelVector v = span.value;
  for (int x = span.x_start; x < span.x_end; ++x) {
    const Fragment f = SegmentInterpolator::fragment(span, x, v);
    std::uint64_t n = 0;
    for (int c = 0; c < 3; ++c) n |= wrap_unsigned(f.normal[c], fmt::NormalInBits) << (c * fmt::NormalInBits);
    out.push_back({false, x, f.depth, (std::uint32_t(f.rgb[0]) << 16) | (std::uint32_t(f.rgb[1]) << 8) | f.rgb[2], n,
                   f.material, f.poly, index, x - span.x_start});
    SegmentInterpolator::step(span, v);
  }
}

struct Result {
  std::uint64_t cycles = 0, fragments = 0, items = 0;
  int worst_line = 0;  // clocks between two markers leaving, at most
};

class Bench {
 public:
  std::uint64_t checked = 0, mismatches = 0, timing_mismatches = 0;

  explicit Bench(std::uint64_t seed) : rng_(seed) {}

  // The items through the unit from reset, offered with gap_pct % gaps, taken with bp_pct %
  // back-pressure; each output beat against the twin, each cycle against the cycle twin.
  Result run(const std::vector<Item>& items, int width, int gap_pct, int bp_pct) {
    Harness<Vcompact_segment_interpolator> h;
    const ChannelFormats& f = formats();
    CompactSegmentInterpolatorTiming twin(f.bits[fmt::ChanX], f.bits[fmt::ChanZ], f.bits[fmt::ChanR],
                                          QuotientBitsPerClock, Lanes);
    const tb::ChannelLayout slots = tb::ChannelLayout::of(f);
    Stalls gaps{rng_, gap_pct}, bp{rng_, bp_pct};
    auto& d = h.dut;
    d.seg_valid_i = 0;
    d.frag_ready_i = 0;
    d.width_i = width;
    h.reset();
    std::deque<Frag> want;
    std::size_t next = 0;
    bool offered = false;
    CompactSegmentInterpolatorTiming::Item titem;
    Result res;
    std::uint64_t moved = 0, last_marker = 0;
    int reported = 0;
    auto fail = [&](const std::string& what) {
      if (reported++ < 8) ADD_FAILURE() << "cycle " << res.cycles << ": " << what;
    };
    while (next < items.size() || offered || !want.empty()) {
      if (!offered && next < items.size() && !gaps.stall()) {
        const Item& it = items[next];
        for (int c = 0; c < NC; ++c) {
          set_bits(d.seg_e_i, slots.lsb[c], slots.bits[c], to_bits(it.seg.e[c], slots.bits[c]));
          set_bits(d.seg_f_i, slots.lsb[c], slots.bits[c], to_bits(it.seg.f[c], slots.bits[c]));
        }
        d.seg_poly_i = static_cast<std::remove_reference_t<decltype(d.seg_poly_i)>>(it.seg.poly);
        d.seg_material_i = static_cast<std::remove_reference_t<decltype(d.seg_material_i)>>(it.seg.material);
        d.seg_eol_i = it.eol;
        const auto px = SegmentInterpolator::pixels(it.seg, width, f.x_frac());
        titem = {it.eol, px.first, px.second};
        offered = true;
      }
      d.seg_valid_i = offered;
      d.frag_ready_i = !bp.stall();
      d.eval();
      const CompactSegmentInterpolatorTiming::Pins t = twin.clock(offered, titem, d.frag_ready_i);
      if ((offered && t.seg_ready != bool(d.seg_ready_o)) || t.frag_valid != bool(d.frag_valid_o) ||
          (t.frag_valid && (t.frag_eol != bool(d.frag_eol_o) || t.frag_pair != bool(d.frag_pair_o) ||
                            (!t.frag_eol && t.frag_x != int(d.frag_x_o))))) {
        ++timing_mismatches;
        fail("rtl seg_ready/frag_valid/eol/pair/x " + std::to_string(d.seg_ready_o) + std::to_string(d.frag_valid_o) +
             std::to_string(d.frag_eol_o) + std::to_string(d.frag_pair_o) + " " + std::to_string(d.frag_x_o) +
             ", cycle twin " + std::to_string(t.seg_ready) + std::to_string(t.frag_valid) +
             std::to_string(t.frag_eol) + std::to_string(t.frag_pair) + " " + std::to_string(t.frag_x));
      }
      // Lanes = 1: lane 1's ports are constant 0.
      if (Lanes == 1 && (d.frag_pair_o || d.frag_depth1_o || d.frag_rgb1_o)) {
        ++mismatches;
        fail("lane 1's ports not 0 at Lanes = 1");
      }
      if (d.frag_valid_o && d.frag_ready_i) {
        // The beat's fragments in stream order: lane 0, then lane 1 of a pair.
        const int lanes = d.frag_pair_o ? 2 : 1;
        std::uint64_t lane0_span = 0;
        for (int lane = 0; lane < lanes; ++lane) {
          if (want.empty()) {
            ADD_FAILURE() << "output without an expected fragment";
            return res;
          }
          const Frag& w = want.front();
          const int x = int(d.frag_x_o) + lane;
          const std::uint32_t depth = lane == 0 ? std::uint32_t(d.frag_depth_o) : std::uint32_t(d.frag_depth1_o);
          const std::uint32_t rgb = lane == 0 ? std::uint32_t(d.frag_rgb_o) : std::uint32_t(d.frag_rgb1_o);
          bool ok = d.frag_eol_o == w.eol &&
                    (w.eol || (x == w.x && depth == w.depth && rgb == w.rgb &&
                               (lane == 1 || d.frag_normal_o == w.normal) && int(d.frag_material_o) == w.material &&
                               int(d.frag_poly_o) == w.poly));
          // A pair's two fragments come from one span; lane 0 sits at an even pixel of its span.
          if (lane == 0) lane0_span = w.span;
          if (lane == 1 && w.span != lane0_span) ok = false;
          if (lane == 0 && !w.eol && w.k % Lanes != 0) ok = false;
          if (!ok) {
            ++mismatches;
            std::ostringstream diff;
            diff << "beat " << checked << " lane " << lane << ": rtl eol " << int(d.frag_eol_o) << " pair "
                 << int(d.frag_pair_o) << " x " << x << " depth " << depth << " rgb " << std::hex << rgb
                 << " normal " << d.frag_normal_o << std::dec << " material " << int(d.frag_material_o) << " poly "
                 << int(d.frag_poly_o) << "; model eol " << w.eol << " x " << w.x << " (pixel " << w.k
                 << " of item " << w.span << ") depth " << w.depth << " rgb " << std::hex << w.rgb << " normal "
                 << w.normal << std::dec << " material " << w.material << " poly " << w.poly;
            fail(diff.str());
          }
          if (w.eol) {
            res.worst_line = std::max(res.worst_line, static_cast<int>(res.cycles + 1 - last_marker));
            last_marker = res.cycles + 1;
          } else {
            ++res.fragments;
          }
          want.pop_front();
        }
        ++checked;
        moved = res.cycles;
      }
      const bool in_fire = offered && d.seg_ready_o;
      h.tick();
      ++res.cycles;
      if (in_fire) {
        expected(items[next], next, width, want);
        ++next;
        ++res.items;
        offered = false;
        moved = res.cycles;
      }
      if (res.cycles - moved > 10000) {
        ADD_FAILURE() << "hang: " << want.size() << " expected beats left, item " << next << " of " << items.size();
        return res;
      }
    }
    return res;
  }

  std::mt19937_64& rng() { return rng_; }

 private:
  std::mt19937_64 rng_;
};

// The segment stream a frame's segment former hands the interpolator, with its markers.
std::vector<Item> segment_stream(const PreparedScene& p, const Config& cfg) {
  std::vector<Item> items;
  PipelineObserver ob;
  ob.segment = [&](int, const Segment& s) { items.push_back({false, s}); };
  ob.segments_end = [&](int) { items.push_back({true, Segment{}}); };
  WatkinsTop(cfg).render(p, ob);
  return items;
}

std::vector<Item> random_items(std::mt19937_64& rng, int n, int width, int eol_every) {
  std::vector<Item> items(static_cast<std::size_t>(n));
  for (Item& it : items) {
    it.eol = rng() % static_cast<std::uint64_t>(eol_every) == 0;
    it.seg = random_segment(rng, width);
  }
  return items;
}

}  // namespace

TEST(RtlCompactSegmentInterpolator, UnitConfiguration) {
  // The bench's formats are the unit's parameters.
  const ChannelFormats f = formats();
#ifdef WATKINS_RTL_PARAM_XBits
  EXPECT_EQ(f.bits[fmt::ChanX], WATKINS_RTL_PARAM_XBits);
  EXPECT_EQ(f.frac[fmt::ChanX], WATKINS_RTL_PARAM_XFracBits);
  EXPECT_EQ(f.bits[fmt::ChanZ], WATKINS_RTL_PARAM_ZBits);
  EXPECT_EQ(f.frac[fmt::ChanZ], WATKINS_RTL_PARAM_ZFracBits);
  EXPECT_EQ(f.bits[fmt::ChanR], WATKINS_RTL_PARAM_AttrBits);
  EXPECT_EQ(f.frac[fmt::ChanR], WATKINS_RTL_PARAM_AttrFracBits);
  EXPECT_EQ(f.depth_bits, WATKINS_RTL_PARAM_DepthBits);
#endif
  const ChannelFormats g = formats();
  const CompactSegmentInterpolatorTiming t(g.bits[fmt::ChanX], g.bits[fmt::ChanZ], g.bits[fmt::ChanR],
                                           QuotientBitsPerClock, Lanes);
  std::printf("issue %d clocks, %d divider iterations, a span every %d clocks\n", t.issue_clocks(), t.iterations(),
              t.span_clocks());
  // The header's latencies, on the cycle twin (which every other test holds equal to the RTL): a
  // span offered at clock 0 to an idle block, its first fragment on the output; a marker.
  auto first_out = [&](const CompactSegmentInterpolatorTiming::Item& in) {
    CompactSegmentInterpolatorTiming twin(g.bits[fmt::ChanX], g.bits[fmt::ChanZ], g.bits[fmt::ChanR],
                                          QuotientBitsPerClock, Lanes);
    bool offered = true;
    for (int cycle = 0; cycle < 1000; ++cycle) {
      const auto pins = twin.clock(offered, in, true);
      if (pins.frag_valid) return cycle;
      if (offered && pins.seg_ready) offered = false;
    }
    return -1;
  };
  EXPECT_EQ(first_out({false, 3, 9}), 2 + t.iterations() + t.issue_clocks() + 7);
  EXPECT_EQ(first_out({true, 0, 0}), 3);
  // Throughput: a span of n pixels leaves in ceil(n / Lanes) beats on consecutive clocks, the
  // last of an odd count at Lanes = 2 without its pair.
  for (const int n : {1, 2, 3, 6, 7}) {
    CompactSegmentInterpolatorTiming twin(g.bits[fmt::ChanX], g.bits[fmt::ChanZ], g.bits[fmt::ChanR],
                                          QuotientBitsPerClock, Lanes);
    bool offered = true;
    int first = -1, last = -1, beats = 0, fragments = 0;
    for (int cycle = 0; cycle < 1000; ++cycle) {
      const auto pins = twin.clock(offered, {false, 5, 5 + n}, true);
      if (offered && pins.seg_ready) offered = false;
      if (!pins.frag_valid) continue;
      if (first < 0) first = cycle;
      last = cycle;
      ++beats;
      fragments += pins.frag_pair ? 2 : 1;
      EXPECT_EQ(pins.frag_x, 5 + (beats - 1) * Lanes);
      EXPECT_EQ(pins.frag_pair, Lanes == 2 && pins.frag_x + 1 < 5 + n);
    }
    EXPECT_EQ(fragments, n);
    EXPECT_EQ(beats, (n + Lanes - 1) / Lanes);
    EXPECT_EQ(last - first + 1, beats);
  }
}

TEST(RtlCompactSegmentInterpolator, RandomSegmentsFullRate) {
  Bench b(1);
  b.run(random_items(b.rng(), 30000, 97, 6), 97, 0, 0);
  EXPECT_EQ(b.mismatches, 0u);
  EXPECT_EQ(b.timing_mismatches, 0u);
  EXPECT_GT(b.checked, 30000u);
}

TEST(RtlCompactSegmentInterpolator, RandomSegmentsGapsAndBackPressure) {
  Bench b(2);
  b.run(random_items(b.rng(), 20000, 64, 5), 64, 35, 35);
  b.run(random_items(b.rng(), 5000, 320, 8), 320, 10, 70);
  b.run(random_items(b.rng(), 5000, 1, 3), 1, 20, 20);  // one pixel wide
  EXPECT_EQ(b.mismatches, 0u);
  EXPECT_EQ(b.timing_mismatches, 0u);
}

// Spans of 1 to 9 pixels (odd and even counts, clipped at 0 and at the width to any count), with
// markers, on lines of odd and even widths: at full rate and under gaps and back-pressure.
TEST(RtlCompactSegmentInterpolator, ShortSpans) {
  Bench b(5);
  for (const int width : {1, 2, 7, 8, 97, 320}) {
    const std::vector<Item> items = short_spans(b.rng(), 3000, width, 4);
    b.run(items, width, 0, 0);
    b.run(items, width, 30, 30);
    b.run(items, width, 5, 60);
  }
  EXPECT_EQ(b.mismatches, 0u);
  EXPECT_EQ(b.timing_mismatches, 0u);
}

// Random scenes prepared at the unit's configuration: their segment streams, full rate and stalled.
TEST(RtlCompactSegmentInterpolator, RandomScenes) {
  Bench b(3);
  const Config& cfg = unit_config();
  int ran = 0;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    PreparedScene p;
    try {
      p = prepare(test::random_scene(seed), cfg);
    } catch (const std::exception&) {
      continue;
    }
    const std::vector<Item> items = segment_stream(p, cfg);
    b.run(items, p.width, 0, 0);
    b.run(items, p.width, 30, 30);
    ++ran;
  }
  std::printf("%d random scenes, %llu beats\n", ran, static_cast<unsigned long long>(b.checked));
  EXPECT_GT(ran, 20);
  EXPECT_EQ(b.mismatches, 0u);
  EXPECT_EQ(b.timing_mismatches, 0u);
}

// Every shipped scene (scenes/*.json) that prepares at the unit's configuration: at full rate (its
// fragments per clock and longest line printed) and under gaps and back-pressure.
TEST(RtlCompactSegmentInterpolator, ShippedScenes) {
  Bench b(4);
  const Config& cfg = unit_config();
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(WATKINS_SOURCE_DIR "/scenes"))
    if (e.path().extension() == ".json") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  int ran = 0;
  for (const std::string& file : files) {
    PreparedScene p;
    try {
      p = prepare(load_scene(file, test::shading_options(ShadingMode::Gouraud)), cfg);
      if (p.config.edge_order != cfg.edge_order) continue;
    } catch (const std::exception&) {
      continue;  // needs more than this configuration
    }
    const std::vector<Item> items = segment_stream(p, cfg);
    const Result r = b.run(items, p.width, 0, 0);
    std::printf("  %s: %llu segments, %llu fragments in %llu clocks (%.3f per clock), longest line %d clocks\n",
                std::filesystem::path(file).filename().c_str(),
                static_cast<unsigned long long>(r.items - static_cast<std::uint64_t>(p.height)),
                static_cast<unsigned long long>(r.fragments), static_cast<unsigned long long>(r.cycles),
                double(r.fragments) / double(std::max<std::uint64_t>(r.cycles, 1)), r.worst_line);
    b.run(items, p.width, 25, 25);
    ++ran;
  }
  std::printf("%d shipped scenes\n", ran);
  EXPECT_GT(ran, 0);
  EXPECT_EQ(b.mismatches, 0u);
  EXPECT_EQ(b.timing_mismatches, 0u);
}

// The cycle twin alone (no RTL) on each shipped scene's segment stream at its own sized Gouraud
// configuration (scenes/sized/<scene>.gouraud.json), items offered back to back and fragments
// taken every clock: fragments per clock and the longest line (clocks between two markers
// leaving), the figures the compact top's throughput and line deadline build on.
TEST(RtlCompactSegmentInterpolator, CycleTwinAtSizedConfigurations) {
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
    const Config cfg = load_config(WATKINS_SOURCE_DIR "/scenes/sized/" + name + ".gouraud.json");
    const PreparedScene p = prepare(load_scene(scene, test::shading_options(ShadingMode::Gouraud)), cfg);
    const ChannelFormats f = cfg.channels(ShadingMode::Gouraud);
    CompactSegmentInterpolatorTiming t(f.bits[fmt::ChanX], f.bits[fmt::ChanZ], f.bits[fmt::ChanR],
                                       QuotientBitsPerClock, Lanes);
    const std::vector<Item> items = segment_stream(p, cfg);
    std::size_t next = 0;
    long long cycle = 0, fragments = 0, last_marker = 0, markers = 0;
    int worst = 0;
    while (markers < p.height) {
      CompactSegmentInterpolatorTiming::Item in;
      const bool valid = next < items.size();
      if (valid) {
        const auto px = SegmentInterpolator::pixels(items[next].seg, p.width, f.x_frac());
        in = {items[next].eol, px.first, px.second};
      }
      const CompactSegmentInterpolatorTiming::Pins pins = t.clock(valid, in, true);
      if (pins.frag_valid && pins.frag_eol) {
        worst = std::max(worst, static_cast<int>(cycle + 1 - last_marker));
        last_marker = cycle + 1;
        ++markers;
      } else if (pins.frag_valid) {
        fragments += pins.frag_pair ? 2 : 1;
      }
      if (valid && pins.seg_ready) ++next;
      ASSERT_LT(++cycle, 100000000);
    }
    std::printf("  %s (%dx%d, X %d bits): %lld fragments in %lld clocks (%.3f per clock), longest line %d clocks\n",
                name.c_str(), p.width, p.height, f.bits[fmt::ChanX], fragments, cycle,
                double(fragments) / double(cycle), worst);
    ++ran;
  }
  EXPECT_GT(ran, 10);
}
