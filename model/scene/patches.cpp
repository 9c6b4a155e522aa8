// Bicubic patches in Bezier form: evaluation, exact normals with their limits, the uniform
// B-spline basis change.
#include "patches.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <glm/geometric.hpp>

namespace watkins {
namespace {

void bernstein(double t, double b[4], double db[4]) {
  double u = 1 - t;
  b[0] = u * u * u; b[1] = 3 * t * u * u; b[2] = 3 * t * t * u; b[3] = t * t * t;
  db[0] = -3 * u * u; db[1] = 3 * u * u - 6 * t * u; db[2] = 6 * t * u - 3 * t * t; db[3] = 3 * t * t;
}

// d2P/dsdt at (s, t): the first-order term of a partial that vanishes along a collapsed boundary.
glm::dvec3 twist(const BicubicPatch& cp, double s, double t) {
  double bs[4], dbs[4], bt[4], dbt[4];
  bernstein(s, bs, dbs);
  bernstein(t, bt, dbt);
  glm::dvec3 st(0.0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) st += dbt[i] * dbs[j] * cp[std::size_t(4 * i + j)];
  return st;
}

// One direction of the basis change on a row of `n` B-spline points (stride apart from `first`):
// the Bezier points of its segments, 3 per segment and the last end, the ends shared by
// neighbouring segments. Segment k uses P[k..k+3] (indices mod n when closed).
std::vector<glm::dvec3> bspline_row(const std::vector<glm::dvec3>& in, std::size_t first, std::size_t stride, int n,
                                    bool closed) {
  const int segments = closed ? n : n - 3;
  auto P = [&](int k) { return in[first + stride * std::size_t(closed ? k % n : k)]; };
  std::vector<glm::dvec3> out(std::size_t(3 * segments + 1));
  for (int k = 0; k <= segments; ++k) {
    // The joint between segments k - 1 and k: one expression, so both see the same doubles (and
    // a closed row's last joint is its first, k = n giving the same points as k = 0).
    out[std::size_t(3 * k)] = (P(k) + 4.0 * P(k + 1) + P(k + 2)) / 6.0;
    if (k == segments) break;
    out[std::size_t(3 * k + 1)] = (2.0 * P(k + 1) + P(k + 2)) / 3.0;
    out[std::size_t(3 * k + 2)] = (P(k + 1) + 2.0 * P(k + 2)) / 3.0;
  }
  return out;
}

}  // namespace

void bezier_point(const BicubicPatch& cp, double s, double t, glm::dvec3& p, glm::dvec3& ds, glm::dvec3& dt) {
  double bs[4], dbs[4], bt[4], dbt[4];
  bernstein(s, bs, dbs);
  bernstein(t, bt, dbt);
  p = ds = dt = glm::dvec3(0.0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const glm::dvec3& c = cp[std::size_t(4 * i + j)];
      p += bt[i] * bs[j] * c;
      ds += bt[i] * dbs[j] * c;
      dt += dbt[i] * bs[j] * c;
    }
}

glm::dvec3 patch_normal(const BicubicPatch& cp, double s, double t) {
  glm::dvec3 p, ds, dt, q;
  bezier_point(cp, s, t, p, ds, dt);
  glm::dvec3 n = glm::cross(ds, dt);
  const double tiny = 1e-12 * (1 + glm::dot(p, p));
  double size = 0;
  for (const glm::dvec3& c : cp) size = std::max(size, glm::length(c - cp[0]));
  // A boundary whose 4 control points lie within 1 % of the patch's size of each other is drawn as
  // a pole: Newell's lid knob (in freeglut's data) has its top row at 0.002 from the axis, folded
  // on itself, and the exact normal of that fold at the pole's grid vertices points anywhere.
  const auto pole = [&](std::size_t first, std::size_t step) {
    double extent = 0;
    for (std::size_t k = 1; k < 4; ++k) extent = std::max(extent, glm::length(cp[first + k * step] - cp[first]));
    return extent <= 1e-2 * size;
  };
  const bool pole_s = (t == 0 && pole(0, 1)) || (t == 1 && pole(12, 1));  // dP/ds vanishes along it
  const bool pole_t = (s == 0 && pole(0, 4)) || (s == 1 && pole(3, 4));  // dP/dt vanishes along it
  if (!pole_s && !pole_t && glm::length(n) >= tiny) return n;
  // At a pole (or where the normal vanishes along a collapsed boundary): along t = 0 (or 1)
  // dP/ds ~ t d2P/dsdt (or -(1 - t) d2P/dsdt) near the boundary; likewise dP/dt along s = 0 or 1.
  // The cross product with the twist in its place is the normal's limit from inside.
  const double zero = 1e-9 * size;
  const bool flat_s = pole_s || (glm::length(ds) <= zero && glm::length(dt) > zero);
  const bool flat_t = pole_t || (glm::length(dt) <= zero && glm::length(ds) > zero);
  if (flat_s && !flat_t) n = (t < 0.5 ? 1.0 : -1.0) * glm::cross(twist(cp, s, t), dt);
  else if (flat_t && !flat_s) n = (s < 0.5 ? 1.0 : -1.0) * glm::cross(ds, twist(cp, s, t));
  // Otherwise (both partials vanish at a corner, or they are parallel), or if that too vanishes:
  // the cross product a little way inside the patch.
  for (double e = 1e-6; glm::length(n) < tiny && e < 0.1; e *= 10) {
    bezier_point(cp, s + (s < 0.5 ? e : -e), t + (t < 0.5 ? e : -e), q, ds, dt);
    n = glm::cross(ds, dt);
  }
  return glm::length(n) < tiny ? glm::dvec3(0.0) : n;
}

std::vector<BicubicPatch> bspline_patches(const std::vector<glm::dvec3>& net, int rows, int cols, bool closed_u,
                                          bool closed_v) {
  // Along u (each row), then along v (each column of that): a (3 pv + 1) x (3 pu + 1) Bezier net
  // whose 4 x 4 windows 3 apart are the patches.
  const int pu = closed_u ? cols : cols - 3, pv = closed_v ? rows : rows - 3;
  const std::size_t mu = std::size_t(3 * pu + 1), mv = std::size_t(3 * pv + 1);
  std::vector<glm::dvec3> half(std::size_t(rows) * mu), bez(mv * mu);
  for (int r = 0; r < rows; ++r) {
    const std::vector<glm::dvec3> row = bspline_row(net, std::size_t(r) * std::size_t(cols), 1, cols, closed_u);
    std::copy(row.begin(), row.end(), half.begin() + std::ptrdiff_t(std::size_t(r) * mu));
  }
  for (std::size_t c = 0; c < mu; ++c) {
    const std::vector<glm::dvec3> col = bspline_row(half, c, mu, rows, closed_v);
    for (std::size_t r = 0; r < mv; ++r) bez[r * mu + c] = col[r];
  }
  std::vector<BicubicPatch> out;
  for (int a = 0; a < pv; ++a)
    for (int b = 0; b < pu; ++b) {
      BicubicPatch p;
      for (std::size_t r = 0; r < 4; ++r)
        for (std::size_t c = 0; c < 4; ++c) p[4 * r + c] = bez[(std::size_t(3 * a) + r) * mu + std::size_t(3 * b) + c];
      out.push_back(p);
    }
  return out;
}

}  // namespace watkins
