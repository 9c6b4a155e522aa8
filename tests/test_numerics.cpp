// Numerical behaviour: stepping drift over the longest edge, eq. (1) against eq. (2).
#include <gtest/gtest.h>

#include <cmath>

#include "active_edge_list.hpp"
#include "test_support.hpp"

using namespace watkins;
using namespace watkins::test;

namespace {

// An edge over all 4096 scan lines: after 4095 increments, X and every shade are within one LSB
// of their output formats (1/16 pixel, one 8-bit level) of the exact values, and within the
// rounded-slope drift bound n·2^-(F+1) of NUMERICS.md.
TEST(Numerics, LongestEdgeDriftStaysWithinOneLsb) {
  const ScreenVertex top = vtx(0.5, 0.0, 0.0, 0, 255, 17);
  const ScreenVertex bot = vtx(3000.3, 4096.0, 0.999, 255, 0, 200);
  const QuantizedVertex a = quantize_vertex(top), b = quantize_vertex(bot);
  EdgeRecord e;
  ASSERT_TRUE(make_edge_record(a, b, 0, 4096, e));
  ASSERT_EQ(e.y0, 0);
  ASSERT_EQ(e.n, 4096);
  ActiveEdge ae{e, e.n};
  for (int k = 0; k < e.n - 1; ++k) EdgeIncrementer::step(ae);
  const double yc = 4095.5;  // centre of the last scan line
  const double t = (yc * 16 - a.y16) / double(b.y16 - a.y16);
  const double drift_bound = 4095.0 / 2 + 1;  // channel units
  for (int c = 0; c < fmt::NumChannels; ++c) {
    const double exact = a.ch[c] + t * (b.ch[c] - a.ch[c]);
    const double err = std::abs(double(ae.rec.value[c]) - exact);
    EXPECT_LE(err, drift_bound) << "channel " << c;
    const double lsb = c == fmt::ChanX ? double(1 << fmt::SubPixelToFrac) : double(1 << fmt::FracBits);
    EXPECT_LE(err, lsb) << "channel " << c;
  }
}

// A plane strongly inclined in depth, projected by hand: eq. (1) (depth = 1 − near/Z, affine in
// 1/Z, so linear in screen space) matches the exact per-pixel depth to a few LSBs; eq. (2)
// (depth linear in Z) does not. Corners project exactly onto the 1/16-pixel grid and have
// dyadic depths, so the only errors left are the pipeline's own.
struct InclinedPlane {
  static constexpr int W = 128, H = 128;
  static constexpr double f = 64, near = 1.0, far = 16.0;
  static ScreenVertex project(double X, double Y, double Z, bool eq1) {
    ScreenVertex v = vtx(W / 2 + f * X / Z, H / 2 - f * Y / Z, eq1 ? 1 - near / Z : (Z - near) / (far - near), 128, 128, 128);
    v.eye_z = Z;
    return v;
  }
  // The quad lies in the plane Z = 5 + 3Y (Y in [-1, 1]); along the ray through screen point
  // (xs, ys), Y = dy·Z with dy = (H/2 − ys)/f, so Z = 5 / (1 − 3 dy).
  static double exact_z(double, double ys) { return 5.0 / (1.0 - 3.0 * (H / 2 - ys) / f); }
  static BuiltScene scene(bool eq1) {
    return screen(W, H, {poly({project(-1, -1, 2, eq1), project(1, -1, 2, eq1), project(1, 1, 8, eq1),
                               project(-1, 1, 8, eq1)})});
  }
};

double max_depth_error(bool eq1) {
  const BuiltScene s = InclinedPlane::scene(eq1);
  const PreparedScene p = prepare(s);
  WatkinsTop pipe;
  double worst = 0;
  pipe.render(p, [&](int y, const Fragment& f, bool) {
    const double z = InclinedPlane::exact_z(f.x + 0.5, y + 0.5);
    const double exact = eq1 ? 1 - InclinedPlane::near / z
                             : (z - InclinedPlane::near) / (InclinedPlane::far - InclinedPlane::near);
    worst = std::max(worst, std::abs(f.depth - exact * (1 << fmt::DepthBits)));
  });
  return worst;
}

TEST(Numerics, InverseZIsExactForDepthAndZIsNot) {
  const double e1 = max_depth_error(true), e2 = max_depth_error(false);
  RecordProperty("eq1_max_depth_error_lsb", std::to_string(e1));
  RecordProperty("eq2_max_depth_error_lsb", std::to_string(e2));
  EXPECT_LE(e1, 8.0);          // a few LSBs of 2^-24: quantization only
  EXPECT_GT(e2, 1000.0 * e1);  // interpolating Z linearly in screen space is wrong by far more
}

}  // namespace
