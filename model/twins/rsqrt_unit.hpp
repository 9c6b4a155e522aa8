// Twin of rtl/rsqrt_unit.sv, stages 1..5 of the normalizer (see normalizer.hpp for the list):
// m = Nx^2 + Ny^2 + Nz^2 -> even-shift normalization m = 2^(4-2j) m', seed y0 ~ 1/sqrt(m'c) from
// a table, one Newton-Raphson step; 1/sqrt(m) = y 2^(j-2). m = 0 gives y = 0 and null.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "fixed_point.hpp"
#include "formats.hpp"
#include "phong_format.hpp"

namespace watkins {

struct RsqrtUnit {
  static constexpr int MBits = 2 * fmt::NormalInBits;  // 36: m < 3 * 2^34
  // One-letter names as the formulas in docs/reference/phong-blocks.md write them; rtl/rsqrt_unit.sv spells
  // them out: W = MantBits, P = IndexBits, T = SeedBits, G = NrBits, F = RsqrtBits.
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
  // The whole ROM (RsqrtSeedRom below, built at compile time): the per-fragment path reads it
  // instead of running the bit-serial square root of seed() (some 700 instructions) per normal.
  static constexpr std::array<std::uint32_t, (1 << P)> seed_rom() {
    std::array<std::uint32_t, (1 << P)> rom{};
    for (int idx = 0; idx < (1 << P); ++idx) rom[static_cast<std::size_t>(idx)] = seed_row(idx);
    return rom;
  }


  static Mantissa normalize_mantissa(std::uint64_t m);
  // Stages 2..5: the refined y ~ 1/sqrt(m'c), RsqrtBits fraction bits, in [1, 2]; 0 for mant 0.
  static std::uint32_t rsqrt_mant(std::uint32_t mant);

  // The narrow set (PhongFormat::Narrow): 1/sqrt(m') - 1 from one 256-row table with linear
  // interpolation. Row k covers m' in [1/4 + k 2^-9, +2^-9) for k < 128 and [k 2^-8, +2^-8) for
  // k >= 128 (7 bits below m''s leading one: the rows are twice as fine where 1/sqrt bends most).
  // Row k holds round(2^16 (1/sqrt(x_k) - 1)), x_k = a_k 2^-9 its start (a_k = 128 + k, or 2k),
  // computed as round(sqrt(2^41 / a_k)) - 2^16 with seed()'s integer rounding; row 0 (y' = 1.0)
  // saturates at 2^16 - 1. The end of row 255 (m' = 1, y' = 0) is the constant 0, not a row.
  static constexpr std::uint32_t narrow_row(int k) {
    const std::uint64_t a = k < 128 ? 128u + static_cast<unsigned>(k) : 2u * static_cast<unsigned>(k);
    const std::uint64_t r = ((isqrt((std::uint64_t{1} << 43) / a) + 1) >> 1) - (std::uint64_t{1} << 16);
    return static_cast<std::uint32_t>(r > 0xffffu ? 0xffffu : r);
  }
  static constexpr std::array<std::uint32_t, 1 << narrow::TableBits> narrow_rom() {
    std::array<std::uint32_t, 1 << narrow::TableBits> rom{};
    for (int k = 0; k < (1 << narrow::TableBits); ++k) rom[static_cast<std::size_t>(k)] = narrow_row(k);
    return rom;
  }
  // y' ~ 1/sqrt(m') - 1 (16 fraction bits, 0..2^16 - 1) for M = m' 2^32 in [2^30, 2^32): row k
  // and the 16 bits d below it, y' = T[k] - round((T[k] - T[k+1]) d / 2^16).
  static std::uint32_t rsqrt_narrow(std::uint32_t big_m);
};

// The seed ROM as rtl/rsqrt_unit.sv holds it, one constant table for every RsqrtUnit.
inline constexpr std::array<std::uint32_t, (1 << RsqrtUnit::P)> RsqrtSeedRom = RsqrtUnit::seed_rom();

// The narrow rsqrt table, one 256 x 16 block RAM.
inline constexpr std::array<std::uint32_t, 1 << narrow::TableBits> RsqrtNarrowRom = RsqrtUnit::narrow_rom();

inline std::uint32_t RsqrtUnit::rsqrt_narrow(std::uint32_t big_m) {
  const bool upper = (big_m >> 31) != 0;  // m' >= 1/2
  const std::uint32_t k = upper ? 128u + ((big_m >> 24) & 127u) : (big_m >> 23) & 127u;
  const std::uint64_t d = upper ? (big_m >> 8) & 0xffffu : (big_m >> 7) & 0xffffu;
  const std::uint64_t t0 = RsqrtNarrowRom[k], t1 = k == 255 ? 0 : RsqrtNarrowRom[k + 1];
  constexpr int S = narrow::RsqrtDeltaBits;
  return static_cast<std::uint32_t>(t0 - (((t0 - t1) * d + (std::uint64_t{1} << (S - 1))) >> S));
}

inline RsqrtUnit::Mantissa RsqrtUnit::normalize_mantissa(std::uint64_t m) {
  Mantissa r;
  if (m == 0) {
    r.null = true;
    return r;
  }
  // Leading zeros of m in MBits bits, rounded down to even: m' = (m << 2j) / 2^36 >= 1/4.
  const int lz = MBits - 1 - msb_index(m);
  r.j = static_cast<int>(static_cast<unsigned>(lz) >> 1);  // lz >= 0: m < 2^MBits
  const std::uint64_t shifted = m << (2 * r.j);  // < 2^36
  r.mant = static_cast<std::uint32_t>(shifted >> (MBits - W));
  return r;
}

inline std::uint32_t RsqrtUnit::rsqrt_mant(std::uint32_t mant) {
  const std::uint64_t mc = (static_cast<std::uint64_t>(mant) << 1) | 1u;  // W+1 fraction bits
  const std::uint64_t y0 = RsqrtSeedRom[mant >> (W - P)];                  // T fraction bits
  // 2T fraction bits, exact: the RTL's ROM holds it beside y0 (tabulated, not multiplied).
  const std::uint64_t y0sq = y0 * y0;
  // 64 bits hold every product: m'c < 2^(W+2), y0^2 < 2^(2T+2), y0 u < 2^(T+1) 2^(G+2).
  // Every word here is >= 0 (u too: m'c y0^2 < 2 for every mant, tests/test_phong_fast_path.cpp
  // runs them all), so round_shift's "add half, shift" is an unsigned add and shift.
  constexpr int S1 = (W + 1) + 2 * T - G, S2 = T + G + 1 - F;
  const std::uint64_t t = (mc * y0sq + (std::uint64_t{1} << (S1 - 1))) >> S1;  // G fraction
  const std::uint64_t u = (std::uint64_t{3} << G) - t;                         // 3 - m'c y0^2
  return static_cast<std::uint32_t>((y0 * u + (std::uint64_t{1} << (S2 - 1))) >> S2);  // y0 u / 2
}

}  // namespace watkins
