// A scene's tessellated objects as STL triangles in world space (`watkins export-stl`), so a
// solid modeller's path (tessellate, export STL, import) can be compared with the built-in one.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene_types.hpp"

namespace watkins {

// One facet in STL's frame: right-handed, z negated from the Watkins world (as OBJ files are read,
// docs/guide/scene-format.md), vertices counter-clockwise seen from the front (the side the object's
// normals point to), normal the unit cross product (v1 - v0) x (v2 - v0).
struct StlFacet {
  glm::dvec3 normal;
  std::array<glm::dvec3, 3> v;
};

struct StlExport {
  std::vector<StlFacet> facets;
  int degenerate = 0;        // zero-area triangles left out (no normal)
  int screen_polygons = 0;   // "polygons" objects left out (screen space has no world geometry)
};

// Every analytic surface and mesh of `sc`, tessellated as the builder does (quads split into
// (v0, v1, v2), (v0, v2, v3)) and transformed to world space; the camera plays no part. A scene
// that gives no facet (only screen-space "polygons" objects) is a SceneError naming it.
StlExport export_stl(const Scene& sc, std::size_t max_faces);

// Binary STL (80-byte header, little-endian float32) and ASCII STL ("solid name" ... "endsolid").
std::vector<unsigned char> stl_binary(const StlExport& e, const std::string& header);
std::string stl_ascii(const StlExport& e, const std::string& name);

}  // namespace watkins
