// Twin of rtl/normalizer.sv: unit normal from an interpolated normal n = (Nx, Ny, Nz), stage by
// stage with the RTL's widths and rounding (see docs/reference/phong-blocks.md for the derivation).
//
//   stage 0  m = Nx^2 + Ny^2 + Nz^2, exact: 36 bits unsigned, 2*FracBits fraction bits
//   stage 1  even-shift normalization m = 2^(4-2j) m',  m' = M' / 2^36 in [1/4, 1), j in 0..17;
//            mant = top RsqrtMantBits bits of M'; m = 0 raises `null`
//   stage 2  seed y0 ~ 1/sqrt(m'c), table indexed by mant's top RsqrtIndexBits bits
//   stage 3  y0^2, exact
//   stage 4  u = 3 - m'c*y0^2 (rounded to RsqrtNrBits fraction bits)
//   stage 5  y = y0*u/2 (rounded to RsqrtBits fraction bits): one Newton-Raphson step
//   stage 6  p = N * y, exact
//   stage 7  unit = saturate(round(p * 2^(j-4-RsqrtBits)), UnitBits): Q2.14
// m'c = mant + half an ulp of mant: the centre of the interval of m' the truncated mantissa
// stands for, which halves the truncation error. Rounding is round_shift (ties toward +inf).
// Null vector (m = 0): mant = 0, j = 0, the seed ROM reads 0, so y = 0 and the result is
// (0, 0, 0); null is set as well. Any m > 0 gives a unit vector
// in the direction of the (quantized) input, however short it is.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "fixed_point.hpp"
#include "formats.hpp"
#include "phong_format.hpp"
#include "rsqrt_unit.hpp"

namespace watkins {

struct Normalizer {
  static constexpr int InBits = fmt::NormalInBits;     // 18, signed, FracBits fraction
  static constexpr int F = RsqrtUnit::F;               // fraction bits of y

  struct Unit {
    std::array<i64, 3> n{};  // Q2.14 components, UnitBits signed
    bool null = false;
  };

  static std::uint64_t sum_of_squares(i64 nx, i64 ny, i64 nz) {
    return static_cast<std::uint64_t>(nx * nx + ny * ny + nz * nz);
  }
  // Stage 7 for one component.
  static i64 scale(i64 n, std::uint32_t y, int j);
  // Stage 7 without the saturation, which never acts on a component of the vector y was worked
  // out for: |n_i| <= |n| < sqrt(mant + 1) 2^(8-j), so |unit| < sqrt((mant + 1) 2^-W) y 2^(UF-F) + 1/2,
  // below sqrt(3) 2^UF + 1/2 for every mant (tests/test_phong_fast_path.cpp runs them all), far
  // inside UnitBits. normalize() uses it.
  static i64 scale_unsaturated(i64 n, std::uint32_t y, int j) {
    // |n| < 2^(NormalInBits-1) and y <= 2^(F+1): |p| < 2^40, in round_shift62's range; the sign
    // of n varies from pixel to pixel, so the rounding takes no branch on it.
    return round_shift62(n * static_cast<i64>(y), F + 4 - j);
  }
  // The whole block: components are NormalInBits signed, FracBits fraction bits.
  static Unit normalize(i64 nx, i64 ny, i64 nz);

  // The narrow set (PhongFormat::Narrow), from the same NormalInBits input:
  //   stage 0  n_c = clamp(round(N_c / 2), -2^15, 2^15 - 1): 16 bits signed, 15 fraction bits
  //            (exact when the normal slot has int_bits 1 and frac_bits <= 15)
  //   stage 1  m = nx^2 + ny^2 + nz^2, exact: < 3 2^30, 30 fraction bits (three 16 x 16 products)
  //   stage 2  j = floor(lz32(m) / 2) in 0..15, M = m << 2j in [2^30, 2^32): m = (M 2^-32) 2^(2-2j)
  //   stage 3  y' = RsqrtUnit::rsqrt_narrow(M) ~ 1/sqrt(M 2^-32) - 1 (one 16 x 16 product)
  //   stage 4  unit_c = saturate16(round(n_c (2^16 + y') / 2^(18-j))): n_c y' + n_c 2^16 is one
  //            16 x 16 product with the MAC16's accumulator adding n_c 2^16
  // m = 0 (every n_c 0) gives unit 0 with no special case (n_c y = 0) and raises null.
  static i64 narrow_input(i64 n) {
    constexpr i64 hi = (i64{1} << (narrow::InBits - 1)) - 1;
    return std::clamp<i64>(round_shift64(n, fmt::FracBits - narrow::InFracBits), -hi - 1, hi);
  }
  static Unit normalize_narrow(i64 nx, i64 ny, i64 nz);
  static Unit normalize(i64 nx, i64 ny, i64 nz, PhongFormat format) {
    return format == PhongFormat::Narrow ? normalize_narrow(nx, ny, nz) : normalize(nx, ny, nz);
  }
};

// Inline: the Phong pipeline runs them per shaded pixel.
inline i64 Normalizer::scale(i64 n, std::uint32_t y, int j) {
  // unit = n 2^-16 * y 2^-F * 2^(j-2) in units of 2^-14: shift right by F + 4 - j >= F - 13.
  constexpr i64 hi = (i64{1} << (fmt::UnitBits - 1)) - 1;
  return std::clamp<i64>(scale_unsaturated(n, y, j), -hi - 1, hi);
}

inline Normalizer::Unit Normalizer::normalize(i64 nx, i64 ny, i64 nz) {
  const RsqrtUnit::Mantissa mm = RsqrtUnit::normalize_mantissa(sum_of_squares(nx, ny, nz));
  const std::uint32_t y = RsqrtUnit::rsqrt_mant(mm.mant);  // 0 for the null vector
  Unit u;
  u.null = mm.null;
  u.n = {scale_unsaturated(nx, y, mm.j), scale_unsaturated(ny, y, mm.j), scale_unsaturated(nz, y, mm.j)};
  return u;
}

inline Normalizer::Unit Normalizer::normalize_narrow(i64 nx, i64 ny, i64 nz) {
  const i64 n[3] = {narrow_input(nx), narrow_input(ny), narrow_input(nz)};
  const std::uint64_t m = static_cast<std::uint64_t>(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  Unit u;
  if (m == 0) {
    u.null = true;
    return u;
  }
  const int j = (31 - msb_index(m)) >> 1;
  const std::uint32_t big_m = static_cast<std::uint32_t>(m << (2 * j));
  const i64 y = (i64{1} << narrow::RsqrtFracBits) + RsqrtUnit::rsqrt_narrow(big_m);
  constexpr i64 hi = (i64{1} << (fmt::UnitBits - 1)) - 1;
  for (int c = 0; c < 3; ++c)
    u.n[static_cast<std::size_t>(c)] = std::clamp<i64>(round_shift64(n[c] * y, 18 - j), -hi - 1, hi);
  return u;
}

}  // namespace watkins
