// A polygon mesh as a file gives it (OBJ or STL), before normals: the one shape both readers
// produce, so face splitting, the normals (file, averaged, crease-angle) and the indexed vertex
// array are shared by every mesh format.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "surfaces.hpp"

namespace watkins {

// Largest mesh file read (larger ones, and anything not a regular file, are refused unread).
constexpr long long kMaxMeshBytes = 64ll << 20;

// In the file's own right-handed frame (z is mirrored only when the IndexedMesh is made).
struct PolygonMesh {
  struct Face {
    std::vector<int> position;  // indices into PolygonMesh::position, counter-clockwise from outside
    std::vector<int> normal;    // per corner: index into PolygonMesh::normal, or -1 (none in the file)
    long origin = 0;            // the file's line (OBJ) or facet number (STL), for messages
  };
  std::vector<glm::dvec3> position;
  std::vector<glm::dvec3> normal;  // the file's vertex normals (OBJ vn), any length
  std::vector<Face> faces;
};

// A coordinate of a mesh file: a whole decimal token, finite, of magnitude at most 1e9 (as scene
// numbers: products stay far from overflow). Returns what is wrong with it, or "" when x is set.
std::string mesh_number(std::string_view token, double& x);

// The bytes of o.file, a regular file of at most kMaxMeshBytes (anything else is refused unread);
// `format` ("OBJ", "STL" or "mesh") names it in messages prefixed with `where`.
std::string read_mesh_file(const SceneObject& o, const std::string& where, const std::string& format);

// Reports a problem with face `origin` (0: the file as a whole); never returns.
using MeshFail = std::function<void(long origin, const std::string& what)>;

// Sets every face corner's normal (PolygonMesh::Face::normal) to the one o asks for: the file's
// (o.normals File: each corner must have one), the area-weighted average of the faces around the
// position (Average), or the crease-angle normal at o.crease_angle_deg (Crease). Computed normals
// are sums, not yet of unit length.
void resolve_normals(PolygonMesh& m, const SceneObject& o, const MeshFail& fail);

// Splits every edge longer than `max_edge` into ceil(length / max_edge) equal pieces, each edge
// once for all the faces sharing it (the same positions, so no T-junction), and triangulates every
// face with a split edge from its subdivided edges: a uniform grid of n = the face's largest piece
// count inside, stitched to the subdivided boundary. Faces whose edges are all short stay as they
// are. The corners' normals (resolved first) are interpolated across a split face, so splitting
// changes the tessellation, not the surface's normals. Refuses, before allocating, a split making
// more than `max_faces` faces in all.
void split_long_edges(PolygonMesh& m, double max_edge, std::size_t max_faces, const MeshFail& fail);

// The indexed vertex array: each corner's position and normal (made unit length), z mirrored into
// the Watkins frame, faces of more than 4 vertices fan-triangulated (and quads split when
// o.triangles). Corners with the same position and normal share a vertex.
IndexedMesh indexed_mesh_from_polygons(const PolygonMesh& m, const SceneObject& o, const MeshFail& fail);

}  // namespace watkins
