// The analytic truth (model/reference/analytic_truth.hpp): exact surfaces ray-cast per pixel with Phong's
// eq. (3). Checks the truth itself on a sphere worked by hand, then what it is for: the double
// reference against the truth measures the algorithm (Gouraud vs Phong, tessellation).
// Bounds were measured first (figures in the comments) and are asserted with a margin.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "analytic_truth.hpp"
#include "build_options.hpp"
#include "float_reference.hpp"
#include "test_support.hpp"

using namespace watkins;

namespace {

// A unit sphere at Z = 5 in front of Gouraud's camera (focal 1, 200x200), eye light, one material.
std::string sphere_scene(int u, int v, const std::string& mode, const std::string& rule) {
  return R"({"screen": {"width": 200, "height": 200}, "camera": {"type": "gouraud", "focal": 1},
    "light": {"type": "eye"}, "shading": {"mode": ")" + mode + R"(", "rule": ")" + rule + R"("},
    "materials": {"m": {"color": [0.5, 0.5, 0.5], "d": 0.25, "W": 0.5, "n": 20}},
    "objects": [{"type": "sphere", "center": [0, 0, 5], "radius": 1, "u": )" + std::to_string(u) +
         R"(, "v": )" + std::to_string(v) + R"(, "material": "m"}]})";
}

ImageError algorithm_error(const BuiltScene& s) {
  const AnalyticTruth t = render_analytic_truth(s);
  EXPECT_TRUE(t.unavailable.empty()) << t.unavailable;
  return compare_with_truth(s, render_float_reference(s), t);
}

}  // namespace

// Worked by hand: the sphere's outline is the cone of rays tangent to it, half-angle asin(1/5),
// so its image is a disc of radius f (W/2) tan(asin(0.2)) = 100 * 0.2041 = 20.41 pixels about the
// centre. Inside, pixel (x, y) is shaded by eq. (3) with the sphere's normal where the ray through
// its centre meets the sphere; with L = E = -Z, cos i = c = N.(-Z) and cos s = 2c^2 - 1:
// level = 255 (0.5 (0.75 c + 0.25) + 0.5 (2 c^2 - 1)^20).
TEST(AnalyticTruth, SphereOutlineAndShadeByHand) {
  const BuiltScene s = load_scene_text(sphere_scene(24, 12, "phong", "phong"), "sphere", ".");
  const AnalyticTruth t = render_analytic_truth(s);
  ASSERT_TRUE(t.unavailable.empty()) << t.unavailable;
  EXPECT_EQ(t.surfaces, 1);
  int covered = 0, wrong = 0;
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x) {
      const double r = std::hypot(x + 0.5 - 100, y + 0.5 - 100);
      const bool in = t.image.is_covered(x, y);
      covered += in;
      if (std::fabs(r - 20.41) > 0.01) wrong += in != (r < 20.41);  // away from the outline itself
      if (in) EXPECT_EQ(t.image.owner[std::size_t(y) * 200 + x], 0);
    }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(covered, 1300);  // pi * 20.41^2 = 1309
  EXPECT_LT(covered, 1320);
  auto by_hand = [](int x, int y) {
    const glm::dvec3 d((x + 0.5 - 100) / 100, (100 - (y + 0.5)) / 100, 1), centre(0, 0, 5);
    const double a = glm::dot(d, d), b = glm::dot(d, centre);
    const double tt = (b - std::sqrt(b * b - a * 24)) / a;  // |t d - C|^2 = 1, nearer root
    const double c = -glm::normalize(tt * d - centre).z;
    return 255 * (0.5 * (0.75 * c + 0.25) + 0.5 * std::pow(2 * c * c - 1, 20));
  };
  for (const auto& [x, y] : {std::pair{100, 100}, std::pair{99, 99}, std::pair{110, 100}, std::pair{95, 112},
                             std::pair{100, 118}, std::pair{84, 100}})
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(t.image.at(x, y)[c], by_hand(x, y), 0.51) << x << "," << y;
}

TEST(AnalyticTruth, OnlyForPhongsIllumination) {
  const BuiltScene s = load_scene_text(sphere_scene(24, 12, "gouraud", "lambert"), "sphere", ".");
  const AnalyticTruth t = render_analytic_truth(s);
  EXPECT_NE(t.unavailable.find("eq. (3)"), std::string::npos) << t.unavailable;
  EXPECT_EQ(t.image.width, 0);
  const BuiltScene hand = test::screen(8, 8, {});
  EXPECT_FALSE(render_analytic_truth(hand).unavailable.empty());
}

// What the algorithm costs, and how tessellation buys it back: Gouraud's per-vertex shade and
// Phong's per-pixel normal on the same sphere against the exact one (double references, so no
// quantization). Measured (max, mean |d| over the ~1290 pixels both cover):
//   12 x 6:  Gouraud 47, 12.58   Phong 45, 4.68
//   24 x 12: Gouraud 24,  2.35   Phong 14, 1.29
//   48 x 24: Gouraud 20,  1.11   Phong  3, 0.31
TEST(AnalyticTruth, PhongCostsLessThanGouraudAndBothFallWithTessellation) {
  struct Bound {
    int u;
    int g_max;
    double g_mean;
    int p_max;
    double p_mean;
  };
  double last_g = 1e9, last_p = 1e9;
  for (const Bound b : {Bound{12, 49, 12.7, 47, 4.8}, Bound{24, 26, 2.45, 16, 1.35}, Bound{48, 22, 1.2, 4, 0.35}}) {
    const ImageError g = algorithm_error(load_scene_text(sphere_scene(b.u, b.u / 2, "gouraud", "phong"), "s", "."));
    const ImageError p = algorithm_error(load_scene_text(sphere_scene(b.u, b.u / 2, "phong", "phong"), "s", "."));
    EXPECT_GT(g.compared, 1200) << b.u;
    EXPECT_EQ(g.compared, p.compared) << b.u;  // same geometry: only the shading differs
    EXPECT_LE(g.max_abs, b.g_max) << b.u;
    EXPECT_LT(g.mean_abs, b.g_mean) << b.u;
    EXPECT_LE(p.max_abs, b.p_max) << b.u;
    EXPECT_LT(p.mean_abs, b.p_mean) << b.u;
    EXPECT_LT(p.mean_abs, 0.6 * g.mean_abs) << b.u;
    EXPECT_LT(g.mean_abs, last_g) << b.u;
    EXPECT_LT(p.mean_abs, last_p) << b.u;
    last_g = g.mean_abs, last_p = p.mean_abs;
  }
}

// A flat patch (control points on the plane Z = 4, a 2 x 2 square) is its own truth: every pixel
// inside its image, the square |x - 100|, |y - 100| < 100 * 1/4 = 25 pixels, has N = -Z, so with
// L = E = -Z the level is 255 (0.5 (0.75 + 0.25) + 0.5) = 255 and outside nothing is covered.
TEST(AnalyticTruth, FlatBezierPatchByHand) {
  std::string cps;
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col)
      cps += std::string(cps.empty() ? "" : ", ") + "[" + std::to_string(-1 + col * 2.0 / 3) + ", " +
             std::to_string(1 - row * 2.0 / 3) + ", 4]";
  const std::string text = R"({"screen": {"width": 200, "height": 200}, "camera": {"type": "gouraud", "focal": 1},
    "light": {"type": "eye"}, "shading": {"mode": "phong", "cull_backfaces": false},
    "materials": {"m": {"color": [0.5, 0.5, 0.5], "d": 0.25, "W": 0.5, "n": 20}},
    "objects": [{"type": "bezier_patch", "u": 4, "v": 4, "material": "m", "control_points": [)" + cps + "]}]}";
  const BuiltScene s = load_scene_text(text, "flat", ".");
  const AnalyticTruth t = render_analytic_truth(s);
  ASSERT_TRUE(t.unavailable.empty()) << t.unavailable;
  int covered = 0, wrong = 0;
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x) {
      const double dx = std::fabs(x + 0.5 - 100), dy = std::fabs(y + 0.5 - 100);
      const bool in = t.image.is_covered(x, y);
      covered += in;
      if (std::fabs(dx - 25) > 0.01 && std::fabs(dy - 25) > 0.01) wrong += in != (dx < 25 && dy < 25);
      if (in) EXPECT_EQ(t.image.at(x, y)[0], 255) << x << "," << y;
    }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(covered, 50 * 50);
}

// The shipped patch (16 x 16 grid elements) with Phong's illumination against the exact patch
// (Newton on P(s, t) per pixel). Measured over 14960 pixels: Gouraud max 93, mean 1.034; Phong
// max 11, mean 0.304.
TEST(AnalyticTruth, ShippedPatch) {
  const test::PhongVsGouraud opt = test::phong_vs_gouraud();
  const ImageError p = algorithm_error(load_scene(WATKINS_SOURCE_DIR "/scenes/patch.json", opt.phong));
  const ImageError g = algorithm_error(load_scene(WATKINS_SOURCE_DIR "/scenes/patch.json", opt.gouraud));
  EXPECT_GT(p.compared, 14000);
  EXPECT_EQ(p.compared, g.compared);
  EXPECT_LE(g.max_abs, 96);
  EXPECT_LT(g.mean_abs, 1.1);
  EXPECT_LE(p.max_abs, 12);
  EXPECT_LT(p.mean_abs, 0.33);
}
