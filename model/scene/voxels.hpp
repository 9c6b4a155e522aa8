// Voxel objects (Herman and Liu 1978): a density volume thresholded into inside and outside voxels,
// or a built-in phantom sampled at the voxel centres, whose surface is the set of voxel faces
// between an inside and an outside voxel — squares parallel to the three coordinate planes, the
// surfaces of their Figs. 2 to 6 ("typically 10,000 of them").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace watkins {

struct IndexedMesh;  // surfaces.hpp

enum class PhantomShape { Ellipsoid, BeadedSphere, TwoLobed };

// A phantom is a union of balls in a unit frame, scaled per axis by `size` into object space: the
// ellipsoid is one ball; the beaded sphere a unit ball with small balls half sunk into its surface
// (the beads of the paper's cast); the two-lobed shape two overlapping balls of unequal size.
// Exact, so the analytic truth ray-casts it (model/reference/analytic_truth.cpp).
struct Phantom {
  struct Ball {
    glm::dvec3 centre{0.0};  // unit frame
    double radius = 1;
  };
  PhantomShape shape = PhantomShape::Ellipsoid;
  glm::dvec3 size{1.0};  // object units per unit-frame unit, per axis
  std::vector<Ball> balls;
  double extent = 1;  // max over balls of |centre| + radius (unit frame): the phantom's reach

  // Object-space point inside (or on) the union.
  bool contains(const glm::dvec3& p) const;
};
Phantom make_phantom(PhantomShape shape, const glm::dvec3& size);
const char* to_string(PhantomShape s);

// Occupancy of an nx x ny x nz grid; voxel (i, j, k) spans [i, i+1] x [j, j+1] x [k, k+1] grid units
// times `spacing`, and the grid is centred on the object's origin: index i along +X, j along +Y
// (up), k along +Z (away from the observer).
class VoxelGrid {
 public:
  VoxelGrid(std::array<int, 3> dims, const glm::dvec3& spacing);

  const std::array<int, 3>& dims() const { return dims_; }
  const glm::dvec3& spacing() const { return spacing_; }
  // False outside the grid: the volume's border is outside, so the surface is closed.
  bool inside(int i, int j, int k) const;
  void set(int i, int j, int k, bool in);
  glm::dvec3 corner(int i, int j, int k) const;  // object-space grid corner
  glm::dvec3 centre(int i, int j, int k) const;  // object-space voxel centre
  std::size_t inside_count() const;
  std::size_t boundary_faces() const;  // faces between an inside and an outside voxel

 private:
  std::array<int, 3> dims_;
  glm::dvec3 spacing_;
  std::vector<std::uint8_t> in_;  // x fastest, then y, then z
};

// The phantom sampled at every voxel centre.
VoxelGrid voxelize(const Phantom& p, std::array<int, 3> dims, const glm::dvec3& spacing);

// Raw densities (x fastest, then y, then z; `bytes_per_voxel` 1: u8, 2: u16 little-endian) -> inside
// where density >= threshold. `raw.size()` must be dims' product times bytes_per_voxel (checked by the caller).
VoxelGrid threshold_volume(const std::vector<std::uint8_t>& raw, int bytes_per_voxel, std::array<int, 3> dims,
                           const glm::dvec3& spacing, double threshold);

// The boundary faces as quads (or two triangles each, `split`) wound front-facing from outside.
// average_normals false: every face has its own four vertices carrying its face normal (positions
// are the same doubles as its neighbours', so shared edges stay watertight); true: one vertex per
// grid corner with the normalized sum of the normals of the faces meeting there (Gouraud's rule,
// the paper's Fig. 3) — where that sum vanishes (faces that cancel, as at two voxels touching along
// an edge only) those faces keep their own normal at that corner.
IndexedMesh voxel_surface(const VoxelGrid& g, bool average_normals, bool split);

}  // namespace watkins
