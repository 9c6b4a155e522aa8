// Analytic surfaces tessellated into Gouraud's grid elements (quads, possibly non-planar) or
// triangles, with the EXACT surface normal at every vertex, in object space.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "patches.hpp"  // bezier_point, patch_normal
#include "scene_types.hpp"

namespace watkins {

// One indexed vertex array per object: polygons sharing a vertex refer to the same doubles,
// so shared edges project to bit-identical screen coordinates (watertight rasterization).
struct IndexedMesh {
  struct Face {
    int n = 0;                    // 3 or 4
    std::array<int, 4> idx{};     // indices into position/normal
  };
  std::vector<glm::dvec3> position;
  std::vector<glm::dvec3> normal;  // unit, outward (the side the face is seen from when front)
  std::vector<Face> faces;

  int add_vertex(const glm::dvec3& p, const glm::dvec3& n);
  // Adds a face wound so that it is front-facing when seen from the side its vertex normals
  // point to (see docs/guide/scene-format.md, "Winding"). Quads become two triangles if `split`.
  void add_face(std::initializer_list<int> idx, bool split);
};

// Sphere, cone, quarter_torus, hyperbolic_paraboloid, bezier_patch, patches, cross_vault, pier, portico, voxels.
// Object space, untransformed.
IndexedMesh tessellate_surface(const SceneObject& o);

// Faces tessellate_surface makes for `o` at most (before culling), for the builder's budget.
std::size_t estimated_faces(const SceneObject& o);

// Any object but "polygons" as an object-space mesh: a mesh file read (OBJ or STL, load_mesh_file:
// at most `max_faces` faces, `strict` and `degenerate` as there) or a surface tessellated, with
// its crease-angle normals when it asks for them. What the builder and the STL export both draw.
IndexedMesh object_mesh(const SceneObject& o, const std::string& where, std::size_t max_faces, bool strict,
                        int& degenerate);

// o.max_edge_length > 0: sets o.u, o.v (cone: o.cap_rings; pier, portico: o.box_segments) to the
// fewest segments for which no edge of the tessellation, measured in world units (after the
// object's scale), is longer than it. Returns an error message (no counts fit in 1024), else "".
std::string choose_tessellation(SceneObject& o);

// Where the parts of a cross_vault, pier or portico object sit in object space: each bay's centre
// on its springing plane (the barrels' axes cross there) and each pier's base centre.
struct VaultLayout {
  std::vector<glm::dvec3> bays, piers;
};
VaultLayout vault_layout(const SceneObject& o);

}  // namespace watkins
