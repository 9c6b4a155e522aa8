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

#include <cstdint>

#include "config.hpp"
#include "edge_record.hpp"

namespace watkins {

struct ActiveEdge {
  EdgeRecord rec;     // rec.value holds the edge's values on the current scan line
  int remaining = 0;  // scan lines left including the current one
};

struct EdgeIncrementer {
  // One scan line: value += slope in every channel, wrapping like a register of the channel's
  // width. A slope wrapped to the word steps the same values (addition modulo 2^bits), so only
  // the values must fit; scene preparation checks that they do.
  static void step(ActiveEdge& e, const ChannelFormats& f) {
    // Modulo 2^64 (unsigned, so defined for any slope), then the word's low bits: the same as
    // the 128-bit sum wrapped, since a word is at most 62 bits.
    auto add = [](i64 a, i64 b, int bits) {
      return wrap_signed64(static_cast<i64>(static_cast<std::uint64_t>(a) + static_cast<std::uint64_t>(b)), bits);
    };
    for (int c = 0; c < fmt::NumChannels; ++c) {
      e.rec.value[c] = add(e.rec.value[c], e.rec.slope[c], f.bits[c]);
      if (f.edge_order == 3) {
        e.rec.slope[c] = add(e.rec.slope[c], e.rec.d2[c], f.bits[c]);
        e.rec.d2[c] = add(e.rec.d2[c], e.rec.d3[c], f.bits[c]);
      }
    }
    --e.remaining;
  }
  // The default configuration (today's ChannelBits words).
  static void step(ActiveEdge& e) { step(e, Config{}.channels(ShadingMode::Gouraud)); }
};

}  // namespace watkins
