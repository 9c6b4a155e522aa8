// OBJ loading: a strict reader of the statements a polygon mesh uses (v, vn, f; vt is checked and
// ignored; every other statement is skipped as OBJ readers do). Written here rather than taken
// from tinyobjloader, whose 2.0.0rc10 keeps a face's vertex count in a byte (a 256-vertex face
// becomes a wrong polygon), reads "nan" and garbage tokens as 0 and wraps indices past 2^63.
#include "mesh_obj.hpp"

#include "mesh_polygons.hpp"

#include <charconv>
#include <utility>


namespace watkins {
namespace {

// The whitespace-separated tokens of one line, comment removed.
std::vector<std::string_view> tokens(std::string_view line) {
  if (const size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r' || line[i] == '\f' || line[i] == '\v')) ++i;
    const size_t b = i;
    while (i < line.size() && !(line[i] == ' ' || line[i] == '\t' || line[i] == '\r' || line[i] == '\f' || line[i] == '\v')) ++i;
    if (i > b) out.push_back(line.substr(b, i - b));
  }
  return out;
}

class ObjReader {
 public:
  ObjReader(const SceneObject& o, std::string where, std::size_t max_faces)
      : o_(o), where_(std::move(where)), max_faces_(max_faces) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw SceneError(where_ + ": OBJ file " + quote_input(o_.file) + (line_ ? ": line " + std::to_string(line_) : "") +
                     ": " + what);
  }

  double number(std::string_view t, const char* what) const {
    double x = 0;
    if (const std::string e = mesh_number(t, x); !e.empty()) fail(std::string(what) + ": " + e);
    return x;
  }

  // An OBJ index: 1-based, or negative (relative to the `count` elements read so far). Returns
  // the 0-based index, which may still be past the end (checked once the file is read).
  long long index(std::string_view t, long long count, const char* what) const {
    long long i = 0;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), i);
    if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size())
      fail(std::string("f: ") + what + " index " + quote_input(std::string(t)) +
           (r.ec == std::errc::result_out_of_range ? " is out of range" : " is not an integer"));
    if (i == 0) fail(std::string("f: ") + what + " index 0 (OBJ indices start at 1)");
    const long long k = i > 0 ? i - 1 : count + i;
    if (k < 0) fail(std::string("f: ") + what + " index " + std::string(t) + " is before the first one");
    return k;
  }

  struct Face {
    std::vector<std::pair<long long, long long>> v;  // (position, normal or -1)
    long line;
  };

  void read(const std::string& text) {
    size_t pos = 0;
    while (pos < text.size()) {
      size_t end = text.find('\n', pos);
      if (end == std::string::npos) end = text.size();
      ++line_;
      statement(std::string_view(text).substr(pos, end - pos));
      pos = end + 1;
    }
    line_ = 0;
  }

  void statement(std::string_view line) {
    if (line.find('\0') != std::string_view::npos) fail("NUL byte (not a text file)");
    const auto t = tokens(line);
    if (t.empty()) return;
    if (t[0] == "v") {
      if (t.size() < 4 || t.size() > 8) fail("v: expected 3 coordinates (and optionally w or r g b)");
      glm::dvec3 p;
      for (int c = 0; c < 3; ++c) p[c] = number(t[1 + c], "v");
      for (size_t k = 4; k < t.size(); ++k) number(t[k], "v");
      position.push_back(p);
    } else if (t[0] == "vn") {
      if (t.size() != 4) fail("vn: expected 3 components");
      glm::dvec3 n;
      for (int c = 0; c < 3; ++c) n[c] = number(t[1 + c], "vn");
      normal.push_back(n);
    } else if (t[0] == "vt") {
      if (t.size() < 2 || t.size() > 4) fail("vt: expected 1 to 3 coordinates");
      for (size_t k = 1; k < t.size(); ++k) number(t[k], "vt");
      ++texcoords_;
    } else if (t[0] == "f") {
      if (t.size() < 4) fail("f: a face needs at least 3 vertices, got " + std::to_string(t.size() - 1));
      const std::size_t n = t.size() - 1;
      // Faces it becomes: a quad stays one (unless split), any other polygon a fan of n - 2.
      const std::size_t made = n == 4 ? (o_.triangles ? 2 : 1) : n - 2;
      faces_made_ += made;
      if (faces_made_ > max_faces_)
        fail("f: the file makes more than " + std::to_string(max_faces_) +
             " faces, the limit left for it (see the pipeline's polygon limit)");
      Face f{{}, line_};
      f.v.reserve(n);
      for (size_t k = 1; k < t.size(); ++k) {
        const std::string_view tok = t[k];
        const size_t s1 = tok.find('/');
        const std::string_view vs = tok.substr(0, s1);
        long long vi = index(vs, static_cast<long long>(position.size()), "vertex");
        long long ni = -1;
        if (s1 != std::string_view::npos) {
          const std::string_view rest = tok.substr(s1 + 1);
          const size_t s2 = rest.find('/');
          const std::string_view ts = rest.substr(0, s2);
          if (!ts.empty()) index(ts, texcoords_, "texture");
          if (s2 != std::string_view::npos) {
            const std::string_view ns = rest.substr(s2 + 1);
            if (ns.find('/') != std::string_view::npos) fail("f: malformed vertex " + quote_input(std::string(tok)));
            if (!ns.empty()) ni = index(ns, static_cast<long long>(normal.size()), "normal");
          }
        }
        f.v.push_back({vi, ni});
      }
      faces.push_back(std::move(f));
    }
    // o, g, s, usemtl, mtllib, l, p and the free-form statements: not a polygon mesh's concern.
  }

  std::vector<glm::dvec3> position, normal;
  std::vector<Face> faces;

 private:
  const SceneObject& o_;
  std::string where_;
  std::size_t max_faces_;
  std::size_t faces_made_ = 0;
  long line_ = 0;
  long long texcoords_ = 0;

 public:
  void at_line(long l) { line_ = l; }
};

}  // namespace

IndexedMesh obj_mesh_from_text(const std::string& text, const SceneObject& o, const std::string& where,
                               std::size_t max_faces) {
  ObjReader r(o, where, max_faces);
  r.read(text);
  const std::vector<glm::dvec3>& pos = r.position;
  const long long npos = static_cast<long long>(pos.size()), nnorm = static_cast<long long>(r.normal.size());
  if (r.faces.empty()) r.fail("has no faces");
  for (const auto& f : r.faces) {
    r.at_line(f.line);
    for (const auto& pv : f.v) {
      if (pv.first >= npos)
        r.fail("f: vertex index " + std::to_string(pv.first + 1) + " is past the last vertex (" +
               std::to_string(npos) + ")");
      if (pv.second >= nnorm)
        r.fail("f: normal index " + std::to_string(pv.second + 1) + " is past the last normal (" +
               std::to_string(nnorm) + ")");
      if (o.normals == MeshNormals::File && pv.second < 0)
        r.fail("f: no vertex normal (use \"normals\": \"average\" for files without vn)");
    }
  }
  r.at_line(0);

  PolygonMesh pm;
  pm.position = std::move(r.position);
  pm.normal = std::move(r.normal);
  pm.faces.reserve(r.faces.size());
  for (const auto& f : r.faces) {
    PolygonMesh::Face pf;
    pf.origin = f.line;
    for (const auto& pv : f.v) {
      pf.position.push_back(static_cast<int>(pv.first));  // < 2^31: the file is at most 64 MiB
      pf.normal.push_back(static_cast<int>(pv.second));
    }
    pm.faces.push_back(std::move(pf));
  }
  const MeshFail fail = [&r](long line, const std::string& what) {
    r.at_line(line);
    r.fail(line ? "f: " + what : what);
  };
  resolve_normals(pm, o, fail);
  if (o.max_edge_length > 0) split_long_edges(pm, o.max_edge_length, o.transform.scale, max_faces, fail);
  return indexed_mesh_from_polygons(pm, o, fail);
}

}  // namespace watkins
