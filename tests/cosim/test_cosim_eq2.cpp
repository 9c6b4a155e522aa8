// Gouraud's eq. (2) on the RTL: the Gouraud top built with the shade divider (HasEq2 = 1,
// tests/configs/eq2.gouraud.json) against the model built for the same configuration. Every
// shipped scene in eq2 mode and seeded random scenes, at full speed (cycles = the cycle model's,
// full-frame and sparse), under input gaps and output stalls and all-stall bursts, sparse; every
// pixel and every stage stream bit for bit. And eq. (1) frames on the same top (eq2_i = 0), and
// the two modes switched frame by frame.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "config_file.hpp"
#include "cosim_support.hpp"
#include "cycle_model.hpp"
#include "random_scene.hpp"

namespace watkins::tb::test {
namespace {

const char* const ConfigFile = "tests/configs/eq2.gouraud.json";

Config eq2_config() { return load_config(WATKINS_SOURCE_DIR "/" + std::string(ConfigFile)); }

#ifdef WATKINS_RTL_CONFIGS_DEFAULT
constexpr bool RequireTop = true;
#else
constexpr bool RequireTop = false;
#endif

#define REQUIRE_EQ2_TOP()                                                            \
  do {                                                                               \
    const std::string why = rtl_unavailable(eq2_config(), ShadingMode::Gouraud, ConfigFile); \
    if (!why.empty()) {                                                              \
      ASSERT_FALSE(RequireTop) << why;                                               \
      GTEST_SKIP() << why;                                                           \
    }                                                                                \
  } while (0)

// The frame at full speed in both output modes (cycles equal to the prediction), then under gaps,
// stalls and all-stall bursts, and sparse under gaps and stalls: every pixel the model's.
void check_frame(const std::string& what, const PreparedScene& p) {
  const Image model = WatkinsTop(p.config).render(p);
  for (const bool sparse : {false, true}) {
    RtlOptions o;
    o.sparse = sparse;
    const RtlResult r = run_rtl(p, o, &model);
    expect_clean(what + (sparse ? " sparse" : ""), o, r);
    if (!r.ok()) return;
    const CyclePrediction c =
        predict_cycles(p, sparse ? PixelOutput::Sparse : PixelOutput::FullFrame, p.config.max_active_edges, p.config);
    EXPECT_EQ(c.cycles, r.cycles) << what << (sparse ? " sparse" : " full-frame");
    EXPECT_EQ(c.pixels, r.pixels) << what << (sparse ? " sparse" : " full-frame");
  }
  RtlOptions patterns[] = {{2, 0.25, 0.3}, {3, 0.1, 0.02, 300}, {5, 0.2, 0.3, 20}};
  patterns[2].sparse = true;
  for (const RtlOptions& o : patterns) {
    const RtlResult r = run_rtl(p, o, &model);
    expect_clean(what + (o.sparse ? " sparse" : "") + " with gaps and stalls", o, r);
    if (!r.ok()) return;
    EXPECT_GT(r.stage_items, 0) << what << ": the stage streams were not checked";
    EXPECT_EQ(r.frames.at(0).image.rgb, model.rgb) << what;
    EXPECT_EQ(r.frames.at(0).image.covered, model.covered) << what;
  }
}

class Eq2Shipped : public ::testing::TestWithParam<std::string> {};

TEST_P(Eq2Shipped, SceneInEq2Mode) {
  REQUIRE_EQ2_TOP();
  const std::string name = GetParam();
  if (name == "<none>") GTEST_SKIP() << "no scenes/*.json";
  BuildOptions opt;
  opt.shading = ShadingMode::Gouraud;
  opt.interpolation = Interpolation::Eq2;
  PreparedScene p;
  try {
    p = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/" + name, opt), eq2_config());
  } catch (const SceneError& e) {
    GTEST_SKIP() << "the scene does not load or fit in eq2 mode: " << e.what();
  }
  if (p.width > rtl_max_width(p.config)) GTEST_SKIP() << "wider than the RTL line buffer";
  ASSERT_TRUE(p.eq2);
  check_frame(name + " eq2", p);
}

INSTANTIATE_TEST_SUITE_P(Shipped, Eq2Shipped, ::testing::ValuesIn(shipped_scenes()), scene_test_name);

// Random scenes (overlapping, interpenetrating, partly off screen), each in eq2 mode under its
// seed's stall pattern; every fourth at full speed with its cycles predicted.
TEST(CosimEq2, RandomScenesUnderStalls) {
  REQUIRE_EQ2_TOP();
  const Config cfg = eq2_config();
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    BuiltScene s = watkins::test::random_scene(seed);
    s.interpolation = Interpolation::Eq2;
    const PreparedScene p = prepare(s, cfg);
    const Image model = WatkinsTop(cfg).render(p);
    const RtlOptions o = random_options(seed);
    const RtlResult r = run_rtl(p, o, &model);
    expect_clean(s.name + " eq2", o, r);
    if (!r.ok()) return;
    EXPECT_EQ(r.frames.at(0).image.rgb, model.rgb) << s.name;
    if (o.gap == 0 && o.stall == 0)
      EXPECT_EQ(r.cycles, predict_cycles(p, PixelOutput::FullFrame, cfg.max_active_edges, cfg).cycles) << s.name;
  }
}

// Eq. (1) on the top with the divider: eq2_i = 0 passes the interpolated shade (the same image
// as the plain top's), 20 cycles later (the divider's latency).
TEST(CosimEq2, EquationOneOnTheSameTop) {
  REQUIRE_EQ2_TOP();
  const Config cfg = eq2_config();
  const PreparedScene p = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/sphere.json"), cfg);
  ASSERT_FALSE(p.eq2);
  EXPECT_EQ(WatkinsTop(cfg).render(p).rgb, WatkinsTop().render(p).rgb);
  check_frame("sphere.json eq1 on the eq2 top", p);
  EXPECT_EQ(predict_cycles(p, PixelOutput::FullFrame, cfg.max_active_edges, cfg).cycles,
            predict_cycles(p, PixelOutput::FullFrame).cycles + rtl_timing::DividerStages);
}

// The modes switched frame by frame in one simulation, under gaps and stalls.
TEST(CosimEq2, SwitchedBetweenFrames) {
  REQUIRE_EQ2_TOP();
  const Config cfg = eq2_config();
  BuildOptions opt;
  opt.interpolation = Interpolation::Eq2;
  const PreparedScene eq2 = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/sphere.json", opt), cfg);
  const PreparedScene eq1 = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/sphere.json"), cfg);
  const Image m2 = WatkinsTop(cfg).render(eq2), m1 = WatkinsTop(cfg).render(eq1);
  EXPECT_NE(m1.rgb, m2.rgb);
  RtlOptions o{6, 0.1, 0.2};
  const RtlResult r = run_rtl_frames({&eq1, &eq2, &eq2, &eq1}, o, {&m1, &m2, &m2, &m1});
  expect_clean("sphere.json, eq1 and eq2 switched", o, r);
  ASSERT_EQ(r.frames.size(), 4u);
  EXPECT_EQ(r.frames[1].image.rgb, m2.rgb);
  EXPECT_EQ(r.frames[3].image.rgb, m1.rgb);
}

// A top without the divider is never driven an eq2 frame.
TEST(CosimEq2, RefusedOnATopWithoutTheDivider) {
  BuildOptions opt;
  opt.interpolation = Interpolation::Eq2;
  PreparedScene p = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/sphere.json", opt), eq2_config());
  p.config = Config{};
  try {
    (void)run_rtl(p, RtlOptions{});
    FAIL() << "an eq2 frame was driven into a top without the divider";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("RTL: eq2: frame 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace watkins::tb::test
