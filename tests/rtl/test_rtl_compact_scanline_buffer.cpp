// rtl/compact_scanline_buffer.sv against ScanlineBuffer (values) and CompactScanlineBufferTiming
// (cycles), full-frame output: every pixel's shade, coverage, position and last flag equal the
// value twin's, and in every cycle frag_ready_o and pixel_valid_o (with the offered pixel's
// position) equal the cycle twin's, under random valid gaps and pixel back-pressure.
// A beat is lane 0's fragment and, at Lanes = 2 with frag_pair_i, lane 1's at x + 1 of the same
// polygon; the value twin writes a beat's fragments in lane order.
// Streams: the fragment streams the pipeline's twin (WatkinsTop) produces for the shipped scenes
// that fit the unit's parameters (the sized configurations of scenes/sized/ on the sized build,
// the default configuration on the default build) and for random scenes, in beats (at Lanes = 2
// a fragment paired with the next when that one is at x + 1 of the same polygon); random
// fragment streams (same x back to back, few depths and few polygon ids so that ties are common,
// empty and full lines, both tie rules), at Lanes = 2 random beats (pairs from even and odd x, a
// beat's pixels hit again by either lane of the next beat, x = width - 1 alone); directed lines
// of equal depths sent back to back to one x (at Lanes = 2 through both lanes); and the clock
// count of empty frames worked by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "Vcompact_scanline_buffer.h"
#include "build_options.hpp"
#include "compact_scanline_buffer_timing.hpp"
#include "config_file.hpp"
#include "prepare.hpp"
#include "random_scene.hpp"
#include "rtl_harness.hpp"
#include "scanline_buffer.hpp"
#include "scene.hpp"
#include "scene_error.hpp"
#include "shipped_scenes.hpp"
#include "twin_error.hpp"
#include "watkins_top.hpp"

using namespace watkins;
using namespace watkins::rtl;
using namespace watkins::test;

namespace {

// PARAMS in tests/rtl/CMakeLists.txt.
constexpr int MaxWidth = WATKINS_RTL_PARAM_MaxWidth;
constexpr int DepthBits = WATKINS_RTL_PARAM_DepthBits;
constexpr int PolyIdBits = WATKINS_RTL_PARAM_PolyIdBits;
#ifndef WATKINS_RTL_PARAM_Lanes
#define WATKINS_RTL_PARAM_Lanes 1
#endif
constexpr int Lanes = WATKINS_RTL_PARAM_Lanes;
// The clear after reset: every way of the RAMs at once.
constexpr int ClearClocks = (MaxWidth + Lanes - 1) / Lanes;

// One input beat: lane 0, and lane 1 (f1, at f0.x + 1, f0's polygon) when pair is set.
struct Beat {
  Fragment f0;
  bool pair = false;
  Fragment f1;
};
using Line = std::vector<Beat>;

// A line's fragments in beats: one each at Lanes = 1; at Lanes = 2 a fragment and the next one
// share a beat when that one is at x + 1 of the same polygon (a span's pixels in pairs from its
// first, as the compact interpolator sends them).
Line beats_of(const std::vector<Fragment>& frags) {
  Line line;
  for (std::size_t i = 0; i < frags.size(); ++i) {
    Beat b;
    b.f0 = frags[i];
    if (Lanes == 2 && i + 1 < frags.size() && frags[i + 1].x == b.f0.x + 1 && frags[i + 1].poly == b.f0.poly) {
      b.pair = true;
      b.f1 = frags[++i];
    }
    line.push_back(b);
  }
  return line;
}

struct FrameSpec {
  std::string name;
  int width = 1;
  std::array<std::uint8_t, 3> bg{};
  DepthTie tie = DepthTie::Arrival;
  std::vector<Line> lines;
};

struct In {
  bool eol;
  Beat b;
};
struct Px {
  std::uint32_t rgb;
  bool covered, last;
  int x, y;
};

std::uint32_t pack(const std::array<std::uint8_t, 3>& p) {
  return (std::uint32_t(p[0]) << 16) | (std::uint32_t(p[1]) << 8) | p[2];
}
std::uint32_t rgb_word(const Fragment& f) {
  return (std::uint32_t(f.rgb[0]) << 16) | (std::uint32_t(f.rgb[1]) << 8) | f.rgb[2];
}

// One unit, reset once, running frames back to back; the cycle twin clocked beside it.
class Bench {
 public:
  Bench(std::uint64_t seed, int gap_pct, int bp_pct) : rng_(seed), gaps_{rng_, gap_pct}, bp_{rng_, bp_pct} {
    h_.dut.frag_valid_i = 0;
    h_.dut.frag_pair_i = 0;
    h_.dut.pixel_ready_i = 0;
    h_.dut.sparse_i = 0;
    h_.dut.width_i = 1;
    h_.dut.height_i = 1;
    h_.reset();
  }

  // Runs one frame; its pixels from the value twin (appended to `pixels` when given). False when
  // it stopped early.
  bool frame(const FrameSpec& spec, std::vector<std::array<std::uint8_t, 3>>* pixels = nullptr) {
    const int width = spec.width;
    const int height = static_cast<int>(spec.lines.size());
    h_.dut.width_i = width;
    h_.dut.height_i = height;
    h_.dut.background_i = pack(spec.bg);
    h_.dut.tie_submission_i = spec.tie == DepthTie::Submission;
    timing_.set_frame(width, height);
    std::deque<In> in;
    std::deque<Px> want;
    ScanlineBuffer model(width, spec.bg, spec.tie);
    for (int y = 0; y < height; ++y) {
      model.clear();
      for (const Beat& b : spec.lines[y]) {
        EXPECT_TRUE(!b.pair || (Lanes == 2 && b.f1.x == b.f0.x + 1 && b.f1.poly == b.f0.poly && b.f1.x < width))
            << spec.name << ": a bench beat breaks the lane rule";
        model.write(b.f0);
        if (b.pair) model.write(b.f1);
        in.push_back({false, b});
      }
      in.push_back({true, Beat{}});
      for (int x = 0; x < width; ++x) {
        want.push_back({pack(model.pixel(x)), model.covered(x), y == height - 1 && x == width - 1, x, y});
        if (pixels) pixels->push_back(model.pixel(x));
      }
    }
    bool offered = false;
    std::uint64_t idle = 0;
    while (!want.empty()) {
      if (!offered && !in.empty() && !gaps_.stall()) {
        const In& i = in.front();
        h_.dut.frag_eol_i = i.eol;
        h_.dut.frag_x_i = i.b.f0.x;
        h_.dut.frag_depth_i = i.b.f0.depth;
        h_.dut.frag_poly_i = i.b.f0.poly;
        h_.dut.frag_rgb_i = rgb_word(i.b.f0);
        h_.dut.frag_pair_i = i.b.pair;
        h_.dut.frag_depth1_i = i.b.pair ? i.b.f1.depth : 0;
        h_.dut.frag_rgb1_i = i.b.pair ? rgb_word(i.b.f1) : 0;
        offered = true;
      }
      h_.dut.frag_valid_i = offered;
      const bool ready = !bp_.stall();
      h_.dut.pixel_ready_i = ready;
      h_.dut.eval();
      // The cycle twin: this clock's handshakes.
      const bool eol = h_.dut.frag_eol_i;
      if (bool(h_.dut.frag_ready_o) != timing_.frag_ready(eol, ready) ||
          bool(h_.dut.pixel_valid_o) != timing_.pixel_valid() ||
          (timing_.pixel_valid() && (int(h_.dut.pixel_x_o) != timing_.pixel_x() ||
                                     int(h_.dut.pixel_y_o) != timing_.pixel_y() ||
                                     bool(h_.dut.pixel_last_o) != timing_.pixel_last()))) {
        if (cycle_mismatches++ < 8)
          ADD_FAILURE() << spec.name << ": cycle " << h_.cycles << ": rtl frag_ready " << int(h_.dut.frag_ready_o)
                        << " pixel_valid " << int(h_.dut.pixel_valid_o) << " (" << h_.dut.pixel_x_o << ", "
                        << h_.dut.pixel_y_o << "); twin " << timing_.frag_ready(eol, ready) << " "
                        << timing_.pixel_valid() << " (" << timing_.pixel_x() << ", " << timing_.pixel_y() << ")";
      }
      const bool in_fire = offered && h_.dut.frag_ready_o;
      if (h_.dut.pixel_valid_o && ready) {
        const Px& w = want.front();
        if (!(h_.dut.pixel_rgb_o == w.rgb && h_.dut.pixel_covered_o == w.covered && h_.dut.pixel_last_o == w.last &&
              int(h_.dut.pixel_x_o) == w.x && int(h_.dut.pixel_y_o) == w.y) &&
            mismatches++ < 8) {
          std::ostringstream d;
          d << spec.name << ": rtl (" << h_.dut.pixel_x_o << ", " << h_.dut.pixel_y_o << ") " << std::hex
            << h_.dut.pixel_rgb_o << " cov " << int(h_.dut.pixel_covered_o) << " last " << int(h_.dut.pixel_last_o)
            << "; model (" << std::dec << w.x << ", " << w.y << ") " << std::hex << w.rgb << " cov " << w.covered
            << " last " << w.last;
          ADD_FAILURE() << d.str();
        }
        want.pop_front();
        ++checked;
        last_take = h_.cycles;
        idle = 0;
      }
      timing_.clock(offered, eol, ready);
      h_.tick();
      if (in_fire) {
        in.pop_front();
        offered = false;
        idle = 0;
      }
      if (++idle > 100000) {
        ADD_FAILURE() << spec.name << ": hang, " << want.size() << " pixels left";
        return false;
      }
    }
    EXPECT_TRUE(in.empty()) << spec.name;
    h_.dut.frag_valid_i = 0;
    h_.dut.pixel_ready_i = 1;
    h_.dut.eval();
    EXPECT_FALSE(h_.dut.pixel_valid_o) << spec.name << ": extra pixel after the frame";
    return in.empty() && !h_.dut.pixel_valid_o;
  }

  std::mt19937_64& rng() { return rng_; }
  std::uint64_t cycles() const { return h_.cycles; }

  std::uint64_t checked = 0, mismatches = 0, cycle_mismatches = 0;
  std::uint64_t last_take = 0;  // the cycle (counted from reset's end) of the last pixel taken

 private:
  Harness<Vcompact_scanline_buffer> h_;
  std::mt19937_64 rng_;
  Stalls gaps_, bp_;
  CompactScanlineBufferTiming timing_{MaxWidth, Lanes};
};

// Random fragment frames as the pipelined unit's bench draws them.
FrameSpec random_frame(std::mt19937_64& rng, int fr, int tie) {
  FrameSpec spec;
  spec.name = "random frame " + std::to_string(fr);
  spec.width = (fr % 3 == 0) ? MaxWidth : 1 + static_cast<int>(rng() % MaxWidth);
  const int height = 1 + static_cast<int>(rng() % 12);
  spec.bg = {std::uint8_t(rng()), std::uint8_t(rng()), std::uint8_t(rng())};
  spec.tie = (tie == 1 || (tie == 2 && fr % 4 >= 2)) ? DepthTie::Submission : DepthTie::Arrival;
  const std::uint32_t depth_max = DepthBits >= 32 ? 0xffffffffu : (1u << DepthBits) - 1;
  const std::uint32_t poly_max = PolyIdBits >= 31 ? 0x7fffffffu : (1u << PolyIdBits) - 1;
  for (int y = 0; y < height; ++y) {
    const int n = (rng() % 5 == 0) ? 0 : static_cast<int>(rng() % (3 * spec.width));
    const std::uint32_t depth_range = (rng() % 2) ? 4 : depth_max + 1;  // few depths: many ties
    const std::uint32_t poly_range = (rng() % 2) ? 6 : poly_max + 1;    // few ids: equal ids too
    int x = static_cast<int>(rng() % spec.width);
    auto draw = [&](Fragment& f) {
      f.depth = static_cast<std::uint32_t>(rng() % depth_range);
      if (rng() % 16 == 0) f.depth = depth_max;
      for (auto& c : f.rgb) c = static_cast<std::uint8_t>(rng());
    };
    auto draw_poly = [&]() {
      const int poly = static_cast<int>(rng() % poly_range);
      return rng() % 16 == 0 ? static_cast<int>(poly_max) : poly;
    };
    if (Lanes == 1) {
      std::vector<Fragment> frags;
      for (int i = 0; i < n; ++i) {
        Fragment f;
        if (rng() % 3) x = static_cast<int>(rng() % spec.width);  // else the same x again
        f.x = x;
        f.depth = static_cast<std::uint32_t>(rng() % depth_range);
        if (rng() % 16 == 0) f.depth = depth_max;
        f.poly = draw_poly();
        for (auto& c : f.rgb) c = static_cast<std::uint8_t>(rng());
        frags.push_back(f);
      }
      spec.lines.push_back(beats_of(frags));
      continue;
    }
    // Lanes = 2: the next beat anywhere, or on the last beat's pixels (x - 1, x, x + 1: a pixel
    // of one lane hit by the other lane or the same), or the span's next pair, or the last x.
    Line line;
    for (int i = 0; i < n; ++i) {
      switch (rng() % 8) {
        case 0: case 1: case 2: x = static_cast<int>(rng() % spec.width); break;
        case 3: break;
        case 4: x = x - 1; break;
        case 5: x = x + 1; break;
        case 6: x = x + 2; break;
        default: x = spec.width - 1; break;
      }
      x = std::clamp(x, 0, spec.width - 1);
      Beat b;
      b.f0.x = x;
      b.f0.poly = draw_poly();
      draw(b.f0);
      b.pair = x + 1 < spec.width && rng() % 4 != 0;
      if (b.pair) {
        b.f1.x = x + 1;
        b.f1.poly = b.f0.poly;
        draw(b.f1);
      }
      line.push_back(b);
    }
    spec.lines.push_back(line);
  }
  return spec;
}

void random_frames(int frames, int gap_pct, int bp_pct, std::uint64_t seed, int tie) {
  Bench b(seed, gap_pct, bp_pct);
  for (int fr = 0; fr < frames; ++fr) ASSERT_TRUE(b.frame(random_frame(b.rng(), fr, tie)));
  EXPECT_EQ(b.mismatches, 0u);
  EXPECT_EQ(b.cycle_mismatches, 0u);
  EXPECT_GT(b.checked, 0u);
}

// The fragment stream WatkinsTop gives the line buffer for a prepared scene, line by line; the
// rendered image returned in `img`.
FrameSpec scene_frame(const PreparedScene& p, const std::string& name, Image* img = nullptr) {
  FrameSpec spec;
  spec.name = name;
  spec.width = p.width;
  spec.bg = p.background;
  spec.tie = p.depth_tie;
  spec.lines.assign(static_cast<std::size_t>(p.height), {});
  std::vector<std::vector<Fragment>> frags(static_cast<std::size_t>(p.height));
  PipelineObserver o;
  o.fragment = [&](int y, const Fragment& f, bool) { frags[static_cast<std::size_t>(y)].push_back(f); };
  Image im = WatkinsTop(p.config).render(p, o);
  if (img) *img = std::move(im);
  for (int y = 0; y < p.height; ++y)
    spec.lines[static_cast<std::size_t>(y)] = beats_of(frags[static_cast<std::size_t>(y)]);
  return spec;
}

// Whether a configuration's fragments fit the unit's parameters.
bool fits(const Config& c, int width, int polygons) {
  return width <= MaxWidth && c.depth_bits <= DepthBits && polygons <= (1 << std::min(PolyIdBits, 30));
}

// A scene's frame run on the unit, its pixels also checked against the rendered image.
void run_scene(Bench& b, const PreparedScene& p, const std::string& name) {
  Image img;
  const FrameSpec spec = scene_frame(p, name, &img);
  std::vector<std::array<std::uint8_t, 3>> px;
  ASSERT_TRUE(b.frame(spec, &px)) << name;
  ASSERT_EQ(px.size() * 3, img.rgb.size()) << name;
  for (std::size_t i = 0; i < px.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(px[i][c], img.rgb[3 * i + c]) << name << " pixel " << i;
}

// The unit's own configuration: the first sized Gouraud configuration (the default scene's, then
// the others by name) whose width and depth word are the unit's, else the default.
Config unit_config() {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(WATKINS_SOURCE_DIR "/scenes/sized")) {
    const std::string n = e.path().filename().string();
    if (n.size() > 13 && n.substr(n.size() - 13) == ".gouraud.json" && n != "default.gouraud.json") names.push_back(n);
  }
  std::sort(names.begin(), names.end());
  names.insert(names.begin(), "default.gouraud.json");
  for (const std::string& n : names) {
    const Config sized = load_config(WATKINS_SOURCE_DIR "/scenes/sized/" + n);
    if (sized.max_width == MaxWidth && sized.depth_bits == DepthBits) return sized;
  }
  return Config{};
}

// Shipped scenes that fit the unit: each scenes/sized/<scene>.<shading>.json configuration with
// its scene whose width, depth word and polygon count fit; on the default build also each
// scenes/*.json at the default configuration, in both shadings (unsmoothed).
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
    if (p.smooth_w == 0 && fits(cfg, p.width, p.polygons)) v.emplace_back(n, std::move(p));
  }
  if (unit_config() == Config{})
    for (const std::string& path : shipped_scene_paths())
      for (const ShadingMode mode : {ShadingMode::Gouraud, ShadingMode::Phong}) {
        try {
          PreparedScene p = prepare(load_scene(path, shading_options(mode)));
          if (p.smooth_w == 0 && fits(p.config, p.width, p.polygons))
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
    run_scene(b, p, name);
    if (::testing::Test::HasFatalFailure()) return;
    ++n;
  }
  EXPECT_GE(n, min_scenes);
  EXPECT_EQ(b.mismatches, 0u);
  EXPECT_EQ(b.cycle_mismatches, 0u);
  std::printf("compact_scanline_buffer: %d shipped frames, %llu pixels, %llu cycles\n", n,
              static_cast<unsigned long long>(b.checked), static_cast<unsigned long long>(b.cycles()));
}

void random_scenes(std::uint64_t seed, int count, int gap_pct, int bp_pct) {
  Bench b(seed, gap_pct, bp_pct);
  const Config cfg = unit_config();
  int n = 0;
  for (std::uint64_t s = seed; n < count && s < seed + 20 * static_cast<std::uint64_t>(count); ++s) {
    PreparedScene p;
    try {
      p = prepare(random_scene(s), cfg);
    } catch (const SceneError&) {
      continue;
    }
    if (!fits(cfg, p.width, p.polygons)) continue;
    run_scene(b, p, "random scene " + std::to_string(s));
    if (::testing::Test::HasFatalFailure()) return;
    ++n;
  }
  EXPECT_EQ(n, count);
  EXPECT_EQ(b.mismatches, 0u);
  EXPECT_EQ(b.cycle_mismatches, 0u);
}

Fragment frag(int x, std::uint32_t depth, int poly, std::uint8_t shade) {
  Fragment f;
  f.x = x;
  f.depth = depth;
  f.poly = poly;
  f.rgb[0] = f.rgb[1] = f.rgb[2] = shade;
  return f;
}

// Equal depths back to back to one x (each tested against the word the fragment before it wrote,
// forwarded), then a nearer fragment and a tie with it, under both rules. The shade of fragment k
// is 10 * k + 10. The directed lines' polygon ids are below 8 (PolyIdBits 3 at the narrowest unit).
static_assert(PolyIdBits >= 3);
void directed(int gap_pct, int bp_pct) {
  Bench b(11, gap_pct, bp_pct);
  const Line line = beats_of({frag(5, 7, 7, 10), frag(5, 7, 3, 20), frag(5, 7, 5, 30), frag(5, 7, 1, 40),  // x 5: ties
                              frag(2, 4, 2, 50), frag(2, 4, 4, 60), frag(2, 3, 6, 70), frag(2, 3, 5, 80),  // x 2
                              frag(6, 9, 4, 90), frag(6, 9, 4, 100)});  // x 6: equal depth, equal id: first stays
  for (DepthTie tie : {DepthTie::Submission, DepthTie::Arrival, DepthTie::Submission}) {
    FrameSpec spec;
    spec.name = "directed";
    spec.width = 8;
    spec.tie = tie;
    spec.lines = {line, line};
    std::vector<std::array<std::uint8_t, 3>> px;
    ASSERT_TRUE(b.frame(spec, &px));
    const bool sub = tie == DepthTie::Submission;
    EXPECT_EQ(px.at(5)[0], sub ? 40 : 10);
    EXPECT_EQ(px.at(2)[0], sub ? 80 : 70);
    EXPECT_EQ(px.at(6)[0], 90);
    EXPECT_EQ(px.at(8 + 5)[0], sub ? 40 : 10) << "second line";
  }
  EXPECT_EQ(b.mismatches, 0u);
  EXPECT_EQ(b.cycle_mismatches, 0u);
}

#if WATKINS_RTL_PARAM_Lanes == 2
Beat pair(int x, std::uint32_t depth0, std::uint32_t depth1, int poly, std::uint8_t shade0, std::uint8_t shade1) {
  Beat b;
  b.f0 = frag(x, depth0, poly, shade0);
  b.pair = true;
  b.f1 = frag(x + 1, depth1, poly, shade1);
  return b;
}

// Lanes = 2: beats whose pixels the next beat hits again, by the other lane or the same, at equal
// depths under both rules, pairs from odd and even x, and x = width - 1 alone; width 9.
void directed_lanes(int gap_pct, int bp_pct) {
  Bench b(12, gap_pct, bp_pct);
  Beat alone;
  alone.f0 = frag(8, 3, 5, 90);  // x = width - 1
  const Line line{pair(4, 7, 7, 6, 10, 20),   // x 4, 5
                  pair(3, 7, 7, 3, 30, 40),   // x 4 again, by lane 1: a tie with lane 0's
                  pair(5, 7, 7, 1, 50, 60),   // x 5 two beats later, by lane 0: a tie
                  pair(5, 7, 6, 1, 70, 80),   // x 5: equal id stays; x 6: nearer
                  alone,
                  pair(7, 9, 3, 0, 100, 110),  // x 8 again, by lane 1: a tie
                  pair(0, 1, 1, 2, 120, 130), pair(1, 1, 1, 2, 140, 150)};  // x 1: equal id stays
  for (DepthTie tie : {DepthTie::Submission, DepthTie::Arrival, DepthTie::Submission}) {
    FrameSpec spec;
    spec.name = "directed lanes";
    spec.width = 9;
    spec.tie = tie;
    spec.lines = {line, line};
    std::vector<std::array<std::uint8_t, 3>> px;
    ASSERT_TRUE(b.frame(spec, &px));
    const bool sub = tie == DepthTie::Submission;
    const std::array<int, 9> want{120, 130, 150, 30, sub ? 40 : 10, sub ? 50 : 20, 80, 100, sub ? 110 : 90};
    for (int l = 0; l < 2; ++l)
      for (int x = 0; x < 9; ++x) EXPECT_EQ(px.at(9 * l + x)[0], want[x]) << "line " << l << " x " << x;
  }
  EXPECT_EQ(b.mismatches, 0u);
  EXPECT_EQ(b.cycle_mismatches, 0u);
}

#endif

}  // namespace

#if WATKINS_RTL_PARAM_Lanes == 2
TEST(RtlCompactScanlineBuffer, PairsHitBackToBack) { directed_lanes(0, 0); }
TEST(RtlCompactScanlineBuffer, PairsHitBackToBackStalled) { directed_lanes(30, 50); }
#endif
TEST(RtlCompactScanlineBuffer, RandomFullRate) { random_frames(40, 0, 0, 1, 0); }
TEST(RtlCompactScanlineBuffer, RandomGapsAndBackPressure) { random_frames(40, 40, 40, 2, 0); }
TEST(RtlCompactScanlineBuffer, RandomHeavyBackPressure) { random_frames(20, 5, 80, 3, 0); }
TEST(RtlCompactScanlineBuffer, RandomTieSubmission) { random_frames(40, 20, 30, 4, 1); }
TEST(RtlCompactScanlineBuffer, RandomTieRulesAlternating) { random_frames(40, 0, 0, 5, 2); }
TEST(RtlCompactScanlineBuffer, TieBackToBackOneX) { directed(0, 0); }
TEST(RtlCompactScanlineBuffer, TieBackToBackOneXStalled) { directed(30, 50); }
TEST(RtlCompactScanlineBuffer, ShippedScenesFullRate) { shipped(21, 0, 0, 10); }
TEST(RtlCompactScanlineBuffer, ShippedScenesStalled) { shipped(22, 30, 30, 10); }
TEST(RtlCompactScanlineBuffer, RandomScenesStalled) { random_scenes(1, 60, 20, 20); }

// Empty frames with the input always offered and the output always ready, by hand: the clear
// after reset takes C = ceil(MaxWidth / Lanes) clocks (0..C-1), so the first marker goes in at
// clock C; each line's read-out is one read clock and W loads, the next marker going in with the
// last load, so line k's marker is taken at C + k(W + 1) and the last pixel is loaded at
// C + H(W + 1) and taken a clock later. The bench offers the next frame from the clock
// after that take, whose first marker the idle reader takes at once: H(W + 1) + 2 clocks more.
TEST(RtlCompactScanlineBuffer, EmptyFrameClocksByHand) {
  Bench b(1, 0, 0);
  const int w = std::min(MaxWidth, 13), h = 5;
  FrameSpec spec;
  spec.name = "empty";
  spec.width = w;
  spec.lines.assign(h, {});
  ASSERT_TRUE(b.frame(spec));
  EXPECT_EQ(b.last_take, static_cast<std::uint64_t>(2 + ClearClocks + h * (w + 1) + 1));  // reset's 2 clocks first
  ASSERT_TRUE(b.frame(spec));
  EXPECT_EQ(b.last_take, static_cast<std::uint64_t>(2 + ClearClocks + 2 * h * (w + 1) + 3));
  EXPECT_EQ(CompactScanlineBufferTiming(MaxWidth, Lanes).clear_clocks(), ClearClocks);
  EXPECT_EQ(b.checked, static_cast<std::uint64_t>(2 * w * h));
}
