// Co-simulation of the Phong top (watkins_top with Phong = 1: normalizer + phong_shader after the
// segment interpolator) against the bit-exact model, under random input gaps and back-pressure.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "build_options.hpp"
#include "cosim_support.hpp"
#include "phong_hard_cases.hpp"
#include "watkins_top.hpp"
#include "prepare.hpp"
#include "random_scene.hpp"
#include "rtl_bench.hpp"
#include "scene.hpp"

using namespace watkins;
using namespace watkins::tb;
using namespace watkins::tb::test;
using namespace watkins::test;

namespace {

// A Gouraud-prepared scene turned into Phong records without scene preparation: each shade
// channel s (0..255 levels) becomes a normal component (s - 127.5) / 128 in [-1, 1), so the
// records are arbitrary (not unit, interpolating through zero) and test the datapath alone.
PreparedScene as_phong_records(PreparedScene p) {
  for (EdgeRecord& e : p.edges) {
    for (int c = fmt::ChanNx; c <= fmt::ChanNz; ++c) {
      e.value[c] = floor_shift(e.value[c] - (i64{255} << (fmt::FracBits - 1)), 7);
      e.slope[c] = floor_shift(e.slope[c], 7);
    }
    e.material = e.poly % 3;
  }
  p.shading = ShadingMode::Phong;
  p.materials = {QuantizedMaterial{{200, 120, 60}, 50, 200, 20}, QuantizedMaterial{{60, 200, 90}, 30, 128, 128},
                 QuantizedMaterial{{255, 255, 255}, 256, 511, 0}};
  p.light = {4000, 6000, -14000};  // roughly unit, towards the viewer, up and right
  p.eye = {0, 0, -16384};
  return p;
}

TEST(PhongCosim, DatapathOnArbitraryNormalRecords) {
  const PreparedScene p = as_phong_records(prepare(load_scene_or_default("")));
  const Image want = WatkinsTop().render(p);
  for (int k = 0; k < 4; ++k) {
    RtlOptions o;
    o.seed = 11 + k;
    o.gap = 0.15 * k;
    o.stall = 0.2 * k;
    o.stall_burst = k == 3 ? 100 : 1;
    o.sparse = k % 2;
    const RtlResult r = run_rtl(p, o, &want);
    expect_clean("default scene as Phong records", o, r);
    EXPECT_GT(r.stage_items, 0);
  }
}

// ---------------------------------------------------------------- random Phong scenes
class RandomPhongScenes : public ::testing::TestWithParam<int> {};

constexpr int PhongScenesPerBatch = 25;

TEST_P(RandomPhongScenes, MatchTheModel) {
  int ran = 0;
  for (int k = 0; k < PhongScenesPerBatch; ++k) {
    const std::uint64_t seed = 5000 + static_cast<std::uint64_t>(GetParam()) * PhongScenesPerBatch + k;
    const BuiltScene scene = random_phong_scene(seed);
    PreparedScene prepared;
    try {
      prepared = prepare(scene);
    } catch (const SceneError&) {  // too many active edges for the hardware: not a co-simulation case
      continue;
    }
    ASSERT_EQ(prepared.shading, ShadingMode::Phong);
    RtlOptions o = random_options(seed);
    o.sparse = k % 2;
    const RtlResult r = run_rtl(prepared, o);
    expect_clean(scene.name + " (" + std::to_string(scene.polygons.size()) + " polygons, " +
                     std::to_string(scene.materials.size()) + " materials)" + (o.sparse ? " sparse" : ""),
                 o, r);
    if (!r.ok()) return;  // one report per batch is enough
    ++ran;
  }
  EXPECT_GE(ran, PhongScenesPerBatch * 4 / 5) << "most random scenes fit the hardware";
}

INSTANTIATE_TEST_SUITE_P(Batches, RandomPhongScenes, ::testing::Range(0, 4));  // 4 x 25 = 100 scenes

// ---------------------------------------------------------------- shipped scenes, Phong shading
class ShippedScenesPhong : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedScenesPhong, MatchTheModelUnderGapsAndStalls) {
  check_shipped_scene(GetParam(), shading_options(ShadingMode::Phong));
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedScenesPhong, ::testing::ValuesIn(shipped_scenes()), scene_test_name);

// ---------------------------------------------------------------- the hard cases on the RTL
// The scenes whose error bounds tests/test_phong_pipeline.cpp asserts, bit for bit on the RTL.
TEST(PhongCosim, HardCasesMatchTheModel) {
  struct Case {
    std::string name;
    BuiltScene scene;
  };
  std::vector<Case> cases = {{"antipodal normals", antipodal_normals_scene()},
                             {"normals in the screen plane", screen_plane_normals_scene()},
                             {"grazing light", grazing_light_scene()}};
  for (int n : {0, 1, 2, 64, 128, 255}) cases.push_back({"n = " + std::to_string(n), shininess_scene(n)});
  std::uint64_t seed = 300;
  for (const Case& c : cases) {
    const PreparedScene p = prepare(c.scene);
    const RtlOptions o{seed++, 0.2, 0.3};
    expect_clean(c.name, o, run_rtl(p, o));
  }
}

// The interior highlight of scenes/highlight.json, both pipelines on the RTL: Phong finds it at
// the centre, Gouraud (the phong vertex rule) cannot.
TEST(PhongCosim, InteriorHighlightPhongFindsItGouraudCannot) {
  const PhongVsGouraud opt = phong_vs_gouraud();
  const PreparedScene pp = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/highlight.json", opt.phong));
  const PreparedScene pg = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/highlight.json", opt.gouraud));
  const RtlOptions o{17, 0.1, 0.1};
  const RtlResult rp = run_rtl(pp, o), rg = run_rtl(pg, o);
  expect_clean("highlight, Phong", o, rp);
  expect_clean("highlight, Gouraud", o, rg);
  auto peak = [](const Image& img, int lo, int hi) {
    int m = 0;
    for (int y = lo; y < hi; ++y)
      for (int x = lo; x < hi; ++x) m = std::max(m, int(img.at(x, y)[0]));
    return m;
  };
  EXPECT_GE(peak(rp.frames.at(0).image, 118, 138), 250);
  EXPECT_LE(peak(rg.frames.at(0).image, 0, 256), 135);
}

// Phong frames back to back with different materials and lights: the bench rewrites the
// material table between frames (after the previous frame's last pixel), the RTL follows.
TEST(PhongCosim, FramesBackToBackWithNewMaterials) {
  const PreparedScene a = prepare(random_phong_scene(77));
  const PreparedScene b = prepare(random_phong_scene(78));
  ASSERT_FALSE(a.materials.size() == b.materials.size() && a.light == b.light);
  const RtlOptions o{23, 0.2, 0.2};
  const RtlResult r = run_rtl_frames({&a, &b, &a, &a}, o);
  expect_clean("Phong frames a b a a", o, r);
  ASSERT_EQ(r.frames.size(), 4u);
  EXPECT_EQ(r.frames[0].image.rgb, r.frames[2].image.rgb);
}

TEST(PhongCosim, OneRunIsGouraudOrPhong) {
  const PreparedScene g = prepare(load_scene_or_default(""));
  const PreparedScene p = as_phong_records(g);
  EXPECT_THROW(run_rtl_frames({&g, &p}), std::invalid_argument);
}

}  // namespace
