// Twin of rtl/normalizer.sv; see normalizer.hpp for the stage list.
#include "normalizer.hpp"

namespace watkins {

Normalizer::Mantissa Normalizer::normalize_mantissa(std::uint64_t m) {
  Mantissa r;
  if (m == 0) {
    r.null = true;
    return r;
  }
  // Leading zeros of m in MBits bits, rounded down to even: m' = (m << 2j) / 2^36 >= 1/4.
  const int lz = MBits - 1 - msb_index(m);
  r.j = lz / 2;
  const std::uint64_t shifted = m << (2 * r.j);  // < 2^36
  r.mant = static_cast<std::uint32_t>(shifted >> (MBits - W));
  return r;
}

std::uint32_t Normalizer::rsqrt_mant(std::uint32_t mant) {
  const std::uint64_t mc = (static_cast<std::uint64_t>(mant) << 1) | 1u;  // W+1 fraction bits
  const std::uint64_t y0 = seed_row(static_cast<int>(mant >> (W - P)));      // T fraction bits
  const std::uint64_t y0sq = y0 * y0;                                     // 2T fraction bits
  const i128 t = round_shift(static_cast<i128>(mc) * y0sq, (W + 1) + 2 * T - G);  // G fraction
  const i128 u = (static_cast<i128>(3) << G) - t;                         // 3 - m'c y0^2
  const i128 y = round_shift(static_cast<i128>(y0) * u, T + G + 1 - F);   // y0 u / 2
  return static_cast<std::uint32_t>(y);
}

i64 Normalizer::scale(i64 n, std::uint32_t y, int j) {
  const i128 p = static_cast<i128>(n) * y;  // FracBits + F fraction bits
  // unit = n 2^-16 * y 2^-F * 2^(j-2) in units of 2^-14: shift right by F + 4 - j >= F - 13.
  return saturate_signed(round_shift(p, F + 4 - j), fmt::UnitBits);
}

Normalizer::Unit Normalizer::normalize(i64 nx, i64 ny, i64 nz) {
  const Mantissa mm = normalize_mantissa(sum_of_squares(nx, ny, nz));
  const std::uint32_t y = rsqrt_mant(mm.mant);  // 0 for the null vector
  Unit u;
  u.null = mm.null;
  u.n = {scale(nx, y, mm.j), scale(ny, y, mm.j), scale(nz, y, mm.j)};
  return u;
}

static_assert(Normalizer::F + 4 - Normalizer::MaxJ >= 1, "final shift must stay a right shift");
static_assert(Normalizer::seed(Normalizer::MantLo >> (Normalizer::W - Normalizer::P)) <
                  (1u << (Normalizer::T + 1)),
              "seed must fit T+1 bits");

}  // namespace watkins
