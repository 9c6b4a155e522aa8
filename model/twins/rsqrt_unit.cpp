// Twin of rtl/rsqrt_unit.sv; see rsqrt_unit.hpp.
#include "rsqrt_unit.hpp"

namespace watkins {

RsqrtUnit::Mantissa RsqrtUnit::normalize_mantissa(std::uint64_t m) {
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

std::uint32_t RsqrtUnit::rsqrt_mant(std::uint32_t mant) {
  const std::uint64_t mc = (static_cast<std::uint64_t>(mant) << 1) | 1u;  // W+1 fraction bits
  const std::uint64_t y0 = RsqrtSeedRom[mant >> (W - P)];                  // T fraction bits
  const std::uint64_t y0sq = y0 * y0;                                     // 2T fraction bits
  // 64 bits hold every product: m'c < 2^(W+2), y0^2 < 2^(2T+2), y0 u < 2^(T+1) 2^(G+2).
  const i64 t = round_shift64(static_cast<i64>(mc * y0sq), (W + 1) + 2 * T - G);  // G fraction
  const i64 u = (i64{3} << G) - t;                                             // 3 - m'c y0^2
  const i64 y = round_shift64(static_cast<i64>(y0) * u, T + G + 1 - F);        // y0 u / 2
  return static_cast<std::uint32_t>(y);
}

static_assert((RsqrtUnit::W + 2) + 2 * (RsqrtUnit::T + 1) <= 62 && (RsqrtUnit::T + 1) + (RsqrtUnit::G + 3) <= 62,
              "rsqrt_mant products fit 64 bits");
static_assert(RsqrtUnit::seed(RsqrtUnit::MantLo >> (RsqrtUnit::W - RsqrtUnit::P)) < (1u << (RsqrtUnit::T + 1)),
              "seed must fit T+1 bits");

}  // namespace watkins
