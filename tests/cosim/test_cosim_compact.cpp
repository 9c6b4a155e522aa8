// The compact top (watkins_top with Compact = 1: the compact_* blocks, docs/reference/compact.md)
// against the model built for the same configuration, at the three compact configurations the build
// Verilates (tests/configs/compact_default.gouraud.json: the default scene's sized configuration,
// the UP5K's; tests/configs/compact.gouraud.json: the default one's sizes;
// tests/configs/compact_lanes.gouraud.json: the default sizes with two fragment lanes): every shipped scene
// that fits, 200 random scenes, and the hard cases (empty frames, frames back to back and runs
// without a reset, an active-edge overflow, depth ties under both rules, the narrowest and the
// widest screens), under random input gaps and output stalls. Every pixel and every stage stream
// (active edges, segments, fragments, shaded fragments) bit for bit. The compact top's cycles are
// the compact cycle model's to predict; nothing here counts them.
#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "build_options.hpp"
#include "config_file.hpp"
#include "cosim_support.hpp"
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

const char* const SizedFile = "tests/configs/compact_default.gouraud.json";  // MaxWidth 320, 36 edges
const char* const WideFile = "tests/configs/compact.gouraud.json";           // MaxWidth 1024, 64 edges
const char* const LanesFile = "tests/configs/compact_lanes.gouraud.json";    // the same, Lanes 2

Config compact_config(const char* file) {
  const Config c = load_config(std::string(WATKINS_SOURCE_DIR "/") + file);
  EXPECT_TRUE(c.compact) << file;
  EXPECT_FALSE(c.smoothing) << file << ": the compact top has no smoother";
  return c;
}

// With the default WATKINS_RTL_CONFIGS (CI's) both compact tops are built: a missing one fails.
#ifdef WATKINS_RTL_CONFIGS_DEFAULT
constexpr bool RequireEveryTop = true;
#else
constexpr bool RequireEveryTop = false;
#endif

#define REQUIRE_COMPACT_TOP(cfg, file)                                             \
  do {                                                                             \
    const std::string why = rtl_unavailable(cfg, ShadingMode::Gouraud, file);      \
    if (!why.empty()) {                                                            \
      ASSERT_FALSE(RequireEveryTop) << why;                                        \
      GTEST_SKIP() << why;                                                         \
    }                                                                              \
  } while (0)

// The frames back to back under `o`, each compared with its model image; every stage stream
// checked. Returns false after the first failing run (its report already given).
bool expect_frames(const std::string& what, const std::vector<const PreparedScene*>& frames, const RtlOptions& o) {
  std::vector<Image> model;
  for (const PreparedScene* p : frames) model.push_back(WatkinsTop(p->config).render(*p));
  std::vector<const Image*> want;
  for (const Image& m : model) want.push_back(&m);
  const RtlResult r = run_rtl_frames(frames, o, want);
  expect_clean(what, o, r);
  if (!r.ok()) return false;
  EXPECT_NE(r.top.find("Compact=1"), std::string::npos) << what << " ran on " << r.top;
  EXPECT_GT(r.stage_items, 0) << what << ": the stage streams were not checked";
  EXPECT_TRUE(r.stage_mismatches.empty()) << what << ": " << r.summary();
  EXPECT_EQ(r.frames.size(), frames.size()) << what;
  for (std::size_t f = 0; f < frames.size() && f < r.frames.size(); ++f) {
    EXPECT_TRUE(r.frames[f].complete) << what << " frame " << f;
    EXPECT_EQ(r.frames[f].image.rgb, model[f].rgb) << what << " frame " << f;
    EXPECT_EQ(r.frames[f].image.covered, model[f].covered) << what << " frame " << f;
  }
  return true;
}

// Full speed, gaps and stalls, all-stall bursts.
std::vector<RtlOptions> stall_patterns(std::uint64_t seed) {
  return {RtlOptions{seed, 0.0, 0.0}, RtlOptions{seed + 1, 0.25, 0.3}, RtlOptions{seed + 2, 0.1, 0.02, 300}};
}

// ---------------------------------------------------------------- shipped scenes

// The scene in Gouraud shading (the compact top's only one) at `file`'s configuration: prepared
// there, or a reason it does not fit (a capacity, a word, a smoothed or curved scene).
std::string prepare_shipped(const std::string& name, const Config& cfg, PreparedScene& p) {
  try {
    const BuiltScene scene = load_scene(WATKINS_SOURCE_DIR "/scenes/" + name, shading_options(ShadingMode::Gouraud));
    p = prepare(scene, cfg);
  } catch (const SceneError& e) {
    return e.what();
  }
  if (p.smoothed()) return "it smooths (the compact top has no smoother)";
  if (p.eq2) return "it divides by eq. (2) (the compact top has no shade divider)";
  if (p.width > cfg.max_width) return "wider than the line buffer";
  return "";
}

class CompactShippedScenes : public ::testing::TestWithParam<std::string> {};

void check_shipped(const std::string& name, const char* file) {
  if (name == "<none>") GTEST_SKIP() << "no scenes/*.json";
  const Config cfg = compact_config(file);
  PreparedScene p;
  const std::string why = prepare_shipped(name, cfg, p);
  if (!why.empty()) GTEST_SKIP() << name << " does not fit " << file << ": " << why;
  REQUIRE_COMPACT_TOP(cfg, file);
  for (const RtlOptions& o : stall_patterns(7))
    if (!expect_frames(name + " at " + file, {&p}, o)) return;
}

TEST_P(CompactShippedScenes, AtTheSizedDefault) { check_shipped(GetParam(), SizedFile); }
TEST_P(CompactShippedScenes, AtTheDefaultSizes) { check_shipped(GetParam(), WideFile); }
TEST_P(CompactShippedScenes, AtTwoLanes) { check_shipped(GetParam(), LanesFile); }

INSTANTIATE_TEST_SUITE_P(Scenes, CompactShippedScenes, ::testing::ValuesIn(shipped_scenes()), scene_test_name);

// How many shipped scenes each compact top holds (the others are skipped above, saying why): the
// default scene's sized configuration holds the scenes sized like it, the default sizes nearly all.
TEST(CosimCompact, ShippedScenesThatFit) {
  int sized = 0, wide = 0, all = 0;
  const Config s = compact_config(SizedFile), w = compact_config(WideFile);
  for (const std::string& name : shipped_scenes()) {
    PreparedScene p;
    ++all;
    const bool in_sized = prepare_shipped(name, s, p).empty();
    const bool in_wide = prepare_shipped(name, w, p).empty();
    sized += in_sized;
    wide += in_wide;
    std::printf("%-24s sized default %-3s default sizes %s\n", name.c_str(), in_sized ? "yes" : "no",
                in_wide ? "yes" : "no");
  }
  std::printf("%d of %d shipped scenes fit the sized default compact top, %d the default-size one\n", sized, all,
              wide);
  EXPECT_GE(sized, 5);
  EXPECT_GE(wide, 29);
}

// ---------------------------------------------------------------- random scenes

class CompactRandomScenes : public ::testing::TestWithParam<int> {};

constexpr int ScenesPerBatch = 25;

// 8 batches of 25 random scenes (tests/support/random_scene) at the default sizes, each batch back
// to back in one run under its own stall pattern (random_options: none, light, heavy, bursts);
// batches 0-7 on the one-lane top, 8-15 (the same scenes) on the two-lane top.
TEST_P(CompactRandomScenes, MatchTheModel) {
  const char* const file = GetParam() < 8 ? WideFile : LanesFile;
  const Config cfg = compact_config(file);
  std::vector<PreparedScene> frames;
  for (std::uint64_t seed = 5000 + static_cast<std::uint64_t>(GetParam() % 8) * 100;
       static_cast<int>(frames.size()) < ScenesPerBatch; ++seed) {
    try {
      frames.push_back(prepare(random_scene(seed), cfg));
    } catch (const SceneError&) {  // over a capacity of the configuration
    }
  }
  REQUIRE_COMPACT_TOP(cfg, file);
  std::vector<const PreparedScene*> ptrs;
  for (const PreparedScene& p : frames) ptrs.push_back(&p);
  expect_frames("random scenes, batch " + std::to_string(GetParam()) + " at " + file, ptrs,
                random_options(static_cast<std::uint64_t>(GetParam())));
}

INSTANTIATE_TEST_SUITE_P(Batches, CompactRandomScenes, ::testing::Range(0, 16));  // 200 scenes on each top

// ---------------------------------------------------------------- hard cases

BuiltScene two_triangles(int w, int h, double shift) {
  return screen(w, h,
                {poly({vtx(1 + shift, 1, 0.2, 255, 0, 0), vtx(w - 2.0, 3 + shift, 0.6, 0, 255, 0),
                       vtx(4, h - 1.5, 0.9, 0, 0, 255)}),
                 poly({vtx(w - 1.0, 1, 0.7, 250, 250, 0), vtx(w * 0.6, h - 1.0, 0.1, 0, 250, 250),
                       vtx(2 + shift, h * 0.4, 0.5, 250, 0, 250)})},
                "two triangles", {7, 70, 170});
}

// Frames of every size the top takes, for `cfg`: random-looking triangles, empty screens, the
// widest screen the line buffer holds and one pixel, and shipped scenes; each only when its values
// fit the configuration's words (the sized default's depth word holds its own scenes, not any).
std::vector<PreparedScene> frames_of_every_size(const Config& cfg) {
  std::vector<PreparedScene> v;
  auto add = [&](const BuiltScene& s) {
    try {
      v.push_back(prepare(s, cfg));
    } catch (const SceneError&) {  // a value over one of the configuration's words
    }
  };
  const ScreenPolygon cover = poly({vtx(-1, -1, 0.5, 9, 99, 199), vtx(3, -1, 0.5, 9, 99, 199), vtx(-1, 3, 0.5, 9, 99, 199)});
  add(two_triangles(40, 30, 0.0));
  add(screen(40, 30, {}, "empty", {1, 2, 3}));
  add(two_triangles(cfg.max_width, 12, 1.7));
  add(screen(1, 1, {cover}, "one pixel"));
  add(screen(1, 1, {}, "one empty pixel", {4, 5, 6}));
  add(two_triangles(3, 41, 0.4));
  for (const char* name : {"default.json", "highlight.json", "cone.json"}) {
    PreparedScene p;
    if (prepare_shipped(name, cfg, p).empty()) v.push_back(p);
  }
  return v;
}

// Frames of several sizes back to back (among them the widest the line buffer holds, one pixel,
// empty ones), then runs one after another without a reset, on both compact tops.
TEST(CosimCompact, FramesBackToBackAndEdgeSizes) {
  for (const char* file : {SizedFile, WideFile, LanesFile}) {
    const Config cfg = compact_config(file);
    const std::vector<PreparedScene> frames = frames_of_every_size(cfg);
    bool widest = false, one = false, empty = false;
    std::vector<const PreparedScene*> ptrs;
    for (const PreparedScene& p : frames) {
      widest = widest || p.width == cfg.max_width;
      one = one || (p.width == 1 && p.height == 1);
      empty = empty || p.edges.empty();
      ptrs.push_back(&p);
    }
    ASSERT_TRUE(widest && one && empty) << file << ": " << frames.size() << " frames, widest " << widest
                                        << ", one pixel " << one << ", empty " << empty;
    REQUIRE_COMPACT_TOP(cfg, file);
    for (const RtlOptions& o : stall_patterns(11))
      if (!expect_frames(std::string("frames back to back at ") + file, ptrs, o)) return;
    for (int k = 0; k < 3; ++k) {
      RtlOptions o{static_cast<std::uint64_t>(20 + k), 0.2, 0.2};
      o.reset = false;
      if (!expect_frames(std::string("consecutive run without a reset at ") + file, {k % 2 ? ptrs.front() : ptrs.back()},
                         o))
        return;
    }
  }
}

// More active edges on one line than the list holds: overflow_o rises (the compact list refuses
// the new record as the pipelined one does); the next run (after the bench's reset) is clean.
TEST(CosimCompact, ActiveEdgeListOverflowSetsOverflowO) {
  const Config cfg = compact_config(WideFile);
  BuiltScene s = screen(96, 20, {}, "overflow");
  for (int k = 0; k < 40; ++k) {  // 40 slivers crossing line 10: 80 active edges > 64
    const double x = 1 + k * 2.3;
    s.polygons.push_back(poly({vtx(x, 2, 0.5, 200, 100, 50), vtx(x + 1.2, 18, 0.5, 200, 100, 50),
                               vtx(x + 0.4, 18, 0.5, 50, 100, 200)}));
  }
  Config roomy = cfg;
  roomy.max_active_edges = 1 << 20;  // past the software check: the hardware must notice
  PreparedScene p = prepare(s, roomy);
  p.config = cfg;  // and run it on the compact top regardless
  ASSERT_GT(p.needs.max_active_edges, cfg.max_active_edges);
  REQUIRE_COMPACT_TOP(cfg, WideFile);
  RtlOptions o;
  o.compare = false;
  o.watchdog = 200000;  // the RTL may drop edges or stop; either way overflow_o must be set
  const RtlResult r = run_rtl(p, o);
  EXPECT_TRUE(r.overflow) << "overflow_o never rose with " << p.needs.max_active_edges << " active edges\n"
                          << r.summary();
  const PreparedScene ok = prepare(two_triangles(32, 24, 0.5), cfg);
  expect_frames("frame after an overflow", {&ok}, RtlOptions{31, 0.1, 0.1});
}

// Depth ties: coplanar.json (made for the rule) under both rules, frame by frame in one run.
TEST(CosimCompact, DepthTieRulesFrameByFrame) {
  for (const char* file : {SizedFile, WideFile, LanesFile}) {
    const Config cfg = compact_config(file);
    PreparedScene sub;
    const std::string why = prepare_shipped("coplanar.json", cfg, sub);
    ASSERT_EQ(why, "") << "coplanar.json at " << file;
    ASSERT_EQ(sub.depth_tie, DepthTie::Submission);
    PreparedScene arr = sub;
    arr.depth_tie = DepthTie::Arrival;
    ASSERT_NE(WatkinsTop(cfg).render(sub).rgb, WatkinsTop(cfg).render(arr).rgb) << "the rules agree at " << file;
    REQUIRE_COMPACT_TOP(cfg, file);
    for (const RtlOptions& o : stall_patterns(40))
      if (!expect_frames(std::string("coplanar.json, rules alternating, at ") + file, {&sub, &arr, &sub, &arr}, o))
        return;
  }
}

// The compact top emits full frames only: the bench refuses a sparse frame before simulating.
TEST(CosimCompact, SparseFrameRefused) {
  const Config cfg = compact_config(SizedFile);
  const PreparedScene p = prepare(two_triangles(20, 10, 0.0), cfg);
  RtlOptions o;
  o.sparse = true;
  try {
    run_rtl(p, o);
    ADD_FAILURE() << "a sparse frame ran on the compact top";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "RTL: sparse: frame 0 asks for sparse output but its configuration has compact "
                                     "true (the compact top emits full frames only)");
  }
}

}  // namespace
