// Wavefront OBJ meshes, kept as quads where the file has quads.
#pragma once

#include <cstddef>
#include <string>

#include "surfaces.hpp"

namespace watkins {

// o.file's text as an object-space mesh (load_mesh_file reads the file and picks OBJ or STL). OBJ
// is right-handed by convention, the Watkins world is left-handed: z is negated on load so the
// model looks as authored and keeps its winding. `where` prefixes messages ("scenes/m.json:
// objects[2].file"); a file making more than `max_faces` faces (quads, and triangles of the fans
// larger polygons become) is refused. Every number must be finite and at most 1e9 in magnitude,
// every index an integer inside the file's vertices and normals.
IndexedMesh obj_mesh_from_text(const std::string& text, const SceneObject& o, const std::string& where,
                               std::size_t max_faces);

}  // namespace watkins
