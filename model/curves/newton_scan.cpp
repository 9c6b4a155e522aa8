#include "newton_scan.hpp"

#include <algorithm>
#include <cmath>

namespace watkins {

void NewtonStats::add(const NewtonStats& o) {
  crossings += o.crossings;
  by_newton += o.by_newton;
  iterations += o.iterations;
  zero_iterations += o.zero_iterations;
  one_iteration += o.one_iteration;
  left_piece += o.left_piece;
  no_convergence += o.no_convergence;
  max_iterations = std::max(max_iterations, o.max_iterations);
  stepped += o.stepped;
  one_iteration_close += o.one_iteration_close;
  max_estimate_residual = std::max(max_estimate_residual, o.max_estimate_residual);
  max_one_iteration_residual = std::max(max_one_iteration_residual, o.max_one_iteration_residual);
}

namespace {

// Bisection on the monotonic piece: E_y(a) <= y < E_y(b) brackets the crossing (a, b in either
// order). Stops at the tolerance or when the bracket cannot shrink further in double.
double bisect(const EdgeY& ey, double a, double b, double target, double tol) {
  double m = a;
  for (int k = 0; k < 200; ++k) {
    m = 0.5 * (a + b);
    if (m == a || m == b) break;
    double y, dy;
    ey(m, y, dy);
    if (std::fabs(y - target) < tol) break;
    (y <= target ? a : b) = m;
  }
  return m;
}

}  // namespace

std::vector<double> scan_line_crossings(const EdgeY& ey, double t_top, double t_end, int line_lo, int line_hi,
                                        int& first_line, NewtonStats& stats, const NewtonOptions& opt) {
  std::vector<double> out;
  double y_top, d_top, y_end, d_end;
  ey(t_top, y_top, d_top);
  ey(t_end, y_end, d_end);
  // The same lines a polygon edge from y_top to y_end covers (float_reference's rule).
  const int n0 = std::max(line_lo, int(std::ceil(y_top - 0.5)));
  const int n1 = std::min(line_hi, int(std::ceil(y_end - 0.5)));
  first_line = n0;
  if (n0 >= n1) return out;
  const double lo = std::min(t_top, t_end), hi = std::max(t_top, t_end);
  double t = t_top, y = y_top, dy = d_top;  // the previous line's solution
  out.reserve(std::size_t(n1 - n0));
  for (int n = n0; n < n1; ++n) {
    const double target = n + 0.5;
    double tn = t - (y - target) / dy;  // first-order estimate from the previous line
    int it = 0;
    bool converged = false, left = false;
    for (;;) {
      if (!(tn >= lo && tn <= hi)) {  // also NaN and infinity (E'_y = 0 at an extremum)
        left = true;
        break;
      }
      ey(tn, y, dy);
      if (it <= 1 && n > n0) {  // stepping from line to line (the first line starts at the end point)
        double& worst = it == 0 ? stats.max_estimate_residual : stats.max_one_iteration_residual;
        worst = std::max(worst, std::fabs(y - target));
        if (it == 0) ++stats.stepped;
        // Within 1/1024 px after at most one iteration: as good as any fixed-point X word needs.
        if (std::fabs(y - target) < 1.0 / 1024 && (it == 1 || std::fabs(y - target) < opt.tolerance))
          ++stats.one_iteration_close;
      }
      if (std::fabs(y - target) < opt.tolerance) {
        converged = true;
        break;
      }
      if (it == opt.max_iterations) break;
      tn -= (y - target) / dy;
      ++it;
    }
    ++stats.crossings;
    if (converged) {
      ++stats.by_newton;
      stats.iterations += it;
      stats.zero_iterations += it == 0;
      stats.one_iteration += it == 1;
      stats.max_iterations = std::max(stats.max_iterations, it);
    } else {
      ++(left ? stats.left_piece : stats.no_convergence);
      tn = bisect(ey, t_top, t_end, target, opt.tolerance);
      ey(tn, y, dy);
    }
    t = tn;
    out.push_back(tn);
  }
  return out;
}

}  // namespace watkins
