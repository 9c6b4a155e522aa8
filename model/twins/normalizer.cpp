// Twin of rtl/normalizer.sv; see normalizer.hpp for the stage list.
#include "normalizer.hpp"

#include <algorithm>

namespace watkins {

i64 Normalizer::scale(i64 n, std::uint32_t y, int j) {
  // |n| < 2^(NormalInBits-1) and y <= 2^(F+1): the product fits 64 bits.
  const i64 p = n * static_cast<i64>(y);  // FracBits + F fraction bits
  // unit = n 2^-16 * y 2^-F * 2^(j-2) in units of 2^-14: shift right by F + 4 - j >= F - 13.
  const i64 hi = (i64{1} << (fmt::UnitBits - 1)) - 1;
  return std::clamp<i64>(round_shift64(p, F + 4 - j), -hi - 1, hi);
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
static_assert(fmt::NormalInBits - 1 + Normalizer::F + 1 <= 62, "scale() products fit 64 bits");

}  // namespace watkins
