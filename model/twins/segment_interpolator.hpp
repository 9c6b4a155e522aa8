// Twin of rtl/segment_interpolator.sv. Span setup for one segment E..F, then one fragment per
// pixel by α stepping: each channel's per-pixel step ΔS/Δx comes from the span reciprocal, and
// the first pixel centre right of X_E gets its value by direct interpolation with
// α0 = (x_c − X_E)/(X_F − X_E) (the sub-pixel prestep, which also absorbs clipping at x = 0).
// Pixels covered: centres x + 1/2 in [X_E, X_F), clipped to [0, width).
#pragma once

#include <array>
#include <cstdint>

#include "segment_former.hpp"
#include "span_reciprocal.hpp"

namespace watkins {

// A fragment leaving the interpolator: one pixel of one segment.
// Both readings of the attribute channels are produced; each pipeline uses one of them.
struct Fragment {
  int x = 0;
  std::uint32_t depth = 0;  // DepthBits, smaller is nearer
  std::uint8_t rgb[3] = {0, 0, 0};  // Gouraud: clamp(round(channel), 0, 255)
  std::array<i64, 3> normal{};      // Phong: saturate(channel, NormalInBits), FracBits fraction
  int poly = 0;
  int material = 0;
};

struct SpanSetup {
  int x_start = 0, x_end = 0;  // pixels [x_start, x_end); empty when x_end <= x_start
  int poly = 0;
  int material = 0;
  ChannelVector value{};       // channel values at pixel x_start (X unused)
  ChannelVector step{};        // per-pixel increments (X unused)
};

struct SegmentInterpolator {
  static SpanSetup setup(const Segment& s, int width);
  // Fragment at pixel x_start + k of a span whose values have been stepped k times.
  static Fragment fragment(const SpanSetup& span, int x, const ChannelVector& value);
  // One α step: value += step in every interpolated channel.
  static void step(const SpanSetup& span, ChannelVector& value);
};

}  // namespace watkins
