// Face splitting by edge length, vertex normals (file, averaged, crease-angle) and the indexed
// vertex array, shared by the OBJ and STL readers.
#include "mesh_polygons.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <tuple>
#include <utility>

#include <glm/geometric.hpp>

namespace watkins {
namespace {

constexpr double kPi = 3.14159265358979323846;

glm::dvec3 mirror_z(const glm::dvec3& v) { return {v.x, v.y, -v.z}; }

// Newell's normal of a face: length twice its area, counter-clockwise faces point outward.
glm::dvec3 newell(const PolygonMesh& m, const PolygonMesh::Face& f) {
  glm::dvec3 nw(0.0);
  const std::size_t n = f.position.size();
  for (std::size_t k = 0; k < n; ++k) nw += glm::cross(m.position[f.position[k]], m.position[f.position[(k + 1) % n]]);
  return nw;
}

// Faces a polygon of n vertices becomes when nothing is split (as indexed_mesh_from_polygons makes them).
double faces_of(std::size_t n) { return n == 4 ? 1.0 : double(n - 2); }

// One triangle of a split face: its corners as the face's positions and (resolved) normals, and
// where the interior and subdivided-edge points come from.
class TriangleSplitter {
 public:
  TriangleSplitter(PolygonMesh& m, double max_edge, const glm::dvec3& scale,
                   std::map<std::pair<int, int>, std::vector<int>>& edges, std::vector<PolygonMesh::Face>& out)
      : m_(m), max_edge_(max_edge), scale_(scale), edges_(edges), out_(out) {}

  // Pieces an edge is split into (at least 1), by its length in world units. Both faces of an
  // edge compute the same number.
  double pieces(int a, int b) const {
    return std::max(1.0, std::ceil(glm::length(scale_ * (m_.position[b] - m_.position[a])) / max_edge_));
  }

  // Faces split() makes of triangle (a, b, c).
  double count(int a, int b, int c) const {
    const double k0 = pieces(a, b), k1 = pieces(b, c), k2 = pieces(c, a);
    const double n = std::max({k0, k1, k2});
    if (n == 1) return 1;
    const double ring = std::max(n - 3, 0.0);
    return ring * ring + k0 + k1 + k2 + 3 * ring;
  }

  // pos/nrm: the triangle's corners (positions, normals or -1), counter-clockwise.
  void split(const int pos[3], const int nrm[3], long origin) {
    for (int k = 0; k < 3; ++k) pos_[k] = pos[k], nrm_[k] = nrm[k];
    origin_ = origin;
    const int k[3] = {int(pieces(pos[0], pos[1])), int(pieces(pos[1], pos[2])), int(pieces(pos[2], pos[0]))};
    n_ = std::max({k[0], k[1], k[2]});
    if (n_ == 1) {
      emit(corner(0), corner(1), corner(2));
      return;
    }
    lattice_.clear();
    // The ring: the uniform grid's points one step inside the boundary; a single point (the
    // centroid) when n is 2 or 3. Sides AB, BC, CA each run from the ring corner near their start.
    const int r = std::max(n_ - 3, 0);
    std::vector<Pt> ring[3];
    for (int t = 0; t <= r; ++t) {
      if (r == 0) {
        const Pt c = centroid();
        ring[0].push_back(c), ring[1].push_back(c), ring[2].push_back(c);
        break;
      }
      ring[0].push_back(lattice(1 + t, 1));
      ring[1].push_back(lattice(n_ - 2 - t, 1 + t));
      ring[2].push_back(lattice(1, n_ - 2 - t));
    }
    for (int s = 0; s < 3; ++s) stitch(side(s, k[s]), ring[s]);
    // The uniform grid inside the ring (r*r triangles), wound as the face.
    for (int i = 1; i <= n_ - 2; ++i)
      for (int j = 1; i + j <= n_ - 2; ++j) {
        emit(lattice(i, j), lattice(i + 1, j), lattice(i, j + 1));
        if (i + j + 2 <= n_ - 1) emit(lattice(i + 1, j), lattice(i + 1, j + 1), lattice(i, j + 1));
      }
  }

 private:
  struct Pt {
    int pos;
    glm::dvec3 w;  // barycentric weights of the corners, for the file normal
  };

  Pt corner(int c) const {
    glm::dvec3 w(0.0);
    w[c] = 1;
    return {pos_[c], w};
  }

  Pt make(const glm::dvec3& w) {
    const glm::dvec3 p = w.x * m_.position[pos_[0]] + w.y * m_.position[pos_[1]] + w.z * m_.position[pos_[2]];
    m_.position.push_back(p);
    return {int(m_.position.size()) - 1, w};
  }

  Pt centroid() { return make(glm::dvec3(1.0 / 3)); }

  // Grid point i steps along AB and j along AC (i, j >= 1: inside the face, owned by it).
  Pt lattice(int i, int j) {
    auto it = lattice_.find({i, j});
    if (it != lattice_.end()) return it->second;
    const Pt p = make(glm::dvec3(double(n_ - i - j) / n_, double(i) / n_, double(j) / n_));
    lattice_.emplace(std::make_pair(i, j), p);
    return p;
  }

  // Side s (from corner s to corner s+1) in k pieces. The points belong to the edge, made once
  // from its lower-numbered end whichever face asks first, so neighbours share them exactly.
  std::vector<Pt> side(int s, int k) {
    const int a = pos_[s], b = pos_[(s + 1) % 3];
    const int lo = std::min(a, b), hi = std::max(a, b);
    auto it = edges_.find({lo, hi});
    if (it == edges_.end()) {
      std::vector<int> ids{lo};
      const glm::dvec3 p = m_.position[lo], d = m_.position[hi] - m_.position[lo];
      for (int t = 1; t < k; ++t) {
        m_.position.push_back(p + d * (double(t) / k));
        ids.push_back(int(m_.position.size()) - 1);
      }
      ids.push_back(hi);
      it = edges_.emplace(std::make_pair(lo, hi), std::move(ids)).first;
    }
    std::vector<Pt> out;
    for (int t = 0; t <= k; ++t) {
      glm::dvec3 w(0.0);
      w[s] = double(k - t) / k;
      w[(s + 1) % 3] = double(t) / k;
      out.push_back({it->second[a == lo ? t : k - t], w});
    }
    return out;
  }

  // Triangulates the strip between a subdivided side and the ring side inside it (a convex
  // trapezoid, or a triangle when the ring is one point): every step advances along the side or
  // the ring, whichever makes the shorter diagonal.
  void stitch(const std::vector<Pt>& outer, const std::vector<Pt>& ring) {
    std::size_t i = 0, j = 0;
    const std::size_t k = outer.size() - 1, r = ring.size() - 1;
    auto at = [&](const Pt& p) { return m_.position[p.pos]; };
    while (i < k || j < r) {
      const bool along_side =
          j == r || (i < k && glm::length(at(outer[i + 1]) - at(ring[j])) <= glm::length(at(outer[i]) - at(ring[j + 1])));
      if (along_side) {
        emit(outer[i], outer[i + 1], ring[j]);
        ++i;
      } else {
        emit(outer[i], ring[j + 1], ring[j]);
        ++j;
      }
    }
  }

  void emit(const Pt& a, const Pt& b, const Pt& c) {
    PolygonMesh::Face f;
    f.origin = origin_;
    for (const Pt* p : {&a, &b, &c}) {
      f.position.push_back(p->pos);
      f.normal.push_back(file_normal(*p));
    }
    out_.push_back(std::move(f));
  }

  int file_normal(const Pt& p) {
    for (int c = 0; c < 3; ++c)
      if (p.w[c] == 1) return nrm_[c];
    if (nrm_[0] < 0 || nrm_[1] < 0 || nrm_[2] < 0) return -1;
    // The corners' directions, blended as Phong blends them along a scan line.
    glm::dvec3 n(0.0);
    for (int c = 0; c < 3; ++c) {
      const glm::dvec3& nc = m_.normal[nrm_[c]];
      const double len = glm::length(nc);
      if (len > 0 && std::isfinite(len)) n += p.w[c] * (nc / len);
    }
    m_.normal.push_back(n);
    return int(m_.normal.size()) - 1;
  }

  PolygonMesh& m_;
  double max_edge_;
  glm::dvec3 scale_;
  std::map<std::pair<int, int>, std::vector<int>>& edges_;
  std::vector<PolygonMesh::Face>& out_;
  int pos_[3] = {}, nrm_[3] = {};
  long origin_ = 0;
  int n_ = 1;
  std::map<std::pair<int, int>, Pt> lattice_;
};

bool has_long_edge(const TriangleSplitter& s, const PolygonMesh::Face& f) {
  const std::size_t n = f.position.size();
  for (std::size_t k = 0; k < n; ++k)
    if (s.pieces(f.position[k], f.position[(k + 1) % n]) > 1) return true;
  return false;
}

}  // namespace

int PositionWelder::add(const glm::dvec3& p, std::vector<glm::dvec3>& out) {
  const std::array<std::int64_t, 3> c = cell(p);
  if (tol_ > 0) {
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == cells_.end()) continue;
          for (int v : it->second) {
            const glm::dvec3 d = glm::abs(out[v] - p);
            if (std::max({d.x, d.y, d.z}) <= tol_) return v;
          }
        }
  } else {
    auto it = cells_.find(c);
    if (it != cells_.end())
      for (int v : it->second)
        if (out[v] == p) return v;
  }
  out.push_back(p);
  const int id = int(out.size()) - 1;
  cells_[c].push_back(id);
  return id;
}

std::array<std::int64_t, 3> PositionWelder::cell(const glm::dvec3& p) const {
  std::array<std::int64_t, 3> c{};
  for (int k = 0; k < 3; ++k) {
    // Below 2^62: coordinates span at most 2e9 and a positive tolerance is at least 1e-9.
    if (tol_ > 0) c[k] = std::int64_t(std::floor((p[k] - lo_[k]) / tol_));
    else std::memcpy(&c[k], &p[k], sizeof(double));  // exact welding: the coordinate's bits
  }
  return c;
}

std::string mesh_number(std::string_view t, double& x) {
  std::string_view s = t;
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  double v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v))
    return "expected a finite number, got " + quote_input(std::string(t));
  if (std::fabs(v) > 1e9) return "expected a number of magnitude at most 1e9, got " + quote_input(std::string(t));
  x = v;
  return "";
}

std::string read_mesh_file(const SceneObject& o, const std::string& where, const std::string& format) {
  const std::string name = format + " file " + quote_input(o.file);
  struct stat st {};
  if (::stat(o.file.c_str(), &st) != 0) throw SceneError(where + ": cannot open " + name + ": " + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw SceneError(where + ": " + name + " is not a regular file");
  if (st.st_size > kMaxMeshBytes)
    throw SceneError(where + ": " + name + " is " + std::to_string(st.st_size) + " bytes, over the limit of " +
                     std::to_string(kMaxMeshBytes));
  std::ifstream in(o.file, std::ios::binary);
  if (!in) throw SceneError(where + ": cannot open " + name + ": " + std::strerror(errno));
  std::string bytes(static_cast<size_t>(st.st_size), '\0');
  in.read(bytes.data(), st.st_size);
  bytes.resize(static_cast<size_t>(in.gcount()));
  if (in.bad()) throw SceneError(where + ": cannot read " + name);
  return bytes;
}

void split_long_edges(PolygonMesh& m, double max_edge, const glm::dvec3& scale, std::size_t max_faces,
                      const MeshFail& fail) {
  std::map<std::pair<int, int>, std::vector<int>> edges;
  std::vector<PolygonMesh::Face> out;
  TriangleSplitter splitter(m, max_edge, scale, edges, out);
  // A face with a long edge becomes a fan of triangles (a quad: two, across corners 0-2) and each
  // triangle is split. Counted first, so a tiny limit on a large mesh is refused unallocated.
  double total = 0;
  for (const auto& f : m.faces) {
    if (!has_long_edge(splitter, f)) {
      total += faces_of(f.position.size());
      continue;
    }
    for (std::size_t k = 1; k + 1 < f.position.size(); ++k)
      total += splitter.count(f.position[0], f.position[k], f.position[k + 1]);
  }
  if (total > double(max_faces))
    fail(0, "max_edge_length " + number_text(max_edge) + " splits the faces into " + number_text(total) +
                " faces, more than the " + std::to_string(max_faces) + " left for this file (see the pipeline's polygon limit)");
  out.reserve(std::size_t(total));
  const std::vector<PolygonMesh::Face> faces = std::move(m.faces);
  for (const auto& f : faces) {
    if (!has_long_edge(splitter, f)) {
      out.push_back(f);
      continue;
    }
    for (std::size_t k = 1; k + 1 < f.position.size(); ++k) {
      const int pos[3] = {f.position[0], f.position[k], f.position[k + 1]};
      const int nrm[3] = {f.normal[0], f.normal[k], f.normal[k + 1]};
      splitter.split(pos, nrm, f.origin);
    }
  }
  m.faces = std::move(out);
}

void resolve_normals(PolygonMesh& pm, const SceneObject& o, const MeshFail& fail) {
  const std::vector<glm::dvec3>& pos = pm.position;
  if (o.normals == MeshNormals::File) {
    for (const auto& f : pm.faces)
      for (int n : f.normal)
        if (n < 0) fail(f.origin, "no vertex normal");
    return;
  }
  std::vector<glm::dvec3> normal;
  if (o.normals == MeshNormals::Average) {
    // Averaged normals: sum of Newell normals (length = twice the face area), i.e. area-weighted,
    // computed in the file's own right-handed frame where counter-clockwise faces point outward.
    // One per position.
    normal.assign(pos.size(), glm::dvec3(0.0));
    for (const auto& f : pm.faces) {
      const glm::dvec3 nw = newell(pm, f);
      for (int p : f.position) normal[p] += nw;
    }
    for (auto& f : pm.faces) f.normal = f.position;
    pm.normal = std::move(normal);
    return;
  }
  // Crease-angle normals: a corner of face f averages the faces g around its vertex whose unit
  // normals are less than the angle away from f's (f itself always), each weighted by g's angle at
  // that vertex. Angle rather than area weights: the normal then does not depend on how a flat
  // region was triangulated (an STL cube's corner meets one triangle of one side and two of
  // another; by angle each side counts 90 degrees, so the corner normal is the diagonal).
  std::vector<glm::dvec3> unit;                           // per face (zero when degenerate)
  std::vector<std::vector<std::pair<int, double>>> ring;  // per position: (face, its angle there)
  const double cos_limit = o.crease_angle_deg >= 180 ? -2  // everything, even faces back to back
                                                     : std::cos(o.crease_angle_deg * (kPi / 180));
  unit.reserve(pm.faces.size());
  ring.assign(pos.size(), {});
  for (std::size_t fi = 0; fi < pm.faces.size(); ++fi) {
    const auto& f = pm.faces[fi];
    const glm::dvec3 nw = newell(pm, f);
    const double len = glm::length(nw);
    unit.push_back(len > 0 && std::isfinite(len) ? nw / len : glm::dvec3(0.0));
    const std::size_t n = f.position.size();
    for (std::size_t k = 0; k < n; ++k) {
      const glm::dvec3& p = pos[f.position[k]];
      const glm::dvec3 a = pos[f.position[(k + n - 1) % n]] - p, b = pos[f.position[(k + 1) % n]] - p;
      ring[f.position[k]].push_back({int(fi), std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b))});
    }
  }
  // (position, normal) -> index: corners agreeing share a normal (and so a vertex), a corner
  // across a crease gets its own.
  std::map<std::tuple<int, double, double, double>, int> index;
  for (std::size_t fi = 0; fi < pm.faces.size(); ++fi) {
    auto& f = pm.faces[fi];
    const glm::dvec3& own = unit[fi];
    const bool flat_face = own == glm::dvec3(0.0);  // a zero-area face takes its neighbours' normal
    for (std::size_t k = 0; k < f.position.size(); ++k) {
      const int p = f.position[k];
      glm::dvec3 sum(0.0);
      for (const auto& [g, angle] : ring[p])
        if (std::size_t(g) == fi || flat_face || glm::dot(own, unit[g]) > cos_limit) sum += angle * unit[g];
      if (sum == glm::dvec3(0.0)) sum = own;
      auto it = index.emplace(std::make_tuple(p, sum.x, sum.y, sum.z), int(normal.size())).first;
      if (it->second == int(normal.size())) normal.push_back(sum);
      f.normal[k] = it->second;
    }
  }
  pm.normal = std::move(normal);
}

IndexedMesh indexed_mesh_from_polygons(const PolygonMesh& pm, const SceneObject& o, const MeshFail& fail) {
  IndexedMesh m;
  // (position, normal) -> vertex: shared vertices stay shared.
  std::map<std::pair<int, int>, int> index;
  auto vertex = [&](const PolygonMesh::Face& f, std::size_t k) {
    const std::pair<int, int> key{f.position[k], f.normal[k]};
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    const glm::dvec3 n = f.normal[k] < 0 ? glm::dvec3(0.0) : pm.normal[f.normal[k]];
    const double len = glm::length(n);
    if (!std::isfinite(len) || len < 1e-300) fail(f.origin, "zero or invalid vertex normal");
    m.position.push_back(mirror_z(pm.position[key.first]));
    m.normal.push_back(mirror_z(n / len));
    const int id = static_cast<int>(m.position.size()) - 1;
    index.emplace(key, id);
    return id;
  };
  // Faces keep the file's order: mirroring z both reverses the handedness and the apparent
  // winding, so a face counter-clockwise from outside in the file stays front-facing here.
  // Polygons of more than 4 vertices become a fan of triangles (right for convex faces).
  for (const auto& f : pm.faces) {
    std::vector<int> id;
    id.reserve(f.position.size());
    for (std::size_t k = 0; k < f.position.size(); ++k) id.push_back(vertex(f, k));
    if (id.size() == 4 && !o.triangles) {
      m.faces.push_back({4, {id[0], id[1], id[2], id[3]}});
    } else {
      for (std::size_t k = 1; k + 1 < id.size(); ++k) m.faces.push_back({3, {id[0], id[k], id[k + 1], 0}});
    }
  }
  return m;
}

void crease_surface_normals(IndexedMesh& m, const SceneObject& o) {
  if (m.faces.empty()) return;
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::dvec3& p : m.position) lo = glm::min(lo, p), hi = glm::max(hi, p);
  // The tessellation computes a seam's or a groin's vertex once per side, so the copies can
  // differ in the last bits: weld to well below any edge, well above the rounding.
  PositionWelder weld(lo, 1e-9 * glm::length(hi - lo));
  // The surfaces are in the Watkins (left-handed) frame and front faces are wound as seen from
  // their normals' side; mirroring z gives the right-handed, counter-clockwise-outside polygons
  // resolve_normals expects, and indexed_mesh_from_polygons mirrors back.
  PolygonMesh pm;
  std::vector<int> welded(m.position.size());
  for (std::size_t k = 0; k < m.position.size(); ++k) welded[k] = weld.add(mirror_z(m.position[k]), pm.position);
  for (const auto& f : m.faces) {
    PolygonMesh::Face pf;
    for (int k = 0; k < f.n; ++k) {
      pf.position.push_back(welded[f.idx[k]]);
      pf.normal.push_back(-1);
    }
    pm.faces.push_back(std::move(pf));
  }
  SceneObject so = o;
  so.normals = MeshNormals::Crease;
  const MeshFail fail = [&o](long, const std::string& what) {
    throw SceneError(o.field + ".crease_angle_deg: " + what);
  };
  resolve_normals(pm, so, fail);
  m = indexed_mesh_from_polygons(pm, so, fail);
}

}  // namespace watkins
