// The STL targets' shared step: the bytes through the STL reader (model/scene/mesh_stl.hpp) as the
// "file" of a mesh object, with the object's options picked by `variant` (0..3; each target derives
// it from its input) so one corpus reaches every normal rule, the edge splitting, a coarse weld and
// --strict.
#pragma once

#include <cstddef>
#include <string>

#include "mesh_stl.hpp"
#include "scene_error.hpp"
#include "scene_types.hpp"

namespace watkins::fuzz {

// Small enough that one input costs a millisecond or so: a binary input packs a facet in 50 bytes,
// and edge splitting multiplies them (the command line allows 2^22; the reader's code is the same
// at any count).
constexpr std::size_t kStlMaxFaces = 4096;

inline void read_stl(const std::string& bytes, unsigned variant) {
  SceneObject o;
  o.type = ObjectType::Mesh;
  o.field = "objects[0]";
  o.file = "fuzz.stl";
  bool strict = false;
  switch (variant % 4) {
    case 0:  // the defaults: averaged normals, welding at 1e-6 of the diagonal
      break;
    case 1:  // crease-angle normals, long edges split
      o.normals = MeshNormals::Crease;
      o.crease_angle_deg = 60;
      o.max_edge_length = 0.5;
      break;
    case 2:  // a coarse weld that makes zero-area facets, refused
      o.normals = MeshNormals::Average;
      o.normals_given = true;
      o.weld_tolerance = 0.01;
      o.triangles = true;
      strict = true;
      break;
    default:  // exact welding (tolerance 0), edges split more finely
      o.weld_tolerance = 0;
      o.max_edge_length = 0.2;
      break;
  }
  int degenerate = 0;
  try {
    (void)stl_mesh_from_bytes(bytes, o, "fuzz.json: objects[0].file", kStlMaxFaces, strict, degenerate);
  } catch (const SceneError&) {  // the expected answer to bad input: one line naming the file
  }
}

}  // namespace watkins::fuzz
