// STL meshes (ASCII and binary), welded into shared vertices, and the mesh-file front door that
// picks OBJ or STL.
#pragma once

#include <cstddef>
#include <string>

#include "surfaces.hpp"

namespace watkins {

// Binary STL: an 80-byte header, a little-endian uint32 facet count n, then n records of 50 bytes.
// A file is read as binary exactly when its size is 84 + 50 n (even if the header starts with
// "solid", as some exporters write), else as ASCII.
bool is_binary_stl(const std::string& bytes);

// The file's facets, welded: corners within o.weld_tolerance of each other in every coordinate
// (default 1e-6 of the bounding box's diagonal) become one vertex, so facets share edges. Facet
// normals are ignored (the winding, counter-clockwise from outside, gives the side). Every
// coordinate must be finite and at most 1e9 in magnitude. A facet of zero area after welding is
// skipped and added to `degenerate`, or an error when `strict`. More than `max_faces` facets are
// refused. z is mirrored as for OBJ (STL, like OBJ, is right-handed).
IndexedMesh stl_mesh_from_bytes(const std::string& bytes, const SceneObject& o, const std::string& where,
                                std::size_t max_faces, bool strict, int& degenerate);

// o.file as a mesh: STL when its name ends in ".stl" (any case), OBJ when in ".obj", otherwise
// STL when the content is binary STL or its first word is "solid" (any case), else OBJ. `degenerate` and `strict`
// as for stl_mesh_from_bytes (an OBJ file's faces are never skipped here).
IndexedMesh load_mesh_file(const SceneObject& o, const std::string& where, std::size_t max_faces, bool strict,
                           int& degenerate);

}  // namespace watkins
