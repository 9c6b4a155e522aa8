// Twin of rtl/phong_shader.sv: Phong's shading rule (Phong 1975 eq. 3)
//   S = Cp [cos(i) (1 - d) + d] + W cos(s)^n
// per pixel from a unit normal N (Q2.14, the normalizer's output), with the light L and the eye
// E at infinity (unit, Q2.14, constants of the frame). cos(i) = N.L. cos(s) = R.E with Phong's
// reflected vector R = 2 (N.L) N - L (eqs. 4-8: in the light's frame Zr = 2 Zn^2 - 1,
// Xr = 2 Zn Xn, Yr = 2 Zn Yn), so
//   cos(s) = R.E = 2 (N.L)(N.E) - L.E,
// the same number for any N (expand R.E), computed with two dot products and one multiply per
// pixel; L.E is computed once per frame by frame_le().
//
// Stages (all in integers; rounding is round_shift, ties toward +inf):
//   1  ndl = N.L, nde = N.E exact (2*UnitFracBits = 28 fraction bits)
//   2  cos_i = max(round(ndl, D bits), 0); ne = round(nde, D bits) (both kept below 2.0);
//      front = cos_i > 0 (Phong p. 313: "only incident angles <= 90 degrees are considered")
//   3  cs = clamp(round(2 cos_i ne - le, P bits), 0, 1); spec = front && cs > 0;
//      f = cos_i (1 - d) + d, exact (D + 8 fraction bits)
//   4..11  cs^n by square-and-multiply over the 8 bits of n, LSB first: acc *= base if bit k,
//      base *= base, each product rounded to P bits (monotone, >= 0; tiny powers flush to 0)
//   12, 13  level = saturate(round(Cp f + 255 W pow), 0..255) per channel (specular is white)
// cos(i) <= 0 (light behind the surface, and the null normal (0,0,0)): diffuse = Cp d,
// specular 0. cos(s) <= 0: specular 0 (also for n = 0, where cos(s)^0 would be 1).
// d is clamped to 1.0 (256); W may exceed 1.0 (up to 511/256), the output saturates.
// cos(i) is not clamped at 1.0 (see round_dot); f = cos(i)(1-d) + d may then exceed 1 by a few
// 2^-14, and the level saturates at 255.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "fixed_point.hpp"
#include "formats.hpp"

namespace watkins {

struct PhongShader {
  static constexpr int UF = fmt::UnitFracBits;       // 14
  static constexpr int D = fmt::PhongDotBits;        // 24: cos(i), N.E, L.E
  static constexpr int P = fmt::PhongPowBits;        // 20: cos(s), cos(s)^n
  static constexpr int MF = fmt::MaterialFracBits;   // 8: d, W
  static constexpr int NBits = fmt::ShininessBits;   // 8: n in 0..255
  static constexpr i64 One = i64{1} << P;            // 1.0 in the power stages
  static constexpr int OutFrac = D + MF;             // fraction bits of the summed level

  using Vec = std::array<i64, 3>;  // Q2.14, UnitBits signed

  struct Pixel {
    Vec n{};                        // unit normal (normalizer output)
    std::array<int, 3> cp{};        // Cp: R, G, B reflectance, 8-bit levels (255 = 1.0)
    int d = 0;                      // environmental diffuse coefficient, MaterialBits, 1.0 = 256
    int w = 0;                      // specular coefficient W, MaterialBits, 1.0 = 256
    int shininess = 1;              // n, 0..255
  };

  struct Terms {  // intermediate values, for tests and the docs
    i64 cos_i = 0, ne = 0, cs = 0, f = 0, pow = 0;
    bool front = false, spec = false;
  };

  static i64 dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  // round(v, D fraction bits) clamped to the (D+2)-bit register: [0 or -2, 2 - 2^-D]. No clamp
  // at 1.0: a normal a rounding step longer than 1 gives N.L slightly above 1, which keeps
  // cos(s) = R.E exact (a clamp there would move highlights of large n); the output saturates.
  static i64 round_dot(i64 v, bool neg_ok) {
    const i64 hi = (i64{1} << (D + 1)) - 1;
    // |v| <= 3 * 2^(2 UF): 64 bits hold it and its rounding constant.
    return std::clamp<i64>(round_shift64(v, 2 * UF - D), neg_ok ? -hi - 1 : 0, hi);
  }
  // L.E once per frame: D fraction bits.
  static i64 frame_le(const Vec& light, const Vec& eye) {
    return round_dot(dot(light, eye), true);
  }
  // base^n, P fraction bits, base in [0, 1]; n's low NBits bits (the RTL's register).
  static i64 power(i64 base, int n);
  // The pixel's terms and levels; `le` = frame_le(light, eye), which a frame works out once.
  static Terms terms(const Pixel& px, const Vec& light, const Vec& eye, i64 le);
  static std::array<int, 3> shade(const Pixel& px, const Vec& light, const Vec& eye, i64 le);
  // The per-pixel path of a frame (WatkinsTop): what depends on the material alone is worked out
  // once per frame (material_terms), the pixel's values with no sign branch (round_shift62).
  // Same bits as shade(Pixel, ...) for every input (the arithmetic is the same, regrouped;
  // tests/test_phong_fast_path.cpp compares the two).
  struct MaterialTerms {
    std::array<i64, 3> cp{};  // Cp, 8-bit levels
    i64 one_minus_d = 0;      // 1 - d, MF fraction bits (d clamped to 1.0)
    i64 d_term = 0;           // d, D + MF fraction bits: f = cos(i) (1 - d) + d
    i64 spec_scale = 0;       // 255 W 2^(D-P): the specular level is spec_scale * cos(s)^n
    int shininess = 0;        // n
    i64 (*power)(i64) = nullptr;  // cs -> cs^n, PhongShader::power for this n (PowerTable)
  };
  static MaterialTerms material_terms(const std::array<int, 3>& cp, int d, int w, int shininess);
  static std::array<int, 3> shade(const Vec& n, const MaterialTerms& m, const Vec& light, const Vec& eye, i64 le);

  static Terms terms(const Pixel& px, const Vec& light, const Vec& eye) {
    return terms(px, light, eye, frame_le(light, eye));
  }
  static std::array<int, 3> shade(const Pixel& px, const Vec& light, const Vec& eye) {
    return shade(px, light, eye, frame_le(light, eye));
  }
};

// Inline (the per-pixel path). Stage for stage as terms_of() and shade() in phong_shader.cpp, with
// two exact rewrites of "round, then clamp": every word rounded is below 2^61 in magnitude (the
// static_asserts in phong_shader.cpp bound them), where round_shift62 equals round_shift64; and
// clamp(round(v), 0, hi) = min(nonneg_round(max(v, 0)), hi), as round(v) <= 0 for every v <= 0 and
// round(0) = 0, so a word clamped below at 0 is rounded as a non-negative number (add, shift).
inline std::array<int, 3> PhongShader::shade(const Vec& n, const MaterialTerms& m, const Vec& light, const Vec& eye,
                                             i64 le) {
  constexpr i64 hi = (i64{1} << (D + 1)) - 1;
  constexpr int SDot = 2 * UF - D, SCs = 2 * D - P;
  const auto nonneg_round = [](i64 v, int s) { return (v + (i64{1} << (s - 1))) >> s; };  // v >= 0
  const i64 cos_i = std::min(nonneg_round(std::max<i64>(dot(n, light), 0), SDot), hi);  // stage 2
  const i64 ne = std::clamp<i64>(round_shift62(dot(n, eye), SDot), -hi - 1, hi);
  const i64 cs = std::min(nonneg_round(std::max<i64>(2 * cos_i * ne - le * (i64{1} << D), 0), SCs), One);  // 3
  const i64 f = cos_i * m.one_minus_d + m.d_term;
  const i64 spec = cos_i > 0 && cs > 0 ? m.spec_scale * m.power(cs) : 0;  // 4..11, 12
  std::array<int, 3> out{};
  for (int c = 0; c < 3; ++c)  // 12, 13
    out[c] = static_cast<int>(std::min<i64>(nonneg_round(std::max<i64>(m.cp[c] * f + spec, 0), OutFrac), fmt::ShadeMax));
  return out;
}

// power() for n's NBits bits, inline: with `bits` a constant (power_of<n>) the loops unroll.
[[gnu::always_inline]] inline i64 power_bits(i64 base, unsigned bits) {
  // The stage list's products, less two that cannot change a bit: acc's first product is
  // One * base, which rounds to base exactly ((2^P base + 2^(P-1)) >> P = base), and the square
  // after n's top bit, which no later stage uses. Stages past n's top bit pass acc unchanged, and
  // once base is 0 every later product is 0 (acc has a factor left to take).
  constexpr int P = PhongShader::P;
  constexpr i64 half = i64{1} << (P - 1);
  if (bits == 0) return PhongShader::One;
  for (; !(bits & 1); bits >>= 1) base = (base * base + half) >> P;
  i64 acc = base;
  while ((bits >>= 1) != 0) {
    base = (base * base + half) >> P;
    if (base == 0) return 0;
    if (bits & 1) acc = (acc * base + half) >> P;
  }
  return acc;
}

inline i64 PhongShader::power(i64 base, int n) {
  return power_bits(base, static_cast<unsigned>(n) & ((1u << NBits) - 1));  // the RTL's NBits register
}

// power() for one n, unrolled; PowerTable[n] (material_terms() picks a material's once per frame).
template <unsigned N>
i64 power_of(i64 base) {
  return power_bits(base, N);
}
template <std::size_t... N>
constexpr std::array<i64 (*)(i64), sizeof...(N)> power_table(std::index_sequence<N...>) {
  return {&power_of<static_cast<unsigned>(N)>...};
}
inline constexpr std::array<i64 (*)(i64), (1 << PhongShader::NBits)> PowerTable =
    power_table(std::make_index_sequence<(1 << PhongShader::NBits)>{});

inline PhongShader::MaterialTerms PhongShader::material_terms(const std::array<int, 3>& cp, int d, int w,
                                                              int shininess) {
  MaterialTerms m;
  for (int c = 0; c < 3; ++c) m.cp[c] = cp[c];
  const i64 dc = d > (1 << MF) ? (1 << MF) : d;
  m.one_minus_d = (1 << MF) - dc;
  m.d_term = dc * (i64{1} << D);
  m.spec_scale = 255 * static_cast<i64>(w) * (i64{1} << (D - P));
  m.shininess = shininess;
  m.power = PowerTable[static_cast<std::size_t>(static_cast<unsigned>(shininess) & ((1u << NBits) - 1))];
  return m;
}

}  // namespace watkins
