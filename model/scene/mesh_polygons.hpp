// A polygon mesh as a file gives it (OBJ or STL), before normals: the one shape both readers
// produce, so face splitting, the normals (file, averaged, crease-angle) and the indexed vertex
// array are shared by every mesh format.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
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

// Corners within `tol` in every coordinate become the first such corner seen (tol 0: the same
// bits): a grid of tol-sized cells, each corner compared with the vertices already in its cell and
// the 26 around it. Used by STL reading and by crease-angle normals on analytic surfaces.
class PositionWelder {
 public:
  // lo: the smallest corner of the positions' bounding box (the grid's origin).
  PositionWelder(const glm::dvec3& lo, double tol) : lo_(lo), tol_(tol) {}
  // The index in `out` of a position within tol of p, appending p when there is none.
  int add(const glm::dvec3& p, std::vector<glm::dvec3>& out);

 private:
  std::array<std::int64_t, 3> cell(const glm::dvec3& p) const;

  glm::dvec3 lo_;
  double tol_;
  std::map<std::array<std::int64_t, 3>, std::vector<int>> cells_;
};

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
// Lengths are measured in world units: each edge scaled by `scale` (the object's scale; its
// rotation keeps lengths), so a scaled mesh splits as a scaled analytic surface does.
void split_long_edges(PolygonMesh& m, double max_edge, const glm::dvec3& scale, std::size_t max_faces,
                      const MeshFail& fail);

// The indexed vertex array: each corner's position and normal (made unit length), z mirrored into
// the Watkins frame, faces of more than 4 vertices fan-triangulated (and quads split when
// o.triangles). Corners with the same position and normal share a vertex.
IndexedMesh indexed_mesh_from_polygons(const PolygonMesh& m, const SceneObject& o, const MeshFail& fail);

// Replaces the normals of a tessellated analytic surface (tessellate_surface's exact ones) by the
// crease-angle normals at o.crease_angle_deg, computed by resolve_normals from its faces. Vertices
// at the same position (to 1e-9 of the bounding box's diagonal) are welded first, so a seam or a
// vault's groin, where the tessellation splits vertices by normal, is smoothed when the faces
// meeting there are less than the angle apart. Positions are kept; faces keep their order.
void crease_surface_normals(IndexedMesh& m, const SceneObject& o);

}  // namespace watkins
