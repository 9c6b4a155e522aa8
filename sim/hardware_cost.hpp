// Storage cost of a configuration beyond its edge record (Config::edge_record_bits), shared by
// watkins sweep and watkins size so both count the same bits.
#pragma once

#include "config.hpp"
#include "formats.hpp"

namespace watkins {

// The ping-pong scan-line buffer rtl/scanline_buffer.sv holds (one line filled while the other is
// read out): two banks of max_width pixels, each a depth word of depth_bits, the winning polygon's
// id (id_bits(max_polygons), for the equal-depth rule by submission order) and 8-bit R, G, B.
inline long long line_buffer_bits(const Config& c) {
  return 2LL * c.max_width * (c.depth_bits + id_bits(c.max_polygons) + 3 * fmt::ShadeBits);
}

}  // namespace watkins
