// rtl/compact_segment_former.sv against SegmentFormer (values) and CompactSegmentFormerTiming
// (cycles): every segment's E, F, polygon and material in closing order and every marker equal
// the value twin's, and in every cycle edge_ready_o and seg_valid_o equal the cycle twin's, under
// random valid gaps and segment back-pressure.
// Streams: the active-edge streams the pipeline's twin (WatkinsTop) produces for the shipped scenes
// that fit the unit (each scenes/sized/ configuration whose polygon ids and channel vector fit,
// with its scene, and on the default build each scene at the default configuration) and for random
// scenes, the expected segments the twin's own segment stream; random lines (2 and 4 edges of one
// polygon, interleaved and nested polygons, an edge left open at a line's end that must not pair
// with the next line's edge of its polygon, ids 0 and the largest, empty lines); a polygon left
// open on one line and next seen 2^PolyIdBits lines later (the table's tag comes round); and the
// clock count worked by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "Vcompact_segment_former.h"
#include "build_options.hpp"
#include "compact_segment_former_timing.hpp"
#include "config_file.hpp"
#include "edge_packing.hpp"
#include "prepare.hpp"
#include "random_scene.hpp"
#include "rtl_harness.hpp"
#include "scene.hpp"
#include "scene_error.hpp"
#include "segment_former.hpp"
#include "shipped_scenes.hpp"
#include "twin_error.hpp"
#include "watkins_top.hpp"

using namespace watkins;
using namespace watkins::rtl;
using namespace watkins::test;

namespace {

// PARAMS in tests/rtl/CMakeLists.txt.
constexpr int VectorBits = WATKINS_RTL_PARAM_VectorBits;
constexpr int PolyIdBits = WATKINS_RTL_PARAM_PolyIdBits;
constexpr int MaterialIdBits = WATKINS_RTL_PARAM_MaterialIdBits;

struct In {
  bool eol = false;
  int poly = 0, material = 0;
  ChannelVector value{};
};
struct Out {
  bool eol = false;
  Segment seg;
};

// One frame's streams: the edges of each line then its marker, and the segments of each line then
// its marker; the channel layout the values are packed with.
struct Stream {
  std::string name;
  tb::ChannelLayout layout;
  std::deque<In> in;
  std::deque<Out> want;
};

// One unit, reset once, running streams back to back; the cycle twin clocked beside it.
class Bench {
 public:
  Bench(std::uint64_t seed, int gap_pct, int bp_pct) : rng_(seed), gaps_{rng_, gap_pct}, bp_{rng_, bp_pct} {
    h_.dut.edge_valid_i = 0;
    h_.dut.seg_ready_i = 0;
    h_.reset();
  }

  bool run(Stream s) {
    bool offered = false;
    std::uint64_t idle = 0;
    while (!s.want.empty()) {
      if (!offered && !s.in.empty() && !gaps_.stall()) {
        const In& i = s.in.front();
        h_.dut.edge_eol_i = i.eol;
        h_.dut.edge_poly_i = i.poly;
        h_.dut.edge_material_i = i.material;
        for (int c = 0; c < fmt::NumChannels; ++c)
          set_bits(h_.dut.edge_value_i, s.layout.lsb[c], s.layout.bits[c], to_bits(i.value[c], s.layout.bits[c]));
        offered = true;
      }
      h_.dut.edge_valid_i = offered;
      const bool ready = !bp_.stall();
      h_.dut.seg_ready_i = ready;
      h_.dut.eval();
      const bool eol = h_.dut.edge_eol_i;
      const int poly = static_cast<int>(h_.dut.edge_poly_i);
      if (bool(h_.dut.edge_ready_o) != timing_.edge_ready(ready) || bool(h_.dut.seg_valid_o) != timing_.seg_valid()) {
        if (cycle_mismatches++ < 8)
          ADD_FAILURE() << s.name << ": cycle " << h_.cycles << ": rtl edge_ready " << int(h_.dut.edge_ready_o)
                        << " seg_valid " << int(h_.dut.seg_valid_o) << "; twin " << timing_.edge_ready(ready) << " "
                        << timing_.seg_valid();
      }
      const bool in_fire = offered && h_.dut.edge_ready_o;
      if (h_.dut.seg_valid_o && ready) {
        const Out& w = s.want.front();
        std::ostringstream d;
        if (bool(h_.dut.seg_eol_o) != w.eol) {
          d << "eol " << int(h_.dut.seg_eol_o) << " want " << w.eol;
        } else if (!w.eol) {
          const ChannelVector e = s.layout.read(tap(h_.dut.seg_e_o));
          const ChannelVector f = s.layout.read(tap(h_.dut.seg_f_o));
          if (int(h_.dut.seg_poly_o) != w.seg.poly || int(h_.dut.seg_material_o) != w.seg.material || e != w.seg.e ||
              f != w.seg.f)
            d << "segment of poly " << h_.dut.seg_poly_o << " material " << int(h_.dut.seg_material_o)
              << "; want poly " << w.seg.poly << " material " << w.seg.material << (e != w.seg.e ? " (E differs)" : "")
              << (f != w.seg.f ? " (F differs)" : "");
        }
        if (!d.str().empty() && mismatches++ < 8) ADD_FAILURE() << s.name << ": output " << checked << ": " << d.str();
        s.want.pop_front();
        ++checked;
        last_take = h_.cycles;
        idle = 0;
      }
      timing_.clock(offered, eol, poly, ready);
      h_.tick();
      if (in_fire) {
        s.in.pop_front();
        offered = false;
        idle = 0;
      }
      if (++idle > 100000 + (1 << PolyIdBits)) {
        ADD_FAILURE() << s.name << ": hang, " << s.want.size() << " outputs left";
        return false;
      }
    }
    EXPECT_TRUE(s.in.empty()) << s.name;
    return s.in.empty();
  }

  std::mt19937_64& rng() { return rng_; }

  std::uint64_t checked = 0, mismatches = 0, cycle_mismatches = 0;
  std::uint64_t last_take = 0;  // the cycle (counted from the reset's first) of the last output taken

 private:
  // A Verilated vector as 32-bit words (VlWide, or QData / IData when 64 bits or fewer).
  template <class W>
  static const std::uint32_t* tap(const W& w) {
    if constexpr (std::is_integral_v<W>)
      return reinterpret_cast<const std::uint32_t*>(&w);
    else
      return w.data();
  }

  Harness<Vcompact_segment_former> h_;
  std::mt19937_64 rng_;
  Stalls gaps_, bp_;
  CompactSegmentFormerTiming timing_{PolyIdBits};
};

// The unit's own layout: the sized default scene's on the sized build, else the default's.
tb::ChannelLayout unit_layout() {
  const Config sized = load_config(WATKINS_SOURCE_DIR "/scenes/sized/default.gouraud.json");
  const tb::ChannelLayout l = tb::ChannelLayout::of(sized.channels(ShadingMode::Gouraud));
  if (l.vector_bits == VectorBits) return l;
  return tb::ChannelLayout::of(Config{}.channels(ShadingMode::Gouraud));
}

// Lines of edges through SegmentFormer: the stream of a frame.
Stream lines_stream(const std::string& name, const std::vector<std::vector<In>>& lines) {
  Stream s;
  s.name = name;
  s.layout = unit_layout();
  SegmentFormer former;
  for (const auto& line : lines) {
    std::vector<ActiveEdge> edges;
    for (const In& i : line) {
      ActiveEdge e;
      e.rec.poly = i.poly;
      e.rec.material = i.material;
      e.rec.value = i.value;
      edges.push_back(e);
      s.in.push_back(i);
    }
    s.in.push_back({true, 0, 0, {}});
    std::vector<Segment> segs;
    former.pair(edges, segs);
    for (const Segment& g : segs) s.want.push_back({false, g});
    s.want.push_back({true, {}});
  }
  return s;
}

ChannelVector random_value(std::mt19937_64& rng, const tb::ChannelLayout& l) {
  ChannelVector v{};
  for (int c = 0; c < fmt::NumChannels; ++c) v[c] = wrap_signed(static_cast<i128>(rng()), l.bits[c]);
  return v;
}

int random_poly(std::mt19937_64& rng) {
  const int max = (1 << PolyIdBits) - 1;
  switch (rng() % 8) {
    case 0: return 0;
    case 1: return max;
    case 2: return static_cast<int>(rng() % 4);  // few ids: the same ids across lines
    default: return static_cast<int>(rng() % (max + 1));
  }
}

// One line's polygon ids, left to right: pairs, 4-edge polygons, nesting and interleaving, odd
// counts (an edge left open).
std::vector<int> random_line_polys(std::mt19937_64& rng) {
  std::vector<int> l;
  const int polys = static_cast<int>(rng() % 8);
  for (int k = 0; k < polys; ++k) {
    const int p = random_poly(rng);
    const int n = (rng() % 6 == 0) ? 4 : (rng() % 8 == 0) ? 1 : (rng() % 10 == 0) ? 3 : 2;
    for (int i = 0; i < n; ++i) l.insert(l.begin() + static_cast<long>(rng() % (l.size() + 1)), p);
  }
  return l;
}

void random_lines(int frames, int gap_pct, int bp_pct, std::uint64_t seed) {
  Bench b(seed, gap_pct, bp_pct);
  const tb::ChannelLayout l = unit_layout();
  for (int fr = 0; fr < frames; ++fr) {
    std::vector<std::vector<In>> lines;
    const int n = 1 + static_cast<int>(b.rng()() % 20);
    for (int y = 0; y < n; ++y) {
      std::vector<In> line;
      for (const int p : random_line_polys(b.rng()))
        line.push_back({false, p, static_cast<int>(b.rng()() % (1u << MaterialIdBits)), random_value(b.rng(), l)});
      lines.push_back(line);
    }
    ASSERT_TRUE(b.run(lines_stream("random frame " + std::to_string(fr), lines)));
  }
  EXPECT_EQ(b.mismatches, 0u);
  EXPECT_EQ(b.cycle_mismatches, 0u);
  EXPECT_GT(b.checked, 0u);
}

// The active-edge and segment streams of a prepared scene from WatkinsTop's observer.
Stream scene_stream(const PreparedScene& p, const std::string& name) {
  Stream s;
  s.name = name;
  s.layout = tb::ChannelLayout::of(p.config.channels(p.shading));
  PipelineObserver o;
  o.active_edge = [&](int, const ActiveEdge& e) { s.in.push_back({false, e.rec.poly, e.rec.material, e.rec.value}); };
  o.active_edges_end = [&](int) { s.in.push_back({true, 0, 0, {}}); };
  o.segment = [&](int, const Segment& g) { s.want.push_back({false, g}); };
  o.segments_end = [&](int) { s.want.push_back({true, {}}); };
  WatkinsTop(p.config).render(p, o);
  return s;
}

bool fits(const PreparedScene& p) {
  return p.polygons <= (1 << PolyIdBits) && tb::ChannelLayout::of(p.config.channels(p.shading)).vector_bits <= VectorBits &&
         (p.shading == ShadingMode::Gouraud || p.materials.size() <= (1u << MaterialIdBits));
}

std::vector<std::pair<std::string, PreparedScene>> shipped_frames() {
  std::vector<std::pair<std::string, PreparedScene>> v;
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(WATKINS_SOURCE_DIR "/scenes/sized")) {
    const std::string n = e.path().filename().string();
    if (e.path().extension() == ".json" && n.find(".curves.") == std::string::npos) names.push_back(n);
  }
  std::sort(names.begin(), names.end());
  for (const std::string& n : names) {
    const Config cfg = load_config(WATKINS_SOURCE_DIR "/scenes/sized/" + n);
    const std::string scene = n.substr(0, n.find('.'));
    const ShadingMode mode = n.find(".phong.") != std::string::npos ? ShadingMode::Phong : ShadingMode::Gouraud;
    PreparedScene p = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/" + scene + ".json", shading_options(mode)), cfg);
    if (fits(p)) v.emplace_back(n, std::move(p));
  }
  if (unit_layout().vector_bits != tb::ChannelLayout::of(load_config(WATKINS_SOURCE_DIR
                                                                     "/scenes/sized/default.gouraud.json")
                                                             .channels(ShadingMode::Gouraud))
                                       .vector_bits)
    for (const std::string& path : shipped_scene_paths())
      for (const ShadingMode mode : {ShadingMode::Gouraud, ShadingMode::Phong}) {
        try {
          PreparedScene p = prepare(load_scene(path, shading_options(mode)));
          if (fits(p))
            v.emplace_back(std::filesystem::path(path).filename().string() +
                               (mode == ShadingMode::Phong ? " phong" : " gouraud"),
                           std::move(p));
        } catch (const SceneError&) {
        } catch (const CapacityError&) {
        }
      }
  return v;
}

void shipped(std::uint64_t seed, int gap_pct, int bp_pct, int min_scenes) {
  Bench b(seed, gap_pct, bp_pct);
  int n = 0;
  for (const auto& [name, p] : shipped_frames()) {
    ASSERT_TRUE(b.run(scene_stream(p, name))) << name;
    ++n;
  }
  EXPECT_GE(n, min_scenes);
  EXPECT_EQ(b.mismatches, 0u);
  EXPECT_EQ(b.cycle_mismatches, 0u);
  std::printf("compact_segment_former: %d shipped frames, %llu outputs\n", n, static_cast<unsigned long long>(b.checked));
}

void random_scenes(std::uint64_t seed, int count, int gap_pct, int bp_pct) {
  Bench b(seed, gap_pct, bp_pct);
  const Config sized = load_config(WATKINS_SOURCE_DIR "/scenes/sized/default.gouraud.json");
  const Config cfg = unit_layout().vector_bits == VectorBits &&
                             tb::ChannelLayout::of(sized.channels(ShadingMode::Gouraud)).vector_bits == VectorBits
                         ? sized
                         : Config{};
  int n = 0;
  for (std::uint64_t s = seed; n < count && s < seed + 20 * static_cast<std::uint64_t>(count); ++s) {
    PreparedScene p;
    try {
      p = prepare(random_scene(s), cfg);
    } catch (const SceneError&) {
      continue;
    }
    if (!fits(p)) continue;
    ASSERT_TRUE(b.run(scene_stream(p, "random scene " + std::to_string(s))));
    ++n;
  }
  EXPECT_EQ(n, count);
  EXPECT_EQ(b.mismatches, 0u);
  EXPECT_EQ(b.cycle_mismatches, 0u);
}

}  // namespace

TEST(RtlCompactSegmentFormer, RandomLinesFullRate) { random_lines(60, 0, 0, 1); }
TEST(RtlCompactSegmentFormer, RandomLinesGapsAndBackPressure) { random_lines(60, 40, 40, 2); }
TEST(RtlCompactSegmentFormer, RandomLinesHeavyBackPressure) { random_lines(30, 5, 80, 3); }
TEST(RtlCompactSegmentFormer, ShippedScenesFullRate) { shipped(21, 0, 0, 5); }
TEST(RtlCompactSegmentFormer, ShippedScenesStalled) { shipped(22, 30, 30, 5); }
TEST(RtlCompactSegmentFormer, RandomScenesStalled) { random_scenes(1, 60, 20, 20); }

// A polygon's edge left open on line 0 (entry tag 0), its id untouched for 2^PolyIdBits lines, so
// the line tag comes round to 0 again: the entry was cleared by a marker in between, so the
// polygon's next edge opens instead of closing with the stale one. Then a pair on that line.
TEST(RtlCompactSegmentFormer, OpenEntryOutlivesTheTag) {
  Bench b(5, 0, 0);
  const tb::ChannelLayout l = unit_layout();
  const int lines = (1 << PolyIdBits) + 3;
  for (const int p : {5, 0, (1 << PolyIdBits) - 1}) {
    std::vector<std::vector<In>> frame(static_cast<std::size_t>(lines));
    frame[0] = {{false, p, 0, random_value(b.rng(), l)}};
    for (int y = 1; y < lines; ++y) frame[static_cast<std::size_t>(y)] = {{false, p ^ 1, 0, random_value(b.rng(), l)}};
    frame[1 << PolyIdBits] = {{false, p, 0, random_value(b.rng(), l)}};
    frame[(1 << PolyIdBits) + 1] = {{false, p, 0, random_value(b.rng(), l)}, {false, p, 0, random_value(b.rng(), l)}};
    const Stream s = lines_stream("stale entry", frame);
    EXPECT_EQ(s.want.size(), static_cast<std::size_t>(lines + 1)) << "one segment, every marker";
    ASSERT_TRUE(b.run(s));
  }
  EXPECT_EQ(b.mismatches, 0u);
  EXPECT_EQ(b.cycle_mismatches, 0u);
}

// A line of two edges of one polygon and its marker, the output always ready, the edges always
// offered, by hand: the clear takes 2^PolyIdBits clocks after reset (0 .. 2^P - 1); the first edge
// goes in at clock 2^P, the second at 2^P + 2, whose segment is offered and taken at 2^P + 4; the
// marker goes in at 2^P + 4 (the segment taken in that clock) and is taken at 2^P + 6.
TEST(RtlCompactSegmentFormer, ClocksByHand) {
  Bench b(5, 0, 0);
  const tb::ChannelLayout l = unit_layout();
  const std::vector<std::vector<In>> frame{{{false, 3, 0, random_value(b.rng(), l)}, {false, 3, 0, random_value(b.rng(), l)}}};
  ASSERT_TRUE(b.run(lines_stream("by hand", frame)));
  EXPECT_EQ(b.last_take, static_cast<std::uint64_t>(2 + (1 << PolyIdBits) + 6));  // the reset's 2 clocks first
  EXPECT_EQ(b.checked, 2u);
}
