// A fixed-point model of the Newton option for stepping curved edges in hardware, to measure it
// against the double Newton of whitted_edges.hpp; not a twin of any RTL (the
// pipeline steps curves by forward differences: docs/reference/whitted.md). Per y-monotonic piece the
// preparation would hand the hardware Whitted's screen-space cubics in s in [0, 1] over the piece
// (here the Hermite of the exact projected edge's end values and slopes) for y, x, depth and the
// three normal components; per scan line the hardware does ONE Newton iteration from the
// first-order estimate, with the divide as an N-bit reciprocal:
//   r = recip(y'(s_e)),  s = s_e - (y(s_e) - y_n) r,  then x, depth, normal at s,
//   next estimate s_e' = s + r (consecutive lines are 1 px apart: no multiply).
// Multipliers per edge per line: y 3 + y' 2 + the step 1 + x 3 + depth 3 + normal 9 = 21, and one
// reciprocal unit (the first line's s and r come from the preparation, as an edge record's do).
#pragma once

#include "whitted_edges.hpp"

namespace watkins {

struct FixedNewtonFormat {
  int s_frac = 24;      // fraction bits of the parameter s
  int value_frac = 16;  // fraction bits of y, x and of the cubics' coefficients (pixels)
  int recip_bits = 12;  // significant bits of the reciprocal 1 / y'
};

struct FixedNewtonError {
  long long lines = 0;
  double max_x = 0, mean_x = 0;            // |x_fixed - x_double| in px over the piece's lines
  double max_y = 0;                        // |y_cubic(s_fixed) - y_n|: what one iteration leaves
  double max_x_cubic = 0;                  // the cubic fit alone: x of the cubic's exact root vs double
  double max_x_step = 0, mean_x_step = 0;  // the stepping alone: x_fixed vs x of the cubic's exact root
  long long step_over_16th = 0;            // lines where the stepping alone is off by more than 1/16 px
  static constexpr int multipliers = 21;   // per edge per line (see above), plus one reciprocal
  void add(const FixedNewtonError& o);
};

// The fixed-point Newton's crossings of `piece` (made by scan_edge on patch f), against its double ones.
FixedNewtonError fixed_newton_error(const PatchPoint& f, const Projection& proj, const EdgePiece& piece,
                                    const FixedNewtonFormat& fmt);

}  // namespace watkins
