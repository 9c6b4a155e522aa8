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
#include "phong_format.hpp"
#include "rsqrt_unit.hpp"

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

  // The narrow set (PhongFormat::Narrow; docs/reference/compact-phong.md, "Narrow formats"):
  //   1  ndl = N.L, nde = N.E exact (28 fraction bits; six 16 x 16 products)
  //   2  cos_i = clamp(round(ndl, 15 bits), 0, 2^16 - 1); ne = clamp(round(nde, 14 bits), -2^15,
  //      2^15 - 1): the model set's clamps to [0, 2) and (-2, 2), each one 16-bit operand
  //   3  cs = clamp(round(cos_i ne - le 2^12, 12 bits), 0, 2^16): 2 cos(i)(N.E) - L.E at 16 bits
  //      (one product; cos_i ne has 29 fraction bits, so it is 2 cos(i)(N.E) at 28);
  //      f = cos_i (256 - d) + d 2^15 exact (23 fraction bits; one product), fr = round(f, 15 bits)
  //   4  pow = power_narrow(cs, n) when front (cos_i > 0) and cs > 0, else 0 (three products)
  //   5  level = clamp(round(Cp fr 2^9 + 255 W pow, 24 bits), 0, 255) (four products: Cp_c fr, W pow)
  // le = narrow_le(light, eye) = clamp(round(L.E, 16 bits), -2^17, 2^17 - 1), once per frame.
  static i64 narrow_round(i64 v, int bits, i64 lo, i64 hi) {
    return std::clamp<i64>(round_shift64(v, 2 * UF - bits), lo, hi);
  }
  static i64 narrow_le(const Vec& light, const Vec& eye) {
    constexpr i64 hi = (i64{1} << (narrow::LeBits + 1)) - 1;
    return narrow_round(dot(light, eye), narrow::LeBits, -hi - 1, hi);
  }
  static i64 frame_le(const Vec& light, const Vec& eye, PhongFormat format) {
    return format == PhongFormat::Narrow ? narrow_le(light, eye) : frame_le(light, eye);
  }
  // cos(s)^n, PowBits fraction bits (0..2^16 - 1), for cs in [0, 2^16] (CosBits fraction bits):
  // -log2 cos(s) from the log table, times n, 2^-(that) from the exp table; 0 for cs = 0.
  static i64 power_narrow(i64 cs, int n);
  static Terms terms_narrow(const Pixel& px, const Vec& light, const Vec& eye, i64 le);
  static std::array<int, 3> shade_narrow(const Pixel& px, const Vec& light, const Vec& eye, i64 le);
  static std::array<int, 3> shade(const Pixel& px, const Vec& light, const Vec& eye, i64 le, PhongFormat format) {
    return format == PhongFormat::Narrow ? shade_narrow(px, light, eye, le) : shade(px, light, eye, le);
  }
};

// The narrow set's power tables, 256 rows of 16 bits each (one block RAM each), filled by integer
// algorithms at G = 30 fraction bits that rtl/ runs as constant functions:
//   log_row(i) = round(2^16 log2(1 + i/256)): 17 bits of log2 by repeated squaring (square,
//     truncate to G bits; a square >= 2 is a 1 bit and is halved), then rounded to 16
//   exp_row(i) = (2^17 - round(2^17 2^(-i/256))) mod 2^16: 2^(-i/256) as the product (truncated to
//     G bits) of c_b = 2^(-2^-b) for the set bits of i/256, c_0 = 1/2, c_b = isqrt(c_(b-1) 2^G)
// Both functions are 0 at both ends of [0, 1] modulo 2^16 (log2 1 = 0, log2 2 = 1; 2 - 2^(1-0) = 0,
// 2 - 2^0 = 1), so row 255's successor is row 0 and the slope (T[i+1] - T[i]) mod 2^16 needs no
// special case.
struct PhongPowerTables {
  static constexpr int G = 30;
  static constexpr std::uint32_t log_row(int i) {
    std::uint64_t x = static_cast<std::uint64_t>(256 + i) << (G - 8), r = 0;
    for (int b = 0; b < narrow::LogFracBits + 1; ++b) {
      x = (x * x) >> G;
      r <<= 1;
      if ((x >> (G + 1)) != 0) r |= 1, x >>= 1;
    }
    return static_cast<std::uint32_t>((r + 1) >> 1);
  }
  static constexpr std::uint32_t exp_row(int i) {
    std::uint64_t c = std::uint64_t{1} << (G - 1), p = std::uint64_t{1} << G;
    for (int b = 1; b <= narrow::TableBits; ++b) {
      c = RsqrtUnit::isqrt(c << G);
      if (((i >> (narrow::TableBits - b)) & 1) != 0) p = (p * c) >> G;
    }
    const std::uint64_t q = (p + (std::uint64_t{1} << (G - 18))) >> (G - 17);
    return static_cast<std::uint32_t>(((std::uint64_t{1} << 17) - q) & 0xffffu);
  }
  static constexpr std::array<std::uint32_t, 1 << narrow::TableBits> rom(bool log) {
    std::array<std::uint32_t, 1 << narrow::TableBits> t{};
    for (int i = 0; i < (1 << narrow::TableBits); ++i) t[static_cast<std::size_t>(i)] = log ? log_row(i) : exp_row(i);
    return t;
  }
};
inline constexpr std::array<std::uint32_t, 1 << narrow::TableBits> PhongLogRom = PhongPowerTables::rom(true);
inline constexpr std::array<std::uint32_t, 1 << narrow::TableBits> PhongExpRom = PhongPowerTables::rom(false);

// A table read with linear interpolation: row i and the 8 bits d below it,
// T[i] + round(((T[i+1] - T[i]) mod 2^16) d / 2^8), row 255's successor row 0.
inline i64 narrow_table_lerp(const std::array<std::uint32_t, 1 << narrow::TableBits>& t, unsigned i, unsigned d) {
  const std::uint32_t t0 = t[i], t1 = t[(i + 1) & 255u];
  const i64 slope = static_cast<i64>((t1 - t0) & 0xffffu);
  return static_cast<i64>(t0) + ((slope * d + 128) >> 8);
}

inline i64 PhongShader::power_narrow(i64 cs, int n) {
  n = static_cast<int>(static_cast<unsigned>(n) & ((1u << NBits) - 1));
  if (cs <= 0) return 0;  // no specular (the shader never asks: spec needs cs > 0)
  // -log2 cs = K - log2(x): cs = x 2^(e - 16), x in [1, 2) from the 16 bits below the leading one.
  const int e = msb_index(static_cast<std::uint64_t>(cs));
  const auto frac = static_cast<unsigned>((cs << (narrow::CosBits - e)) & 0xffff);
  const i64 lx = narrow_table_lerp(PhongLogRom, frac >> 8, frac & 255u);  // [0, 2^16]
  const i64 lc = (i64{narrow::CosBits - e} << narrow::LogFracBits) - lx;     // [0, 16 2^16]
  // n lc as one 16 x 16 product: lc < 1 as it is; lc >= 1 (cs <= 1/2) only matters for n <= 16
  // (else n lc >= 17 and the power is 0), as lc >> 5 (truncated) times n 2^5.
  i64 et;
  if (lc < (i64{1} << narrow::LogFracBits)) {
    et = n * lc;
  } else {
    if (n > 16) return 0;
    et = (i64{n} << 5) * (lc >> 5);
  }
  const i64 ei = et >> narrow::LogFracBits;
  if (ei > 16) return 0;
  const auto ef = static_cast<unsigned>(et & 0xffff);
  const i64 h = narrow_table_lerp(PhongExpRom, ef >> 8, ef & 255u);  // 2^17 - 2^(17 - ef), [0, 2^16]
  return std::min<i64>(round_shift64((i64{1} << 17) - h, static_cast<int>(ei) + 1), (i64{1} << narrow::PowBits) - 1);
}

inline PhongShader::Terms PhongShader::terms_narrow(const Pixel& px, const Vec& light, const Vec& eye, i64 le) {
  using namespace narrow;
  Terms t;
  t.cos_i = narrow_round(dot(px.n, light), CosIBits, 0, (i64{1} << (CosIBits + 1)) - 1);
  t.ne = narrow_round(dot(px.n, eye), NeBits, -(i64{1} << (NeBits + 1)), (i64{1} << (NeBits + 1)) - 1);
  t.front = t.cos_i > 0;
  constexpr int CsFrac = CosIBits + NeBits - 1;  // 28: cos_i ne is 2 cos(i)(N.E) at 28 fraction bits
  const i64 cs2 = t.cos_i * t.ne - le * (i64{1} << (CsFrac - LeBits));
  t.cs = std::clamp<i64>(round_shift64(cs2, CsFrac - CosBits), 0, i64{1} << CosBits);
  t.spec = t.front && t.cs > 0;
  const i64 d = px.d > (1 << MF) ? (1 << MF) : px.d;
  t.f = round_shift64(t.cos_i * ((1 << MF) - d) + (d << CosIBits), CosIBits + MF - DiffuseBits);
  t.pow = t.spec ? power_narrow(t.cs, px.shininess) : 0;
  return t;
}

inline std::array<int, 3> PhongShader::shade_narrow(const Pixel& px, const Vec& light, const Vec& eye, i64 le) {
  const Terms t = terms_narrow(px, light, eye, le);
  constexpr int L = narrow::LevelFracBits;
  const i64 spec = 255 * static_cast<i64>(px.w) * t.pow;  // MF + PowBits = 24 fraction bits
  std::array<int, 3> out{};
  for (int c = 0; c < 3; ++c) {
    const i64 level = px.cp[c] * t.f * (i64{1} << (L - narrow::DiffuseBits)) + spec;  // Cp fr 2^9
    out[c] = static_cast<int>(std::clamp<i64>(round_shift64(level, L), 0, fmt::ShadeMax));
  }
  return out;
}

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
