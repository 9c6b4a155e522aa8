// Twin of rtl/edge_incrementer.sv: steps one active edge to the next scan line by adding each
// channel's slope (Watkins: "for the next scan line it is sufficient to add the slope"); at
// edge order 3 (ChannelFormats::edge_order, the RTL's EdgeOrder) it steps a cubic by forward
// differences instead: value += d1, d1 += d2, d2 += d3, all from the old values, each wrapping.
//
// Widths from the configuration (config.hpp), as the RTL takes them (XBits, ZBits, AttrBits):
//   value_o[c], slope_i[c]   ChannelFormats::bits[c] (slot c's word: X, Z, R|Nx, G|Ny, B|Nz);
//   (order 3: d2, d3 too)    the sum keeps the low bits[c] bits (wrap_signed below)
//   remaining                LineBits (not configurable)
#pragma once

#include <array>
#include <cstdint>

#include "config.hpp"
#include "edge_record.hpp"

namespace watkins {

struct ActiveEdge {
  EdgeRecord rec;     // rec.value holds the edge's values on the current scan line
  int remaining = 0;  // scan lines left including the current one
};

struct EdgeIncrementer {
  // Slot c's sign bit 2^(bits[c]-1), the word wrap_to_sign keeps: worked out once per list.
  using Signs = std::array<i64, fmt::NumChannels>;
  static Signs signs(const ChannelFormats& f) {
    Signs s{};
    for (int c = 0; c < fmt::NumChannels; ++c) s[c] = i64{1} << (f.bits[c] - 1);
    return s;
  }
  // One scan line at edge order Order (1 or 3): value += slope in every channel, wrapping like
  // a register of the channel's width. A slope wrapped to the word steps the same values
  // (addition modulo 2^bits), so only the values must fit; scene preparation checks that they
  // do. The order is a template parameter: a list steps every edge at its configuration's.
  template <int Order>
  static void step(ActiveEdge& e, const Signs& sign) {
    static_assert(Order == 1 || Order == 3, "edge order 1 or 3");
    // Modulo 2^64 (unsigned, so defined for any slope), then the word's low bits: the same as
    // the 128-bit sum wrapped, since a word is at most 62 bits.
    auto add = [](i64 a, i64 b, i64 sign_bit) {
      return wrap_to_sign(static_cast<i64>(static_cast<std::uint64_t>(a) + static_cast<std::uint64_t>(b)), sign_bit);
    };
    for (int c = 0; c < fmt::NumChannels; ++c) {
      e.rec.value[c] = add(e.rec.value[c], e.rec.slope[c], sign[c]);
      if (Order == 3) {
        e.rec.slope[c] = add(e.rec.slope[c], e.rec.d2[c], sign[c]);
        e.rec.d2[c] = add(e.rec.d2[c], e.rec.d3[c], sign[c]);
      }
    }
    --e.remaining;
  }
  // k scan lines at once (k >= 0): the edge as k calls of step<Order> leave it, each word
  // computed directly. Straight: value + k·slope. Cubic (forward differences advanced k steps):
  // value + k·d1 + C(k,2)·d2 + C(k,3)·d3, d1 + k·d2 + C(k,2)·d3, d2 + k·d3. Every word is a sum of
  // products modulo 2^64 (unsigned), then wrapped to its slot: the same low bits as k wrapped
  // additions, since a wrap keeps the sum modulo 2^bits and bits <= 62.
  template <int Order>
  static void step_lines(ActiveEdge& e, int k, const Signs& sign) {
    static_assert(Order == 1 || Order == 3, "edge order 1 or 3");
    using u64 = std::uint64_t;
    const u64 k1 = static_cast<u64>(k), k2 = k1 * (k1 - 1) / 2, k3 = k2 * (k1 - 2) / 3;  // C(k,2), C(k,3) exactly
    for (int c = 0; c < fmt::NumChannels; ++c) {
      const u64 v = static_cast<u64>(e.rec.value[c]), d1 = static_cast<u64>(e.rec.slope[c]);
      if (Order == 1) {
        e.rec.value[c] = wrap_to_sign(static_cast<i64>(v + k1 * d1), sign[c]);
      } else {
        const u64 d2 = static_cast<u64>(e.rec.d2[c]), d3 = static_cast<u64>(e.rec.d3[c]);
        e.rec.value[c] = wrap_to_sign(static_cast<i64>(v + k1 * d1 + k2 * d2 + k3 * d3), sign[c]);
        e.rec.slope[c] = wrap_to_sign(static_cast<i64>(d1 + k1 * d2 + k2 * d3), sign[c]);
        e.rec.d2[c] = wrap_to_sign(static_cast<i64>(d2 + k1 * d3), sign[c]);
      }
    }
    e.remaining -= k;
  }
  // The same for one edge of the configuration f (its widths and edge order).
  static void step(ActiveEdge& e, const ChannelFormats& f) {
    if (f.edge_order == 3)
      step<3>(e, signs(f));
    else
      step<1>(e, signs(f));
  }
  // The default configuration (formats.hpp's ChannelBits words).
  static void step(ActiveEdge& e) { step(e, Config{}.channels(ShadingMode::Gouraud)); }
};

}  // namespace watkins
