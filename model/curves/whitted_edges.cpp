#include "whitted_edges.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <glm/geometric.hpp>

namespace watkins {

void EdgeStats::add(const EdgeStats& o) {
  newton.add(o.newton);
  cells += o.cells;
  regions += o.regions;
  culled_regions += o.culled_regions;
  silhouettes += o.silhouettes;
  default_one += o.default_one;
  default_many += o.default_many;
  default_side_twice += o.default_side_twice;
  default_inside += o.default_inside;
  pieces += o.pieces;
  y_splits += o.y_splits;
}

glm::dvec2 ParamCurve::at(double t) const {
  if (!hermite) return (1 - t) * a + t * b;  // exactly a at t = 0 and b at t = 1
  // Whitted's p(t) = [t^3 t^2 t 1] M [a b ta tb]^T with M the Hermite matrix.
  const double t2 = t * t, t3 = t2 * t;
  const double h00 = 2 * t3 - 3 * t2 + 1, h01 = -2 * t3 + 3 * t2, h10 = t3 - 2 * t2 + t, h11 = t3 - t2;
  return h00 * a + h01 * b + h10 * ta + h11 * tb;
}

glm::dvec2 ParamCurve::derivative(double t) const {
  if (!hermite) return b - a;
  const double t2 = t * t;
  return (6 * t2 - 6 * t) * a + (-6 * t2 + 6 * t) * b + (3 * t2 - 4 * t + 1) * ta + (3 * t2 - 2 * t) * tb;
}

ParamCurve whitted_silhouette(const glm::dvec2& a, const glm::dvec2& b) {
  ParamCurve c;
  c.kind = EdgeKind::Silhouette;
  c.a = a, c.b = b, c.hermite = true;
  const double du = b.x - a.x, dv = b.y - a.y;
  const double chord = std::sqrt(du * du + dv * dv);
  // |alpha'_u| = 1 / (1 + |dv| / |du|), written |du| / (|du| + |dv|) so du = 0 needs no case.
  const double au1 = std::fabs(du) / (std::fabs(du) + std::fabs(dv));
  const double av1 = 1 - au1;
  const glm::dvec2 alpha(std::copysign(au1 * chord, du), std::copysign(av1 * chord, dv));
  c.ta = c.tb = alpha;  // beta = alpha
  return c;
}

glm::dvec3 unit_normal(const PatchPoint& f, double u, double v, const PatchNormal& given) {
  if (given) {
    const glm::dvec3 n = given(u, v);
    const double len = glm::length(n);
    if (len > 0) return n / len;
  }
  glm::dvec3 p, pu, pv;
  f(u, v, p, pu, pv);
  glm::dvec3 n = glm::cross(pu, pv);
  // A collapsed boundary or a zero partial has no tangent plane there: step towards the patch's
  // centre until the cross product is not negligible (as the tessellation does).
  for (double e = 1e-7; glm::length(n) < 1e-12 * (1 + glm::dot(p, p)) && e < 0.2; e *= 4) {
    glm::dvec3 q;
    f(u + (u < 0.5 ? e : -e), v + (v < 0.5 ? e : -e), q, pu, pv);
    n = glm::cross(pu, pv);
  }
  const double len = glm::length(n);
  return len > 0 ? n / len : glm::dvec3(0, 0, -1);
}

double silhouette_cosine(const PatchPoint& f, double u, double v, const PatchNormal& n) {
  glm::dvec3 p, pu, pv;
  f(u, v, p, pu, pv);
  return glm::dot(unit_normal(f, u, v, n), p / glm::length(p));
}

void ScreenEdge::y(double t, double& y, double& dy) const {
  const glm::dvec2 uv = c_.at(t), d = c_.derivative(t);
  glm::dvec3 p, pu, pv;
  f_(uv.x, uv.y, p, pu, pv);
  const glm::dvec3 dp = pu * d.x + pv * d.y;
  const double k = proj_.focal * proj_.half_w;
  y = proj_.y(p);
  dy = -k * (dp.y * p.z - p.y * dp.z) / (p.z * p.z);
}

namespace {

// Zeros of g on [0, 1] where it changes sign between grid points, refined by bisection to the
// last bit; zeros within 1e-12 of an end are left out (those are the ends themselves).
std::vector<double> sign_changes(const std::function<double(double)>& g, int samples) {
  std::vector<double> out;
  double t0 = 0, g0 = g(0);
  for (int k = 1; k <= samples; ++k) {
    const double t1 = double(k) / samples, g1 = g(t1);
    if ((g0 < 0) != (g1 < 0)) {
      double a = t0, b = t1, ga = g0;
      for (int it = 0; it < 200; ++it) {
        const double m = 0.5 * (a + b);
        if (m == a || m == b) break;
        const double gm = g(m);
        if ((gm < 0) == (ga < 0)) a = m, ga = gm;
        else b = m;
      }
      const double z = 0.5 * (a + b);
      if (z > 1e-12 && z < 1 - 1e-12) out.push_back(z);
    }
    t0 = t1, g0 = g1;
  }
  return out;
}

}  // namespace

// A polynomial sum c[k] t^k.
using Poly = std::vector<double>;

double eval(const Poly& p, double t) {
  double v = 0;
  for (std::size_t k = p.size(); k-- > 0;) v = v * t + p[k];
  return v;
}

Poly derivative(const Poly& p) {
  Poly d;
  for (std::size_t k = 1; k < p.size(); ++k) d.push_back(double(k) * p[k]);
  return d;
}

// The roots of p in (0, 1) where it changes sign, exactly isolated: between consecutive zeros of
// p' (found the same way) p is monotonic, so each interval holds at most one, found by bisection.
// A root of even multiplicity (p touches zero) is no sign change and is left out.
std::vector<double> poly_roots(const Poly& p) {
  std::vector<double> cuts = {0};
  if (p.size() > 2)
    for (double t : poly_roots(derivative(p))) cuts.push_back(t);
  cuts.push_back(1);
  std::vector<double> out;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    double a = cuts[k], b = cuts[k + 1], pa = eval(p, a);
    if ((pa < 0) == (eval(p, b) < 0)) continue;
    for (int it = 0; it < 200; ++it) {
      const double m = 0.5 * (a + b);
      if (m == a || m == b) break;
      const double pm = eval(p, m);
      if ((pm < 0) == (pa < 0)) a = m, pa = pm;
      else b = m;
    }
    const double z = 0.5 * (a + b);
    if (z > 1e-12 && z < 1 - 1e-12) out.push_back(z);
  }
  return out;
}

std::vector<double> ScreenEdge::y_extrema(int samples) const {
  if (!c_.hermite) {
    // An iso-parameter line of a bicubic patch is a cubic in t, and so are its camera-space Y and
    // Z (a linear map): their Hermite form from the end points and end tangents is exact. Then
    // Y' Z - Y Z' is a quartic (the t^5 terms cancel) whose sign changes are the extrema of y_s.
    glm::dvec3 p0, p1, u0, v0, u1, v1;
    f_(c_.a.x, c_.a.y, p0, u0, v0);
    f_(c_.b.x, c_.b.y, p1, u1, v1);
    const glm::dvec2 d = c_.b - c_.a;
    const glm::dvec3 d0 = u0 * d.x + v0 * d.y, d1 = u1 * d.x + v1 * d.y;
    auto cubic = [&](int axis) {
      return Poly{p0[axis], d0[axis], 3 * (p1[axis] - p0[axis]) - 2 * d0[axis] - d1[axis],
                  2 * (p0[axis] - p1[axis]) + d0[axis] + d1[axis]};
    };
    const Poly Y = cubic(1), Z = cubic(2), dY = derivative(Y), dZ = derivative(Z);
    Poly n(5, 0.0);
    for (std::size_t i = 0; i < dY.size(); ++i)
      for (std::size_t j = 0; j < Z.size(); ++j)
        if (i + j < 5) n[i + j] += dY[i] * Z[j] - Y[j] * dZ[i];
    return poly_roots(n);
  }
  // The silhouette's Hermite in (u, v) mapped through the patch is of degree 18 in t: its extrema
  // are bracketed on a grid instead.
  return sign_changes(
      [this](double t) {
        const glm::dvec2 uv = c_.at(t), d = c_.derivative(t);
        glm::dvec3 p, pu, pv;
        f_(uv.x, uv.y, p, pu, pv);
        const glm::dvec3 dp = pu * d.x + pv * d.y;
        return dp.y * p.z - p.y * dp.z;
      },
      samples);
}

std::vector<EdgePiece> scan_edge(const PatchPoint& f, const Projection& proj, const ParamCurve& c, double a, double b,
                                 const WhittedOptions& opt, EdgeStats& stats) {
  const ScreenEdge e(f, proj, c);
  std::vector<double> cuts = {a};
  for (double t : e.y_extrema())
    if (t > a && t < b) cuts.push_back(t), ++stats.y_splits;
  cuts.push_back(b);
  std::vector<EdgePiece> out;
  const EdgeY ey = [&e](double t, double& y, double& dy) { e.y(t, y, dy); };
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    double t_top = cuts[k], t_end = cuts[k + 1], y0, y1, d;
    e.y(t_top, y0, d);
    e.y(t_end, y1, d);
    if (y0 == y1) continue;  // a horizontal piece crosses no scan line by the half-open rule
    if (y0 > y1) std::swap(t_top, t_end);
    EdgePiece piece;
    piece.kind = c.kind;
    piece.curve = c;
    piece.t_top = t_top, piece.t_end = t_end;
    const std::vector<double> ts =
        scan_line_crossings(ey, t_top, t_end, opt.line_lo, opt.line_hi, piece.y0, stats.newton, opt.newton);
    if (ts.empty()) continue;
    for (double t : ts) {
      EdgeCrossing x;
      x.t = t;
      const glm::dvec2 uv = c.at(t);
      glm::dvec3 pu, pv;
      f(uv.x, uv.y, x.p, pu, pv);
      x.x = proj.x(x.p);
      x.y = proj.y(x.p);
      x.normal = unit_normal(f, uv.x, uv.y, opt.normal);
      piece.lines.push_back(x);
    }
    ++stats.pieces;
    out.push_back(std::move(piece));
  }
  return out;
}

namespace {

// A part of a subpatch's boundary: side `side` (canonical orientation) on t in [a, b].
struct SideRange {
  int side;
  double a, b;
};

}  // namespace

PatchEdges describe_patch(const PatchPoint& f, const Projection& proj, const WhittedOptions& opt, EdgeStats& stats) {
  std::vector<double> U = {0}, V = {0};
  for (double k : opt.k_u) U.push_back(k);
  for (double k : opt.k_v) V.push_back(k);
  U.push_back(1), V.push_back(1);
  std::sort(U.begin(), U.end());
  std::sort(V.begin(), V.end());
  const int nu = int(U.size()) - 1, nv = int(V.size()) - 1;
  // Sides in canonical orientation: H(j, i) is v = V[j] from u = U[i] to U[i+1]; V(i, j) is
  // u = U[i] from v = V[j] to V[j+1]. An interior side borders two subpatches: both use it as is.
  const int n_h = (nv + 1) * nu;
  auto h_side = [&](int j, int i) { return j * nu + i; };
  auto v_side = [&](int i, int j) { return n_h + i * nv + j; };
  std::vector<ParamCurve> sides(std::size_t(n_h + (nu + 1) * nv));
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i < nu; ++i) {
      ParamCurve& c = sides[std::size_t(h_side(j, i))];
      c.kind = (j == 0 || j == nv) ? EdgeKind::Boundary : EdgeKind::Interior;
      c.a = {U[std::size_t(i)], V[std::size_t(j)]}, c.b = {U[std::size_t(i) + 1], V[std::size_t(j)]};
    }
  for (int i = 0; i <= nu; ++i)
    for (int j = 0; j < nv; ++j) {
      ParamCurve& c = sides[std::size_t(v_side(i, j))];
      c.kind = (i == 0 || i == nu) ? EdgeKind::Boundary : EdgeKind::Interior;
      c.a = {U[std::size_t(i)], V[std::size_t(j)]}, c.b = {U[std::size_t(i)], V[std::size_t(j) + 1]};
    }
  // Silhouette points on every side, once (both subpatches of an interior side see the same ones).
  std::vector<std::vector<double>> zeros(sides.size());
  for (std::size_t s = 0; s < sides.size(); ++s)
    zeros[s] = sign_changes(
        [&](double t) {
          const glm::dvec2 uv = sides[s].at(t);
          return silhouette_cosine(f, uv.x, uv.y, opt.normal);
        },
        opt.silhouette_samples);
  // Crossings per (side, range): a side shared by two regions is stepped once, so both get the
  // same doubles and their common edge has no crack or overlap.
  std::map<std::tuple<int, double, double>, std::vector<EdgePiece>> stepped;
  auto side_pieces = [&](const SideRange& r) -> const std::vector<EdgePiece>& {
    const auto key = std::make_tuple(r.side, r.a, r.b);
    auto it = stepped.find(key);
    if (it == stepped.end())
      it = stepped.emplace(key, scan_edge(f, proj, sides[std::size_t(r.side)], r.a, r.b, opt, stats)).first;
    return it->second;
  };

  PatchEdges out;
  auto add_region = [&](int cell, bool front, const std::vector<SideRange>& parts,
                        const std::vector<EdgePiece>* silhouette) {
    if (!front && opt.cull) {
      ++stats.culled_regions;
      return;
    }
    const int r = int(out.regions.size());
    out.regions.push_back({front, cell});
    ++stats.regions;
    auto add = [&](const std::vector<EdgePiece>& ps) {
      for (EdgePiece p : ps) {
        p.region = r;
        out.pieces.push_back(std::move(p));
      }
    };
    for (const SideRange& s : parts) add(side_pieces(s));
    if (silhouette) add(*silhouette);
  };

  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      ++stats.cells;
      const int cell = j * nu + i;
      // The subpatch's boundary as a loop: bottom (forward), right (forward), top and left
      // (reversed). Loop position s in [0, 4): side floor(s), fraction along the loop direction.
      const int loop[4] = {h_side(j, i), v_side(i + 1, j), h_side(j + 1, i), v_side(i, j)};
      const bool reversed[4] = {false, false, true, true};
      // Silhouette points: side k of the loop at canonical t (kept exact: the Hermite starts at
      // side.at(t) and the side's pieces end at t, so the region's boundary closes bit-exactly).
      struct Hit {
        int k;
        double t, s;  // s: position along the loop, for sorting only
      };
      std::vector<Hit> hits;
      int per_side_max = 0;
      for (int k = 0; k < 4; ++k) {
        const auto& z = zeros[std::size_t(loop[k])];
        per_side_max = std::max(per_side_max, int(z.size()));
        for (double t : z) hits.push_back({k, t, k + (reversed[k] ? 1 - t : t)});
      }
      std::sort(hits.begin(), hits.end(), [](const Hit& l, const Hit& r) { return l.s < r.s; });
      const glm::dvec2 centre(0.5 * (U[std::size_t(i)] + U[std::size_t(i) + 1]),
                              0.5 * (V[std::size_t(j)] + V[std::size_t(j) + 1]));
      const std::vector<SideRange> whole = {{loop[0], 0, 1}, {loop[1], 0, 1}, {loop[2], 0, 1}, {loop[3], 0, 1}};
      if (hits.size() != 2 || per_side_max > 1) {
        if (hits.empty()) {
          // Whitted's last default: a silhouette contained entirely within the subpatch.
          bool neg = false, pos = false;
          for (int a = 0; a <= 6; ++a)
            for (int b = 0; b <= 6; ++b) {
              const double u = U[std::size_t(i)] + (U[std::size_t(i) + 1] - U[std::size_t(i)]) * a / 6.0;
              const double v = V[std::size_t(j)] + (V[std::size_t(j) + 1] - V[std::size_t(j)]) * b / 6.0;
              (silhouette_cosine(f, u, v, opt.normal) < 0 ? neg : pos) = true;
            }
          stats.default_inside += neg && pos;
        } else if (hits.size() % 2) {
          ++stats.default_one;
        } else if (hits.size() > 2) {
          ++stats.default_many;
        } else {
          ++stats.default_side_twice;
        }
        add_region(cell, silhouette_cosine(f, centre.x, centre.y, opt.normal) < 0, whole, nullptr);
        continue;
      }
      // Two points on two sides: Whitted's Hermite silhouette between them splits the subpatch.
      auto point = [&](const Hit& h) { return sides[std::size_t(loop[h.k])].at(h.t); };
      const ParamCurve sil = whitted_silhouette(point(hits[0]), point(hits[1]));
      ++stats.silhouettes;
      out.silhouettes.push_back(sil);
      const std::vector<EdgePiece> sil_pieces = scan_edge(f, proj, sil, 0, 1, opt, stats);
      // The boundary from hit `from` to hit `to` along the loop (they are on different sides), as
      // side ranges, and the facing in the middle of its longest range.
      auto arc = [&](const Hit& from, const Hit& to, bool& front) {
        std::vector<SideRange> parts;
        auto range = [&](int k, double t0, double t1) { parts.push_back({loop[k], std::min(t0, t1), std::max(t0, t1)}); };
        range(from.k, from.t, reversed[from.k] ? 0.0 : 1.0);  // on to the end of its side
        for (int k = (from.k + 1) % 4; k != to.k; k = (k + 1) % 4) range(k, 0, 1);
        range(to.k, reversed[to.k] ? 1.0 : 0.0, to.t);
        const SideRange* longest = &parts[0];
        for (const SideRange& p : parts)
          if (p.b - p.a > longest->b - longest->a) longest = &p;
        const glm::dvec2 uv = sides[std::size_t(longest->side)].at(0.5 * (longest->a + longest->b));
        front = silhouette_cosine(f, uv.x, uv.y, opt.normal) < 0;
        return parts;
      };
      bool front1 = true, front2 = true;
      const std::vector<SideRange> arc1 = arc(hits[0], hits[1], front1);
      const std::vector<SideRange> arc2 = arc(hits[1], hits[0], front2);
      add_region(cell, front1, arc1, &sil_pieces);
      add_region(cell, front2, arc2, &sil_pieces);
    }
  return out;
}

}  // namespace watkins
