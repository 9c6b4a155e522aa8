// Power-up state: the SystemC bench's tops (Verilated with --x-initial unique) started with every
// register and RAM word that has no reset at random values (rtl_initial_state(seed), Verilator's
// randReset(2) + randSeed) render every frame exactly as when they start at zero: the image is
// the model's, pixel for pixel, in the cycles the cycle model predicts. One process per seed
// (the SystemC tops are built once per process): ctest runs this binary with seed 0 (zeros) and
// with seeds 1, 2 and 3, so the images of all seeds are the model's and hence identical.
// Usage: watkins_x_initial_tests SEED [gtest flags]
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "cosim_support.hpp"
#include "cycle_model.hpp"

namespace watkins::tb::test {
namespace {

// The frame on the RTL at full speed (the cycle count must be the model's prediction), then in
// sparse output mode and under gaps and stalls.
void check_frame(const PreparedScene& p, const std::string& what) {
  const Image model = WatkinsTop(p.config).render(p);
  for (int k = 0; k < 3; ++k) {
    RtlOptions o;
    o.seed = 7 + k;
    o.sparse = k == 1;
    if (k == 2) o.gap = 0.2, o.stall = 0.3;
    const std::string run = what + (k == 1 ? " sparse" : k == 2 ? " with gaps and stalls" : "");
    const RtlResult r = run_rtl(p, o, &model);
    expect_clean(run, o, r);
    ASSERT_TRUE(r.ok()) << run;
    EXPECT_EQ(r.frames.at(0).image.rgb, model.rgb) << run;
    EXPECT_EQ(r.frames.at(0).image.covered, model.covered) << run;
    if (k < 2) {
      const CyclePrediction c = predict_cycles(p, o.sparse ? PixelOutput::Sparse : PixelOutput::FullFrame,
                                               p.config.max_active_edges, p.config);
      EXPECT_EQ(r.cycles, c.cycles) << run;
    }
  }
}

TEST(XInitial, DefaultSceneGouraud) { check_frame(prepare(load_scene_or_default("")), "default scene, gouraud"); }

TEST(XInitial, DefaultScenePhong) {
  BuildOptions opt;
  opt.shading = ShadingMode::Phong;
  check_frame(prepare(load_scene_or_default("", opt)), "default scene, phong");
}

TEST(XInitial, HighlightPhong) {
  check_frame(prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/highlight.json")), "highlight.json, phong");
}

// The equal-depth rule's id word starts random too.
TEST(XInitial, CoplanarSubmission) {
  check_frame(prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/coplanar.json")), "coplanar.json, submission");
}

}  // namespace
}  // namespace watkins::tb::test

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s SEED [gtest flags]  (SEED 0: zero power-up state)\n", argv[0]);
    return 2;
  }
  const int seed = std::atoi(argv[1]);
  std::printf("power-up state: %s (seed %d)\n", seed == 0 ? "zeros" : "random", seed);
  watkins::tb::rtl_initial_state(seed);
  return RUN_ALL_TESTS();
}
