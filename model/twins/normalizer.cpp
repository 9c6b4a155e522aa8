// Twin of rtl/normalizer.sv; see normalizer.hpp for the stage list.
#include "normalizer.hpp"

namespace watkins {

i64 Normalizer::scale(i64 n, std::uint32_t y, int j) {
  const i128 p = static_cast<i128>(n) * y;  // FracBits + F fraction bits
  // unit = n 2^-16 * y 2^-F * 2^(j-2) in units of 2^-14: shift right by F + 4 - j >= F - 13.
  return saturate_signed(round_shift(p, F + 4 - j), fmt::UnitBits);
}

Normalizer::Unit Normalizer::normalize(i64 nx, i64 ny, i64 nz) {
  const RsqrtUnit::Mantissa mm = RsqrtUnit::normalize_mantissa(sum_of_squares(nx, ny, nz));
  const std::uint32_t y = RsqrtUnit::rsqrt_mant(mm.mant);  // 0 for the null vector
  Unit u;
  u.null = mm.null;
  u.n = {scale(nx, y, mm.j), scale(ny, y, mm.j), scale(nz, y, mm.j)};
  return u;
}

static_assert(Normalizer::F + 4 - RsqrtUnit::MaxJ >= 1, "final shift must stay a right shift");

}  // namespace watkins
