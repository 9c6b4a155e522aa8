// Twin of rtl/normalizer.sv: unit normal from an interpolated normal n = (Nx, Ny, Nz), stage by
// stage with the RTL's widths and rounding (see docs/phong-blocks.md for the derivation).
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

#include <array>
#include <cstdint>

#include "fixed_point.hpp"
#include "formats.hpp"

namespace watkins {

struct Normalizer {
  static constexpr int InBits = fmt::NormalInBits;     // 18, signed, FracBits fraction
  static constexpr int MBits = 2 * InBits;             // 36: m < 3 * 2^34
  static constexpr int W = fmt::RsqrtMantBits;         // 20
  static constexpr int P = fmt::RsqrtIndexBits;        // 10
  static constexpr int T = fmt::RsqrtSeedBits;         // 14
  static constexpr int G = fmt::RsqrtNrBits;           // 24
  static constexpr int F = fmt::RsqrtBits;             // 22
  static constexpr int JBits = 5;                      // j in 0..17
  static constexpr int MaxJ = MBits / 2 - 1;           // 17
  static constexpr int SeedRows = (1 << P) - (1 << (P - 2));  // 768: m' >= 1/4
  static constexpr int MantLo = 1 << (W - 2), MantHi = 1 << W;  // mant in [MantLo, MantHi)

  // Stage 1 result: m = mant * 2^(-W) * 2^(4-2j) (up to the truncated bits).
  struct Mantissa {
    std::uint32_t mant = 0;  // in [2^(W-2), 2^W), 0 when null
    int j = 0;               // even-shift count
    bool null = false;       // m == 0
  };

  struct Unit {
    std::array<i64, 3> n{};  // Q2.14 components, UnitBits signed
    bool null = false;
  };

  // floor(sqrt(v)), bit by bit (the RTL's constant function runs the same loop).
  static constexpr std::uint64_t isqrt(std::uint64_t v) {
    std::uint64_t rem = v, root = 0;
    for (int i = 31; i >= 0; --i) {
      const std::uint64_t b = std::uint64_t{1} << (2 * i);
      if (rem >= root + b) {
        rem -= root + b;
        root = (root >> 1) + b;
      } else {
        root >>= 1;
      }
    }
    return root;
  }

  // Seed for table index idx in [2^(P-2), 2^P): round(2^T / sqrt(c)) where c = (2 idx + 1) /
  // 2^(P+1) is the centre of the idx-th interval of m'. Computed exactly with integers:
  // round(sqrt(x)) = (floor(sqrt(4x)) + 1) / 2 and floor(sqrt(floor(y))) = floor(sqrt(y)).
  static constexpr std::uint32_t seed(int idx) {
    const std::uint64_t q = (std::uint64_t{1} << (2 * T + P + 3)) / static_cast<std::uint64_t>(2 * idx + 1);
    return static_cast<std::uint32_t>((isqrt(q) + 1) >> 1);
  }

  // The seed ROM read: rows below 2^(P-2) (only mant = 0, the null vector) read 0, so y = 0
  // and every unit component becomes 0 without a special case.
  static constexpr std::uint32_t seed_row(int idx) { return idx < (1 << (P - 2)) ? 0u : seed(idx); }

  static std::uint64_t sum_of_squares(i64 nx, i64 ny, i64 nz) {
    return static_cast<std::uint64_t>(nx * nx + ny * ny + nz * nz);
  }
  static Mantissa normalize_mantissa(std::uint64_t m);
  // Stages 2..5: the refined y ~ 1/sqrt(m'c), RsqrtBits fraction bits, in [1, 2]; 0 for mant 0.
  static std::uint32_t rsqrt_mant(std::uint32_t mant);
  // Stage 7 for one component.
  static i64 scale(i64 n, std::uint32_t y, int j);
  // The whole block: components are NormalInBits signed, FracBits fraction bits.
  static Unit normalize(i64 nx, i64 ny, i64 nz);
};

}  // namespace watkins
