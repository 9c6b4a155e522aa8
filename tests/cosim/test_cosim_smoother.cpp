// Herman & Liu's smoother in the top (smooth_w_i != 0) on the RTL against the model: shipped
// scenes in both pipelines, at full speed (cycles = the cycle model's, sparse_i ignored: a
// smoothed frame comes in full), under gaps and stalls and all-stall bursts; 0 mismatching pixels
// and every stage stream the model's. And smoothing switched and W changed frame by frame.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cosim_support.hpp"
#include "cycle_model.hpp"

namespace watkins::tb::test {
namespace {

// W = 0.8 (Herman & Liu's Fig. 4) in the smoother's format: 102/128.
constexpr double PaperW = 0.8;

void check_smoothed(const std::string& name, ShadingMode shading, double w) {
  BuildOptions opt;
  opt.shading = shading;
  opt.smooth = w;
  PreparedScene p;
  try {
    p = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/" + name, opt));
  } catch (const SceneError& e) {
    GTEST_SKIP() << "the scene does not load or fit in this mode: " << e.what();
  }
  if (p.width > rtl_max_width()) GTEST_SKIP() << "wider than the RTL line buffer";
  ASSERT_EQ(p.smooth_w, quantize_smooth_weight(w));
  const Image model = WatkinsTop().render(p);
  PreparedScene plain = p;
  plain.smooth_w = 0;
  EXPECT_NE(model.rgb, WatkinsTop().render(plain).rgb) << name << ": smoothing changed nothing";
  RtlOptions patterns[] = {{1, 0.0, 0.0}, {2, 0.0, 0.0}, {3, 0.25, 0.3}, {4, 0.1, 0.02, 300}};
  patterns[1].sparse = true;  // ignored: the frame is smoothed, so it comes in full
  for (const RtlOptions& o : patterns) {
    const std::string what = name + (shading == ShadingMode::Phong ? " phong" : " gouraud") + " W " +
                             std::to_string(w) + (o.sparse ? " sparse" : "") +
                             (o.gap > 0 ? " with gaps and stalls" : "");
    const RtlResult r = run_rtl(p, o, &model);
    expect_clean(what, o, r);
    if (!r.ok()) return;
    EXPECT_EQ(r.frames.at(0).image.rgb, model.rgb) << what;
    EXPECT_EQ(r.frames.at(0).image.covered, model.covered) << what;
    EXPECT_EQ(r.pixels, static_cast<long long>(p.width) * p.height) << what;
    if (o.gap == 0 && o.stall == 0) {
      const CyclePrediction c = predict_cycles(p, o.sparse ? PixelOutput::Sparse : PixelOutput::FullFrame);
      EXPECT_EQ(r.cycles, c.cycles) << what;
      // The smoother's flush of the last line and its 14 stages, on top of the unsmoothed frame.
      EXPECT_EQ(c.cycles, predict_cycles(plain, PixelOutput::FullFrame).cycles + p.width + 15) << what;
    }
  }
}

TEST(CosimSmoother, SphereGouraud) { check_smoothed("sphere.json", ShadingMode::Gouraud, PaperW); }
TEST(CosimSmoother, SpherePhong) { check_smoothed("sphere.json", ShadingMode::Phong, PaperW); }
TEST(CosimSmoother, ScreenPolygonsGouraud) { check_smoothed("screen_polygons.json", ShadingMode::Gouraud, 1.5); }
TEST(CosimSmoother, OverdrawPhong) { check_smoothed("overdraw.json", ShadingMode::Phong, 0.25); }
// The paper's own case: a voxel phantom with one normal per face, smoothed at W = 0.8 (the scene's
// shading.smooth), and a heavier W on the Phong pipeline.
TEST(CosimSmoother, VoxelPhantomGouraud) { check_smoothed("voxel_smoothed.json", ShadingMode::Gouraud, PaperW); }
TEST(CosimSmoother, VoxelPhantomPhong) { check_smoothed("voxel_smoothed.json", ShadingMode::Phong, 1.0); }

// Smoothing off, on, another W and off again in one simulation, under gaps and stalls, with
// sparse_i requested throughout: the unsmoothed frames stay sparse.
TEST(CosimSmoother, SwitchedBetweenFrames) {
  PreparedScene off = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/sphere.json"));
  ASSERT_LE(off.width, rtl_max_width());
  PreparedScene on = off, heavy = off;
  on.smooth_w = 102;
  heavy.smooth_w = 255;
  const Image m_off = WatkinsTop().render(off), m_on = WatkinsTop().render(on), m_heavy = WatkinsTop().render(heavy);
  RtlOptions o{6, 0.1, 0.2};
  o.sparse = true;
  const RtlResult r = run_rtl_frames({&off, &on, &heavy, &off}, o, {&m_off, &m_on, &m_heavy, &m_off});
  expect_clean("sphere.json, smoothing switched", o, r);
  ASSERT_EQ(r.frames.size(), 4u);
  EXPECT_EQ(r.frames[1].image.rgb, m_on.rgb);
  EXPECT_EQ(r.frames[2].image.rgb, m_heavy.rgb);
  EXPECT_TRUE(r.frames[0].sparse && r.frames[3].sparse);
  EXPECT_FALSE(r.frames[1].sparse || r.frames[2].sparse);
  EXPECT_EQ(r.frames[1].pixels, static_cast<long long>(on.width) * on.height);
}

}  // namespace
}  // namespace watkins::tb::test
