// Fixed-point helpers shared by every model stage. All shifts here are defined for negative
// numbers (C++17 leaves >> of a negative value implementation-defined before C++20, so we
// divide by powers of two through floor_shift, which is exact and portable).
#pragma once

#include <cstdint>

namespace watkins {

using i64 = std::int64_t;
using i128 = __int128;

// floor(v / 2^s) for any sign of v; s in [0, 126]. Only non-negative numbers are shifted:
// for v < 0, ~v = -v - 1 >= 0 and floor(v / 2^s) = ~(~v >> s). Cheap for a run-time s too
// (a division by a run-time power of two would be a library call on 128 bits).
constexpr i128 floor_shift(i128 v, int s) {
  return v < 0 ? ~(~v >> s) : v >> s;
}

// round(v / 2^s), ties toward +infinity: floor((v + 2^(s-1)) / 2^s). Same rule as the RTL's
// "add half, arithmetic shift right".
constexpr i128 round_shift(i128 v, int s) {
  if (s == 0) return v;
  return floor_shift(v + (static_cast<i128>(1) << (s - 1)), s);
}

// floor_shift on 64 bits (a 128-bit shift by a run-time amount costs a branch and two words).
constexpr i64 floor_shift64(i64 v, int s) { return v < 0 ? ~(~v >> s) : v >> s; }

// round_shift on 64 bits, for words of at most 62 bits (the per-pixel path, where 128-bit shifts
// by a run-time amount cost the model a quarter of its speed).
constexpr i64 round_shift64(i64 v, int s) {
  if (s == 0) return v;
  const i64 t = v + (i64{1} << (s - 1));
  return t < 0 ? ~(~t >> s) : t >> s;
}

// round_shift64 without its sign branch, for |v| < 2^61 and s in [1, 61]: the bias 2^62, a
// multiple of 2^s, makes the sum non-negative, so a plain shift floors it, and comes off after:
// floor((v + 2^(s-1) + 2^62) / 2^s) = floor((v + 2^(s-1)) / 2^s) + 2^(62-s), with no overflow as
// 0 < v + 2^(s-1) + 2^62 < 2^63. For per-pixel words whose sign varies from pixel to pixel (normal
// components, dot products), where the branch would be mispredicted. Same value as round_shift64.
constexpr i64 round_shift62(i64 v, int s) {
  constexpr i64 bias = i64{1} << 62;
  return ((v + (i64{1} << (s - 1)) + bias) >> s) - (bias >> s);
}

// round(a / b) for b > 0, ties toward +infinity; exact for any a.
constexpr i128 round_div(i128 a, i128 b) {
  i128 n = 2 * a + b;
  const i128 d = 2 * b;
  i128 q = n / d;
  if ((n % d) != 0 && n < 0) --q;
  return q;
}

// round_div on 64 bits, for |a| < 2^61 and 0 < b < 2^61 (a 128-bit division is a library call).
constexpr i64 round_div64(i64 a, i64 b) {
  const i64 n = 2 * a + b, d = 2 * b;
  i64 q = n / d;
  if ((n % d) != 0 && n < 0) --q;
  return q;
}

// Keep the low `bits` bits and sign-extend them: what a signed register of that width holds.
constexpr i64 wrap_signed(i128 v, int bits) {
  const i128 m = (static_cast<i128>(1) << bits) - 1;
  i128 u = v & m;
  if (u >> (bits - 1)) u -= static_cast<i128>(1) << bits;
  return static_cast<i64>(u);
}

// wrap_signed on 64 bits for a word whose sign bit is `sign` (2^(bits-1)): keep the low bits and
// sign-extend them by flipping and subtracting the sign bit (exact, no branch, no shift of a
// negative value). Loops over one word keep `sign` instead of recomputing it.
constexpr i64 wrap_to_sign(i64 v, i64 sign) { return ((v & (2 * sign - 1)) ^ sign) - sign; }

// wrap_signed on 64 bits, for words of at most 62 bits.
constexpr i64 wrap_signed64(i64 v, int bits) { return wrap_to_sign(v, i64{1} << (bits - 1)); }

// Keep the low `bits` bits as an unsigned value.
constexpr std::uint64_t wrap_unsigned(i128 v, int bits) {
  const i128 m = (static_cast<i128>(1) << bits) - 1;
  return static_cast<std::uint64_t>(v & m);
}

constexpr i128 clamp_i(i128 v, i128 lo, i128 hi) { return v < lo ? lo : (v > hi ? hi : v); }

// Saturate to a signed register of `bits` bits.
constexpr i64 saturate_signed(i128 v, int bits) {
  const i128 hi = (static_cast<i128>(1) << (bits - 1)) - 1;
  return static_cast<i64>(clamp_i(v, -hi - 1, hi));
}

constexpr bool fits_signed(i128 v, int bits) {
  const i128 hi = (static_cast<i128>(1) << (bits - 1)) - 1;
  return v >= -hi - 1 && v <= hi;
}

// Index of the most significant set bit of v > 0 (floor(log2 v)).
constexpr int msb_index(std::uint64_t v) { return v ? 63 - __builtin_clzll(v) : -1; }

}  // namespace watkins
