// The compact Phong top (watkins_top with Compact = 1 and Phong = 1: compact_normalizer and
// compact_phong_shader after the compact interpolator, docs/reference/compact.md) against the model
// built for the same configuration, at tests/configs/compact.phong.json (the default scene's sized
// Phong configuration with compact true, the UP5K's) and at tests/configs/compact_narrow.phong.json
// (the same with "phong": {"formats": "narrow"}: compact_normalizer_narrow and
// compact_phong_shader_narrow, docs/reference/compact-phong.md): every shipped scene that fits in Phong
// shading, 100 random Phong scenes, and the hard cases (antipodal and in-plane normals, n = 0 and
// 255, lights from every side, the eye at the light), under random input gaps and output stalls.
// Every pixel and every stage stream (active edges, segments, fragments, shaded fragments) bit for
// bit. Every frame's cycles are CompactCycleModel's for the configuration (its narrow path at the
// narrow formats).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "build_options.hpp"
#include "config_file.hpp"
#include "cosim_support.hpp"
#include "phong_hard_cases.hpp"
#include "prepare.hpp"
#include "random_scene.hpp"
#include "rtl_bench.hpp"
#include "scene.hpp"

using namespace watkins;
using namespace watkins::tb;
using namespace watkins::tb::test;
using namespace watkins::test;

namespace {

// MaxWidth 320, 36 edges, 2 materials; the model's formats and the narrow ones.
const char* const PhongFiles[] = {"tests/configs/compact.phong.json", "tests/configs/compact_narrow.phong.json"};

Config compact_phong_config(const char* file) {
  const Config c = load_config(std::string(WATKINS_SOURCE_DIR "/") + file);
  EXPECT_TRUE(c.compact) << file;
  EXPECT_EQ(c.lanes, 1) << file << ": the compact Phong top shades one fragment a beat";
  return c;
}

std::string file_test_name(const ::testing::TestParamInfo<const char*>& info) {
  return std::string(info.param).find("narrow") != std::string::npos ? "Narrow" : "ModelFormats";
}

// With the default WATKINS_RTL_CONFIGS (CI's) the compact Phong top is built: a missing one fails.
#ifdef WATKINS_RTL_CONFIGS_DEFAULT
constexpr bool RequireTop = true;
#else
constexpr bool RequireTop = false;
#endif

#define REQUIRE_COMPACT_PHONG_TOP(cfg, file)                                   \
  do {                                                                         \
    const std::string why = rtl_unavailable(cfg, ShadingMode::Phong, file);    \
    if (!why.empty()) {                                                        \
      ASSERT_FALSE(RequireTop) << why;                                         \
      GTEST_SKIP() << why;                                                     \
    }                                                                          \
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
  EXPECT_NE(r.top.find("Phong=1"), std::string::npos) << what << " ran on " << r.top;
  const bool narrow = frames.front()->config.phong == PhongFormat::Narrow;
  EXPECT_EQ(r.top.find("PhongNarrow=1") != std::string::npos, narrow) << what << " ran on " << r.top;
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

// Prepared at `cfg`, or the reason it does not fit (a capacity, a word, a smoothed scene).
std::string prepare_at(const BuiltScene& scene, const Config& cfg, PreparedScene& p) {
  try {
    p = prepare(scene, cfg);
  } catch (const SceneError& e) {
    return e.what();
  }
  if (p.smoothed()) return "it smooths (the compact top has no smoother)";
  if (p.width > cfg.max_width) return "wider than the line buffer";
  return "";
}

std::string prepare_shipped(const std::string& name, const Config& cfg, PreparedScene& p) {
  try {
    return prepare_at(load_scene(WATKINS_SOURCE_DIR "/scenes/" + name, shading_options(ShadingMode::Phong)), cfg, p);
  } catch (const SceneError& e) {
    return e.what();
  }
}

// ---------------------------------------------------------------- shipped scenes

class CompactPhongShippedScenes : public ::testing::TestWithParam<std::tuple<const char*, std::string>> {};

TEST_P(CompactPhongShippedScenes, MatchTheModel) {
  const char* const PhongFile = std::get<0>(GetParam());
  const std::string name = std::get<1>(GetParam());
  if (name == "<none>") GTEST_SKIP() << "no scenes/*.json";
  const Config cfg = compact_phong_config(PhongFile);
  PreparedScene p;
  const std::string why = prepare_shipped(name, cfg, p);
  if (!why.empty()) GTEST_SKIP() << name << " does not fit " << PhongFile << ": " << why;
  ASSERT_EQ(p.shading, ShadingMode::Phong);
  REQUIRE_COMPACT_PHONG_TOP(cfg, PhongFile);
  for (const RtlOptions& o : stall_patterns(7))
    if (!expect_frames(name + " at " + PhongFile, {&p}, o)) return;
}

INSTANTIATE_TEST_SUITE_P(Scenes, CompactPhongShippedScenes,
                         ::testing::Combine(::testing::ValuesIn(PhongFiles), ::testing::ValuesIn(shipped_scenes())),
                         [](const ::testing::TestParamInfo<std::tuple<const char*, std::string>>& info) {
                           return file_test_name({std::get<0>(info.param), info.index}) + "_" +
                                  scene_test_name({std::get<1>(info.param), info.index});
                         });

// How many shipped scenes the compact Phong top holds (the others are skipped above, saying why).
class CosimCompactPhong : public ::testing::TestWithParam<const char*> {};

TEST_P(CosimCompactPhong, ShippedScenesThatFit) {
  const char* const PhongFile = GetParam();
  const Config cfg = compact_phong_config(PhongFile);
  int fit = 0, all = 0;
  for (const std::string& name : shipped_scenes()) {
    PreparedScene p;
    ++all;
    const std::string why = prepare_shipped(name, cfg, p);
    fit += why.empty();
    std::printf("%-24s %s\n", name.c_str(), why.empty() ? "fits" : why.c_str());
  }
  std::printf("%d of %d shipped scenes fit the compact Phong top at %s\n", fit, all, PhongFile);
  EXPECT_GE(fit, 5);
}

// ---------------------------------------------------------------- random scenes

// random_phong_scene(seed) with its materials folded onto the configuration's table (polygon k's
// material mod max_materials), prepared at `cfg`; or the reason it does not fit.
std::string prepare_random(std::uint64_t seed, const Config& cfg, PreparedScene& p) {
  BuiltScene s = random_phong_scene(seed);
  if (static_cast<int>(s.materials.size()) > cfg.max_materials) {
    for (ScreenPolygon& poly : s.polygons) poly.material %= cfg.max_materials;
    s.materials.resize(static_cast<std::size_t>(cfg.max_materials));
  }
  return prepare_at(s, cfg, p);
}

class CompactPhongRandomScenes : public ::testing::TestWithParam<std::tuple<const char*, int>> {};

constexpr int ScenesPerBatch = 25;

// 4 batches of 25 random Phong scenes (the first 25 seeds of each batch's range that fit the
// configuration), each batch back to back in one run (the bench writes each frame's materials
// between frames; L and E change with every frame) under its own stall pattern (random_options).
TEST_P(CompactPhongRandomScenes, MatchTheModel) {
  const char* const PhongFile = std::get<0>(GetParam());
  const int batch = std::get<1>(GetParam());
  const Config cfg = compact_phong_config(PhongFile);
  std::vector<PreparedScene> frames;
  const std::uint64_t first = 7000 + static_cast<std::uint64_t>(batch) * 1000;
  for (std::uint64_t seed = first; static_cast<int>(frames.size()) < ScenesPerBatch && seed < first + 1000; ++seed) {
    PreparedScene p;
    if (prepare_random(seed, cfg, p).empty()) frames.push_back(std::move(p));
  }
  ASSERT_EQ(static_cast<int>(frames.size()), ScenesPerBatch) << "random Phong scenes that fit " << PhongFile;
  REQUIRE_COMPACT_PHONG_TOP(cfg, PhongFile);
  std::vector<const PreparedScene*> ptrs;
  for (const PreparedScene& p : frames) ptrs.push_back(&p);
  expect_frames("random Phong scenes at " + std::string(PhongFile) + ", batch " + std::to_string(batch), ptrs,
                random_options(static_cast<std::uint64_t>(batch)));
}

// 100 scenes per configuration.
INSTANTIATE_TEST_SUITE_P(Batches, CompactPhongRandomScenes,
                         ::testing::Combine(::testing::ValuesIn(PhongFiles), ::testing::Range(0, 4)),
                         [](const ::testing::TestParamInfo<std::tuple<const char*, int>>& info) {
                           return file_test_name({std::get<0>(info.param), info.index}) + "_" +
                                  std::to_string(std::get<1>(info.param));
                         });

// ---------------------------------------------------------------- hard cases

// The hard cases of tests/support/phong_hard_cases.hpp, lights from each side of a quad whose
// normals tilt outwards (from behind included), the eye at the light and opposite it.
std::vector<BuiltScene> hard_cases() {
  std::vector<BuiltScene> v = {antipodal_normals_scene(), screen_plane_normals_scene(), grazing_light_scene()};
  for (int n : {0, 1, 2, 64, 128, 255}) v.push_back(shininess_scene(n));
  const double sides[][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 1, 1}, {-1, -1, 0.2}};
  for (const auto& l : sides) {
    BuiltScene s = phong_scene(64, 48, {tilted_quad(4, 4, 56, 40, 0.9)}, material(0.8, 0.3, 1.0, 20), l[0], l[1], l[2]);
    s.name = "light from (" + std::to_string(l[0]) + ", " + std::to_string(l[1]) + ", " + std::to_string(l[2]) + ")";
    v.push_back(s);
  }
  // phong_scene's eye is (0, 0, -1): a light there is the eye at the light; opposite, behind the
  // surface.
  BuiltScene at = phong_scene(48, 40, {tilted_quad(2, 2, 44, 36, 0.6)}, material(1.0, 0.5, 1.5, 8), 0, 0, -1);
  at.name = "eye at the light";
  v.push_back(at);
  BuiltScene opposite = phong_scene(48, 40, {tilted_quad(2, 2, 44, 36, 0.6)}, material(1.0, 0.5, 1.5, 8), 0, 0, 1);
  opposite.name = "eye opposite the light";
  v.push_back(opposite);
  return v;
}

TEST_P(CosimCompactPhong, HardCasesMatchTheModel) {
  const char* const PhongFile = GetParam();
  const Config cfg = compact_phong_config(PhongFile);
  std::vector<PreparedScene> frames;
  std::vector<std::string> names;
  for (const BuiltScene& s : hard_cases()) {
    PreparedScene p;
    const std::string why = prepare_at(s, cfg, p);
    ASSERT_EQ(why, "") << s.name;
    frames.push_back(std::move(p));
    names.push_back(s.name + " at " + PhongFile);
  }
  REQUIRE_COMPACT_PHONG_TOP(cfg, PhongFile);
  std::uint64_t seed = 300;
  for (std::size_t k = 0; k < frames.size(); ++k)
    for (const RtlOptions& o : {RtlOptions{seed++, 0.0, 0.0}, RtlOptions{seed++, 0.2, 0.3}})
      if (!expect_frames(names[k], {&frames[k]}, o)) return;
  // All of them back to back: materials, L and E change at every frame start.
  std::vector<const PreparedScene*> ptrs;
  for (const PreparedScene& p : frames) ptrs.push_back(&p);
  expect_frames(std::string("hard cases back to back at ") + PhongFile, ptrs, RtlOptions{seed, 0.1, 0.2, 40});
}

// Lanes 2 is the compact Gouraud top's only: the configuration check refuses it for Phong.
TEST_P(CosimCompactPhong, TwoLanesRefused) {
  Config cfg = compact_phong_config(GetParam());
  cfg.lanes = 2;
  EXPECT_EQ(cfg.check(), "");
  EXPECT_EQ(cfg.check(ShadingMode::Phong), "lanes: 2 is Gouraud only (the compact Phong blocks shade one fragment a beat)");
  EXPECT_THROW(prepare(hard_cases().front(), cfg), SceneError);
}

INSTANTIATE_TEST_SUITE_P(Configs, CosimCompactPhong, ::testing::ValuesIn(PhongFiles), file_test_name);

}  // namespace
