// The cycle model (model/twins/cycle_model.hpp) against the Verilated top: with no input gaps and
// no output stalls, the predicted cycles per frame must equal the bench's `rtl cycles` exactly,
// on every shipped scene and on random scenes, Gouraud and Phong tops, full-frame and sparse.
// Under output back-pressure (any pixel_ready_i pattern, random or a function of the pixels
// taken, as a line buffer drives it), the cycle of every pixel taken must equal the model's.
// The compact tops (Compact = 1, Gouraud and Phong) the same way: every frame's cycles and every pixel's take equal
// to the compact composition's, from the bench's reset.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "build_options.hpp"
#include "config_file.hpp"
#include "cosim_support.hpp"
#include "cycle_model.hpp"
#include "frame_driver.hpp"
#include "phong_hard_cases.hpp"
#include "prepare.hpp"
#include "random_scene.hpp"
#include "rtl_bench.hpp"
#include "scene.hpp"
#include "scene_builder.hpp"

using namespace watkins;
using namespace watkins::tb;
using namespace watkins::tb::test;
using namespace watkins::test;

namespace {

// The frame on the RTL at full speed in both output modes; the prediction must equal its cycles.
// Pixels are not compared here (the other co-simulation tests do that): cycles only.
void expect_predicted(const std::string& name, const PreparedScene& p) {
  for (const bool sparse : {false, true}) {
    RtlOptions o;
    o.gap = 0;
    o.stall = 0;
    o.sparse = sparse;
    o.compare = false;
    const RtlResult r = run_rtl(p, o);
    const std::string what = name + (p.shading == ShadingMode::Phong ? " phong" : " gouraud") +
                             (sparse ? " sparse" : " full-frame") + " " + std::to_string(p.width) + "x" +
                             std::to_string(p.height) + ", " + std::to_string(p.edges.size()) + " edge records";
    ASSERT_TRUE(r.ok()) << what << ": " << r.summary();
    const CyclePrediction c = predict_cycles(p, sparse ? PixelOutput::Sparse : PixelOutput::FullFrame);
    EXPECT_EQ(c.cycles, r.cycles) << what;
    EXPECT_EQ(c.pixels, r.pixels) << what;
  }
}

void expect_predicted_shipped(const std::string& name, ShadingMode mode) {
  if (name == "<none>") GTEST_SKIP() << "no scenes/*.json";
  BuiltScene scene;
  PreparedScene prepared;
  try {
    scene = load_scene(WATKINS_SOURCE_DIR "/scenes/" + name, shading_options(mode));
    prepared = prepare(scene);
  } catch (const SceneError& e) {
    GTEST_SKIP() << "the scene does not load or fit in this mode: " << e.what();
  }
  if (prepared.width > rtl_max_width()) GTEST_SKIP() << "wider than the RTL line buffer";
  expect_predicted(name, prepared);
}

class CycleModelShipped : public ::testing::TestWithParam<std::string> {};

TEST_P(CycleModelShipped, GouraudEqualsRtl) { expect_predicted_shipped(GetParam(), ShadingMode::Gouraud); }
TEST_P(CycleModelShipped, PhongEqualsRtl) { expect_predicted_shipped(GetParam(), ShadingMode::Phong); }

INSTANTIATE_TEST_SUITE_P(Scenes, CycleModelShipped, ::testing::ValuesIn(shipped_scenes()), scene_test_name);

class CycleModelRandom : public ::testing::TestWithParam<int> {};

constexpr int ScenesPerBatch = 25;

TEST_P(CycleModelRandom, EqualsRtl) {
  int ran = 0;
  for (int k = 0; k < ScenesPerBatch; ++k) {
    const std::uint64_t seed = 9000 + static_cast<std::uint64_t>(GetParam()) * ScenesPerBatch + k;
    for (const bool phong : {false, true}) {
      const BuiltScene scene = phong ? random_phong_scene(seed) : random_scene(seed);
      PreparedScene prepared;
      try {
        prepared = prepare(scene);
      } catch (const SceneError&) {  // too many active edges for the hardware
        continue;
      }
      expect_predicted(scene.name, prepared);
      if (HasFailure()) return;  // one report per batch is enough
      ++ran;
    }
  }
  EXPECT_GE(ran, 2 * ScenesPerBatch * 4 / 5) << "most random scenes fit the hardware";
}

INSTANTIATE_TEST_SUITE_P(Batches, CycleModelRandom, ::testing::Range(0, 4));  // 4 x 25 x 2 shadings

// Harder timing: many small polygons and bow-ties (lines with many edges and short spans, where the
// active-edge list and the span setup rather than the pixels set the pace), tall thin and wide flat
// frames, and jittered meshes (shared edges, equal X on a line).
TEST(CycleModel, StressScenesEqualRtl) {
  const int seeds = 60;
  int ran = 0;
  for (int k = 0; k < seeds; ++k) {
    std::mt19937_64 rng(77000 + static_cast<std::uint64_t>(k));
    RandomSceneSpec spec;
    switch (k % 4) {
      case 0: spec.min_polygons = 20, spec.max_polygons = 40, spec.convex_quads = false; break;
      case 1: spec.min_width = 1, spec.max_width = 12, spec.min_height = 30, spec.max_height = 200; break;
      case 2: spec.min_width = 100, spec.max_width = 400, spec.min_height = 1, spec.max_height = 12; break;
      case 3: spec.max_polygons = 30, spec.snap_one_in = 2; break;
    }
    std::vector<BuiltScene> scenes{random_scene(rng, spec), mesh_scene(rng, 20 + k, 16 + k % 7, 1 + k % 9, 1 + k % 5)};
    for (BuiltScene& scene : scenes) {
      PreparedScene prepared;
      try {
        prepared = prepare(scene);
      } catch (const SceneError&) {  // too many active edges for the hardware
        continue;
      }
      if (prepared.width > rtl_max_width()) continue;
      expect_predicted(scene.name + " " + std::to_string(k), prepared);
      if (HasFailure()) return;
      ++ran;
    }
  }
  EXPECT_GE(ran, seeds);
}

// Shapes the random scenes rarely draw: an empty frame, a one-line and a one-column frame, a
// frame whose last line is uncovered, many one-pixel spans back to back (the interpolator's FIFO
// runs dry and full), a tall frame with long empty stretches.
TEST(CycleModel, CornerFramesEqualRtl) {
  expect_predicted("empty", prepare(screen(13, 5, {}, "empty", {1, 2, 3})));
  expect_predicted("one line", prepare(screen(40, 1, {poly({vtx(2, -3, 0.3, 200, 10, 10), vtx(30, -2, 0.5, 10, 200, 10),
                                                            vtx(12, 4, 0.7, 10, 10, 200)})}, "one line")));
  expect_predicted("one column", prepare(screen(1, 30, {poly({vtx(-3, 2, 0.3, 200, 10, 10), vtx(3, 5, 0.5, 10, 200, 10),
                                                              vtx(0, 25, 0.7, 10, 10, 200)})}, "one column")));
  expect_predicted("inner triangle",
                   prepare(screen(30, 20, {poly({vtx(5, 4, 0.3, 200, 10, 10), vtx(25, 6, 0.5, 10, 200, 10),
                                                 vtx(12, 14, 0.7, 10, 10, 200)})}, "inner triangle")));
  std::vector<ScreenPolygon> slivers;
  for (int i = 0; i < 30; ++i) {
    const double x = 1 + 2 * i;
    slivers.push_back(poly({vtx(x, 1, 0.5, 10, 20, 30), vtx(x + 1.2, 1, 0.5, 10, 20, 30), vtx(x + 0.6, 40, 0.4, 90, 20, 30)}));
  }
  expect_predicted("slivers", prepare(screen(64, 48, slivers, "slivers")));
  expect_predicted("tall", prepare(screen(8, 400, {poly({vtx(1, 350, 0.3, 1, 2, 3), vtx(7, 352, 0.3, 1, 2, 3),
                                                         vtx(4, 399, 0.3, 1, 2, 3)})}, "tall")));
}

// ---------------------------------------------------------------- under back-pressure

// A pixel_ready_i pattern: one function for the bench and the model.
using ReadyPattern = std::function<bool(long long cycle, long long taken)>;

class PatternReady : public PixelReady {
 public:
  explicit PatternReady(const ReadyPattern& f) : f_(f) {}
  bool ready(long long cycle, long long taken) override { return f_(cycle, taken); }

 private:
  const ReadyPattern& f_;
};

std::uint64_t mix(std::uint64_t x) {  // splitmix64's finalizer: a stateless random bit per cycle
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

struct NamedPattern {
  std::string name;
  ReadyPattern ready;
};

// Random stalls light and heavy, every other cycle, long all-stall bursts, a stall at each
// line's last pixel, and a line buffer's back-pressure: a line may be written while fewer than
// two taken lines wait for a reader that frees one every 1.5 line widths.
std::vector<NamedPattern> ready_patterns(int width) {
  const long long w = width;
  return {
      {"random 30 %", [](long long c, long long) { return mix(std::uint64_t(c) * 3 + 1) % 100 >= 30; }},
      {"random 85 %", [](long long c, long long) { return mix(std::uint64_t(c) * 5 + 2) % 100 >= 85; }},
      {"every other cycle", [](long long c, long long) { return c % 2 == 1; }},
      {"bursts", [](long long c, long long) { return (c / 97) % 3 != 1; }},
      {"line ends", [w](long long c, long long n) { return n % w != w - 1 || c % 5 == 0; }},
      {"two line slots", [w](long long c, long long n) { return n / w - (2 * c) / (3 * w) < 2; }},
  };
}

void expect_takes(const std::string& what, const PreparedScene& p, bool sparse, const NamedPattern& pattern) {
  RtlOptions o;
  o.gap = 0;
  o.stall = 0;
  o.sparse = sparse;
  o.compare = false;
  o.pixel_ready = pattern.ready;
  const RtlResult r = run_rtl(p, o);
  const std::string at = what + (sparse ? " sparse" : " full-frame") + ", ready " + pattern.name;
  ASSERT_TRUE(r.ok()) << at << ": " << r.summary();
  PatternReady ready(pattern.ready);
  std::vector<long long> takes;
  CycleOptions co;
  co.output = sparse ? PixelOutput::Sparse : PixelOutput::FullFrame;
  co.pixel_ready = &ready;
  co.take_cycles = &takes;
  const CyclePrediction c = predict_cycles(p, Config{}, co);
  const std::vector<long long>& rtl = r.frames.at(0).take_cycles;
  EXPECT_EQ(c.cycles, r.cycles) << at;
  ASSERT_EQ(takes.size(), rtl.size()) << at;
  for (std::size_t i = 0; i < takes.size(); ++i)
    ASSERT_EQ(takes[i], rtl[i]) << at << ": pixel (beat) " << i << " of " << takes.size();
}

// Each RTL run under stalls costs seconds: a scene runs two of the patterns, three apart, picked
// by its name, so the shipped scenes together run every pattern; WATKINS_ALL_READY_PATTERNS=1 in
// the environment runs all of them on every scene.
std::vector<std::size_t> pick_patterns(const std::string& name, std::size_t patterns) {
  const char* all = std::getenv("WATKINS_ALL_READY_PATTERNS");
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a of the name: the same pick on every machine
  for (const char ch : name) h = (h ^ static_cast<unsigned char>(ch)) * 1099511628211ull;
  std::vector<std::size_t> picked;
  if (all && std::string(all) == "1") {
    for (std::size_t k = 0; k < patterns; ++k) picked.push_back(k);
  } else {
    picked = {h % patterns, (h + 3) % patterns};
  }
  return picked;
}

void expect_takes_shipped(const std::string& name, ShadingMode mode, double smooth) {
  if (name == "<none>") GTEST_SKIP() << "no scenes/*.json";
  PreparedScene p;
  try {
    BuildOptions bo = shading_options(mode);
    if (smooth > 0) bo.smooth = smooth;
    p = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/" + name, bo));
  } catch (const SceneError& e) {
    GTEST_SKIP() << "the scene does not load or fit in this mode: " << e.what();
  }
  if (p.width > rtl_max_width()) GTEST_SKIP() << "wider than the RTL line buffer";
  const std::string what = name + (mode == ShadingMode::Phong ? " phong" : " gouraud") + (p.smoothed() ? " smoothed" : "");
  const std::vector<NamedPattern> patterns = ready_patterns(p.width);
  const std::vector<std::size_t> picked = pick_patterns(name, patterns.size());
  for (std::size_t i = 0; i < picked.size(); ++i) {
    expect_takes(what, p, false, patterns[picked[i]]);
    if (i % 3 == 0 && !p.smoothed()) expect_takes(what, p, true, patterns[picked[i]]);  // sparse too
    if (::testing::Test::HasFailure()) return;
  }
}

class CycleModelStalled : public ::testing::TestWithParam<std::string> {};

TEST_P(CycleModelStalled, GouraudTakesEqualRtl) { expect_takes_shipped(GetParam(), ShadingMode::Gouraud, 0); }
TEST_P(CycleModelStalled, PhongTakesEqualRtl) { expect_takes_shipped(GetParam(), ShadingMode::Phong, 0); }

INSTANTIATE_TEST_SUITE_P(Scenes, CycleModelStalled, ::testing::ValuesIn(shipped_scenes()), scene_test_name);

// Herman & Liu's smoother between the buffer and the skid, stalled by the consumer.
TEST(CycleModelStalled, SmoothedSphereTakesEqualRtl) {
  expect_takes_shipped("sphere.json", ShadingMode::Gouraud, 0.8);
  expect_takes_shipped("sphere.json", ShadingMode::Phong, 0.8);
  expect_takes_shipped("screen_polygons.json", ShadingMode::Gouraud, 1.5);
}

// Random scenes (many small polygons: the front half sets the pace as often as the output).
TEST(CycleModelStalled, RandomScenesTakesEqualRtl) {
  int ran = 0;
  for (int k = 0; k < 12; ++k) {
    std::mt19937_64 rng(88000 + static_cast<std::uint64_t>(k));
    RandomSceneSpec spec;
    if (k % 2) spec.min_polygons = 20, spec.max_polygons = 40, spec.convex_quads = false;
    const BuiltScene scene = k % 3 == 2 ? random_phong_scene(88000 + k) : random_scene(rng, spec);
    PreparedScene p;
    try {
      p = prepare(scene);
    } catch (const SceneError&) {
      continue;
    }
    if (p.width > rtl_max_width()) continue;
    const std::vector<NamedPattern> patterns = ready_patterns(p.width);
    const NamedPattern& pattern = patterns[std::size_t(k) % patterns.size()];
    expect_takes(scene.name + " " + std::to_string(k), p, false, pattern);
    expect_takes(scene.name + " " + std::to_string(k), p, true, pattern);
    if (HasFailure()) return;
    ++ran;
  }
  EXPECT_GE(ran, 8);
}

// ---------------------------------------------------------------- the compact top

// The three compact tops the test build Verilates: the default scene's sized configuration (the
// UP5K's: MaxWidth 320, 36 active edges), the default sizes (MaxWidth 1,024, 64) and the default
// sizes with two fragment lanes.
const char* const CompactFiles[] = {"tests/configs/compact_default.gouraud.json", "tests/configs/compact.gouraud.json",
                                    "tests/configs/compact_lanes.gouraud.json"};

#ifdef WATKINS_RTL_CONFIGS_DEFAULT
constexpr bool RequireCompactTops = true;  // CI's build has both: a missing one fails
#else
constexpr bool RequireCompactTops = false;
#endif

// The frame on the compact top, at full rate (pattern null) or under a ready pattern: its
// cycles and every pixel's take equal to predict_cycles with the configuration's compact true,
// its reset clears running from the bench's reset (the first beat offered first_edge_cycle -
// ResetCycles clocks after it).
void expect_compact_takes(const std::string& what, const PreparedScene& p, const NamedPattern* pattern) {
  RtlOptions o;
  o.gap = 0;
  o.stall = 0;
  o.compare = false;
  if (pattern) o.pixel_ready = pattern->ready;
  const RtlResult r = run_rtl(p, o);
  const std::string at = what + " " + std::to_string(p.width) + "x" + std::to_string(p.height) + ", " +
                         std::to_string(p.edges.size()) + " edge records, ready " + (pattern ? pattern->name : "always");
  ASSERT_TRUE(r.ok()) << at << ": " << r.summary();
  ASSERT_NE(r.top.find("Compact=1"), std::string::npos) << at << " ran on " << r.top;
  ASSERT_EQ(r.top.find("PhongNarrow=1") != std::string::npos, p.config.phong == PhongFormat::Narrow)
      << at << " ran on " << r.top;
  const RtlFrame& f = r.frames.at(0);
  std::vector<long long> takes;
  CycleOptions co;
  co.max_active_edges = p.config.max_active_edges;
  co.after_reset = f.first_edge_cycle - detail::FrameDriver::ResetCycles;
  co.take_cycles = &takes;
  std::unique_ptr<PatternReady> ready;
  if (pattern) {
    ready = std::make_unique<PatternReady>(pattern->ready);
    co.pixel_ready = ready.get();
  }
  const CyclePrediction c = predict_cycles(p, p.config, co);
  EXPECT_EQ(c.cycles, r.cycles) << at;
  ASSERT_EQ(takes.size(), f.take_cycles.size()) << at;
  for (std::size_t i = 0; i < takes.size(); ++i)
    ASSERT_EQ(takes[i], f.take_cycles[i]) << at << ": pixel " << i << " of " << takes.size();
}

// Prepared at the compact configuration `file`, or the reason the compact top cannot run it.
std::string prepare_compact(const BuiltScene& scene, const Config& cfg, PreparedScene& p) {
  try {
    p = prepare(scene, cfg);
  } catch (const SceneError& e) {
    return e.what();
  }
  if (p.smoothed()) return "it smooths (the compact top has no smoother)";
  if (p.eq2) return "it divides by eq. (2) (the compact top has no shade divider)";
  if (p.width > cfg.max_width) return "wider than the line buffer";
  return "";
}

#define REQUIRE_COMPACT_TOP(cfg, file)                                          \
  do {                                                                          \
    const std::string why = rtl_unavailable(cfg, ShadingMode::Gouraud, file);   \
    if (!why.empty()) {                                                         \
      ASSERT_FALSE(RequireCompactTops) << why;                                  \
      GTEST_SKIP() << why;                                                      \
    }                                                                           \
  } while (0)

// Every shipped scene that fits a compact top in Gouraud shading: at full rate, then under two
// of the ready patterns picked by its name.
class CompactCycleModelShipped : public ::testing::TestWithParam<std::string> {};

void expect_compact_shipped(const std::string& name, const char* file) {
  if (name == "<none>") GTEST_SKIP() << "no scenes/*.json";
  const Config cfg = load_config(std::string(WATKINS_SOURCE_DIR "/") + file);
  ASSERT_TRUE(cfg.compact) << file;
  PreparedScene p;
  std::string why;
  try {
    why = prepare_compact(load_scene(WATKINS_SOURCE_DIR "/scenes/" + name, shading_options(ShadingMode::Gouraud)), cfg, p);
  } catch (const SceneError& e) {
    why = e.what();
  }
  if (!why.empty()) GTEST_SKIP() << name << " does not fit " << file << ": " << why;
  REQUIRE_COMPACT_TOP(cfg, file);
  const std::string what = name + " at " + file;
  expect_compact_takes(what, p, nullptr);
  const std::vector<NamedPattern> patterns = ready_patterns(p.width);
  for (const std::size_t k : pick_patterns(name, patterns.size())) {
    if (::testing::Test::HasFailure()) return;
    expect_compact_takes(what, p, &patterns[k]);
  }
}

TEST_P(CompactCycleModelShipped, AtTheSizedDefault) { expect_compact_shipped(GetParam(), CompactFiles[0]); }
TEST_P(CompactCycleModelShipped, AtTheDefaultSizes) { expect_compact_shipped(GetParam(), CompactFiles[1]); }
TEST_P(CompactCycleModelShipped, AtTwoLanes) { expect_compact_shipped(GetParam(), CompactFiles[2]); }

INSTANTIATE_TEST_SUITE_P(Scenes, CompactCycleModelShipped, ::testing::ValuesIn(shipped_scenes()), scene_test_name);

// Random scenes (many small polygons and bow-ties every other one: the list, the former and the
// span setup set the pace as often as the reader) on each compact top, at full rate and under
// one ready pattern each; and the corner frames.
TEST(CompactCycleModel, RandomScenesEqualRtl) {
  for (const char* file : CompactFiles) {
    const Config cfg = load_config(std::string(WATKINS_SOURCE_DIR "/") + file);
    REQUIRE_COMPACT_TOP(cfg, file);
    int ran = 0;
    for (int k = 0; k < 24; ++k) {
      std::mt19937_64 rng(99000 + static_cast<std::uint64_t>(k));
      RandomSceneSpec spec;
      if (k % 2) spec.min_polygons = 20, spec.max_polygons = 40, spec.convex_quads = false;
      const BuiltScene scene = random_scene(rng, spec);
      PreparedScene p;
      if (!prepare_compact(scene, cfg, p).empty()) continue;
      const std::string what = scene.name + " " + std::to_string(k) + " at " + file;
      expect_compact_takes(what, p, nullptr);
      const std::vector<NamedPattern> patterns = ready_patterns(p.width);
      expect_compact_takes(what, p, &patterns[std::size_t(k) % patterns.size()]);
      if (HasFailure()) return;
      ++ran;
    }
    EXPECT_GE(ran, 8) << file;  // the sized default's 5-bit depth word refuses more of them
  }
}

TEST(CompactCycleModel, CornerFramesEqualRtl) {
  const char* file = CompactFiles[1];
  const Config cfg = load_config(std::string(WATKINS_SOURCE_DIR "/") + file);
  REQUIRE_COMPACT_TOP(cfg, file);
  std::vector<ScreenPolygon> slivers;
  for (int i = 0; i < 30; ++i) {
    const double x = 1 + 2 * i;
    slivers.push_back(poly({vtx(x, 1, 0.5, 10, 20, 30), vtx(x + 1.2, 1, 0.5, 10, 20, 30), vtx(x + 0.6, 40, 0.4, 90, 20, 30)}));
  }
  const std::vector<BuiltScene> frames = {
      screen(13, 5, {}, "empty", {1, 2, 3}),
      screen(1, 1, {}, "one pixel"),
      screen(40, 1, {poly({vtx(2, -3, 0.3, 200, 10, 10), vtx(30, -2, 0.5, 10, 200, 10), vtx(12, 4, 0.7, 10, 10, 200)})}, "one line"),
      screen(1, 30, {poly({vtx(-3, 2, 0.3, 200, 10, 10), vtx(3, 5, 0.5, 10, 200, 10), vtx(0, 25, 0.7, 10, 10, 200)})}, "one column"),
      screen(64, 48, slivers, "slivers"),
      screen(8, 400, {poly({vtx(1, 350, 0.3, 1, 2, 3), vtx(7, 352, 0.3, 1, 2, 3), vtx(4, 399, 0.3, 1, 2, 3)})}, "tall"),
      screen(cfg.max_width, 3, {poly({vtx(0, 0, 0.3, 1, 2, 3), vtx(cfg.max_width, 0, 0.3, 1, 2, 3), vtx(5, 3, 0.3, 1, 2, 3)})}, "widest"),
  };
  for (const BuiltScene& scene : frames) {
    PreparedScene p;
    const std::string why = prepare_compact(scene, cfg, p);
    ASSERT_TRUE(why.empty()) << scene.name << ": " << why;
    expect_compact_takes(scene.name, p, nullptr);
    const std::vector<NamedPattern> patterns = ready_patterns(p.width);
    expect_compact_takes(scene.name, p, &patterns[2]);  // every other cycle
    if (HasFailure()) return;
  }
}

}  // namespace

// ---------------------------------------------------------------- the compact Phong top
namespace {

// The compact Phong tops the test build Verilates: the default scene's sized Phong configuration
// with compact true (the UP5K's), at the model's formats and at the narrow ones (CompactCycleModel's
// narrow path: compact_normalizer_narrow and compact_phong_shader_narrow).
const char* const CompactPhongFiles[] = {"tests/configs/compact.phong.json", "tests/configs/compact_narrow.phong.json"};

std::string phong_file_name(const char* file) {
  return std::string(file).find("narrow") != std::string::npos ? "Narrow" : "ModelFormats";
}

#define REQUIRE_COMPACT_PHONG_TOP(cfg, CompactPhongFile)                               \
  do {                                                                                 \
    const std::string why = rtl_unavailable(cfg, ShadingMode::Phong, CompactPhongFile); \
    if (!why.empty()) {                                                                \
      ASSERT_FALSE(RequireCompactTops) << why;                                         \
      GTEST_SKIP() << why;                                                             \
    }                                                                                  \
  } while (0)

// Every shipped scene that fits the compact Phong top in Phong shading: at full rate, then under
// two of the ready patterns picked by its name.
class CompactPhongCycleModelShipped : public ::testing::TestWithParam<std::tuple<const char*, std::string>> {};

TEST_P(CompactPhongCycleModelShipped, EqualsRtl) {
  const char* const CompactPhongFile = std::get<0>(GetParam());
  const std::string name = std::get<1>(GetParam());
  if (name == "<none>") GTEST_SKIP() << "no scenes/*.json";
  const Config cfg = load_config(std::string(WATKINS_SOURCE_DIR "/") + CompactPhongFile);
  PreparedScene p;
  std::string why;
  try {
    why = prepare_compact(load_scene(WATKINS_SOURCE_DIR "/scenes/" + name, shading_options(ShadingMode::Phong)), cfg, p);
  } catch (const SceneError& e) {
    why = e.what();
  }
  if (!why.empty()) GTEST_SKIP() << name << " does not fit " << CompactPhongFile << ": " << why;
  ASSERT_EQ(p.shading, ShadingMode::Phong);
  REQUIRE_COMPACT_PHONG_TOP(cfg, CompactPhongFile);
  const std::string what = name + " at " + CompactPhongFile;
  expect_compact_takes(what, p, nullptr);
  const std::vector<NamedPattern> patterns = ready_patterns(p.width);
  for (const std::size_t k : pick_patterns(name, patterns.size())) {
    if (HasFailure()) return;
    expect_compact_takes(what, p, &patterns[k]);
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, CompactPhongCycleModelShipped,
                         ::testing::Combine(::testing::ValuesIn(CompactPhongFiles), ::testing::ValuesIn(shipped_scenes())),
                         [](const ::testing::TestParamInfo<std::tuple<const char*, std::string>>& info) {
                           return phong_file_name(std::get<0>(info.param)) + "_" +
                                  scene_test_name({std::get<1>(info.param), info.index});
                         });

// Random Phong scenes (materials folded onto the table's two) and the hard cases, at full rate
// and under one ready pattern each: the normalizer's and the shader's 5-clock schedules, their
// stalls, and the interpolator's stall on the normalizer.
class CompactPhongCycleModel : public ::testing::TestWithParam<const char*> {};

TEST_P(CompactPhongCycleModel, RandomAndHardScenesEqualRtl) {
  const char* const CompactPhongFile = GetParam();
  const Config cfg = load_config(std::string(WATKINS_SOURCE_DIR "/") + CompactPhongFile);
  REQUIRE_COMPACT_PHONG_TOP(cfg, CompactPhongFile);
  std::vector<BuiltScene> scenes = {antipodal_normals_scene(), screen_plane_normals_scene(), grazing_light_scene(),
                                    shininess_scene(0), shininess_scene(255)};
  for (std::uint64_t seed = 8000; seed < 8040; ++seed) {
    BuiltScene s = random_phong_scene(seed);
    if (static_cast<int>(s.materials.size()) > cfg.max_materials) {
      for (ScreenPolygon& poly : s.polygons) poly.material %= cfg.max_materials;
      s.materials.resize(static_cast<std::size_t>(cfg.max_materials));
    }
    scenes.push_back(s);
  }
  int ran = 0;
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    PreparedScene p;
    if (!prepare_compact(scenes[k], cfg, p).empty()) continue;
    const std::string what = scenes[k].name + " at " + CompactPhongFile;
    expect_compact_takes(what, p, nullptr);
    const std::vector<NamedPattern> patterns = ready_patterns(p.width);
    expect_compact_takes(what, p, &patterns[k % patterns.size()]);
    if (HasFailure()) return;
    ++ran;
  }
  EXPECT_GE(ran, 20);
}

INSTANTIATE_TEST_SUITE_P(Configs, CompactPhongCycleModel, ::testing::ValuesIn(CompactPhongFiles),
                         [](const ::testing::TestParamInfo<const char*>& info) { return phong_file_name(info.param); });

}  // namespace
