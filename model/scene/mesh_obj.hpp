// Wavefront OBJ meshes (via tinyobjloader), kept as quads where the file has quads.
#pragma once

#include <string>

#include "surfaces.hpp"

namespace watkins {

// Loads o.file into object space. OBJ is right-handed by convention, the Watkins world is
// left-handed: z is negated on load so the model looks as authored and keeps its winding.
// `where` prefixes messages ("scenes/m.json: objects[2].file").
IndexedMesh load_obj_mesh(const SceneObject& o, const std::string& where);

}  // namespace watkins
