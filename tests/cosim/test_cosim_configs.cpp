// The RTL built for other configurations (CMake option WATKINS_RTL_CONFIGS) against the
// model built for the same configuration: every shipped scene at its sized configuration
// (scenes/sized/<scene>.<shading>.json) on the top built for it, and random scenes at the narrow and
// wide test configurations (tests/configs/), both shadings. Every pixel and every stage stream bit
// for bit, under input gaps and output stalls, full-frame and sparse; and the cycle model's
// prediction equal to the RTL's cycles with no gaps or stalls.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "build_options.hpp"
#include "cli_run.hpp"
#include "config_file.hpp"
#include "cosim_support.hpp"
#include "curve_scenes.hpp"
#include "cycle_model.hpp"
#include "float_reference.hpp"
#include "image_io.hpp"
#include "prepare.hpp"
#include "random_scene.hpp"
#include "rtl_bench.hpp"
#include "scene.hpp"

using namespace watkins;
using namespace watkins::tb;
using namespace watkins::tb::test;
using namespace watkins::test;

namespace {

// With the default WATKINS_RTL_CONFIGS (what CI builds) a configuration without its top is a
// failure; with another list its tests are skipped, saying why.
#ifdef WATKINS_RTL_CONFIGS_DEFAULT
constexpr bool RequireEveryTop = true;
#else
constexpr bool RequireEveryTop = false;
#endif

#define REQUIRE_TOP(cfg, shading, file)                             \
  do {                                                              \
    const std::string why = rtl_unavailable(cfg, shading, file);    \
    if (!why.empty()) {                                             \
      ASSERT_FALSE(RequireEveryTop) << why;                         \
      GTEST_SKIP() << why;                                          \
    }                                                               \
  } while (0)

// The frames at full speed (full-frame and sparse): the prediction must equal the RTL's cycles.
void expect_predicted(const std::string& what, const std::vector<const PreparedScene*>& frames) {
  for (const bool sparse : {false, true}) {
    RtlOptions o;
    o.sparse = sparse;
    o.compare = false;
    for (const PreparedScene* p : frames) {
      const RtlResult r = run_rtl(*p, o);
      ASSERT_TRUE(r.ok()) << what << ": " << r.summary();
      const CyclePrediction c = predict_cycles(*p, sparse ? PixelOutput::Sparse : PixelOutput::FullFrame,
                                               p->config.max_active_edges, p->config);
      EXPECT_EQ(c.cycles, r.cycles) << what << (sparse ? " sparse" : " full-frame");
      EXPECT_EQ(c.pixels, r.pixels) << what << (sparse ? " sparse" : " full-frame");
    }
  }
}

// The frames back to back at full speed, under gaps and stalls, under all-stall bursts, and in
// sparse mode under gaps and stalls: every frame the model's, every stage stream checked.
void expect_clean_frames(const std::string& what, const std::vector<const PreparedScene*>& frames) {
  std::vector<Image> model;
  for (const PreparedScene* p : frames) model.push_back(WatkinsTop(p->config).render(*p));
  std::vector<const Image*> want;
  for (const Image& m : model) want.push_back(&m);
  RtlOptions patterns[] = {{1, 0.0, 0.0}, {2, 0.2, 0.3}, {3, 0.1, 0.02, 300}, {4, 0.2, 0.3}};
  patterns[3].sparse = true;
  for (const RtlOptions& o : patterns) {
    const RtlResult r = run_rtl_frames(frames, o, want);
    const std::string w = what + (o.sparse ? " sparse" : "");
    expect_clean(w, o, r);
    if (!r.ok()) return;
    EXPECT_GT(r.stage_items, 0) << w << ": the stage streams were not checked";
    ASSERT_EQ(r.frames.size(), frames.size());
    for (std::size_t f = 0; f < frames.size(); ++f) {
      EXPECT_EQ(r.frames[f].image.rgb, model[f].rgb) << w << " frame " << f;
      EXPECT_EQ(r.frames[f].image.covered, model[f].covered) << w << " frame " << f;
    }
  }
}

// scenes/sized/<scene>.<shading>.json file names, sorted; the curves configuration (one for several
// scenes, patches.curves.phong.json) has tests of its own below.
std::vector<std::string> sized_configs() {
  std::vector<std::string> v;
  for (const auto& e : std::filesystem::directory_iterator(WATKINS_SOURCE_DIR "/scenes/sized")) {
    const std::string name = e.path().filename().string();
    if (e.path().extension() == ".json" && name.find(".curves.") == std::string::npos) v.push_back(name);
  }
  std::sort(v.begin(), v.end());
  if (v.empty()) v.push_back("<none>");
  return v;
}

class SizedConfig : public ::testing::TestWithParam<std::string> {};

// <scene>.<gouraud|phong>.json: scenes/<scene>.json in that shading at that configuration.
TEST_P(SizedConfig, ShippedSceneOnItsOwnRtl) {
  const std::string name = GetParam();
  if (name == "<none>") GTEST_SKIP() << "no scenes/sized/*.json";
  const auto dot = name.find('.');
  const std::string scene_name = name.substr(0, dot);
  const std::string shading_name = name.substr(dot + 1, name.rfind('.') - dot - 1);
  ASSERT_TRUE(shading_name == "gouraud" || shading_name == "phong") << name;
  const ShadingMode shading = shading_name == "phong" ? ShadingMode::Phong : ShadingMode::Gouraud;
  const std::string file = "scenes/sized/" + name;
  const Config cfg = load_config(WATKINS_SOURCE_DIR "/" + file);
  const BuiltScene scene = load_scene(WATKINS_SOURCE_DIR "/scenes/" + scene_name + ".json", shading_options(shading));
  const PreparedScene p = prepare(scene, cfg);
  ASSERT_EQ(p.config, cfg);
  ASSERT_NE(rtl_parameters(cfg, shading), rtl_parameters(Config{}, shading)) << "a sized configuration is not the default";
  REQUIRE_TOP(cfg, shading, file);
  EXPECT_EQ(rtl_max_width(cfg, shading), cfg.max_width);
  expect_clean_frames(name, {&p});
  expect_predicted(name, {&p});
}

INSTANTIATE_TEST_SUITE_P(Sized, SizedConfig, ::testing::ValuesIn(sized_configs()), scene_test_name);

// A top without the smoother (Smoothing = 0, as the sized default scene's is) ignores smooth_w_i:
// the bench refuses a smoothed frame for it before simulating anything, naming the field (prepare()
// refuses such a scene first; this is a frame changed after preparation). Unsmoothed frames on
// that top are SizedConfig's above.
TEST(CosimConfigs, SmoothedFrameRefusedWithoutTheSmoother) {
  const Config cfg = load_config(WATKINS_SOURCE_DIR "/scenes/sized/default.gouraud.json");
  ASSERT_FALSE(cfg.smoothing) << "the default scene never smooths: its sized top has no smoother";
  PreparedScene p = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/default.json", shading_options(ShadingMode::Gouraud)), cfg);
  ASSERT_EQ(p.smooth_w, 0);
  p.smooth_w = 102;
  try {
    run_rtl(p);
    ADD_FAILURE() << "a smoothed frame ran on a top without the smoother";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "RTL: smoothing: frame 0 smooths (smooth_w 102) but its configuration has "
                                     "smoothing false (the top has no smoother)");
  }
}

// Herman and Liu at their own resolution (64 x 64 x 28 voxels, about 200 active edges): one top,
// sized to hold the smoothed ellipsoid and the three phantoms with averaged normals, runs them back
// to back, with the smoother (W = 0.8) and without it (smooth_w 0: the smoother passes pixels
// through), bit for bit and cycle for cycle.
TEST(CosimConfigs, HermanLiuAtThePapersResolution) {
  const std::string file = "scenes/sized/voxel_smoothed_64.gouraud.json";
  const Config cfg = load_config(WATKINS_SOURCE_DIR "/" + file);
  ASSERT_TRUE(cfg.smoothing);
  ASSERT_GE(cfg.max_active_edges, 196);
  std::vector<PreparedScene> frames;
  for (const char* scene : {"voxel_smoothed_64", "voxel_ellipsoid_64", "voxel_beaded_64", "voxel_two_lobed_64"})
    frames.push_back(prepare(load_scene(std::string(WATKINS_SOURCE_DIR "/scenes/") + scene + ".json",
                                        shading_options(ShadingMode::Gouraud)),
                             cfg));
  BuildOptions unsmoothed = shading_options(ShadingMode::Gouraud);
  unsmoothed.smooth = 0.0;
  frames.push_back(prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/voxel_smoothed_64.json", unsmoothed), cfg));
  ASSERT_GT(frames[0].smooth_w, 0);
  ASSERT_EQ(frames[4].smooth_w, 0);
  for (const PreparedScene& p : frames) EXPECT_GE(p.needs.max_active_edges, 190);
  REQUIRE_TOP(cfg, ShadingMode::Gouraud, file);
  std::vector<const PreparedScene*> ptrs;
  for (const PreparedScene& p : frames) ptrs.push_back(&p);
  expect_clean_frames("Herman and Liu 64 x 64 x 28", ptrs);
  expect_predicted("Herman and Liu 64 x 64 x 28", ptrs);
}

// Random scenes (tests/support/random_scene) that fit `cfg`, `count` of them from `seed` on.
std::vector<PreparedScene> random_frames(const Config& cfg, bool phong, std::uint64_t seed, int count) {
  std::vector<PreparedScene> v;
  for (std::uint64_t s = seed; static_cast<int>(v.size()) < count && s < seed + 20 * count; ++s) {
    try {
      v.push_back(prepare(phong ? random_phong_scene(s) : random_scene(s), cfg));
    } catch (const SceneError&) {  // over a capacity or a word of this configuration
    }
  }
  return v;
}

struct TestConfig {
  const char* file;
  bool phong;
};

// How ctest names the parameter: "narrow.json phong".
void PrintTo(const TestConfig& c, std::ostream* os) { *os << c.file << (c.phong ? " phong" : " gouraud"); }

class RandomAtConfig : public ::testing::TestWithParam<TestConfig> {};

TEST_P(RandomAtConfig, RandomScenesUnderStalls) {
  const std::string file = std::string("tests/configs/") + GetParam().file;
  const bool phong = GetParam().phong;
  const ShadingMode shading = phong ? ShadingMode::Phong : ShadingMode::Gouraud;
  const Config cfg = load_config(WATKINS_SOURCE_DIR "/" + file);
  constexpr int Frames = 8;
  const std::vector<PreparedScene> frames = random_frames(cfg, phong, phong ? 7100 : 7000, Frames);
  ASSERT_EQ(static_cast<int>(frames.size()), Frames) << "too few random scenes fit " << file;
  REQUIRE_TOP(cfg, shading, file);
  std::vector<const PreparedScene*> ptrs;
  for (const PreparedScene& p : frames) ptrs.push_back(&p);
  const std::string what = file + (phong ? " phong" : " gouraud") + " random scenes";
  expect_clean_frames(what, ptrs);
  expect_predicted(what, ptrs);
}

INSTANTIATE_TEST_SUITE_P(Configs, RandomAtConfig,
                         ::testing::Values(TestConfig{"narrow.json", false}, TestConfig{"narrow.json", true},
                                           TestConfig{"wide.json", false}, TestConfig{"wide.json", true}),
                         [](const ::testing::TestParamInfo<TestConfig>& i) {
                           return std::string(i.param.file).substr(0, std::string(i.param.file).find('.')) +
                                  (i.param.phong ? "_phong" : "_gouraud");
                         });

// The order-3 Phong configuration of Whitted's curves: the shipped patch scenes drawn by curves
// and the synthetic curve scene, one Verilated top for all.
constexpr const char* CurvesConfig = "scenes/sized/patches.curves.phong.json";

// Whitted's curved edges on the forward-difference top (EdgeOrder 3): the synthetic curve scene
// (a disc, a sine-like band, a steep curve over a triangle) and random scenes of straight edges
// (d2 = d3 = 0) on the same top, back to back.
TEST(CosimConfigs, CurvedEdgesOnTheCubicTop) {
  const std::string file = CurvesConfig;
  const Config cfg = load_config(WATKINS_SOURCE_DIR "/" + file);
  ASSERT_EQ(cfg.edge_order, 3);
  const PreparedScene curves = prepare(curve_scene(ShadingMode::Phong), cfg);
  ASSERT_GT(curves.needs.curve_edges, 6);
  const std::vector<PreparedScene> random = random_frames(cfg, true, 7300, 3);
  ASSERT_EQ(random.size(), 3u);
  REQUIRE_TOP(cfg, ShadingMode::Phong, file);
  std::vector<const PreparedScene*> ptrs{&curves};
  for (const PreparedScene& p : random) ptrs.push_back(&p);
  ptrs.push_back(&curves);
  expect_clean_frames(file + " curve scene", ptrs);
  expect_predicted(file + " curve scene", ptrs);
}

// The shipped patch scenes drawn by Whitted's curves (`watkins render --patches curves`, each with
// its k_u, k_v interior edges), Phong, on the order-3 top: back to back under gaps and stalls,
// every pixel and stage stream the model's, the cycle model's cycles the RTL's. Each frame also
// covers what the double reference does, but for a few pixels at the curved silhouettes.
TEST(CosimConfigs, ShippedPatchScenesByCurves) {
  const std::string file = CurvesConfig;
  const Config cfg = load_config(WATKINS_SOURCE_DIR "/" + file);
  ASSERT_EQ(cfg.edge_order, 3);
  BuildOptions opt = shading_options(ShadingMode::Phong);
  opt.patches_as_curves = true;
  struct Shipped {
    const char* scene;
    int most_curved_edges;  // on one scan line, at the scene's k_u, k_v
  };
  std::vector<PreparedScene> frames;
  for (const Shipped& s : {Shipped{"patch", 28}, Shipped{"bspline", 54}, Shipped{"teapot", 68}}) {
    const BuiltScene scene = load_scene(WATKINS_SOURCE_DIR "/scenes/" + std::string(s.scene) + ".json", opt);
    ASSERT_TRUE(scene.polygons.empty()) << s.scene << ": every patch drawn by curves";
    frames.push_back(prepare(scene, cfg));
    const PreparedScene& p = frames.back();
    EXPECT_EQ(p.needs.max_curve_edges, s.most_curved_edges) << s.scene;
    EXPECT_EQ(p.needs.curve_edges, static_cast<int>(p.edges.size())) << s.scene << ": every edge a curve's";
    const Image model = WatkinsTop(cfg).render(p);
    const Image reference = render_float_reference(scene);
    EXPECT_GT(std::count(model.covered.begin(), model.covered.end(), 1), 10000) << s.scene;
    // Measured: coverage 0, 1, 1 pixels; another region visible at 1, 1, 6; max |d| 1, 1, 4 levels.
    const ImageError e = compare_images(model, reference);
    EXPECT_LE(e.coverage_differs, 2) << s.scene;
    EXPECT_LE(e.visibility_differs, 10) << s.scene;
    EXPECT_LE(e.max_abs, 6) << s.scene;
    EXPECT_LT(e.mean_abs, 0.3) << s.scene;
  }
  REQUIRE_TOP(cfg, ShadingMode::Phong, file);
  const std::vector<const PreparedScene*> ptrs{&frames[0], &frames[1], &frames[2]};
  expect_clean_frames(file + " shipped patch scenes by curves", ptrs);
  expect_predicted(file + " shipped patch scenes by curves", ptrs);
}

// Frames prepared for two configurations cannot share a run (the RTL is built for one).
TEST(CosimConfigs, MixedConfigurationsAreRefused) {
  const BuiltScene s = random_scene(std::uint64_t{7000});
  const PreparedScene a = prepare(s);
  const PreparedScene b = prepare(s, load_config(WATKINS_SOURCE_DIR "/tests/configs/wide.json"));
  EXPECT_THROW(run_rtl_frames({&a, &b}), std::invalid_argument);
}

// A configuration no top was built for: nothing runs, and the result says how to build one.
TEST(CosimConfigs, MissingTopIsNamed) {
  Config cfg;
  cfg.max_width = 200;  // MaxWidth = 200: no build of ours has it
  const PreparedScene p = prepare(random_scene(std::uint64_t{7000}), cfg);
  const RtlResult r = run_rtl(p);
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(r.frames.empty());
  EXPECT_NE(r.unavailable.find("MaxWidth=200"), std::string::npos) << r.unavailable;
  EXPECT_NE(r.unavailable.find("-DWATKINS_RTL_CONFIGS="), std::string::npos) << r.unavailable;
  EXPECT_NE(r.summary().find(r.unavailable), std::string::npos);
  EXPECT_EQ(rtl_max_width(cfg, ShadingMode::Gouraud), 0);
  EXPECT_EQ(rtl_unavailable(Config{}, ShadingMode::Phong), "");
}

}  // namespace

namespace {

// `watkins render --rtl --config F` with no top built for F: one line naming the configuration
// and the CMake option, exit code 2 (usage), no image.
TEST(CosimConfigs, CliRefusesAConfigurationWithoutATop) {
  const ScratchDir dir;
  const std::string cfg = dir.write("unbuilt.json", "{\"max_width\": 333}\n");
  const std::string png = dir.write("out.png", "");
  std::filesystem::remove(png);
  const CliRun r = run_cli("render --rtl --config " + cfg + " --out " + png);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  const auto line = r.output.find("watkins: usage: --rtl --config " + cfg + ": no Verilated watkins_top");
  ASSERT_NE(line, std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\n', line), r.output.size() - 1) << "one line, the last:\n" << r.output;
  EXPECT_NE(r.output.find("-DWATKINS_RTL_CONFIGS=" + cfg + "@gouraud"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(png));
}

}  // namespace
