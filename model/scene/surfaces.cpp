// Tessellation of the analytic surfaces of Gouraud's and Phong's figures.
#include "surfaces.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "mesh_polygons.hpp"
#include "mesh_stl.hpp"
#include "voxels.hpp"

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
    // cap_rings > 1 (max_edge_length): rings of quads inside the rim, so no spoke is longer than the limit.
    for (int k = 1; k < o.cap_rings; ++k) {
      std::vector<int> inner;
      const double f = 1.0 - static_cast<double>(k) / o.cap_rings;
      for (int i = 0; i < nu; ++i) {
        const double phi = 2 * kPi * i / nu;
        inner.push_back(m.add_vertex(o.center + glm::dvec3(f * r * std::cos(phi), 0, f * r * std::sin(phi)), {0, -1, 0}));
      }
      for (int i = 0; i < nu; ++i) m.add_face({rim[i], rim[(i + 1) % nu], inner[(i + 1) % nu], inner[i]}, o.triangles);
      rim = std::move(inner);
    }
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

// Welds the boundary vertices of an object's patches: a vertex within `tol` of one already made
// on a boundary (of this patch or another) takes that vertex's doubles, so a shared boundary
// projects to bit-identical screen coordinates whatever the two patches' directions. Where the
// normals agree too (within kSmoothJoin: a smooth join, a pole) the two are one vertex whose
// normal is the mean of the patches' exact normals, bit-identical on both sides; where they do
// not (a crease) each side keeps its own normal on the common position.
class BoundaryWeld {
 public:
  // `size`: the largest coordinate magnitude; the cells stay at least 1e-12 of it, so a cell
  // index (coordinate / cell) stays far inside a long long even for a patch of zero extent.
  BoundaryWeld(IndexedMesh& m, double tol, double size) : m_(m), tol_(tol), cell_(std::max(tol * 1024, 1e-12 * (size + 1))) {}
  int vertex(const glm::dvec3& p, const glm::dvec3& n) {
    const glm::dvec3 u = glm::normalize(n);
    const std::array<long long, 3> key = cell(p);
    int same_place = -1;
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find({key[0] + dx, key[1] + dy, key[2] + dz});
          if (it == cells_.end()) continue;
          for (int id : it->second) {
            if (glm::length(m_.position[std::size_t(id)] - p) > tol_) continue;
            if (glm::dot(first_[std::size_t(id)], u) >= kSmoothJoin) {
              sum_[std::size_t(id)] += u;
              ++count_[std::size_t(id)];
              return id;
            }
            same_place = id;
          }
        }
    const int id = m_.add_vertex(same_place < 0 ? p : m_.position[std::size_t(same_place)], n);
    first_.resize(std::size_t(id) + 1), sum_.resize(std::size_t(id) + 1), count_.resize(std::size_t(id) + 1);
    first_[std::size_t(id)] = sum_[std::size_t(id)] = u;
    count_[std::size_t(id)] = 1;
    cells_[cell(m_.position[std::size_t(id)])].push_back(id);
    return id;
  }
  // The mean normal of every vertex that patches share (the others keep add_vertex's).
  void finish() {
    for (std::size_t id = 0; id < count_.size(); ++id)
      if (count_[id] > 1) m_.normal[id] = glm::normalize(sum_[id]);
  }

 private:
  static constexpr double kSmoothJoin = 0.9998476951563913;  // cos 1 degree
  std::array<long long, 3> cell(const glm::dvec3& p) const {
    return {static_cast<long long>(std::floor(p.x / cell_)), static_cast<long long>(std::floor(p.y / cell_)),
            static_cast<long long>(std::floor(p.z / cell_))};
  }
  IndexedMesh& m_;
  double tol_, cell_;
  std::map<std::array<long long, 3>, std::vector<int>> cells_;
  std::vector<glm::dvec3> first_, sum_;
  std::vector<int> count_;
};

// Bicubic patches ("bezier_patch", "patches"): each a grid over s, t in [0, 1] of o.u x o.v
// segments (Whitted's interior edges k_u, k_v are the curves' only: a scene that sets them for
// drawing by curves keeps its polygons, and u, v stay the polygon cells), exact normals
// (patch_normal: the limit from inside at a collapsed boundary). Rows top first, left to right as
// seen from the front, give a patch facing the viewer (left-handed world). A grid element with a
// collapsed side (at a pole) becomes a triangle.
IndexedMesh bezier_patches(const SceneObject& o) {
  IndexedMesh m;
  auto grid_lines = [](int segments) {
    std::vector<double> lines;
    for (int i = 0; i <= segments; ++i) lines.push_back(static_cast<double>(i) / segments);
    return lines;
  };
  const std::vector<double> su = grid_lines(o.u), tv = grid_lines(o.v);
  const std::size_t cu = su.size(), cv = tv.size();
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const BicubicPatch& cp : o.patches)
    for (const glm::dvec3& c : cp) lo = glm::min(lo, c), hi = glm::max(hi, c);
  const double size = std::max(glm::length(lo), glm::length(hi));
  BoundaryWeld weld(m, 1e-9 * glm::length(hi - lo), size);
  std::vector<int> id(cu * cv);
  for (const BicubicPatch& cp : o.patches) {
    for (std::size_t j = 0; j < cv; ++j)
      for (std::size_t i = 0; i < cu; ++i) {
        glm::dvec3 p, ds, dt;
        bezier_point(cp, su[i], tv[j], p, ds, dt);
        glm::dvec3 n = patch_normal(cp, su[i], tv[j]);
        if (glm::length(n) == 0) n = glm::dvec3(0, 0, -1);
        const bool boundary = i == 0 || j == 0 || i + 1 == cu || j + 1 == cv;
        id[j * cu + i] = boundary ? weld.vertex(p, n) : m.add_vertex(p, n);
      }
    for (std::size_t j = 0; j + 1 < cv; ++j)
      for (std::size_t i = 0; i + 1 < cu; ++i) {
        const int q[4] = {id[j * cu + i], id[j * cu + i + 1], id[(j + 1) * cu + i + 1], id[(j + 1) * cu + i]};
        int kept[4], n = 0;
        for (int k = 0; k < 4; ++k)  // drop a corner where the side to the next one has length 0
          if (m.position[std::size_t(q[k])] != m.position[std::size_t(q[(k + 1) % 4])]) kept[n++] = q[k];
        if (n == 4) m.add_face({kept[0], kept[1], kept[2], kept[3]}, o.triangles);
        else if (n == 3) m.add_face({kept[0], kept[1], kept[2]}, false);
      }
  }
  weld.finish();
  return m;
}

}  // namespace

VaultLayout vault_layout(const SceneObject& o) {
  VaultLayout l;
  switch (o.type) {
    case ObjectType::CrossVault: l.bays.push_back(glm::dvec3(0.0)); break;
    case ObjectType::Pier: l.piers.push_back(o.center); break;
    case ObjectType::Portico:
      // Bays along +X from x = 0, centred on z = 0; a pier under every corner of every bay.
      for (int k = 0; k < o.bays; ++k) l.bays.push_back({(k + 0.5) * o.span_x, o.pier_height, 0.0});
      for (int k = 0; k <= o.bays; ++k)
        for (double side : {-0.5, 0.5}) l.piers.push_back({k * o.span_x, 0.0, side * o.span_z});
      break;
    default: break;
  }
  return l;
}

namespace {

// Arch samples of a bay's barrels: angle pi*k/nu for k = 0..nu/2, exact at the springing (k = 0)
// and at the key (2k = nu), so the four webs meet at one point and the corners are exact.
struct ArchSamples {
  std::vector<double> c, s;  // cos, sin
  explicit ArchSamples(int nu) : c(std::size_t(nu / 2 + 1)), s(std::size_t(nu / 2 + 1)) {
    for (int k = 0; k <= nu / 2; ++k) {
      c[std::size_t(k)] = std::cos(kPi * k / nu);
      s[std::size_t(k)] = std::sin(kPi * k / nu);
    }
    c.front() = 1, s.front() = 0, c.back() = 0, s.back() = 1;
  }
};

// One web of a cross vault, as a (u, v) patch for the edge-length measure and the tessellation:
// `across` 0 is barrel X (axis along X, spanning z: y = h sqrt(1 - (z/B)^2)), 1 is barrel Z (axis
// along Z, spanning x); `side` is the sign of x (barrel X) or z (barrel Z) of the web. Arch row i
// (0..nu) is the barrel's angle pi*i/nu; along a row the web runs from the groin (j = 0), where
// |x|/A = |z|/B, to the face arch (j = nw) at |x| = A (barrel X) or |z| = B (barrel Z).
struct Web {
  const ArchSamples& arch;
  glm::dvec3 c;
  double A, B, h;
  int nu, across, side;
  int k(int i) const { return std::min(i, nu - i); }
  int arch_sign(int i) const { return 2 * i <= nu ? 1 : -1; }
  // The groin point of row i: one expression for both webs that share it, so both get the same doubles.
  glm::dvec3 groin(int sx, int sz, int kk) const {
    return c + glm::dvec3(sx * A * arch.c[std::size_t(kk)], h * arch.s[std::size_t(kk)], sz * B * arch.c[std::size_t(kk)]);
  }
  glm::dvec3 point(int i, double t) const {
    const int kk = k(i), sg = arch_sign(i);
    const double ck = arch.c[std::size_t(kk)], sk = arch.s[std::size_t(kk)];
    if (t == 0) return across == 0 ? groin(side, sg, kk) : groin(sg, side, kk);
    if (across == 0) {
      const double xg = A * ck, x = t == 1 ? A : xg + t * (A - xg);
      return c + glm::dvec3(side * x, h * sk, sg * B * ck);
    }
    const double zg = B * ck, z = t == 1 ? B : zg + t * (B - zg);
    return c + glm::dvec3(sg * A * ck, h * sk, side * z);
  }
  // The intrados normal: towards the barrel's axis (into the vaulted space), minus grad of
  // (z/B)^2 + (y/h)^2 (barrel X) or (x/A)^2 + (y/h)^2 (barrel Z).
  glm::dvec3 normal(int i) const {
    const int kk = k(i), sg = arch_sign(i);
    const double ck = arch.c[std::size_t(kk)], sk = arch.s[std::size_t(kk)];
    return across == 0 ? -glm::dvec3(0, sk / h, sg * ck / B) : -glm::dvec3(sg * ck / A, sk / h, 0);
  }
};

// One bay (volta a crociera): two half-elliptic barrels of rise h over a plan of half spans A (x)
// and B (z), springing plane through c. Seen from below each barrel is the ceiling where it is the
// higher of the two, |x|/A >= |z|/B for barrel X: four triangular webs whose edges are the face
// arches and the groins, half ellipses in the vertical planes of the plan's diagonals. The groin
// vertices are shared in position (not in normal) by the two webs meeting there, so the crease stays
// sharp with each web's exact normals; rows 0 and nu collapse to the springing corner (triangles).
void cross_vault_bay(IndexedMesh& m, const ArchSamples& arch, const glm::dvec3& c, double A, double B, double h,
                     int nu, int nw, bool split) {
  for (int across = 0; across < 2; ++across)
    for (int side : {1, -1}) {
      const Web w{arch, c, A, B, h, nu, across, side};
      std::vector<std::vector<int>> row(std::size_t(nu) + 1);
      for (int i = 0; i <= nu; ++i) {
        const glm::dvec3 n = w.normal(i);
        auto& r = row[std::size_t(i)];
        if (w.k(i) == 0) {
          r.push_back(m.add_vertex(w.point(i, 0), n));
          continue;
        }
        for (int j = 0; j <= nw; ++j) r.push_back(m.add_vertex(w.point(i, static_cast<double>(j) / nw), n));
      }
      for (int i = 0; i < nu; ++i) {
        const auto &a = row[std::size_t(i)], &b = row[std::size_t(i) + 1];
        for (int j = 0; j < nw; ++j) {
          const std::size_t jj = std::size_t(j);
          if (a.size() == 1) m.add_face({a[0], b[jj], b[jj + 1]}, false);
          else if (b.size() == 1) m.add_face({a[jj], a[jj + 1], b[0]}, false);
          else m.add_face({a[jj], a[jj + 1], b[jj + 1], b[jj]}, split);
        }
      }
    }
}

// A box column: base centre `base`, size (x, height, z), each face a grid of seg[] segments with
// its own vertices (sharp edges, exact face normals). A coordinate is computed by one expression
// on every face that has it, so the edges between faces are watertight.
void box(IndexedMesh& m, const glm::dvec3& base, const glm::dvec3& size, const std::array<int, 3>& seg, bool split) {
  const glm::dvec3 lo = base - glm::dvec3(size.x / 2, 0, size.z / 2), hi = base + glm::dvec3(size.x / 2, size.y, size.z / 2);
  auto coord = [&](int axis, int i) {
    const int n = seg[std::size_t(axis)];
    return i == 0 ? lo[axis] : i == n ? hi[axis] : lo[axis] + (hi[axis] - lo[axis]) * i / n;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int end = 0; end < 2; ++end) {
      const int b = (axis + 1) % 3, cc = (axis + 2) % 3, nb = seg[std::size_t(b)], nc = seg[std::size_t(cc)];
      glm::dvec3 n(0.0);
      n[axis] = end ? 1 : -1;
      std::vector<int> id;
      for (int j = 0; j <= nc; ++j)
        for (int i = 0; i <= nb; ++i) {
          glm::dvec3 p;
          p[axis] = end ? hi[axis] : lo[axis];
          p[b] = coord(b, i);
          p[cc] = coord(cc, j);
          id.push_back(m.add_vertex(p, n));
        }
      auto at = [&](int i, int j) { return id[std::size_t(j) * std::size_t(nb + 1) + std::size_t(i)]; };
      for (int j = 0; j < nc; ++j)
        for (int i = 0; i < nb; ++i) m.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, split);
    }
}

IndexedMesh vaulted(const SceneObject& o) {
  IndexedMesh m;
  const VaultLayout l = vault_layout(o);
  const ArchSamples arch(o.u);
  for (const glm::dvec3& c : l.bays) cross_vault_bay(m, arch, c, o.span_x / 2, o.span_z / 2, o.rise, o.u, o.v, o.triangles);
  for (const glm::dvec3& p : l.piers) box(m, p, {o.pier_x, o.pier_height, o.pier_z}, o.box_segments, o.triangles);
  return m;
}

// ---- Tessellation by maximum edge length -----------------------------------------------------

using PatchFn = std::function<glm::dvec3(double s, double t)>;

struct Longest {
  double u = 0, v = 0, diagonal = 0;  // world units
};

// Longest edge along s, along t and across each quad (the diagonal a split quad gets) of an
// nu x nv grid over each patch; lengths in world units (after the object's scale).
Longest longest_edges(const std::vector<PatchFn>& patches, int nu, int nv, const glm::dvec3& scale) {
  Longest e;
  std::vector<glm::dvec3> p(std::size_t(nu + 1) * std::size_t(nv + 1));
  auto at = [&](int i, int j) -> glm::dvec3& { return p[std::size_t(j) * std::size_t(nu + 1) + std::size_t(i)]; };
  for (const PatchFn& f : patches) {
    for (int j = 0; j <= nv; ++j)
      for (int i = 0; i <= nu; ++i) at(i, j) = scale * f(static_cast<double>(i) / nu, static_cast<double>(j) / nv);
    for (int j = 0; j <= nv; ++j)
      for (int i = 0; i <= nu; ++i) {
        if (i < nu) e.u = std::max(e.u, glm::length(at(i + 1, j) - at(i, j)));
        if (j < nv) e.v = std::max(e.v, glm::length(at(i, j + 1) - at(i, j)));
        if (i < nu && j < nv) e.diagonal = std::max(e.diagonal, glm::length(at(i + 1, j + 1) - at(i, j)));
      }
  }
  return e;
}

constexpr int kMaxSegments = 1024;
constexpr long long kMaxSamples = 1 << 24;  // grid points fit_grid measures at once

// Grows nu and nv from their minimums until no edge is longer than L. A chord shrinks about as
// 1/n, so n * (longest / L) segments is the next guess; ok once every edge fits.
// `patches(nu)` gives the surface's patches sampled for nu segments along s (the cross vault's
// arch rows depend on nu; the other surfaces ignore it).
std::string fit_grid(const std::function<std::vector<PatchFn>(int)>& patches, double L, const glm::dvec3& scale,
                     bool split, int umin, int vmin, bool u_even, int& nu, int& nv) {
  nu = umin, nv = vmin;
  auto grow = [&](int n, double len) {
    const double ratio = len / L;
    if (!(ratio < 2.0 * kMaxSegments)) return kMaxSegments + 1;  // hopeless (or not a number): refused below
    return std::max(n + 1, static_cast<int>(std::min(std::ceil(n * ratio), 2.0 * kMaxSegments)));
  };
  for (;;) {
    const std::vector<PatchFn> pieces = patches(nu);
    // Many patches (a "patches" object) at a fine grid: refused before millions of samples.
    if (static_cast<long long>(pieces.size()) * (nu + 1) * (nv + 1) > kMaxSamples)
      return number_text(L) + " needs more than " + std::to_string(kMaxSamples) +
             " grid points over the object's patches (the tessellation's limit)";
    const Longest e = longest_edges(pieces, nu, nv, scale);
    const bool ok_u = e.u <= L, ok_v = e.v <= L, ok_d = !split || e.diagonal <= L;
    if (ok_u && ok_v && ok_d) return "";
    if (!ok_u) nu = grow(nu, e.u);
    if (!ok_v) nv = grow(nv, e.v);
    if (ok_u && ok_v) (e.u >= e.v ? nu : nv) += 1;  // only a split quad's diagonal is too long
    if (u_even && nu % 2) ++nu;
    if (nu > kMaxSegments || nv > kMaxSegments)
      return number_text(L) + " needs more than " + std::to_string(kMaxSegments) + " segments along " +
             (nu > kMaxSegments ? "u" : "v") + " (the tessellation's limit)";
  }
}

// Segments of a box's edges (x, height, z) so that no edge, nor a split face's diagonal, is longer than L.
std::string fit_box(const glm::dvec3& size, double L, bool split, std::array<int, 3>& seg) {
  for (int a = 0; a < 3; ++a) seg[std::size_t(a)] = std::max(1, static_cast<int>(std::ceil(std::min(size[a] / L, 2.0 * kMaxSegments))));
  for (;;) {
    int worst = -1;
    if (split)
      for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3;
        const double db = size[b] / seg[std::size_t(b)], da = size[a] / seg[std::size_t(a)];
        if (std::hypot(da, db) > L) worst = da >= db ? a : b;
      }
    for (int a = 0; a < 3; ++a)
      if (seg[std::size_t(a)] > kMaxSegments)
        return number_text(L) + " needs more than " + std::to_string(kMaxSegments) + " segments along a pier's " +
               (a == 0 ? "x" : a == 1 ? "height" : "z") + " (the tessellation's limit)";
    if (worst < 0) return "";
    ++seg[std::size_t(worst)];
  }
}

std::vector<PatchFn> vault_patches(const SceneObject& o, const ArchSamples& arch, int nu) {
  std::vector<PatchFn> v;
  for (int across = 0; across < 2; ++across)
    for (int side : {1, -1}) {
      const Web w{arch, glm::dvec3(0.0), o.span_x / 2, o.span_z / 2, o.rise, nu, across, side};
      // s picks the arch row, so the measure sees exactly the tessellation's rows for this nu.
      v.push_back([w](double s, double t) { return w.point(static_cast<int>(std::lround(s * w.nu)), t); });
    }
  return v;
}

}  // namespace

std::string choose_tessellation(SceneObject& o) {
  const double L = o.max_edge_length;
  if (!(L > 0)) return "";
  const glm::dvec3 sc = o.transform.scale;
  const bool split = o.triangles;
  std::vector<PatchFn> p;
  const auto fixed = [&p](int) { return p; };
  switch (o.type) {
    case ObjectType::Sphere:
      p.push_back([&o](double s, double t) {
        const double phi = 2 * kPi * s, th = kPi * t;
        return o.center + o.radius * glm::dvec3(std::sin(th) * std::cos(phi), std::cos(th), std::sin(th) * std::sin(phi));
      });
      return fit_grid(fixed, L, sc, split, 3, 2, false, o.u, o.v);
    case ObjectType::Cone: {
      p.push_back([&o](double s, double t) {
        const double phi = 2 * kPi * s;
        return o.center + glm::dvec3((1 - t) * o.radius * std::cos(phi), t * o.height, (1 - t) * o.radius * std::sin(phi));
      });
      const std::string e = fit_grid(fixed, L, sc, split, 3, 1, false, o.u, o.v);
      if (!e.empty() || !o.cap) return e;
      // The cap's spokes: rings of equal width, the widest of the plan scale.
      const double spoke = o.radius * std::max(sc.x, sc.z);
      o.cap_rings = std::max(1, static_cast<int>(std::ceil(std::min(spoke / L, 2.0 * kMaxSegments))));
      // Split cap quads: the diagonal across a ring's outermost quad.
      while (split && o.cap_rings <= kMaxSegments &&
             std::hypot(spoke / o.cap_rings, 2 * spoke * std::sin(kPi / o.u)) > L)
        ++o.cap_rings;
      if (o.cap_rings > kMaxSegments)
        return number_text(L) + " needs more than " + std::to_string(kMaxSegments) + " rings in the cone's cap";
      return "";
    }
    case ObjectType::QuarterTorus:
      p.push_back([&o](double s, double t) {
        const double phi = 0.5 * kPi * s, th = 2 * kPi * t, R = o.major_radius, r = o.minor_radius;
        return glm::dvec3((R + r * std::cos(th)) * std::cos(phi), r * std::sin(th), (R + r * std::cos(th)) * std::sin(phi));
      });
      return fit_grid(fixed, L, sc, split, 2, 3, false, o.u, o.v);
    case ObjectType::HyperbolicParaboloid:
      p.push_back([&o](double s, double t) {
        const double x = o.size * (2 * s - 1), y = o.size * (2 * t - 1);
        return glm::dvec3(x, y, (x * x - y * y) / o.c);
      });
      return fit_grid(fixed, L, sc, split, 2, 2, false, o.u, o.v);
    case ObjectType::BezierPatch:
    case ObjectType::Patches:
      for (const BicubicPatch& cp : o.patches)
        p.push_back([&cp](double s, double t) {
          glm::dvec3 q, ds, dt;
          bezier_point(cp, s, t, q, ds, dt);
          return q;
        });
      return fit_grid(fixed, L, sc, split, 2, 2, false, o.u, o.v);
    case ObjectType::CrossVault:
    case ObjectType::Portico:
    case ObjectType::Pier: {
      if (o.type != ObjectType::Pier) {
        std::unique_ptr<ArchSamples> arch;  // alive while fit_grid measures the patches built on it
        const std::string e = fit_grid(
            [&](int nu) {
              arch = std::make_unique<ArchSamples>(nu);
              return vault_patches(o, *arch, nu);
            },
            L, sc, split, 2, 1, true, o.u, o.v);
        if (!e.empty()) return e;
      }
      if (o.type == ObjectType::CrossVault) return "";
      return fit_box(sc * glm::dvec3(o.pier_x, o.pier_height, o.pier_z), L, split, o.box_segments);
    }
    default: return "";
  }
}

std::size_t estimated_faces(const SceneObject& o) {
  const std::size_t split = o.triangles ? 2 : 1, u = std::size_t(o.u), v = std::size_t(o.v);
  const std::size_t sx = std::size_t(o.box_segments[0]), sy = std::size_t(o.box_segments[1]),
                    sz = std::size_t(o.box_segments[2]);
  const std::size_t box_faces = 2 * (sx * sy + sy * sz + sz * sx) * split, bay = 4 * u * v * split;
  switch (o.type) {
    case ObjectType::Mesh: return 0;  // counted while the file is read
    case ObjectType::Polygons: return o.polygons.size();
    case ObjectType::Voxels: return o.voxels ? o.voxels->boundary_faces() * split : 0;
    case ObjectType::CrossVault: return bay;
    case ObjectType::Pier: return box_faces;
    case ObjectType::Portico: return std::size_t(o.bays) * bay + 2 * std::size_t(o.bays + 1) * box_faces;
    case ObjectType::Cone: return u * (v + std::size_t(o.cap_rings)) * split;
    case ObjectType::BezierPatch:
    case ObjectType::Patches: return o.patches.size() * u * v * split;
    default: return u * (v + 1) * split;  // a u x v grid (a sphere's poles, a torus' ring)
  }
}

IndexedMesh tessellate_surface(const SceneObject& o) {
  switch (o.type) {
    case ObjectType::Sphere: return sphere(o);
    case ObjectType::Cone: return cone(o);
    case ObjectType::QuarterTorus: return quarter_torus(o);
    case ObjectType::HyperbolicParaboloid: return hypar(o);
    case ObjectType::BezierPatch:
    case ObjectType::Patches: return bezier_patches(o);
    case ObjectType::CrossVault:
    case ObjectType::Pier:
    case ObjectType::Portico: return vaulted(o);
    case ObjectType::Voxels: return voxel_surface(*o.voxels, o.normals == MeshNormals::Average, o.triangles);
    default: return {};
  }
}

IndexedMesh object_mesh(const SceneObject& o, const std::string& where, std::size_t max_faces, bool strict,
                        int& degenerate) {
  if (o.type == ObjectType::Mesh) return load_mesh_file(o, where, max_faces, strict, degenerate);
  IndexedMesh m = tessellate_surface(o);
  if (o.normals == MeshNormals::Crease) crease_surface_normals(m, o);
  return m;
}

}  // namespace watkins
