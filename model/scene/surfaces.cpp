// Tessellation of the analytic surfaces of Gouraud's and Phong's figures.
#include "surfaces.hpp"

#include <cmath>
#include <functional>

#include <glm/geometric.hpp>

namespace watkins {

int IndexedMesh::add_vertex(const glm::dvec3& p, const glm::dvec3& n) {
  position.push_back(p);
  normal.push_back(glm::normalize(n));
  return static_cast<int>(position.size()) - 1;
}

void IndexedMesh::add_face(std::initializer_list<int> idx, bool split) {
  Face f;
  for (int i : idx) f.idx[f.n++] = i;
  // The world is left-handed, so a polygon that looks counter-clockwise from the side its
  // outward normal points to has a Newell (numeric cross-product) normal pointing INWARD.
  // Deciding per face from the exact vertex normals keeps every surface consistent without
  // reasoning about each parameterization's orientation.
  glm::dvec3 newell(0.0), nsum(0.0);
  for (int k = 0; k < f.n; ++k) {
    const glm::dvec3& a = position[f.idx[k]];
    const glm::dvec3& b = position[f.idx[(k + 1) % f.n]];
    newell += glm::cross(a, b);
    nsum += normal[f.idx[k]];
  }
  if (glm::dot(newell, nsum) > 0) std::swap(f.idx[1], f.idx[f.n - 1]);  // a,b,c,d -> a,d,c,b
  if (f.n == 4 && split) {
    faces.push_back(Face{3, {f.idx[0], f.idx[1], f.idx[2], 0}});
    faces.push_back(Face{3, {f.idx[0], f.idx[2], f.idx[3], 0}});
  } else {
    faces.push_back(f);
  }
}

namespace {

constexpr double kPi = 3.14159265358979323846;

using SurfaceFn = std::function<void(double s, double t, glm::dvec3& p, glm::dvec3& n)>;

// (nu+1) x (nv+1) grid over s,t in [0,1]; wrap_u / wrap_v close the seam onto the first
// column / row so seam vertices are shared, not duplicated.
void grid(IndexedMesh& m, int nu, int nv, bool wrap_u, bool wrap_v, bool split, const SurfaceFn& f) {
  const int cu = wrap_u ? nu : nu + 1, cv = wrap_v ? nv : nv + 1;
  std::vector<int> id(static_cast<size_t>(cu) * cv);
  for (int j = 0; j < cv; ++j)
    for (int i = 0; i < cu; ++i) {
      glm::dvec3 p, n;
      f(static_cast<double>(i) / nu, static_cast<double>(j) / nv, p, n);
      id[static_cast<size_t>(j) * cu + i] = m.add_vertex(p, n);
    }
  auto at = [&](int i, int j) { return id[static_cast<size_t>(j % cv) * cu + (i % cu)]; };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) m.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, split);
}

IndexedMesh sphere(const SceneObject& o) {
  IndexedMesh m;
  const int nu = o.u, nv = o.v;
  auto dir = [&](int i, int j) {
    double phi = 2 * kPi * i / nu, th = kPi * j / nv;
    return glm::dvec3(std::sin(th) * std::cos(phi), std::cos(th), std::sin(th) * std::sin(phi));
  };
  // Poles are single vertices with triangles around them: quads there would have a
  // zero-length edge and would mostly be dropped as degenerate anyway.
  int top = m.add_vertex(o.center + glm::dvec3(0, o.radius, 0), {0, 1, 0});
  std::vector<int> ring;  // rings j = 1..nv-1, nu vertices each (seam shared)
  for (int j = 1; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      glm::dvec3 d = dir(i, j);
      ring.push_back(m.add_vertex(o.center + o.radius * d, d));
    }
  int bottom = m.add_vertex(o.center - glm::dvec3(0, o.radius, 0), {0, -1, 0});
  auto at = [&](int i, int j) { return ring[static_cast<size_t>(j - 1) * nu + (i % nu)]; };
  for (int i = 0; i < nu; ++i) {
    if (nv == 2) {
      m.add_face({top, at(i, 1), at(i + 1, 1)}, false);
      m.add_face({bottom, at(i, 1), at(i + 1, 1)}, false);
      continue;
    }
    m.add_face({top, at(i, 1), at(i + 1, 1)}, false);
    for (int j = 1; j < nv - 1; ++j) m.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, o.triangles);
    m.add_face({bottom, at(i, nv - 1), at(i + 1, nv - 1)}, false);
  }
  return m;
}

// Phong's Fig. 1: the side is a ring of planar facets meeting at the apex. The side normal is
// exact and constant along each generator; the apex, where the surface has no normal, gets
// one vertex per facet carrying the normal of the facet's middle generator.
IndexedMesh cone(const SceneObject& o) {
  IndexedMesh m;
  const int nu = o.u, nv = o.v;
  const double r = o.radius, h = o.height;
  auto side_normal = [&](double phi) { return glm::dvec3(h * std::cos(phi), r, h * std::sin(phi)); };
  std::vector<int> ring;  // rings j = 0..nv-1 from the base up
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      double phi = 2 * kPi * i / nu, t = static_cast<double>(j) / nv;
      glm::dvec3 p = o.center + glm::dvec3((1 - t) * r * std::cos(phi), t * h, (1 - t) * r * std::sin(phi));
      ring.push_back(m.add_vertex(p, side_normal(phi)));
    }
  auto at = [&](int i, int j) { return ring[static_cast<size_t>(j) * nu + (i % nu)]; };
  const glm::dvec3 apex = o.center + glm::dvec3(0, h, 0);
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j + 1 < nv; ++j) m.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, o.triangles);
    int a = m.add_vertex(apex, side_normal(2 * kPi * (i + 0.5) / nu));
    m.add_face({at(i, nv - 1), at(i + 1, nv - 1), a}, false);
  }
  if (o.cap) {
    // Copy the rim positions so the cap's edge is bit-identical to the side's.
    int c = m.add_vertex(o.center, {0, -1, 0});
    std::vector<int> rim;
    for (int i = 0; i < nu; ++i) rim.push_back(m.add_vertex(m.position[at(i, 0)], {0, -1, 0}));
    for (int i = 0; i < nu; ++i) m.add_face({c, rim[i], rim[(i + 1) % nu]}, false);
  }
  return m;
}

// Gouraud's Fig. 2b: a quarter of a torus about the Y axis, from +X to +Z; open ends.
IndexedMesh quarter_torus(const SceneObject& o) {
  IndexedMesh m;
  const double R = o.major_radius, r = o.minor_radius;
  grid(m, o.u, o.v, false, true, o.triangles, [&](double s, double t, glm::dvec3& p, glm::dvec3& n) {
    double phi = 0.5 * kPi * s, th = 2 * kPi * t;
    n = glm::dvec3(std::cos(th) * std::cos(phi), std::sin(th), std::cos(th) * std::sin(phi));
    p = glm::dvec3((R + r * std::cos(th)) * std::cos(phi), r * std::sin(th), (R + r * std::cos(th)) * std::sin(phi));
  });
  return m;
}

// Gouraud's Fig. 2a: z = (x^2 - y^2)/c over |x|, |y| <= size. The front side faces -Z
// (towards an observer at the origin when the surface lies at positive Z).
IndexedMesh hypar(const SceneObject& o) {
  IndexedMesh m;
  grid(m, o.u, o.v, false, false, o.triangles, [&](double s, double t, glm::dvec3& p, glm::dvec3& n) {
    double x = o.size * (2 * s - 1), y = o.size * (2 * t - 1);
    p = glm::dvec3(x, y, (x * x - y * y) / o.c);
    n = glm::dvec3(2 * x / o.c, -2 * y / o.c, -1);
  });
  return m;
}

void bernstein(double t, double b[4], double db[4]) {
  double u = 1 - t;
  b[0] = u * u * u; b[1] = 3 * t * u * u; b[2] = 3 * t * t * u; b[3] = t * t * t;
  db[0] = -3 * u * u; db[1] = 3 * u * u - 6 * t * u; db[2] = 6 * t * u - 3 * t * t; db[3] = 3 * t * t;
}

}  // namespace

void bezier_point(const std::vector<glm::dvec3>& cp, double s, double t, glm::dvec3& p, glm::dvec3& ds,
                  glm::dvec3& dt) {
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

namespace {

// Bicubic Bezier: control_points[4*row + col]; s runs along a row, t from row to row. The
// normal is dP/ds x dP/dt: rows listed top first, left to right, as seen from the front,
// give a patch facing the viewer (left-handed world).
IndexedMesh bezier(const SceneObject& o) {
  IndexedMesh m;
  const auto& cp = o.control_points;
  auto eval = [&](double s, double t, glm::dvec3& p, glm::dvec3& ds, glm::dvec3& dt) {
    bezier_point(cp, s, t, p, ds, dt);
  };
  grid(m, o.u, o.v, false, false, o.triangles, [&](double s, double t, glm::dvec3& p, glm::dvec3& n) {
    glm::dvec3 ds, dt, q;
    eval(s, t, p, ds, dt);
    n = glm::cross(ds, dt);
    // A degenerate corner (coincident control points) has no tangent plane there; take the
    // limit from just inside the patch.
    for (double e = 1e-6; glm::length(n) < 1e-12 * (1 + glm::dot(p, p)) && e < 0.1; e *= 10) {
      eval(s + (s < 0.5 ? e : -e), t + (t < 0.5 ? e : -e), q, ds, dt);
      n = glm::cross(ds, dt);
    }
    if (glm::length(n) == 0) n = glm::dvec3(0, 0, -1);
  });
  return m;
}

}  // namespace

IndexedMesh tessellate_surface(const SceneObject& o) {
  switch (o.type) {
    case ObjectType::Sphere: return sphere(o);
    case ObjectType::Cone: return cone(o);
    case ObjectType::QuarterTorus: return quarter_torus(o);
    case ObjectType::HyperbolicParaboloid: return hypar(o);
    case ObjectType::BezierPatch: return bezier(o);
    default: return {};
  }
}

}  // namespace watkins
