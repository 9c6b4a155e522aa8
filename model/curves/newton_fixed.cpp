#include "newton_fixed.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace watkins {

void FixedNewtonError::add(const FixedNewtonError& o) {
  const long long n = lines + o.lines;
  if (n) mean_x = (mean_x * double(lines) + o.mean_x * double(o.lines)) / double(n);
  if (n) mean_x_step = (mean_x_step * double(lines) + o.mean_x_step * double(o.lines)) / double(n);
  max_x_step = std::max(max_x_step, o.max_x_step);
  step_over_16th += o.step_over_16th;
  lines = n;
  max_x = std::max(max_x, o.max_x);
  max_y = std::max(max_y, o.max_y);
  max_x_cubic = std::max(max_x_cubic, o.max_x_cubic);
}

namespace {

// A cubic c0 + c1 s + c2 s^2 + c3 s^3 with its coefficients in units of 2^-value_frac.
struct FixedCubic {
  std::int64_t c[4];
  double real[4];  // the unquantized coefficients (for the fit's own error)
};

// v / 2^sh rounded half up, without shifting a negative number.
std::int64_t round_shift(__int128 v, int sh) {
  const __int128 q = v + (__int128(1) << (sh - 1)), one = __int128(1) << sh;
  return std::int64_t(q >= 0 ? q / one : -((-q + one - 1) / one));
}

FixedCubic hermite(double v0, double v1, double d0, double d1, int frac) {
  FixedCubic q;
  q.real[0] = v0, q.real[1] = d0, q.real[2] = 3 * (v1 - v0) - 2 * d0 - d1, q.real[3] = 2 * (v0 - v1) + d0 + d1;
  for (int k = 0; k < 4; ++k) q.c[k] = std::llround(std::ldexp(q.real[k], frac));
  return q;
}

// Horner in fixed point: every product rounded back to the value format (s has s_frac bits).
std::int64_t value(const FixedCubic& q, std::int64_t s, int s_frac) {
  std::int64_t acc = q.c[3];
  for (int k = 2; k >= 0; --k) acc = round_shift(__int128(acc) * s, s_frac) + q.c[k];
  return acc;
}

std::int64_t slope(const FixedCubic& q, std::int64_t s, int s_frac) {
  std::int64_t acc = 3 * q.c[3];
  acc = round_shift(__int128(acc) * s, s_frac) + 2 * q.c[2];
  return round_shift(__int128(acc) * s, s_frac) + q.c[1];
}

double real_value(const FixedCubic& q, double s) { return ((q.real[3] * s + q.real[2]) * s + q.real[1]) * s + q.real[0]; }

// 1 / d rounded to `bits` significant bits (a normalizing reciprocal unit), as a double.
double recip(double d, int bits) {
  if (d == 0) return 0;
  int e;
  const double m = std::frexp(1.0 / d, &e);
  return std::ldexp(std::round(std::ldexp(m, bits)), e - bits);
}

}  // namespace

FixedNewtonError fixed_newton_error(const PatchPoint& f, const Projection& proj, const EdgePiece& piece,
                                    const FixedNewtonFormat& fmt) {
  FixedNewtonError err;
  if (piece.lines.empty()) return err;
  const ParamCurve& c = piece.curve;
  const double dt = piece.t_end - piece.t_top;
  // End values and slopes (per unit s) of the exact projected edge.
  auto ends = [&](double t, double& x, double& y, double& dx, double& dy) {
    const glm::dvec2 uv = c.at(t), d = c.derivative(t);
    glm::dvec3 p, pu, pv;
    f(uv.x, uv.y, p, pu, pv);
    const glm::dvec3 dp = (pu * d.x + pv * d.y) * dt;
    const double k = proj.focal * proj.half_w;
    x = proj.x(p), y = proj.y(p);
    dx = k * (dp.x * p.z - p.x * dp.z) / (p.z * p.z);
    dy = -k * (dp.y * p.z - p.y * dp.z) / (p.z * p.z);
  };
  double x0, y0, dx0, dy0, x1, y1, dx1, dy1;
  ends(piece.t_top, x0, y0, dx0, dy0);
  ends(piece.t_end, x1, y1, dx1, dy1);
  const FixedCubic qy = hermite(y0, y1, dy0, dy1, fmt.value_frac), qx = hermite(x0, x1, dx0, dx1, fmt.value_frac);
  const double one_s = std::ldexp(1.0, fmt.s_frac), one_v = std::ldexp(1.0, fmt.value_frac);
  const std::int64_t s_max = std::int64_t(one_s);
  // The preparation's start: s and 1 / y' at the first line.
  double s_first = (piece.lines[0].t - piece.t_top) / dt;
  std::int64_t s = std::llround(s_first * one_s);
  double r = recip(double(slope(qy, s, fmt.s_frac)) / one_v, fmt.recip_bits);
  double sum = 0, step_sum = 0;
  for (std::size_t k = 0; k < piece.lines.size(); ++k) {
    const double target = piece.y0 + int(k) + 0.5;
    if (k > 0) {
      // One iteration from the estimate s_e = s + r (in s units).
      const std::int64_t se = std::clamp<std::int64_t>(s + std::llround(r * one_s), 0, s_max);
      const std::int64_t ye = value(qy, se, fmt.s_frac);
      r = recip(double(slope(qy, se, fmt.s_frac)) / one_v, fmt.recip_bits);
      const std::int64_t target_q = std::llround(target * one_v);
      s = std::clamp<std::int64_t>(se - std::llround(double(ye - target_q) / one_v * r * one_s), 0, s_max);
    }
    const double xq = double(value(qx, s, fmt.s_frac)) / one_v;
    const double ex = std::fabs(xq - piece.lines[k].x);
    err.max_x = std::max(err.max_x, ex);
    sum += ex;
    err.max_y = std::max(err.max_y, std::fabs(real_value(qy, double(s) / one_s) - target));
    // The cubic's own root (bisection in double) and its x: the fit's error apart from stepping.
    double a = 0, b = 1;
    const bool up = real_value(qy, 1) > real_value(qy, 0);
    for (int it = 0; it < 80; ++it) {
      const double m = 0.5 * (a + b);
      ((real_value(qy, m) < target) == up ? a : b) = m;
    }
    const double x_root = real_value(qx, 0.5 * (a + b));
    err.max_x_cubic = std::max(err.max_x_cubic, std::fabs(x_root - piece.lines[k].x));
    err.max_x_step = std::max(err.max_x_step, std::fabs(xq - x_root));
    step_sum += std::fabs(xq - x_root);
    err.step_over_16th += std::fabs(xq - x_root) > 1.0 / 16;
    ++err.lines;
  }
  err.mean_x = sum / double(err.lines);
  err.mean_x_step = step_sum / double(err.lines);
  return err;
}

}  // namespace watkins
