// The one bit packer of the benches: a field of a packed SystemVerilog vector held as
// little-endian 32-bit words (bit b in word b / 32 at b % 32), as Verilator stores any port or
// signal wider than 64 bits (VlWide<N>) and as EdgeWords holds an edge record. Used by the edge
// packer (edge_packing.hpp), the RTL unit benches (tests/rtl/rtl_harness.hpp) and the stage
// checker (stage_checker.cpp). A field is at most 64 bits; only the words it touches are read or
// written, so a raw word pointer into a Verilated model works as well as a container.
#pragma once

#include <cstdint>

#include "fixed_point.hpp"

namespace watkins::tb {

namespace bit_field_detail {
using u128 = unsigned __int128;
constexpr u128 low_mask(int width) { return (u128{1} << width) - 1; }
}  // namespace bit_field_detail

// Bits [lsb, lsb + width) of `words` := the low `width` bits of v (1 <= width <= 64).
template <class Words>
void set_bits(Words& words, int lsb, int width, std::uint64_t v) {
  using bit_field_detail::u128;
  const int first = lsb / 32, last = (lsb + width - 1) / 32, shift = lsb % 32;
  const u128 mask = bit_field_detail::low_mask(width) << shift;
  const u128 bits = (u128{v} << shift) & mask;
  for (int k = first; k <= last; ++k) {
    const int at = 32 * (k - first);
    const auto m = static_cast<std::uint32_t>(mask >> at);
    words[k] = (words[k] & ~m) | static_cast<std::uint32_t>(bits >> at);
  }
}

// Bits [lsb, lsb + width) of `words`, zero-extended (1 <= width <= 64).
template <class Words>
std::uint64_t get_bits(const Words& words, int lsb, int width) {
  using bit_field_detail::u128;
  const int first = lsb / 32, last = (lsb + width - 1) / 32;
  u128 v = 0;
  for (int k = first; k <= last; ++k) v |= u128{static_cast<std::uint32_t>(words[k])} << (32 * (k - first));
  return static_cast<std::uint64_t>((v >> (lsb % 32)) & bit_field_detail::low_mask(width));
}

// The same field read as a two's complement number, sign-extended from bit lsb + width - 1.
template <class Words>
i64 get_signed(const Words& words, int lsb, int width) {
  return wrap_signed(static_cast<i128>(get_bits(words, lsb, width)), width);
}

}  // namespace watkins::tb
