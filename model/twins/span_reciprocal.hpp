// Twin of rtl/span_reciprocal.sv: 1/dx for a segment width dx > 0 (X channel units, FracBits
// fraction) as a normalized mantissa and an exponent, the way a pipelined restoring divider
// computes it. With p = floor(log2 dx) and m = dx scaled to exactly RecipBits bits
// (m in [2^(R-1), 2^R), low bits truncated when dx is wider), recip = floor(2^(2R-1) / m), so
// 1/dx ~= recip * 2^-(p + R) with relative error below 2^-(R-1).
//
// Widths from the configuration (config.hpp), as the RTL takes them: DxBits = bits[ChanX] + 1
// (the X slot's word plus one), so ExpBits = clog2(DxBits) and the leading-one search shrink
// with X (a dx narrower than R bits is widened before normalization). R is RecipBits, a package
// constant, for the span (the reciprocal's error is in units of the span, not of any channel); the
// eq. (2) shade divider (shade_divider.hpp) takes 1/depth from the same block with R =
// Config::eq2_recip_bits (the RTL's RecipBits parameter).
#pragma once

#include "fixed_point.hpp"
#include "formats.hpp"

namespace watkins {

struct SpanReciprocal {
  i64 recip = 0;  // in (2^(R-1), 2^R], R = RecipBits unless given
  int p = 0;      // floor(log2 dx)

  static SpanReciprocal of(i64 dx, int R = fmt::RecipBits) {
    SpanReciprocal r;
    r.p = msb_index(static_cast<std::uint64_t>(dx));
    const i64 m = r.p >= R - 1 ? (dx >> (r.p - (R - 1))) : (dx << ((R - 1) - r.p));
    static_assert(2 * fmt::RecipBits - 1 <= 62, "the dividend 2^(2R-1) is a 64-bit number");  // R <= 31 given
    r.recip = R <= 26 ? quotient_via_double(R, m) : (i64{1} << (2 * R - 1)) / m;
    return r;
  }

  // floor(2^(2R-1) / m) for m in [2^(R-1), 2^R), R <= 26, by one double division: both operands
  // are exact doubles, and the exact quotient q + r/m (r the remainder) is either the integer q
  // or at least 1/m > 2^-R away from every integer, which is more than half an ulp of a double
  // below 2^R (2^(R-54)) when R <= 26, so the correctly rounded double lies in [q, q + 1) and
  // truncates to q (q = 2^R, at m = 2^(R-1), is exact). The integer division's value, in a
  // fraction of its latency.
  static i64 quotient_via_double(int R, i64 m) {
    return static_cast<i64>(static_cast<double>(i64{1} << (2 * R - 1)) / static_cast<double>(m));
  }
};

}  // namespace watkins
