// Whitted's curved edges for the forward-difference edge incrementer (Config::edge_order 3):
// scene preparation turns each y-monotonic screen curve (ScreenCurve: its double crossing of
// every scan line) into edge records whose channels are cubics in the scan-line index. Per
// channel the record carries the value on its first line and the forward differences d1, d2, d3;
// the incrementer steps value += d1, d1 += d2, d2 += d3, so on line k of the record the hardware
// holds exactly v0 + d1·C(k,1) + d2·C(k,2) + d3·C(k,3) (modulo the slot's word).
//
// The fit: every line's crossing is quantized to the slot formats (X to the X word's fraction
// bits, depth, shade and normal as quantize_vertex quantizes a vertex); a run of lines is fitted
// by least squares in that binomial basis, rounding the coefficients from d3 down and refitting
// the lower ones to what is left, so each rounding is absorbed by the coefficients below it.
// The integer accumulation is then evaluated exactly on every line of the run and compared with
// the quantized crossings; the run is the longest from its first line whose every line is within
// the bound (CurveFitBounds) in every channel. A run of at most four lines interpolates its
// quantized crossings exactly (integer differences), so a fit always exists. The pieces of one
// curve cover consecutive lines: one piece of a curve is active on any line.
#pragma once

#include <array>
#include <vector>

#include "config.hpp"
#include "edge_record.hpp"
#include "screen_curve.hpp"

namespace watkins {

// The largest difference allowed between the hardware's value and the quantized crossing on any
// line, per channel group, in the group's own unit; converted to the slot's least significant
// bits by rounding down (a fraction too coarse for the bound asks for exactness).
struct CurveFitBounds {
  double x = 1.0 / 16;          // pixels
  double depth = 1.0 / 65536;   // of the depth range [0, 1) (256 steps of a 24-bit depth)
  double shade = 1.0 / 8;       // 8-bit levels
  double normal = 1.0 / 2048;   // units of 1.0
  // The bound of each slot of `formats` (shade or normal in slots 2..4 by `shading`), in LSBs.
  std::array<i64, fmt::NumChannels> lsb(const ChannelFormats& formats, ShadingMode shading) const;
};

// One curve's edge records and what the fit measured.
struct CurveEdges {
  std::vector<EdgeRecord> records;  // y0, n, value, slope (d1), d2, d3 (wrapped to the words); poly,
                                    // material and id are the caller's
  std::vector<ChannelVector> quantized;  // the quantized crossing of every line kept (on screen)
  int first_line = 0;                    // the line of quantized[0]
  // Largest |hardware − quantized| over the lines, per slot, in LSBs (<= the bound).
  std::array<i64, fmt::NumChannels> max_error{};
  // Signed bits of the values the hardware holds on every line (exact, before any wrap).
  std::array<int, fmt::NumChannels> value_bits{};
};

// The quantized crossing of one line (its vertex's channels in the slot formats; X at the X
// word's fraction bits). Throws SceneError when a value is out of range.
ChannelVector quantize_crossing(const ScreenVertex& v, int line, ShadingMode shading, const Config& config);

// The records of `curve` for a screen of `height` lines (lines at and below it are dropped; no
// record when none is left). Throws SceneError for out-of-range crossings.
CurveEdges fit_curve(const ScreenCurve& curve, int height, ShadingMode shading, const Config& config,
                     const CurveFitBounds& bounds = {});

// The value an order-3 record's channel holds on its line k: v0 + d1·C(k,1) + d2·C(k,2) +
// d3·C(k,3) wrapped to the `bits`-bit word (what k steps of the incrementer give, in closed form).
i64 forward_difference_value(const EdgeRecord& e, int channel, int k, int bits);

}  // namespace watkins
