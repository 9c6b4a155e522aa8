// Twin of rtl/phong_shader.sv; see phong_shader.hpp for the stage list.
#include "phong_shader.hpp"

namespace watkins {

i64 PhongShader::power(i64 base, int n) {
  i64 acc = One;
  for (int k = 0; k < NBits; ++k) {  // stage 4 + k
    if ((n >> k) & 1) acc = static_cast<i64>(round_shift(static_cast<i128>(acc) * base, P));
    base = static_cast<i64>(round_shift(static_cast<i128>(base) * base, P));
  }
  return acc;
}

PhongShader::Terms PhongShader::terms(const Pixel& px, const Vec& light, const Vec& eye) {
  Terms t;
  const i64 le = frame_le(light, eye);
  // Stage 1: exact dot products.
  const i64 ndl = dot(px.n, light), nde = dot(px.n, eye);
  // Stage 2: round to D bits and clamp; i > 90 degrees is clamped to cos(i) = 0.
  t.cos_i = round_dot(ndl, false);
  t.ne = round_dot(nde, true);
  t.front = t.cos_i > 0;
  // Stage 3: cos(s) = 2 (N.L)(N.E) - L.E, and the diffuse factor.
  const i128 cs2 = 2 * static_cast<i128>(t.cos_i) * t.ne - (static_cast<i128>(le) << D);  // 2D frac
  t.cs = static_cast<i64>(clamp_i(round_shift(cs2, 2 * D - P), 0, One));
  t.spec = t.front && t.cs > 0;
  const i64 d = px.d > (1 << MF) ? (1 << MF) : px.d;
  t.f = t.cos_i * ((1 << MF) - d) + (static_cast<i64>(d) << D);  // D + MF fraction bits
  // Stages 4..11.
  t.pow = t.spec ? power(t.cs, px.shininess) : 0;
  return t;
}

std::array<int, 3> PhongShader::shade(const Pixel& px, const Vec& light, const Vec& eye) {
  const Terms t = terms(px, light, eye);
  // Stages 12, 13: levels with D + MF fraction bits; specular W pow is white (255 per channel).
  const i128 spec = static_cast<i128>(255 * px.w) * t.pow << (D - P);
  std::array<int, 3> out{};
  for (int c = 0; c < 3; ++c) {
    const i128 level = static_cast<i128>(px.cp[c]) * t.f + spec;
    out[c] = static_cast<int>(clamp_i(round_shift(level, OutFrac), 0, fmt::ShadeMax));
  }
  return out;
}

static_assert(PhongShader::D >= PhongShader::P, "specular term is aligned by a left shift");

}  // namespace watkins
