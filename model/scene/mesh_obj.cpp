// OBJ loading. The tinyobjloader implementation is compiled here (header-only use), in double
// precision so file coordinates are not rounded to float on the way in.
#define TINYOBJLOADER_IMPLEMENTATION
#define TINYOBJLOADER_USE_DOUBLE
#include <tiny_obj_loader.h>

#include "mesh_obj.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

#include <glm/geometric.hpp>

namespace watkins {
namespace {

glm::dvec3 mirror_z(const glm::dvec3& v) { return {v.x, v.y, -v.z}; }

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  return s;
}

}  // namespace

IndexedMesh load_obj_mesh(const SceneObject& o, const std::string& where) {
  std::ifstream in(o.file, std::ios::binary);
  if (!in) throw SceneError(where + ": cannot open OBJ file \"" + o.file + "\": " + std::strerror(errno));
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  // No material reader: colours come from the scene's material, mtllib lines are ignored.
  bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, nullptr,
                             /*triangulate=*/false, /*default_vcols_fallback=*/false);
  if (!ok || !err.empty())
    throw SceneError(where + ": malformed OBJ file \"" + o.file + "\": " + trim(err.empty() ? "parse failed" : err));

  const size_t npos = attrib.vertices.size() / 3, nnorm = attrib.normals.size() / 3;
  auto pos = [&](int i) {
    return glm::dvec3(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
  };
  auto fail = [&](size_t face, const std::string& what) {
    throw SceneError(where + ": OBJ file \"" + o.file + "\": face " + std::to_string(face + 1) + ": " + what);
  };
  for (double x : attrib.vertices)
    if (!std::isfinite(x)) throw SceneError(where + ": OBJ file \"" + o.file + "\": non-finite vertex coordinate");

  // Gather faces as (position, normal) index lists, validating indices.
  struct RawFace { std::vector<std::pair<int, int>> v; };
  std::vector<RawFace> raw;
  for (const auto& sh : shapes) {
    size_t off = 0;
    for (size_t f = 0; f < sh.mesh.num_face_vertices.size(); ++f) {
      const size_t n = sh.mesh.num_face_vertices[f];
      RawFace rf;
      for (size_t k = 0; k < n; ++k) {
        const tinyobj::index_t& ix = sh.mesh.indices[off + k];
        if (ix.vertex_index < 0 || static_cast<size_t>(ix.vertex_index) >= npos)
          fail(raw.size(), "vertex index out of range");
        int ni = -1;
        if (o.normals == MeshNormals::File) {
          if (ix.normal_index < 0 || static_cast<size_t>(ix.normal_index) >= nnorm)
            fail(raw.size(), "no vertex normal (use \"normals\": \"average\" for files without vn)");
          ni = ix.normal_index;
        }
        rf.v.push_back({ix.vertex_index, ni});
      }
      off += n;
      if (rf.v.size() < 3) fail(raw.size(), "fewer than 3 vertices");
      raw.push_back(std::move(rf));
    }
  }
  if (raw.empty()) throw SceneError(where + ": OBJ file \"" + o.file + "\" has no faces");

  // Averaged normals: sum of Newell normals (length = twice the face area), i.e. area-weighted,
  // computed in the file's own right-handed frame where counter-clockwise faces point outward.
  std::vector<glm::dvec3> avg;
  if (o.normals == MeshNormals::Average) {
    avg.assign(npos, glm::dvec3(0.0));
    for (const RawFace& rf : raw) {
      glm::dvec3 nw(0.0);
      for (size_t k = 0; k < rf.v.size(); ++k) nw += glm::cross(pos(rf.v[k].first), pos(rf.v[(k + 1) % rf.v.size()].first));
      for (const auto& pv : rf.v) avg[pv.first] += nw;
    }
  }

  IndexedMesh m;
  std::map<std::pair<int, int>, int> index;  // (position, normal) -> vertex: shared vertices stay shared
  auto vertex = [&](size_t face, const std::pair<int, int>& pv) {
    auto it = index.find(pv);
    if (it != index.end()) return it->second;
    glm::dvec3 n = o.normals == MeshNormals::File
                       ? glm::dvec3(attrib.normals[3 * pv.second], attrib.normals[3 * pv.second + 1], attrib.normals[3 * pv.second + 2])
                       : avg[pv.first];
    double len = glm::length(n);
    if (!std::isfinite(len) || len < 1e-300) fail(face, "zero or invalid vertex normal");
    m.position.push_back(mirror_z(pos(pv.first)));
    m.normal.push_back(mirror_z(n / len));
    int id = static_cast<int>(m.position.size()) - 1;
    index.emplace(pv, id);
    return id;
  };
  // Faces keep the file's order: mirroring z both reverses the handedness and the apparent
  // winding, so a face counter-clockwise from outside in the file stays front-facing here.
  for (size_t f = 0; f < raw.size(); ++f) {
    const RawFace& rf = raw[f];
    std::vector<int> id;
    for (const auto& pv : rf.v) id.push_back(vertex(f, pv));
    if (id.size() == 4 && !o.triangles) {
      m.faces.push_back({4, {id[0], id[1], id[2], id[3]}});
    } else {
      for (size_t k = 1; k + 1 < id.size(); ++k) m.faces.push_back({3, {id[0], id[k], id[k + 1], 0}});
    }
  }
  return m;
}

}  // namespace watkins
