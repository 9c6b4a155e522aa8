// Twin of rtl/edge_incrementer.sv: steps one active edge to the next scan line by adding each
// channel's slope (Watkins: "for the next scan line it is sufficient to add the slope").
#pragma once

#include "edge_record.hpp"

namespace watkins {

struct ActiveEdge {
  EdgeRecord rec;     // rec.value holds the edge's values on the current scan line
  int remaining = 0;  // scan lines left including the current one
};

struct EdgeIncrementer {
  // One scan line: value += slope in every channel, wrapping like a ChannelBits register.
  static void step(ActiveEdge& e) {
    for (int c = 0; c < fmt::NumChannels; ++c)
      e.rec.value[c] = wrap_signed(static_cast<i128>(e.rec.value[c]) + e.rec.slope[c],
                                   fmt::ChannelBits);
    --e.remaining;
  }
};

}  // namespace watkins
