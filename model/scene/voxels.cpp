// Voxel grids, phantoms and their boundary faces (voxels.hpp).
#include "voxels.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "surfaces.hpp"

namespace watkins {

bool Phantom::contains(const glm::dvec3& p) const {
  const glm::dvec3 q = p / size;
  for (const Ball& b : balls) {
    const glm::dvec3 d = q - b.centre;
    if (glm::dot(d, d) <= b.radius * b.radius) return true;
  }
  return false;
}

Phantom make_phantom(PhantomShape shape, const glm::dvec3& size) {
  Phantom p;
  p.shape = shape;
  p.size = size;
  switch (shape) {
    case PhantomShape::Ellipsoid: p.balls.push_back({glm::dvec3(0.0), 1.0}); break;
    case PhantomShape::BeadedSphere: {
      // The body and 14 beads (the cube's 8 corner directions and its 6 face directions), half
      // sunk: a bead's centre on the body's surface. Radius 0.2: about two voxels across at the
      // phantom scenes' resolution, the beads' size against the cast in the paper's Fig. 1.
      p.balls.push_back({glm::dvec3(0.0), 0.8});
      for (int x = -1; x <= 1; x += 2)
        for (int y = -1; y <= 1; y += 2)
          for (int z = -1; z <= 1; z += 2) p.balls.push_back({0.8 * glm::normalize(glm::dvec3(x, y, z)), 0.2});
      for (int a = 0; a < 3; ++a)
        for (int s = -1; s <= 1; s += 2) {
          glm::dvec3 c(0.0);
          c[a] = 0.8 * s;
          p.balls.push_back({c, 0.2});
        }
      break;
    }
    case PhantomShape::TwoLobed:
      // Two lobes of unequal size meeting in a crease (a heart's ventricles, roughly).
      p.balls.push_back({glm::dvec3(-0.4, -0.05, 0.0), 0.6});
      p.balls.push_back({glm::dvec3(0.5, 0.1, 0.05), 0.48});
      break;
  }
  p.extent = 0;
  for (const Phantom::Ball& b : p.balls) p.extent = std::max(p.extent, glm::length(b.centre) + b.radius);
  return p;
}

const char* to_string(PhantomShape s) {
  switch (s) {
    case PhantomShape::Ellipsoid: return "ellipsoid";
    case PhantomShape::BeadedSphere: return "beaded_sphere";
    case PhantomShape::TwoLobed: return "two_lobed";
  }
  return "?";
}

VoxelGrid::VoxelGrid(std::array<int, 3> dims, const glm::dvec3& spacing)
    : dims_(dims), spacing_(spacing), in_(std::size_t(dims[0]) * std::size_t(dims[1]) * std::size_t(dims[2]), 0) {}

bool VoxelGrid::inside(int i, int j, int k) const {
  if (i < 0 || j < 0 || k < 0 || i >= dims_[0] || j >= dims_[1] || k >= dims_[2]) return false;
  return in_[(std::size_t(k) * std::size_t(dims_[1]) + std::size_t(j)) * std::size_t(dims_[0]) + std::size_t(i)] != 0;
}

void VoxelGrid::set(int i, int j, int k, bool in) {
  in_.at((std::size_t(k) * std::size_t(dims_[1]) + std::size_t(j)) * std::size_t(dims_[0]) + std::size_t(i)) = in;
}

glm::dvec3 VoxelGrid::corner(int i, int j, int k) const {
  // Integer grid units first, one product each: every face meeting at a corner gets the same doubles.
  return glm::dvec3((i - 0.5 * dims_[0]) * spacing_.x, (j - 0.5 * dims_[1]) * spacing_.y,
                    (k - 0.5 * dims_[2]) * spacing_.z);
}

glm::dvec3 VoxelGrid::centre(int i, int j, int k) const {
  return glm::dvec3((i + 0.5 - 0.5 * dims_[0]) * spacing_.x, (j + 0.5 - 0.5 * dims_[1]) * spacing_.y,
                    (k + 0.5 - 0.5 * dims_[2]) * spacing_.z);
}

std::size_t VoxelGrid::inside_count() const {
  return static_cast<std::size_t>(std::count(in_.begin(), in_.end(), std::uint8_t{1}));
}

namespace {

// Calls f(i, j, k, axis, side) for every boundary face: voxel (i, j, k) is inside and its
// neighbour at side (+1 / -1) along axis is not. Order: voxels in memory order, then axis, side.
template <typename F>
void for_each_face(const VoxelGrid& g, F f) {
  const auto& d = g.dims();
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i) {
        if (!g.inside(i, j, k)) continue;
        for (int axis = 0; axis < 3; ++axis)
          for (int side = -1; side <= 1; side += 2) {
            const int ni = i + (axis == 0 ? side : 0), nj = j + (axis == 1 ? side : 0), nk = k + (axis == 2 ? side : 0);
            if (!g.inside(ni, nj, nk)) f(i, j, k, axis, side);
          }
      }
}

// The face's four grid corners, wound so that it is front-facing from outside: in this left-handed
// world a front face's Newell normal points inward (docs/guide/scene-format.md, "Winding"), so the corners
// run b then c (Newell along +axis) for side -1 and c then b for side +1.
std::array<std::array<int, 3>, 4> face_corners(int i, int j, int k, int axis, int side) {
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;
  std::array<int, 3> p0{i, j, k};
  if (side > 0) ++p0[std::size_t(axis)];
  auto step = [&](bool db, bool dc) {
    std::array<int, 3> p = p0;
    p[std::size_t(b)] += db;
    p[std::size_t(c)] += dc;
    return p;
  };
  if (side < 0) return {p0, step(1, 0), step(1, 1), step(0, 1)};
  return {p0, step(0, 1), step(1, 1), step(1, 0)};
}

}  // namespace

std::size_t VoxelGrid::boundary_faces() const {
  std::size_t n = 0;
  for_each_face(*this, [&](int, int, int, int, int) { ++n; });
  return n;
}

VoxelGrid voxelize(const Phantom& p, std::array<int, 3> dims, const glm::dvec3& spacing) {
  VoxelGrid g(dims, spacing);
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i) g.set(i, j, k, p.contains(g.centre(i, j, k)));
  return g;
}

VoxelGrid threshold_volume(const std::vector<std::uint8_t>& raw, int bytes_per_voxel, std::array<int, 3> dims,
                           const glm::dvec3& spacing, double threshold) {
  VoxelGrid g(dims, spacing);
  std::size_t at = 0;
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i, at += std::size_t(bytes_per_voxel)) {
        const unsigned v = bytes_per_voxel == 1 ? raw.at(at) : unsigned(raw.at(at)) | unsigned(raw.at(at + 1)) << 8;
        g.set(i, j, k, v >= threshold);
      }
  return g;
}

IndexedMesh voxel_surface(const VoxelGrid& g, bool average_normals, bool split) {
  IndexedMesh m;
  const auto& d = g.dims();
  auto key = [&](const std::array<int, 3>& c) {
    return (std::size_t(c[2]) * std::size_t(d[1] + 1) + std::size_t(c[1])) * std::size_t(d[0] + 1) + std::size_t(c[0]);
  };
  auto normal_of = [](int axis, int side) {
    glm::dvec3 n(0.0);
    n[axis] = side;
    return n;
  };
  // Averaged normals: the sum of the face normals at every corner that a face touches.
  std::unordered_map<std::size_t, glm::dvec3> sum;
  std::unordered_map<std::size_t, int> shared;  // corner -> its vertex
  if (average_normals)
    for_each_face(g, [&](int i, int j, int k, int axis, int side) {
      for (const auto& c : face_corners(i, j, k, axis, side)) sum[key(c)] += normal_of(axis, side);
    });
  for_each_face(g, [&](int i, int j, int k, int axis, int side) {
    const glm::dvec3 n = normal_of(axis, side);
    std::array<int, 4> idx{};
    const auto corners = face_corners(i, j, k, axis, side);
    for (std::size_t q = 0; q < 4; ++q) {
      const auto& c = corners[q];
      const glm::dvec3 p = g.corner(c[0], c[1], c[2]);
      if (average_normals) {
        const glm::dvec3 s = sum.at(key(c));
        // The sums are of unit axis vectors: zero exactly, or of length at least 1.
        if (glm::dot(s, s) > 0.5) {
          auto it = shared.find(key(c));
          if (it == shared.end()) it = shared.emplace(key(c), m.add_vertex(p, s)).first;
          idx[q] = it->second;
          continue;
        }
      }
      idx[q] = m.add_vertex(p, n);
    }
    if (split) {
      m.faces.push_back(IndexedMesh::Face{3, {idx[0], idx[1], idx[2], 0}});
      m.faces.push_back(IndexedMesh::Face{3, {idx[0], idx[2], idx[3], 0}});
    } else {
      m.faces.push_back(IndexedMesh::Face{4, idx});
    }
  });
  return m;
}

}  // namespace watkins
