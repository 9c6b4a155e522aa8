// STL loading: a strict reader of both encodings, then vertex welding (STL repeats every corner
// in every facet), then the shared mesh path (mesh_polygons.hpp) that OBJ files take as well.
#include "mesh_stl.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "mesh_obj.hpp"
#include "mesh_polygons.hpp"

namespace watkins {
namespace {

constexpr std::size_t kHeaderBytes = 84, kFacetBytes = 50;

std::uint32_t le32(const std::string& b, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(b[at + k]);
  return v;
}

float le_float(const std::string& b, std::size_t at) {
  const std::uint32_t bits = le32(b, at);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// `k` in lower case; `t` matches it in any case (the format's keywords are case-insensitive).
bool keyword(std::string_view t, const char* k) {
  const std::size_t n = std::strlen(k);
  if (t.size() != n) return false;
  for (std::size_t i = 0; i < n; ++i)
    if (std::tolower(static_cast<unsigned char>(t[i])) != k[i]) return false;
  return true;
}

// The first token is "solid" in any case (the rest of the line is the solid's name).
bool starts_with_solid(const std::string& bytes) {
  std::size_t i = 0;
  auto space = [&](std::size_t k) { return std::isspace(static_cast<unsigned char>(bytes[k])) != 0; };
  while (i < bytes.size() && space(i)) ++i;
  const std::size_t b = i;
  while (i < bytes.size() && !space(i)) ++i;
  return keyword(std::string_view(bytes).substr(b, i - b), "solid");
}

std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  auto space = [&](std::size_t k) { return std::isspace(static_cast<unsigned char>(line[k])) != 0; };
  while (i < line.size()) {
    while (i < line.size() && space(i)) ++i;
    const std::size_t b = i;
    while (i < line.size() && !space(i)) ++i;
    if (i > b) out.push_back(line.substr(b, i - b));
  }
  return out;
}

class StlReader {
 public:
  StlReader(const std::string& bytes, const SceneObject& o, std::string where, std::size_t max_faces)
      : bytes_(bytes), o_(o), where_(std::move(where)), max_faces_(max_faces) {}

  // `origin`: a line of an ASCII file, a facet (from 1) of a binary one; 0: the file.
  [[noreturn]] void fail(long origin, const std::string& what) const {
    throw SceneError(where_ + ": STL file " + quote_input(o_.file) +
                     (origin ? (binary_ ? ": facet " : ": line ") + std::to_string(origin) : "") + ": " + what);
  }

  struct Facet {
    std::array<glm::dvec3, 3> corner;
    long origin;
  };
  std::vector<Facet> facets;

  void read() {
    binary_ = is_binary_stl(bytes_);
    if (binary_) return read_binary();
    if (!starts_with_solid(bytes_)) {
      if (bytes_.size() >= kHeaderBytes) {
        const std::uint64_t n = le32(bytes_, 80);
        fail(0, "neither ASCII STL (it does not start with \"solid\") nor binary STL (its header gives " + std::to_string(n) +
                    " facets, 84 + 50 x " + std::to_string(n) + " = " + std::to_string(kHeaderBytes + kFacetBytes * n) +
                    " bytes, but the file has " + std::to_string(bytes_.size()) + ": truncated?)");
      }
      fail(0, "neither ASCII STL (it does not start with \"solid\") nor binary STL (" + std::to_string(bytes_.size()) +
                  " bytes, shorter than the 84-byte header)");
    }
    read_ascii();
  }

 private:
  glm::dvec3 checked(const float v[3], long facet, const char* what) const {
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(v[c])) fail(facet, std::string(what) + ": expected a finite number, got " + number_text(v[c]));
      if (std::fabs(v[c]) > 1e9)
        fail(facet, std::string(what) + ": expected a number of magnitude at most 1e9, got " + number_text(v[c]));
    }
    return {v[0], v[1], v[2]};
  }

  void read_binary() {
    const std::size_t n = le32(bytes_, 80);
    if (n == 0) fail(0, "binary STL with no facets");
    if (n > max_faces_)
      fail(0, "has " + std::to_string(n) + " facets, more than the " + std::to_string(max_faces_) +
                  " faces left for it (see the pipeline's polygon limit)");
    facets.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t at = kHeaderBytes + kFacetBytes * i + 12;  // past the facet normal (ignored)
      Facet f{{}, long(i + 1)};
      for (int k = 0; k < 3; ++k) {
        const float v[3] = {le_float(bytes_, at + 12 * k), le_float(bytes_, at + 12 * k + 4), le_float(bytes_, at + 12 * k + 8)};
        f.corner[k] = checked(v, f.origin, ("vertex " + std::to_string(k + 1)).c_str());
      }
      facets.push_back(f);
    }
  }

  // solid [name] / { facet normal x y z / outer loop / vertex x y z (3 times) / endloop / endfacet }
  // / endsolid [name], one statement a line, keywords in any case; x y z of the normal any 3 tokens.
  void read_ascii() {
    std::size_t pos = 0;
    long line = 0;
    auto next = [&]() -> std::vector<std::string_view> {  // the next non-blank line's tokens
      while (pos < bytes_.size()) {
        std::size_t end = bytes_.find('\n', pos);
        if (end == std::string::npos) end = bytes_.size();
        const std::string_view l = std::string_view(bytes_).substr(pos, end - pos);
        pos = end + 1;
        ++line;
        if (l.find('\0') != std::string_view::npos)
          fail(line, "NUL byte (not ASCII STL; nor binary STL: its size, " + std::to_string(bytes_.size()) +
                         " bytes, is not 84 + 50 x the header's facet count)");
        auto t = tokens(l);
        if (!t.empty()) return t;
      }
      return {};
    };
    auto expect = [&](const std::vector<std::string_view>& t, const char* what, const char* k1, const char* k2,
                      std::size_t numbers) {
      if (t.empty()) fail(line, std::string("the file ends where \"") + what + "\" was expected (truncated?)");
      const std::size_t words = k2 ? 2 : 1;
      if (!keyword(t[0], k1) || (k2 && (t.size() < 2 || !keyword(t[1], k2))))
        fail(line, std::string("expected \"") + what + "\", got " + quote_input(std::string(t[0])));
      if (t.size() != words + numbers)
        fail(line, std::string("\"") + what + "\": expected " +
                       (numbers ? std::to_string(numbers) + " numbers" : std::string("nothing more")) + ", got " +
                       std::to_string(t.size() - words) + " tokens after it");
    };
    auto t = next();
    if (t.empty() || !keyword(t[0], "solid")) fail(line, "expected \"solid\"");
    for (;;) {
      t = next();
      if (t.empty()) fail(line, "the file ends before \"endsolid\" (truncated?)");
      if (keyword(t[0], "endsolid")) break;
      if (!keyword(t[0], "facet"))
        fail(line, "expected \"facet normal\" or \"endsolid\", got " + quote_input(std::string(t[0])));
      // The normal's three tokens are skipped unread, whatever their text (nan, 1e999, ...): the
      // winding gives the facet's side and the shading normals are computed.
      expect(t, "facet normal", "facet", "normal", 3);
      if (facets.size() == max_faces_)
        fail(line, "the file has more than " + std::to_string(max_faces_) +
                       " facets, the faces left for it (see the pipeline's polygon limit)");
      Facet f{{}, line};
      expect(next(), "outer loop", "outer", "loop", 0);
      for (int k = 0; k < 3; ++k) {
        t = next();
        if (!t.empty() && (keyword(t[0], "endloop")))
          fail(line, "a facet has 3 vertices, got " + std::to_string(k));
        expect(t, "vertex", "vertex", nullptr, 3);
        for (int c = 0; c < 3; ++c)
          if (std::string e = mesh_number(t[1 + c], f.corner[k][c]); !e.empty()) fail(line, "vertex: " + e);
      }
      t = next();
      if (!t.empty() && keyword(t[0], "vertex")) fail(line, "a facet has 3 vertices (STL facets are triangles), got a 4th");
      expect(t, "endloop", "endloop", nullptr, 0);
      expect(next(), "endfacet", "endfacet", nullptr, 0);
      facets.push_back(f);
    }
    const long end_line = line;
    if (!next().empty()) fail(line, "text after \"endsolid\" (line " + std::to_string(end_line) + "; one solid per file)");
    if (facets.empty()) fail(0, "has no facets");
  }

  const std::string& bytes_;
  const SceneObject& o_;
  std::string where_;
  std::size_t max_faces_;
  bool binary_ = false;
};

}  // namespace

bool is_binary_stl(const std::string& bytes) {
  return bytes.size() >= kHeaderBytes && bytes.size() == kHeaderBytes + kFacetBytes * std::uint64_t(le32(bytes, 80));
}

IndexedMesh stl_mesh_from_bytes(const std::string& bytes, const SceneObject& o, const std::string& where,
                                std::size_t max_faces, bool strict, int& degenerate) {
  StlReader r(bytes, o, where, max_faces);
  if (o.normals_given && o.normals == MeshNormals::File)
    r.fail(0, "has no vertex normals (its facet normals are not used for shading): use \"normals\": \"average\" "
              "or \"crease_angle_deg\"");
  r.read();
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& f : r.facets)
    for (const glm::dvec3& p : f.corner) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const double tol = o.weld_tolerance >= 0 ? o.weld_tolerance : 1e-6 * glm::length(hi - lo);
  PositionWelder weld(lo, tol);
  PolygonMesh pm;
  int skipped = 0;
  for (const auto& f : r.facets) {
    PolygonMesh::Face pf;
    pf.origin = f.origin;
    for (const glm::dvec3& p : f.corner) {
      pf.position.push_back(weld.add(p, pm.position));
      pf.normal.push_back(-1);
    }
    const glm::dvec3 &a = pm.position[pf.position[0]], &b = pm.position[pf.position[1]], &c = pm.position[pf.position[2]];
    const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    // Zero area: corners welded together, or in a line to within 1e-12 of the longest edge squared.
    if (pf.position[0] == pf.position[1] || pf.position[1] == pf.position[2] || pf.position[2] == pf.position[0] ||
        glm::length(glm::cross(b - a, c - a)) <= 1e-12 * longest * longest) {
      if (strict)
        r.fail(f.origin, "facet of zero area (its corners weld together or lie in a line; skipped without --strict)");
      ++skipped;
      continue;
    }
    pm.faces.push_back(std::move(pf));
  }
  if (pm.faces.empty()) r.fail(0, "every facet has zero area");
  degenerate += skipped;
  SceneObject so = o;
  if (!o.normals_given && o.normals == MeshNormals::File) so.normals = MeshNormals::Average;  // STL's default
  const MeshFail fail = [&r](long origin, const std::string& what) { r.fail(origin, what); };
  resolve_normals(pm, so, fail);
  if (o.max_edge_length > 0) split_long_edges(pm, o.max_edge_length, o.transform.scale, max_faces, fail);
  return indexed_mesh_from_polygons(pm, so, fail);
}

IndexedMesh load_mesh_file(const SceneObject& o, const std::string& where, std::size_t max_faces, bool strict,
                           int& degenerate) {
  std::string ext = o.file.size() >= 4 ? o.file.substr(o.file.size() - 4) : "";
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  const bool stl_name = ext == ".stl", obj_name = ext == ".obj";
  const std::string bytes = read_mesh_file(o, where, stl_name ? "STL" : obj_name ? "OBJ" : "mesh");
  const bool stl = stl_name || (!obj_name && (is_binary_stl(bytes) || starts_with_solid(bytes)));
  if (stl) return stl_mesh_from_bytes(bytes, o, where, max_faces, strict, degenerate);
  if (o.weld_tolerance >= 0)
    throw SceneError(where + ": OBJ file " + quote_input(o.file) +
                     ": weld_tolerance applies to STL files (OBJ faces share vertices by index)");
  return obj_mesh_from_text(bytes, o, where, max_faces);
}

}  // namespace watkins
