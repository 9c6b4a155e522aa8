// World-space triangles of a scene, written as STL.
#include "stl_export.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "camera.hpp"
#include "scene_error.hpp"
#include "surfaces.hpp"

namespace watkins {

StlExport export_stl(const Scene& sc, std::size_t max_faces) {
  StlExport out;
  std::size_t faces = 0;
  for (const SceneObject& o : sc.objects)
    if ((faces += estimated_faces(o)) > max_faces)
      throw SceneError(sc.name + ": " + o.field + ": the objects up to here make about " + std::to_string(faces) +
                       " faces, over the limit of " + std::to_string(max_faces));
  for (const SceneObject& o : sc.objects) {
    if (o.type == ObjectType::Polygons) {
      ++out.screen_polygons;
      continue;
    }
    const IndexedMesh m = object_mesh(o, sc.name + ": " + o.field + ".file", max_faces, false, out.degenerate);
    const glm::dmat3 rot = rotation(o.transform.rotate_deg);
    std::vector<glm::dvec3> world(m.position.size());
    // World -> STL: z negated (right-handed); with the vertex order kept, the mirror turns the
    // inward cross product of a front face (left-handed world) into STL's outward one.
    for (std::size_t k = 0; k < world.size(); ++k) {
      world[k] = rot * (o.transform.scale * m.position[k]) + o.transform.translate;
      world[k].z = -world[k].z;
    }
    for (const IndexedMesh::Face& f : m.faces)
      for (int t = 0; t + 2 < f.n; ++t) {
        StlFacet s;
        s.v = {world[std::size_t(f.idx[0])], world[std::size_t(f.idx[t + 1])], world[std::size_t(f.idx[t + 2])]};
        const glm::dvec3 n = glm::cross(s.v[1] - s.v[0], s.v[2] - s.v[0]);
        const double len = glm::length(n);
        if (!(len > 0)) {
          ++out.degenerate;
          continue;
        }
        s.normal = n / len;
        out.facets.push_back(s);
      }
  }
  // An STL file of no facets is one no reader (this one included) accepts: refused, nothing written.
  if (out.facets.empty()) {
    if (sc.objects.empty()) throw SceneError(sc.name + ": no world-space surfaces to export (the scene has no objects)");
    if (out.screen_polygons == int(sc.objects.size()))
      throw SceneError(sc.name + ": no world-space surfaces to export (" + std::to_string(out.screen_polygons) +
                       " screen-space polygons object(s) have no world geometry)");
    throw SceneError(sc.name + ": no facets to export (all " + std::to_string(out.degenerate) +
                     " triangles have zero area)");
  }
  return out;
}

namespace {

void put_u32(std::vector<unsigned char>& b, std::uint32_t x) {
  for (int i = 0; i < 4; ++i) b.push_back(static_cast<unsigned char>(x >> (8 * i)));
}

void put_f32(std::vector<unsigned char>& b, double x) {
  const float f = static_cast<float>(x);
  std::uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  put_u32(b, bits);  // little-endian whatever the host's order
}

}  // namespace

std::vector<unsigned char> stl_binary(const StlExport& e, const std::string& header) {
  std::vector<unsigned char> b(80, ' ');
  // A header starting with "solid" makes some readers take the file for ASCII.
  const std::string h = header.rfind("solid", 0) == 0 ? "binary " + header : header;
  std::memcpy(b.data(), h.data(), std::min<std::size_t>(h.size(), 80));
  put_u32(b, static_cast<std::uint32_t>(e.facets.size()));
  for (const StlFacet& f : e.facets) {
    for (int c = 0; c < 3; ++c) put_f32(b, f.normal[c]);
    for (const glm::dvec3& v : f.v)
      for (int c = 0; c < 3; ++c) put_f32(b, v[c]);
    b.push_back(0), b.push_back(0);  // attribute byte count
  }
  return b;
}

std::string stl_ascii(const StlExport& e, const std::string& name) {
  std::string s = "solid " + name + "\n";
  char line[160];
  auto vec = [&](const char* what, const glm::dvec3& v) {
    std::snprintf(line, sizeof line, "%s %.9g %.9g %.9g\n", what, v.x, v.y, v.z);
    s += line;
  };
  for (const StlFacet& f : e.facets) {
    vec("  facet normal", f.normal);
    s += "    outer loop\n";
    for (const glm::dvec3& v : f.v) vec("      vertex", v);
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid " + name + "\n";
}

}  // namespace watkins
