// Gouraud's eq. (2) in the model: the shade divider's twin on hand-worked values (every number
// below computed on paper from shade_divider.hpp's rules), and whole frames in eq2 mode against
// the double reference and against the eq. (2) formula itself.
#include <gtest/gtest.h>

#include <cmath>

#include "scene_builder.hpp"
#include "shade_divider.hpp"
#include "test_support.hpp"

using namespace watkins;
using namespace watkins::test;

namespace {

constexpr i64 kLevel = i64{1} << fmt::FracBits;  // one level in the default shade word

Config eq2_config() {
  Config c;
  c.eq2 = true;
  return c;
}

ShadeDivider default_divider() { return ShadeDivider(eq2_config().channels(ShadingMode::Gouraud)); }

}  // namespace

// Default formats: depth_bits 24, shade fraction 16, R = 16, so s = p + 8.
TEST(ShadeDivider, HalfDepthDoublesTheNumerator) {
  // Z = 0.5 (d = 2^23), N = 50 levels: p = 23, m = 2^15, recip = 2^31 / 2^15 = 2^16, s = 31,
  // prod = 50·2^16·2^16 = 50·2^32, round_shift(prod, 31) = 100.
  const ShadeDivider::Trace t = default_divider().trace(1u << 23, {50 * kLevel, 0, 25 * kLevel});
  EXPECT_EQ(t.dz, 1 << 23);
  EXPECT_EQ(t.r.p, 23);
  EXPECT_EQ(t.r.recip, 1 << 16);
  EXPECT_EQ(t.s, 31);
  EXPECT_EQ(t.prod[0], static_cast<unsigned __int128>(50) << 32);
  EXPECT_EQ(t.rgb[0], 100);
  EXPECT_EQ(t.rgb[1], 0);
  EXPECT_EQ(t.rgb[2], 50);
}

TEST(ShadeDivider, ThreeEighthsDepth) {
  // Z = 0.375 (d = 3·2^21), N = 30 levels: exact S = 80. p = 22, m = d >> 7 = 49152,
  // recip = floor(2^31 / 49152) = 43690, s = 30, prod = 1966080·43690 = 85898035200;
  // prod >> 29 = 159, (159 + 1) >> 1 = 80.
  const ShadeDivider::Trace t = default_divider().trace(3u << 21, {30 * kLevel, 30 * kLevel, 30 * kLevel});
  EXPECT_EQ(t.r.p, 22);
  EXPECT_EQ(t.r.recip, 43690);
  EXPECT_EQ(t.s, 30);
  EXPECT_EQ(t.prod[0], static_cast<unsigned __int128>(85898035200LL));
  EXPECT_EQ(t.rgb[0], 80);
}

TEST(ShadeDivider, SaturatesAndClamps) {
  const ShadeDivider d = default_divider();
  // Negative numerators read 0; one of 300 levels saturates to 2^24 − 1 and, over the largest
  // depth (Z just below 1), still gives more than 255.
  const ShadeDivider::Trace t = d.trace((1u << 24) - 1, {-5, 300 * kLevel, 255 * kLevel});
  EXPECT_EQ(t.n[0], 0);
  EXPECT_EQ(t.n[1], (i64{1} << 24) - 1);
  EXPECT_EQ(t.rgb[0], 0);
  EXPECT_EQ(t.rgb[1], 255);
  EXPECT_EQ(t.rgb[2], 255);  // 255 / (1 − 2^−24), rounded
  // Depth 0 divides by one unit: p = 0, recip = 2^16, s = 8; n = 1 (2^−16 level) gives
  // round_shift(2^16, 8) = 256, clamped to 255; n = 0 gives 0.
  const ShadeDivider::Trace z = d.trace(0, {1, 0, 2});
  EXPECT_EQ(z.dz, 1);
  EXPECT_EQ(z.s, 8);
  EXPECT_EQ(z.rgb[0], 255);
  EXPECT_EQ(z.rgb[1], 0);
}

TEST(ShadeDivider, ShiftNotPositiveSaturates) {
  // Shade fraction 0, depth_bits 24, R = 9: s = p − 15. d = 2^10: p = 10, s = −5: any numerator
  // but 0 is above 255 (n·recip·2^5 >= 2^8·2^5).
  Config c = eq2_config();
  c.shade.frac_bits = 0;
  c.eq2_recip_bits = 9;
  const ShadeDivider::Trace t = ShadeDivider(c.channels(ShadingMode::Gouraud)).trace(1u << 10, {1, 0, 7});
  EXPECT_EQ(t.s, -5);
  EXPECT_EQ(t.rgb[0], 255);
  EXPECT_EQ(t.rgb[1], 0);
  EXPECT_EQ(t.rgb[2], 255);
}

TEST(ShadeDivider, WithinTheReciprocalsErrorOfTheQuotient) {
  // Every depth of a sweep and a spread of numerators: |S − N/Z| ≤ 1/2 + 255·2^−(R−1) (+ the
  // saturation at 255).
  const ShadeDivider d = default_divider();
  const double slack = 0.5 + 255.0 * std::ldexp(1.0, -(fmt::Eq2RecipBits - 1)) + 1e-9;
  for (std::uint32_t depth = 1000; depth < (1u << 24); depth = depth * 5 / 4 + 7)
    for (i64 n = 0; n < 256 * kLevel; n = n * 3 / 2 + 12345) {
      const double want = std::min(255.0, double(n) / kLevel / (double(depth) / (1 << 24)));
      const int got = d.shade(depth, {n, 0, 0})[0];
      ASSERT_LE(std::fabs(got - want), slack) << "depth " << depth << " n " << n;
    }
}

// A quad whose depth runs from 0.1 on the left to 0.4 on the right and whose shade runs from 200
// to 40: eq. (2)'s S = N/Z with N and Z linear in x. The model's frame equals the formula within
// the divider's rounding and the formats' quantization (one level), and the double reference.
TEST(ShadeDivider, FrameFollowsEquationTwo) {
  BuiltScene s = screen(64, 8, {poly({vtx(0, 0, 0.1, 200, 200, 200), vtx(64, 0, 0.4, 40, 40, 40),
                                      vtx(64, 8, 0.4, 40, 40, 40), vtx(0, 8, 0.1, 200, 200, 200)})});
  s.interpolation = Interpolation::Eq2;
  const PreparedScene p = prepare(s, eq2_config());
  EXPECT_TRUE(p.eq2);
  const Image img = WatkinsTop(p.config).render(p);
  int max_diff = 0, differs_from_eq1 = 0;
  for (int x = 0; x < 64; ++x) {
    const double a = (x + 0.5) / 64;
    const double z = 0.1 + a * 0.3;
    const double n = (1 - a) * 200 * 0.1 + a * 40 * 0.4;
    const double eq1 = (1 - a) * 200 + a * 40;
    for (int y = 0; y < 8; ++y) {
      const int got = img.at(x, y)[0];
      max_diff = std::max(max_diff, static_cast<int>(std::lround(std::fabs(got - n / z))));
      EXPECT_LE(std::fabs(got - n / z), 1.0) << x << "," << y;
    }
    differs_from_eq1 += std::fabs(img.at(x, 0)[0] - eq1) > 2;
  }
  EXPECT_LE(max_diff, 1);
  EXPECT_GT(differs_from_eq1, 32);  // hyperbolic, not linear: most of the span differs from eq. (1)
  const ImageError e = compare_images(img, render_float_reference(s));
  EXPECT_LE(e.max_abs, 1);
  EXPECT_EQ(e.coverage_differs, 0);
}

TEST(ShadeDivider, RefusedWithoutTheDivider) {
  BuiltScene s = screen(8, 8, {poly({vtx(0, 0, 0.2, 10), vtx(8, 0, 0.2, 10), vtx(8, 8, 0.2, 10)})});
  s.interpolation = Interpolation::Eq2;
  EXPECT_NE(error_of([&] { (void)prepare(s, Config{}); }).find("configuration has eq2 false"), std::string::npos);
  EXPECT_TRUE(with_scene_edge_order(s, Config{}).eq2);
}

TEST(ShadeDivider, ConfigurationListsTheDividerOnlyWhenPresent) {
  const std::vector<RtlParameter> plain = rtl_parameters(Config{}, ShadingMode::Gouraud);
  std::vector<RtlParameter> with = rtl_parameters(eq2_config(), ShadingMode::Gouraud);
  ASSERT_EQ(with.size(), plain.size() + 2);
  EXPECT_EQ(with[plain.size()], (RtlParameter{"HasEq2", 1}));
  EXPECT_EQ(with[plain.size() + 1], (RtlParameter{"Eq2RecipBits", fmt::Eq2RecipBits}));
  EXPECT_EQ(rtl_parameters(eq2_config(), ShadingMode::Phong), rtl_parameters(Config{}, ShadingMode::Phong));
  Config bad = eq2_config();
  bad.eq2_recip_bits = 8;
  EXPECT_NE(bad.check().find("eq2_recip_bits"), std::string::npos);
}

// The scene file's "interpolation": its values, and the combinations eq. (2) refuses, each one line
// naming the field.
TEST(ShadeDivider, SceneInterpolationField) {
  auto scene = [](const std::string& shading) {
    return "{\"screen\": {\"width\": 32, \"height\": 32}, \"shading\": " + shading +
           ", \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 5], \"radius\": 1}]}";
  };
  const BuiltScene eq2 = load_scene_text(scene("{\"interpolation\": \"eq2\"}"), "s.json", ".");
  EXPECT_EQ(eq2.interpolation, Interpolation::Eq2);
  EXPECT_EQ(eq2.depth, DepthMode::Z);
  // Depth Z/far: the camera's far plane is 1000, the sphere's front at Z = 4.
  double lo = 1;
  for (const ScreenPolygon& p : eq2.polygons)
    for (const ScreenVertex& v : p.v) lo = std::min(lo, v.depth);
  EXPECT_NEAR(lo, 4.0 / 1000, 1e-4);
  EXPECT_EQ(load_scene_text(scene("{}"), "s.json", ".").interpolation, Interpolation::Eq1);
  EXPECT_NE(error_of([&] { (void)load_scene_text(scene("{\"interpolation\": \"eq3\"}"), "s.json", "."); })
                .find("shading.interpolation: expected \"eq1\" or \"eq2\""),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              (void)load_scene_text(scene("{\"interpolation\": \"eq2\", \"depth\": \"inverse-z\"}"), "s.json", ".");
            }).find("shading.depth: \"inverse-z\" contradicts"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              (void)load_scene_text(scene("{\"interpolation\": \"eq2\", \"mode\": \"phong\"}"), "s.json", ".");
            }).find("eq2 is a mode of the gouraud pipeline"),
            std::string::npos);
  BuildOptions opt;
  opt.interpolation = Interpolation::Eq2;
  opt.depth = DepthMode::InverseZ;
  EXPECT_NE(error_of([&] { (void)load_scene_text(scene("{}"), "s.json", ".", opt); }).find("--depth inverse-z"),
            std::string::npos);
}
