// The edge record: the hardware boundary between scene preparation (software) and the
// pipeline. Gouraud 1971 lists what Watkins keeps per edge — first scan line, number of scan
// lines, X and Z at the highest point and their slopes — plus the shade S and its slope
// ΔS = (S2 − S1)/n. We keep a channel vector instead of named fields so the same record carries
// X, Z and R, G, B (Gouraud) or Nx, Ny, Nz (Phong). rtl/watkins_pkg.sv has the same layout.
//
// Widths from the configuration (config.hpp, Config::edge_record_bits): value[c] and slope[c]
// are ChannelFormats::bits[c] wide in the RTL's edge_t (X, depth, then shade or normal by the
// top's Phong parameter), poly clog2(max_polygons), material clog2(max_materials); y0 and n
// LineBits. Here every channel is held in an i64, already wrapped to its slot's width.
// Curved edges (Config::edge_order 3, Whitted 1978): the channel is a cubic in the scan-line
// index, stepped by forward differences: slope is d1, and d2, d3 follow it in the record
// (watkins_pkg::edge_bits, model/twins/edge_packing.hpp); a straight edge has d2 = d3 = 0, and an
// order-1 record carries neither.
#pragma once

#include <array>
#include <cstdint>

#include "fixed_point.hpp"
#include "formats.hpp"

namespace watkins {

using ChannelVector = std::array<i64, fmt::NumChannels>;  // each a ChannelBits-bit signed word

struct EdgeRecord {
  int y0 = 0;          // first scan line whose pixel centre the edge crosses (already clipped to >= 0)
  int n = 0;           // number of scan lines it crosses (>= 1; clipped to the screen)
  int poly = 0;        // polygon id (PolyIdBits): segments pair the edges of one polygon
  int material = 0;    // material id (MaterialIdBits) of the polygon; Phong shades with it
  int id = 0;          // position in the y-sorted stream; breaks ties in X order deterministically
  ChannelVector value{};  // channel values at the centre of scan line y0 (prestepped)
  ChannelVector slope{};  // per-scan-line increments, rounded to nearest (d1 at order 3)
  ChannelVector d2{};     // order 3: second and third forward differences (0 on straight edges)
  ChannelVector d3{};
};

}  // namespace watkins
