// Twin of rtl/phong_shader.sv; see phong_shader.hpp for the stage list.
#include "phong_shader.hpp"

namespace watkins {

namespace {

// terms(), in this file so that shade(Pixel, ...) inlines it (the per-pixel path of a frame is
// shade(n, MaterialTerms, ...) in phong_shader.hpp).
inline PhongShader::Terms terms_of(const PhongShader::Pixel& px, const PhongShader::Vec& light,
                                   const PhongShader::Vec& eye, i64 le) {
  using PS = PhongShader;
  constexpr int D = PS::D, P = PS::P, MF = PS::MF;
  constexpr i64 One = PS::One;
  PS::Terms t;
  // Stage 1: exact dot products.
  const i64 ndl = PS::dot(px.n, light), nde = PS::dot(px.n, eye);
  // Stage 2: round to D bits and clamp; i > 90 degrees is clamped to cos(i) = 0.
  t.cos_i = PS::round_dot(ndl, false);
  t.ne = PS::round_dot(nde, true);
  t.front = t.cos_i > 0;
  // Stage 3: cos(s) = 2 (N.L)(N.E) - L.E, and the diffuse factor.
  const i64 cs2 = 2 * t.cos_i * t.ne - le * (i64{1} << D);  // 2D frac
  t.cs = std::clamp<i64>(round_shift64(cs2, 2 * D - P), 0, One);
  t.spec = t.front && t.cs > 0;
  const i64 d = px.d > (1 << MF) ? (1 << MF) : px.d;
  t.f = t.cos_i * ((1 << MF) - d) + (static_cast<i64>(d) << D);  // D + MF fraction bits
  // Stages 4..11.
  t.pow = t.spec ? PS::power(t.cs, px.shininess) : 0;
  return t;
}

}  // namespace

PhongShader::Terms PhongShader::terms(const Pixel& px, const Vec& light, const Vec& eye, i64 le) {
  return terms_of(px, light, eye, le);
}

std::array<int, 3> PhongShader::shade(const Pixel& px, const Vec& light, const Vec& eye, i64 le) {
  const Terms t = terms_of(px, light, eye, le);
  // Stages 12, 13: levels with D + MF fraction bits; specular W pow is white (255 per channel).
  const i64 spec = 255 * px.w * t.pow * (i64{1} << (D - P));
  std::array<int, 3> out{};
  for (int c = 0; c < 3; ++c) {
    const i64 level = px.cp[c] * t.f + spec;
    out[c] = static_cast<int>(std::clamp<i64>(round_shift64(level, OutFrac), 0, fmt::ShadeMax));
  }
  return out;
}

static_assert(PhongShader::D >= PhongShader::P, "specular term is aligned by a left shift");
// Every product above fits 64 bits (with its rounding constant), as the RTL's widths do: powers
// multiply two numbers <= 1.0 with P fraction bits; cos(i) and N.E are below 2^(D+1), L.E too;
// a level is an 8-bit reflectance times f < 2^(D+MF+1) plus the specular term.
static_assert(2 * (PhongShader::P + 1) <= 62, "power products fit 64 bits");
static_assert(2 * (PhongShader::D + 1) + 2 <= 62, "cos(s) products fit 64 bits");
static_assert(8 + PhongShader::D + PhongShader::MF + 3 <= 62, "levels fit 64 bits");

}  // namespace watkins
