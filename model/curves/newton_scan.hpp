// Whitted's intersection processor for one y-monotonic edge piece: the parameter t of its
// crossing of every scan line it spans, by Newton's iteration on E_y(t) = y_n started from the
// previous line's solution with his first-order estimate t_{n+1} = t_n - (y_n - y_{n+1}) / E'_y(t_n),
// and a brute-force search (bisection on the monotonic piece) when an iterate leaves the piece or
// Newton does not converge. Double precision: the reference the hardware's stepping is measured by.
#pragma once

#include <functional>
#include <vector>

namespace watkins {

struct NewtonStats {
  long long crossings = 0;        // scan-line crossings found
  long long by_newton = 0;        // of which Newton converged (the others: brute force)
  long long iterations = 0;       // Newton iterations over those (the first-order estimate is not one)
  long long zero_iterations = 0;  // the estimate alone was within the tolerance
  long long one_iteration = 0;    // converged after one iteration (Whitted: "usually in the first")
  long long left_piece = 0;       // brute force because an iterate left the piece (or was not finite)
  long long no_convergence = 0;   // brute force because the iteration limit was reached
  int max_iterations = 0;
  // |E_y(t) - y_n| in pixels, largest over the crossings after a piece's first (those step from
  // the previous line; the first starts from the end point): of the first-order estimate alone,
  // and after exactly one Newton iteration (what hardware doing one iteration per line would leave).
  double max_estimate_residual = 0, max_one_iteration_residual = 0;
  long long stepped = 0;              // crossings after a piece's first, where Newton ran
  long long one_iteration_close = 0;  // of which within 1/1024 px after one iteration (or none)
  long long brute_force() const { return crossings - by_newton; }
  double mean_iterations() const { return by_newton ? double(iterations) / double(by_newton) : 0.0; }
  void add(const NewtonStats& o);
};

struct NewtonOptions {
  double tolerance = 5e-10;  // |E_y(t) - y_n| in pixels at which a crossing is accepted
  int max_iterations = 8;
};

// E_y and dE_y/dt at t.
using EdgeY = std::function<void(double t, double& y, double& dy)>;

// Crossings of the piece t in [t_top, t_end] (either order; E_y(t_top) <= E_y(t_end), monotonic
// between) with the scan lines n, y_n = n + 0.5, that the polygon edges' half-open rule gives it:
// E_y(t_top) <= y_n < E_y(t_end), clipped to line_lo <= n < line_hi. Returns t per line from
// first_line on (empty when it crosses none). The iteration starts from the top end point as
// "line n" of the first crossing. An iterate is kept inside the piece, not [0, 1]: beyond its
// end the same E_y value is met again on the next piece.
std::vector<double> scan_line_crossings(const EdgeY& ey, double t_top, double t_end, int line_lo, int line_hi,
                                        int& first_line, NewtonStats& stats, const NewtonOptions& opt = {});

}  // namespace watkins
