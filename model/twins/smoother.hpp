// Twin of rtl/smoother.sv: Herman & Liu's image-space smoothing (1978), a 3x3 weighted mean per
// channel on the finished frame, after the scanline buffer:
//   G1' = (G1 + W·Σ_{edges} f_i·G_i + W²·Σ_{corners} f_i·G_i) / (1 + W·Σ_{edges} f_i + W²·Σ_{corners} f_i)
// G2..G5 the four edge neighbours, G6..G9 the four corners; f_i = 1 when the neighbour is on the
// screen and covered (on the object), else 0. A pixel no polygon covers keeps its background and
// is not smoothed. W is the frame's weight, unsigned with SmoothWFracBits fraction bits (w = W ·
// 2^F, F = SmoothWFracBits, w < 2^SmoothWBits); w = 0 is the identity exactly (d = 2^2F).
//
// Arithmetic, all integer: numerator n = 2^2F·G1 + 2^F·w·S_edge + w²·S_corner, denominator
// d = 2^2F + 2^F·w·n_edge + w²·n_corner (n_edge, n_corner in 0..4), and the result is the exact
// quotient rounded half up, q = floor((2n + d) / 2d): error <= 1/2 level against the real-valued
// mean, 0 against exact division (round_div, fixed_point.hpp). q <= 255 because n <= 255·d, so
// 2n + d < 256·2d: the RTL finds q's 8 bits with a pipelined restoring divider (8 compare-subtract stages per channel).
// Why a divider and not a per-frame table of the 25 reciprocals 1/d: an exact rounded quotient
// from a reciprocal needs one about as wide as the dividend plus the divisor (≈ 47 bits here),
// a wide multiplier per channel, and either a table-load path from preparation software or a
// sequential unit that costs cycles at frame start; the divider needs neither, starts on the
// frame's first pixel, and its 3 × 8 subtractors (≤ 28 bits) use no multiplier blocks.
#pragma once

#include <array>
#include <cstdint>

#include "fixed_point.hpp"
#include "formats.hpp"
#include "image.hpp"

namespace watkins {

class Smoother {
 public:
  // w: W · 2^SmoothWFracBits, 0 .. 2^SmoothWBits - 1 (masked to SmoothWBits, as the pin is).
  explicit Smoother(int w) : w_(w & ((1 << fmt::SmoothWBits) - 1)) {}

  // The smoothed shade of pixel (x, y) of `in` (its own shade when it is not covered).
  std::array<std::uint8_t, 3> pixel(const Image& in, int x, int y) const;
  // The whole frame: shades smoothed, coverage and owners kept. w = 0 returns `in` unchanged.
  Image apply(const Image& in) const;

  // The denominator for n_edge edge and n_corner corner neighbours on the object.
  std::int64_t denominator(int n_edge, int n_corner) const {
    const std::int64_t one = std::int64_t{1} << fmt::SmoothWFracBits;
    return one * one + one * w_ * n_edge + std::int64_t{w_} * w_ * n_corner;
  }

 private:
  int w_;
};

}  // namespace watkins
