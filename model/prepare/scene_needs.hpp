// What a frame needs from the hardware — capacities and ranges — so the hardware can be sized
// to the scene instead of a worst case. Measured in one place: the active-edge list and the
// widest span by walking the frame with the twins' own front half (model/twins/scan_lines.hpp),
// the value ranges from the edge records.
#pragma once

#include <array>

#include "config.hpp"
#include "edge_record.hpp"
#include "frame.hpp"

namespace watkins {

struct SceneNeeds {
  int polygons = 0;
  int edges = 0;              // edge records after dropping horizontal and off-screen edges
  int max_active_edges = 0;   // largest active-edge list on any scan line
  int max_active_line = -1;   // the scan line where it occurs
  int curve_edges = 0;        // edge records of curved edges (polygon id >= polygons), among `edges`
  int max_curve_edges = 0;    // most curved edges active on one scan line (counted in max_active_edges too)
  int max_curve_line = -1;    // the scan line where it occurs
  int max_edge_lines = 0;     // largest n of an edge record
  int max_segment_pixels = 0; // widest span, in pixels (after clipping to the screen)
  ChannelVector value_min{}, value_max{};  // ranges of edge-record channel values
  ChannelVector slope_min{}, slope_max{};  // and of their per-scan-line slopes
  int bits_for_value(int channel) const;   // signed bits the channel's values and slopes need
  // Signed bits of every value channel c holds in the pipeline: edge values on every scan line
  // and span values on every pixel (exact, before any wrap). Slopes are not counted: a slope
  // wrapped to the word steps the same values (addition modulo 2^bits).
  std::array<int, fmt::NumChannels> value_bits{};
  // Integer bits (sign included) channel c needs at fraction bits `frac`.
  int int_bits_needed(int channel, int frac) const { return value_bits[channel] - frac; }
};

// Measures `frame`, made of `polygons` polygons (edge records with a larger polygon id are
// curved edges), on the pipeline whose channel slots have `formats`.
SceneNeeds measure_needs(const Frame& frame, int polygons, const ChannelFormats& formats);

}  // namespace watkins
