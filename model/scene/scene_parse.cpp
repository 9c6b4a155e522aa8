// JSON -> Scene with strict validation: unknown keys, wrong types, missing keys, out-of-range
// and non-finite numbers are all errors naming the file and the JSON field, so a typo in a
// scene never silently renders something else.
#include <algorithm>
#include <array>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "formats.hpp"
#include "strict_json.hpp"
#include "scene_types.hpp"
#include "patches.hpp"
#include "surfaces.hpp"

namespace watkins {
namespace {

using nlohmann::json;

constexpr double kCoordLimit = fmt::VertexLimit;  // screen-space vertices: [-8192, 8192) pixels

// Largest magnitude of any number in a scene: products of two stay far from overflow (a
// direction, eye or normal of 1e200 would give an infinite length and a NaN camera basis).
constexpr double kMaxMagnitude = 1e9;
// Smallest positive number a positive field takes (its reciprocal stays bounded as well).
constexpr double kMinPositive = 1e-9;
// A patch object's limits: patches, points of an indexed list, interior edges per direction.
constexpr int kMaxPatches = 4096, kMaxControlPoints = 65536, kMaxInteriorEdges = 64;

std::string show(const json& j) { return show_json(j); }

// Field-path aware accessors. `name` is the scene name used as the message prefix.
class Reader {
 public:
  explicit Reader(std::string name) : name_(std::move(name)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw SceneError(name_ + ": " + (field.empty() ? "" : field + ": ") + what);
  }

  void expect_object(const json& j, const std::string& field) const {
    if (!j.is_object()) fail(field, "expected an object, got " + show(j));
  }

  void check_keys(const json& j, const std::string& field,
                  std::initializer_list<const char*> allowed) const {
    for (auto it = j.begin(); it != j.end(); ++it) {
      bool ok = false;
      for (const char* a : allowed) ok = ok || it.key() == a;
      if (!ok) fail(field, "unknown key " + quote_input(it.key()));
    }
  }

  static std::string sub(const std::string& field, const std::string& key) {
    return field.empty() ? key : field + "." + key;
  }

  const json& required(const json& j, const std::string& field, const char* key) const {
    auto it = j.find(key);
    if (it == j.end()) fail(field, std::string("missing required key \"") + key + "\"");
    return *it;
  }

  double number(const json& v, const std::string& field) const {
    if (!v.is_number()) fail(field, "expected a number, got " + show(v));
    double x = v.get<double>();
    if (!std::isfinite(x)) fail(field, "expected a finite number, got " + show(v));
    if (std::fabs(x) > kMaxMagnitude)
      fail(field, "expected a number of magnitude at most " + number_text(kMaxMagnitude) + ", got " + show(v));
    return x;
  }

  // [lo, hi] inclusive; hi_open makes it [lo, hi).
  double number_in(const json& v, const std::string& field, double lo, double hi,
                   bool hi_open = false) const {
    double x = number(v, field);
    if (x < lo || x > hi || (hi_open && x == hi))
      fail(field, "expected a number in [" + number_text(lo) + ", " + number_text(hi) + (hi_open ? ")" : "]") +
                      ", got " + show(v));
    return x;
  }

  double positive(const json& v, const std::string& field) const {
    double x = number(v, field);
    if (!(x >= kMinPositive))
      fail(field, "expected a positive number (at least " + number_text(kMinPositive) + "), got " + show(v));
    return x;
  }

  int integer_in(const json& v, const std::string& field, int lo, int hi) const {
    bool integral = v.is_number_integer() ||
                    (v.is_number_float() && std::isfinite(v.get<double>()) &&
                     std::floor(v.get<double>()) == v.get<double>());
    if (!integral) fail(field, "expected an integer, got " + show(v));
    double x = v.get<double>();
    if (x < lo || x > hi)
      fail(field, "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                      "], got " + show(v));
    return static_cast<int>(x);
  }

  bool boolean(const json& v, const std::string& field) const {
    if (!v.is_boolean()) fail(field, "expected true or false, got " + show(v));
    return v.get<bool>();
  }

  std::string string(const json& v, const std::string& field) const {
    if (!v.is_string()) fail(field, "expected a string, got " + show(v));
    return v.get<std::string>();
  }

  const json& array(const json& v, const std::string& field) const {
    if (!v.is_array()) fail(field, "expected an array, got " + show(v));
    return v;
  }

  glm::dvec3 vec3(const json& v, const std::string& field) const {
    if (!v.is_array() || v.size() != 3) fail(field, "expected an array of 3 numbers, got " + show(v));
    return {number(v[0], field + "[0]"), number(v[1], field + "[1]"), number(v[2], field + "[2]")};
  }

  glm::dvec3 vec3_in(const json& v, const std::string& field, double lo, double hi) const {
    if (!v.is_array() || v.size() != 3) fail(field, "expected an array of 3 numbers, got " + show(v));
    return {number_in(v[0], field + "[0]", lo, hi), number_in(v[1], field + "[1]", lo, hi),
            number_in(v[2], field + "[2]", lo, hi)};
  }

 private:
  std::string name_;
};

// Optional-key helpers: call f(value, field) only when the key is present.
template <typename F>
void opt(const json& j, const std::string& field, const char* key, F f) {
  auto it = j.find(key);
  if (it != j.end()) f(*it, Reader::sub(field, key));
}

void parse_screen(const Reader& r, const json& j, Scene& s) {
  const std::string f = "screen";
  r.expect_object(j, f);
  r.check_keys(j, f, {"width", "height", "background"});
  s.width = r.integer_in(r.required(j, f, "width"), "screen.width", 1, 4096);
  s.height = r.integer_in(r.required(j, f, "height"), "screen.height", 1, 4096);
  opt(j, f, "background", [&](const json& v, const std::string& ff) {
    glm::dvec3 b = r.vec3_in(v, ff, 0, 255);
    for (int c = 0; c < 3; ++c) s.background[c] = b[c];
  });
}

void parse_camera(const Reader& r, const json& j, Camera& cam) {
  const std::string f = "camera";
  r.expect_object(j, f);
  std::string type = r.string(r.required(j, f, "type"), "camera.type");
  if (type == "gouraud") {
    cam.type = Camera::Type::Gouraud;
    r.check_keys(j, f, {"type", "focal", "near", "far"});
    opt(j, f, "focal", [&](const json& v, const std::string& ff) { cam.focal = r.positive(v, ff); });
  } else if (type == "lookat") {
    cam.type = Camera::Type::LookAt;
    r.check_keys(j, f, {"type", "eye", "target", "up", "fov_deg", "near", "far"});
    cam.eye = r.vec3(r.required(j, f, "eye"), "camera.eye");
    cam.target = r.vec3(r.required(j, f, "target"), "camera.target");
    opt(j, f, "up", [&](const json& v, const std::string& ff) { cam.up = r.vec3(v, ff); });
    double fov = 40;
    opt(j, f, "fov_deg", [&](const json& v, const std::string& ff) {
      fov = r.number_in(v, ff, 1, 179);
    });
    cam.focal = 1.0 / std::tan(fov * (3.14159265358979323846 / 360.0));  // horizontal fov
    glm::dvec3 fwd = cam.target - cam.eye;
    double fl = std::sqrt(fwd.x * fwd.x + fwd.y * fwd.y + fwd.z * fwd.z);
    if (!(fl > 1e-12)) r.fail("camera.target", "must differ from camera.eye");
    fwd /= fl;
    glm::dvec3 up = cam.up;
    double ul = std::sqrt(up.x * up.x + up.y * up.y + up.z * up.z);
    if (!(ul > 1e-12)) r.fail("camera.up", "must be a non-zero vector");
    double cosang = (fwd.x * up.x + fwd.y * up.y + fwd.z * up.z) / ul;
    if (std::fabs(cosang) > 0.9999) r.fail("camera.up", "must not be parallel to the viewing direction");
  } else {
    r.fail("camera.type", "expected \"gouraud\" or \"lookat\", got " + show(j["type"]));
  }
  opt(j, f, "near", [&](const json& v, const std::string& ff) { cam.near = r.positive(v, ff); });
  opt(j, f, "far", [&](const json& v, const std::string& ff) { cam.far = r.positive(v, ff); });
  if (!(cam.far > cam.near)) r.fail("camera.far", "must be greater than camera.near (" + number_text(cam.near) + ")");
  // 1 - near/Z must stay distinguishable from 1 in double precision, with a wide margin.
  if (cam.far / cam.near > 1e7) r.fail("camera.far", "far/near ratio above 1e7");
}

void parse_light(const Reader& r, const json& j, Light& l) {
  const std::string f = "light";
  r.expect_object(j, f);
  std::string type = r.string(r.required(j, f, "type"), "light.type");
  if (type == "eye") {
    l.type = Light::Type::Eye;
    r.check_keys(j, f, {"type"});
  } else if (type == "directional") {
    l.type = Light::Type::Directional;
    r.check_keys(j, f, {"type", "direction"});
    glm::dvec3 d = r.vec3(r.required(j, f, "direction"), "light.direction");
    double len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (!(len > 1e-12)) r.fail("light.direction", "must be a non-zero vector");
    l.towards = d / len;
  } else {
    r.fail("light.type", "expected \"directional\" or \"eye\", got " + show(j["type"]));
  }
}

void parse_shading(const Reader& r, const json& j, Shading& s) {
  const std::string f = "shading";
  r.expect_object(j, f);
  r.check_keys(j, f, {"mode", "rule", "depth", "interpolation", "depth_tie", "cull_backfaces", "specular_m", "flat",
                     "smooth"});
  opt(j, f, "mode", [&](const json& v, const std::string& ff) {
    auto mode = parse_shading_mode(r.string(v, ff));
    if (!mode) r.fail(ff, "expected \"gouraud\" or \"phong\", got " + show(v));
    s.mode = *mode;
  });
  opt(j, f, "rule", [&](const json& v, const std::string& ff) {
    auto rule = parse_shading_rule(r.string(v, ff));
    if (!rule)
      r.fail(ff, "expected \"gouraud\", \"lambert\", \"warnock\", \"romney\" or \"phong\", got " + show(v));
    s.rule = *rule;
  });
  opt(j, f, "depth", [&](const json& v, const std::string& ff) {
    auto d = parse_depth_mode(r.string(v, ff));
    if (!d) r.fail(ff, "expected \"inverse-z\" or \"z\", got " + show(v));
    s.depth = *d;
  });
  opt(j, f, "interpolation", [&](const json& v, const std::string& ff) {
    auto i = parse_interpolation(r.string(v, ff));
    if (!i) r.fail(ff, "expected \"eq1\" or \"eq2\", got " + show(v));
    s.interpolation = *i;
  });
  // Eq. (2) divides by the interpolated Z: its depth channel carries Z, never 1/Z.
  if (s.interpolation == Interpolation::Eq2) {
    if (j.contains("depth") && s.depth == DepthMode::InverseZ)
      r.fail(f + ".depth", "\"inverse-z\" contradicts \"interpolation\": \"eq2\", which divides by the "
                           "interpolated Z (give \"z\" or leave it out)");
    s.depth = DepthMode::Z;
  }
  opt(j, f, "depth_tie", [&](const json& v, const std::string& ff) {
    auto t = parse_depth_tie(r.string(v, ff));
    if (!t) r.fail(ff, "expected \"arrival\" or \"submission\", got " + show(v));
    s.depth_tie = *t;
  });
  opt(j, f, "cull_backfaces", [&](const json& v, const std::string& ff) { s.cull_backfaces = r.boolean(v, ff); });
  opt(j, f, "flat", [&](const json& v, const std::string& ff) { s.flat = r.boolean(v, ff); });
  // W of the smoother's word: 0 .. fmt::SmoothWMax.
  opt(j, f, "smooth", [&](const json& v, const std::string& ff) { s.smooth = r.number_in(v, ff, 0, fmt::SmoothWMax); });
  opt(j, f, "specular_m", [&](const json& v, const std::string& ff) { s.specular_m = r.number_in(v, ff, 1, 1000); });
}

std::map<std::string, Material> parse_materials(const Reader& r, const json& j) {
  const std::string f = "materials";
  r.expect_object(j, f);
  std::map<std::string, Material> out;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string mf = f + "." + field_key(it.key());
    const json& m = it.value();
    r.expect_object(m, mf);
    r.check_keys(m, mf, {"color", "d", "W", "n", "rule"});
    Material mat;
    mat.name = it.key();
    mat.color = r.vec3_in(r.required(m, mf, "color"), mf + ".color", 0, 1);
    // Whitted's S = hue (.25 + .75 N.I) + glossiness (R.I)^60 is eq. (3) with d = 0.25, n = 60,
    // Cp = hue and W = glossiness (docs/reference/whitted.md): the rule fixes d and n.
    opt(m, mf, "rule", [&](const json& v, const std::string& ff) {
      if (r.string(v, ff) != "whitted") r.fail(ff, "expected \"whitted\", got " + show(v));
      for (const char* k : {"d", "n"})
        if (m.contains(k)) r.fail(mf + "." + k, "\"rule\": \"whitted\" fixes d = 0.25 and n = 60; leave it out");
      mat.d = 0.25, mat.n = 60;
    });
    opt(m, mf, "d", [&](const json& v, const std::string& ff) { mat.d = r.number_in(v, ff, 0, 1); });
    // W up to 511/256: the phong_shader's MaterialBits word (specular may saturate the level).
    opt(m, mf, "W", [&](const json& v, const std::string& ff) { mat.W = r.number_in(v, ff, 0, 511.0 / 256); });
    opt(m, mf, "n", [&](const json& v, const std::string& ff) { mat.n = r.number_in(v, ff, 0, 1000); });
    out[it.key()] = mat;
  }
  return out;
}

void parse_transform(const Reader& r, const json& j, const std::string& f, Transform& t) {
  opt(j, f, "translate", [&](const json& v, const std::string& ff) { t.translate = r.vec3(v, ff); });
  opt(j, f, "rotate_deg", [&](const json& v, const std::string& ff) { t.rotate_deg = r.vec3(v, ff); });
  opt(j, f, "scale", [&](const json& v, const std::string& ff) {
    if (v.is_number()) {
      double s = r.positive(v, ff);
      t.scale = glm::dvec3(s);
    } else {
      t.scale = r.vec3(v, ff);
      for (int c = 0; c < 3; ++c)
        if (!(t.scale[c] >= kMinPositive))
          r.fail(ff + "[" + std::to_string(c) + "]", "expected a positive number (at least " +
                                                      number_text(kMinPositive) + "), got " + number_text(t.scale[c]));
    }
  });
}

// A screen-space polygon. "rgb" (Gouraud) and "normal" (Phong) are each optional here; the first
// vertex lacking one is recorded in `o` and rejected by the builder when its mode needs it.
ScreenPolygon parse_screen_polygon(const Reader& r, const json& j, const std::string& f, SceneObject& o) {
  r.expect_object(j, f);
  r.check_keys(j, f, {"vertices"});
  const json& vs = r.array(r.required(j, f, "vertices"), f + ".vertices");
  if (vs.size() < 3 || vs.size() > 4)
    r.fail(f, "a polygon has 3 or 4 vertices, got " + std::to_string(vs.size()));
  ScreenPolygon p;
  for (size_t k = 0; k < vs.size(); ++k) {
    const std::string vf = f + ".vertices[" + std::to_string(k) + "]";
    const json& v = vs[k];
    r.expect_object(v, vf);
    r.check_keys(v, vf, {"x", "y", "depth", "rgb", "normal"});
    ScreenVertex sv;
    for (const char* key : {"x", "y"}) {
      const std::string cf = vf + "." + key;
      double x = r.number(r.required(v, vf, key), cf);
      if (x < -kCoordLimit || x >= kCoordLimit)
        r.fail(cf, number_text(x) + " is outside the representable range [" + number_text(-kCoordLimit) + ", " + number_text(kCoordLimit) + ") pixels");
      (key[0] == 'x' ? sv.x : sv.y) = x;
    }
    sv.depth = r.number_in(r.required(v, vf, "depth"), vf + ".depth", 0, 1, true);
    opt(v, vf, "rgb", [&](const json& jv, const std::string& ff) {
      const glm::dvec3 c = r.vec3_in(jv, ff, 0, 255);
      for (int ch = 0; ch < 3; ++ch) sv.rgb[ch] = c[ch];
    });
    // Camera-space normal (any non-zero length, stored as a unit vector), not turned: passed through.
    opt(v, vf, "normal", [&](const json& jv, const std::string& ff) {
      const glm::dvec3 n = r.vec3(jv, ff);
      const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
      if (!(len > 1e-12)) r.fail(ff, "must be a non-zero vector");
      for (int ch = 0; ch < 3; ++ch) sv.normal[ch] = n[ch] / len;
    });
    if (!v.contains("rgb") && o.vertex_without_rgb.empty()) o.vertex_without_rgb = vf;
    if (!v.contains("normal") && o.vertex_without_normal.empty()) o.vertex_without_normal = vf;
    p.v.push_back(sv);
  }
  // A zero-area polygon is skipped (and counted) by the builder as GL skips it; fatal only with
  // BuildOptions::strict.
  return p;
}

const Material& find_material(const Reader& r, const std::map<std::string, Material>& mats, const json& v,
                              const std::string& field) {
  const std::string name = r.string(v, field);
  auto m = mats.find(name);
  if (m == mats.end()) r.fail(field, "unknown material " + quote_input(name));
  return m->second;
}

// A "voxels" object: a raw density file thresholded, or a built-in phantom, on a grid of `dims`
// voxels of `spacing` (voxels.hpp). The surface is extracted here so that a bad volume is refused at
// its field, before anything is built.
void parse_voxels(const Reader& r, const json& j, const std::string& f, const std::string& base_dir, SceneObject& o) {
  // Voxel faces meet at right angles only: a crease angle would be all or nothing, which "normals" says.
  if (j.contains("crease_angle_deg"))
    r.fail(f + ".crease_angle_deg", "voxel faces meet at 90 degrees: choose \"normals\": \"face\" or \"average\"");
  const bool has_file = j.contains("file"), has_phantom = j.contains("phantom");
  if (has_file == has_phantom) r.fail(f, "give exactly one of \"file\" (a raw density volume) or \"phantom\"");
  std::array<int, 3> dims{};
  const std::string df = f + ".dims";
  const json& d = r.required(j, f, "dims");
  if (!d.is_array() || d.size() != 3) r.fail(df, "expected an array of 3 integers [nx, ny, nz], got " + show(d));
  for (std::size_t a = 0; a < 3; ++a) dims[a] = r.integer_in(d[a], df + "[" + std::to_string(a) + "]", 1, 1024);
  const std::size_t voxels = std::size_t(dims[0]) * std::size_t(dims[1]) * std::size_t(dims[2]);
  if (voxels > (std::size_t{1} << 24))
    r.fail(df, std::to_string(voxels) + " voxels, over the limit of " + std::to_string(std::size_t{1} << 24));
  glm::dvec3 spacing(1.0);
  opt(j, f, "spacing", [&](const json& v, const std::string& ff) {
    spacing = r.vec3(v, ff);
    for (int a = 0; a < 3; ++a)
      if (!(spacing[a] >= kMinPositive)) r.positive(v[std::size_t(a)], ff + "[" + std::to_string(a) + "]");
  });
  o.normals = MeshNormals::Face;
  opt(j, f, "normals", [&](const json& v, const std::string& ff) {
    const std::string n = r.string(v, ff);
    if (n == "face") o.normals = MeshNormals::Face;
    else if (n == "average") o.normals = MeshNormals::Average;
    else r.fail(ff, "expected \"face\" or \"average\", got " + show(v));
  });
  std::string limit_field = df;  // what to change when the surface has too many faces
  if (has_phantom) {
    for (const char* k : {"format", "threshold"})
      if (j.contains(k)) r.fail(Reader::sub(f, k), "applies to a raw \"file\" only, not to a phantom");
    const std::string pf = f + ".phantom", name = r.string(j["phantom"], pf);
    PhantomShape shape = PhantomShape::Ellipsoid;
    if (name == "ellipsoid") shape = PhantomShape::Ellipsoid;
    else if (name == "beaded_sphere") shape = PhantomShape::BeadedSphere;
    else if (name == "two_lobed") shape = PhantomShape::TwoLobed;
    else r.fail(pf, "expected \"ellipsoid\", \"beaded_sphere\" or \"two_lobed\", got " + show(j["phantom"]));
    // Default size: the phantom reaches to 90% of the grid's half extent along every axis.
    const double reach = make_phantom(shape, glm::dvec3(1.0)).extent;
    glm::dvec3 size(0.0);
    for (int a = 0; a < 3; ++a) size[a] = 0.45 * dims[std::size_t(a)] * spacing[a] / reach;
    opt(j, f, "size", [&](const json& v, const std::string& ff) {
      if (v.is_number()) {
        size = glm::dvec3(r.positive(v, ff));
        return;
      }
      size = r.vec3(v, ff);
      for (int a = 0; a < 3; ++a)
        if (!(size[a] >= kMinPositive)) r.positive(v[std::size_t(a)], ff + "[" + std::to_string(a) + "]");
    });
    o.has_phantom = true;
    o.phantom = make_phantom(shape, size);
    o.voxels = std::make_shared<const VoxelGrid>(voxelize(o.phantom, dims, spacing));
  } else {
    if (j.contains("size")) r.fail(f + ".size", "applies to a phantom only");
    const std::string ff = f + ".file", file = r.string(j["file"], ff);
    if (file.empty()) r.fail(ff, "must not be empty");
    std::filesystem::path p(file);
    const std::string path = p.is_absolute() || base_dir.empty() ? p.string() : (std::filesystem::path(base_dir) / p).string();
    int bytes = 1;
    opt(j, f, "format", [&](const json& v, const std::string& fmtf) {
      const std::string s = r.string(v, fmtf);
      if (s == "u8") bytes = 1;
      else if (s == "u16") bytes = 2;
      else r.fail(fmtf, "expected \"u8\" or \"u16\" (little-endian), got " + show(v));
    });
    const double threshold = r.number_in(r.required(j, f, "threshold"), f + ".threshold", 0, bytes == 1 ? 255 : 65535);
    std::error_code ec;
    const std::uintmax_t have = std::filesystem::is_regular_file(path, ec) ? std::filesystem::file_size(path, ec) : 0;
    if (ec || !std::filesystem::is_regular_file(path, ec)) r.fail(ff, quote_input(path) + " is not a readable regular file");
    const std::size_t need = voxels * std::size_t(bytes);
    if (have != need)
      r.fail(ff, quote_input(path) + " holds " + std::to_string(have) + " bytes; dims [" + std::to_string(dims[0]) + ", " +
                     std::to_string(dims[1]) + ", " + std::to_string(dims[2]) + "] of " + (bytes == 1 ? "u8" : "u16") +
                     " need " + std::to_string(need));
    std::vector<std::uint8_t> raw(need);
    std::FILE* in = std::fopen(path.c_str(), "rb");
    const bool ok = in && std::fread(raw.data(), 1, need, in) == need;
    if (in) std::fclose(in);
    if (!ok) r.fail(ff, "cannot read " + quote_input(path));
    o.voxels = std::make_shared<const VoxelGrid>(threshold_volume(raw, bytes, dims, spacing, threshold));
    o.file = path;  // the run's inputs include it (files_read)
    limit_field = f + ".threshold";
  }
  const std::size_t faces = o.voxels->boundary_faces() * (o.triangles ? 2 : 1);
  if (faces == 0) r.fail(limit_field, "no voxel is inside: the surface is empty");
  if (faces > std::size_t(fmt::MaxPolygons))
    r.fail(limit_field, "the surface has " + std::to_string(faces) + " voxel faces" + (o.triangles ? " (as triangles)" : "") +
                            ", over the pipeline's " + std::to_string(fmt::MaxPolygons) + " polygons");
}

// Whitted's interior edges "k_u", "k_v": a count of equal parts (n: edges at i/n, i = 1..n-1) or a
// list of parameters, ascending, in (0, 1).
void parse_interior_edges(const Reader& r, const json& j, const std::string& f, SceneObject& o) {
  for (const char* key : {"k_u", "k_v"})
    opt(j, f, key, [&](const json& v, const std::string& ff) {
      std::vector<double>& k = key[2] == 'u' ? o.k_u : o.k_v;
      if (v.is_number()) {
        const int n = r.integer_in(v, ff, 1, kMaxInteriorEdges + 1);
        for (int i = 1; i < n; ++i) k.push_back(static_cast<double>(i) / n);
        return;
      }
      if (!v.is_array()) r.fail(ff, "expected a count of equal parts or an array of parameters in (0, 1), got " + show(v));
      if (v.size() > std::size_t(kMaxInteriorEdges))
        r.fail(ff, "at most " + std::to_string(kMaxInteriorEdges) + " interior edges, got " + std::to_string(v.size()));
      for (std::size_t i = 0; i < v.size(); ++i) {
        const std::string kf = ff + "[" + std::to_string(i) + "]";
        const double x = r.number(v[i], kf);
        if (!(x > 0 && x < 1)) r.fail(kf, "expected a parameter in (0, 1), got " + show(v[i]));
        if (!k.empty() && !(x > k.back())) r.fail(kf, "must be greater than the one before (" + number_text(k.back()) + ")");
        k.push_back(x);
      }
    });
}

// "draw": how a patch object is drawn, "polygons" (tessellated, the default) or "curves" (Whitted's
// edge description, model/curves).
void parse_draw(const Reader& r, const json& j, const std::string& f, SceneObject& o) {
  opt(j, f, "draw", [&](const json& v, const std::string& ff) {
    const std::string d = r.string(v, ff);
    if (d != "curves" && d != "polygons") r.fail(ff, "expected \"curves\" or \"polygons\", got " + show(v));
    o.draw_curves = d == "curves";
  });
}

// A "patches" object: Bezier patches (16 indices into "control_points" each, or 16 points each) or
// a uniform B-spline "control_net" of rows of points, every patch resolved into Bezier form.
void parse_patches(const Reader& r, const json& j, const std::string& f, SceneObject& o) {
  const std::string bf = f + ".basis", basis = r.string(r.required(j, f, "basis"), bf);
  if (basis == "bezier") {
    for (const char* k : {"control_net", "closed_u", "closed_v"})
      if (j.contains(k)) r.fail(Reader::sub(f, k), "applies to \"basis\": \"bspline\" only");
    std::vector<glm::dvec3> points;
    opt(j, f, "control_points", [&](const json& v, const std::string& ff) {
      r.array(v, ff);
      if (v.empty() || v.size() > std::size_t(kMaxControlPoints))
        r.fail(ff, "expected 1 to " + std::to_string(kMaxControlPoints) + " points, got " + std::to_string(v.size()));
      for (std::size_t k = 0; k < v.size(); ++k) points.push_back(r.vec3(v[k], ff + "[" + std::to_string(k) + "]"));
    });
    const std::string pf = f + ".patches";
    const json& ps = r.array(r.required(j, f, "patches"), pf);
    if (ps.empty() || ps.size() > std::size_t(kMaxPatches))
      r.fail(pf, "expected 1 to " + std::to_string(kMaxPatches) + " patches, got " + std::to_string(ps.size()));
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const std::string ef = pf + "[" + std::to_string(i) + "]";
      const json& e = ps[i];
      if (!e.is_array() || e.size() != 16)
        r.fail(ef, "expected 16 control point indices or 16 points (4 rows of 4), got " + show(e));
      BicubicPatch patch;
      const bool indexed = e[0].is_number();
      if (indexed && points.empty()) r.fail(ef, "indices need \"control_points\"");
      for (std::size_t k = 0; k < 16; ++k) {
        const std::string kf = ef + "[" + std::to_string(k) + "]";
        if (indexed) patch[k] = points[std::size_t(r.integer_in(e[k], kf, 0, int(points.size()) - 1))];
        else patch[k] = r.vec3(e[k], kf);
      }
      o.patches.push_back(patch);
    }
  } else if (basis == "bspline") {
    for (const char* k : {"control_points", "patches"})
      if (j.contains(k)) r.fail(Reader::sub(f, k), "applies to \"basis\": \"bezier\" only (a B-spline object has a \"control_net\")");
    bool closed_u = false, closed_v = false;
    opt(j, f, "closed_u", [&](const json& v, const std::string& ff) { closed_u = r.boolean(v, ff); });
    opt(j, f, "closed_v", [&](const json& v, const std::string& ff) { closed_v = r.boolean(v, ff); });
    const std::string nf = f + ".control_net";
    const json& net = r.array(r.required(j, f, "control_net"), nf);
    // A patch spans 4 x 4 points; a closed direction needs 3 (the net wraps around).
    const int min_rows = closed_v ? 3 : 4, min_cols = closed_u ? 3 : 4;
    if (net.size() < std::size_t(min_rows) || net.size() > 1024)
      r.fail(nf, "expected " + std::to_string(min_rows) + " to 1024 rows, got " + std::to_string(net.size()));
    std::vector<glm::dvec3> points;
    std::size_t cols = 0;
    for (std::size_t row = 0; row < net.size(); ++row) {
      const std::string rf = nf + "[" + std::to_string(row) + "]";
      const json& pts = r.array(net[row], rf);
      if (row == 0) cols = pts.size();
      if (pts.size() != cols)
        r.fail(rf, "every row has as many points as the first (" + std::to_string(cols) + "), got " + std::to_string(pts.size()));
      if (cols < std::size_t(min_cols) || cols > 1024)
        r.fail(rf, "expected " + std::to_string(min_cols) + " to 1024 points in a row, got " + std::to_string(cols));
      for (std::size_t k = 0; k < cols; ++k) points.push_back(r.vec3(pts[k], rf + "[" + std::to_string(k) + "]"));
    }
    const std::size_t count = (closed_v ? net.size() : net.size() - 3) * (closed_u ? cols : cols - 3);
    if (count > std::size_t(kMaxPatches))
      r.fail(nf, "makes " + std::to_string(count) + " patches, over the limit of " + std::to_string(kMaxPatches));
    o.patches = bspline_patches(points, int(net.size()), int(cols), closed_u, closed_v);
  } else {
    r.fail(bf, "expected \"bezier\" or \"bspline\", got " + show(j["basis"]));
  }
}

SceneObject parse_object(const Reader& r, const json& j, const std::string& f, int index,
                         const std::map<std::string, Material>& mats, const std::string& base_dir) {
  r.expect_object(j, f);
  SceneObject o;
  o.field = f;
  const std::string type = r.string(r.required(j, f, "type"), f + ".type");
  // Keys every camera-space object accepts.
  auto common = [&](std::initializer_list<const char*> extra) {
    // crease_angle_deg: meshes and the tessellated analytic surfaces alike.
    std::vector<const char*> keys = {"type", "material", "translate", "rotate_deg", "scale", "triangles",
                                     "crease_angle_deg"};
    keys.insert(keys.end(), extra.begin(), extra.end());
    for (auto it = j.begin(); it != j.end(); ++it) {
      bool ok = false;
      for (const char* a : keys) ok = ok || it.key() == a;
      if (!ok) r.fail(f, "unknown key " + quote_input(it.key()));
    }
    opt(j, f, "material", [&](const json& v, const std::string& ff) { o.material = find_material(r, mats, v, ff); });
    parse_transform(r, j, f, o.transform);
    opt(j, f, "triangles", [&](const json& v, const std::string& ff) { o.triangles = r.boolean(v, ff); });
  };
  auto uv = [&](int umin, int udef, int vmin, int vdef) {
    o.u = udef;
    o.v = vdef;
    opt(j, f, "u", [&](const json& v, const std::string& ff) { o.u = r.integer_in(v, ff, umin, 1024); });
    opt(j, f, "v", [&](const json& v, const std::string& ff) { o.v = r.integer_in(v, ff, vmin, 1024); });
    // "max_edge_length" (world units) chooses the segments instead: giving both is an error.
    opt(j, f, "max_edge_length", [&](const json& v, const std::string& ff) {
      for (const char* k : {"u", "v"})
        if (j.contains(k)) r.fail(ff, std::string("give either \"") + k + "\" or \"max_edge_length\", not both");
      o.max_edge_length = r.positive(v, ff);
    });
  };
  // A plan size: one number (square) or [x, z].
  auto plan = [&](const json& v, const std::string& ff, double& x, double& z) {
    if (v.is_number()) {
      x = z = r.positive(v, ff);
      return;
    }
    if (!v.is_array() || v.size() != 2) r.fail(ff, "expected a number or an array of 2 numbers [x, z], got " + show(v));
    x = r.positive(v[0], ff + "[0]");
    z = r.positive(v[1], ff + "[1]");
  };
  // The barrels' rise: by default a half circle over the narrower span.
  auto rise = [&]() {
    o.rise = std::min(o.span_x, o.span_z) / 2;
    opt(j, f, "rise", [&](const json& v, const std::string& ff) { o.rise = r.positive(v, ff); });
  };

  if (type == "sphere") {
    o.type = ObjectType::Sphere;
    common({"center", "radius", "u", "v", "max_edge_length"});
    opt(j, f, "center", [&](const json& v, const std::string& ff) { o.center = r.vec3(v, ff); });
    o.radius = r.positive(r.required(j, f, "radius"), f + ".radius");
    uv(3, 24, 2, 12);
  } else if (type == "cone") {
    o.type = ObjectType::Cone;
    common({"center", "radius", "height", "u", "v", "max_edge_length", "cap"});
    opt(j, f, "center", [&](const json& v, const std::string& ff) { o.center = r.vec3(v, ff); });
    o.radius = r.positive(r.required(j, f, "radius"), f + ".radius");
    o.height = r.positive(r.required(j, f, "height"), f + ".height");
    opt(j, f, "cap", [&](const json& v, const std::string& ff) { o.cap = r.boolean(v, ff); });
    uv(3, 12, 1, 1);
  } else if (type == "quarter_torus") {
    o.type = ObjectType::QuarterTorus;
    common({"major_radius", "minor_radius", "u", "v", "max_edge_length"});
    o.major_radius = r.positive(r.required(j, f, "major_radius"), f + ".major_radius");
    o.minor_radius = r.positive(r.required(j, f, "minor_radius"), f + ".minor_radius");
    if (!(o.minor_radius < o.major_radius))
      r.fail(f + ".minor_radius", "must be smaller than major_radius (" + number_text(o.major_radius) + ")");
    uv(2, 12, 3, 16);
  } else if (type == "hyperbolic_paraboloid") {
    o.type = ObjectType::HyperbolicParaboloid;
    common({"c", "size", "u", "v", "max_edge_length"});
    o.c = r.number(r.required(j, f, "c"), f + ".c");
    if (o.c == 0) r.fail(f + ".c", "must be non-zero");
    o.size = r.positive(r.required(j, f, "size"), f + ".size");
    uv(2, 12, 2, 12);
  } else if (type == "bezier_patch") {
    o.type = ObjectType::BezierPatch;
    common({"control_points", "k_u", "k_v", "u", "v", "max_edge_length", "draw"});
    const std::string cf = f + ".control_points";
    const json& cp = r.array(r.required(j, f, "control_points"), cf);
    if (cp.size() != 16) r.fail(cf, "expected 16 points (4 rows of 4), got " + std::to_string(cp.size()));
    BicubicPatch patch;
    for (size_t k = 0; k < 16; ++k) patch[k] = r.vec3(cp[k], cf + "[" + std::to_string(k) + "]");
    o.patches.push_back(patch);
    parse_interior_edges(r, j, f, o);
    parse_draw(r, j, f, o);
    uv(2, 12, 2, 12);
  } else if (type == "patches") {
    o.type = ObjectType::Patches;
    common({"basis", "control_points", "patches", "control_net", "closed_u", "closed_v", "k_u", "k_v", "u", "v",
            "max_edge_length", "draw"});
    parse_patches(r, j, f, o);
    parse_interior_edges(r, j, f, o);
    parse_draw(r, j, f, o);
    uv(2, 8, 2, 8);
  } else if (type == "cross_vault") {
    o.type = ObjectType::CrossVault;
    common({"span", "rise", "u", "v", "max_edge_length"});
    plan(r.required(j, f, "span"), f + ".span", o.span_x, o.span_z);
    rise();
    uv(2, 16, 1, 1);  // v = 1: the barrels are straight along their axes
    if (o.u % 2) r.fail(f + ".u", "must be even (the key of the vault is a vertex), got " + std::to_string(o.u));
  } else if (type == "pier") {
    o.type = ObjectType::Pier;
    common({"center", "size", "height", "max_edge_length"});
    opt(j, f, "center", [&](const json& v, const std::string& ff) { o.center = r.vec3(v, ff); });
    plan(r.required(j, f, "size"), f + ".size", o.pier_x, o.pier_z);
    o.pier_height = r.positive(r.required(j, f, "height"), f + ".height");
    opt(j, f, "max_edge_length", [&](const json& v, const std::string& ff) { o.max_edge_length = r.positive(v, ff); });
  } else if (type == "portico") {
    o.type = ObjectType::Portico;
    common({"bays", "span", "rise", "pier", "springing", "u", "v", "max_edge_length"});
    o.bays = r.integer_in(r.required(j, f, "bays"), f + ".bays", 1, 64);
    plan(r.required(j, f, "span"), f + ".span", o.span_x, o.span_z);
    rise();
    o.pier_x = o.pier_z = std::min(o.span_x, o.span_z) / 8;
    opt(j, f, "pier", [&](const json& v, const std::string& ff) { plan(v, ff, o.pier_x, o.pier_z); });
    if (!(o.pier_x < o.span_x && o.pier_z < o.span_z))
      r.fail(f + ".pier", "must be smaller than the span in x and in z (the piers would fill the bays)");
    o.pier_height = r.positive(r.required(j, f, "springing"), f + ".springing");
    uv(2, 16, 1, 1);  // v = 1: the barrels are straight along their axes
    if (o.u % 2) r.fail(f + ".u", "must be even (the key of the vault is a vertex), got " + std::to_string(o.u));
  } else if (type == "mesh") {
    o.type = ObjectType::Mesh;
    common({"file", "normals", "max_edge_length", "weld_tolerance"});
    std::string file = r.string(r.required(j, f, "file"), f + ".file");
    if (file.empty()) r.fail(f + ".file", "must not be empty");
    std::filesystem::path p(file);
    o.file = p.is_absolute() || base_dir.empty() ? p.string() : (std::filesystem::path(base_dir) / p).string();
    opt(j, f, "normals", [&](const json& v, const std::string& ff) {
      std::string n = r.string(v, ff);
      if (n == "file") o.normals = MeshNormals::File;
      else if (n == "average") o.normals = MeshNormals::Average;
      else r.fail(ff, "expected \"file\" or \"average\", got " + show(v));
    });
    o.normals_given = j.contains("normals");
    opt(j, f, "max_edge_length", [&](const json& v, const std::string& ff) { o.max_edge_length = r.positive(v, ff); });
    opt(j, f, "weld_tolerance", [&](const json& v, const std::string& ff) {
      o.weld_tolerance = r.number_in(v, ff, 0, kMaxMagnitude);
      if (o.weld_tolerance > 0 && o.weld_tolerance < kMinPositive)
        r.fail(ff, "expected 0 (exact) or at least " + number_text(kMinPositive) + ", got " + show(v));
    });
  } else if (type == "voxels") {
    o.type = ObjectType::Voxels;
    common({"file", "format", "threshold", "phantom", "size", "dims", "spacing", "normals"});
    parse_voxels(r, j, f, base_dir, o);
  } else if (type == "polygons") {
    o.type = ObjectType::Polygons;
    r.check_keys(j, f, {"type", "polygons", "material"});
    opt(j, f, "material", [&](const json& v, const std::string& ff) { o.material = find_material(r, mats, v, ff); });
    const std::string pf = f + ".polygons";
    const json& ps = r.array(r.required(j, f, "polygons"), pf);
    for (size_t k = 0; k < ps.size(); ++k) {
      ScreenPolygon p = parse_screen_polygon(r, ps[k], pf + "[" + std::to_string(k) + "]", o);
      p.object = index;
      o.polygons.push_back(std::move(p));
    }
  } else {
    r.fail(f + ".type",
           "unknown object type " + show(j["type"]) +
               " (expected sphere, cone, quarter_torus, hyperbolic_paraboloid, bezier_patch, patches, cross_vault, pier, "
               "portico, "
               "mesh, voxels or polygons)");
  }
  // A mesh's or a tessellated surface's normals from its faces by the crease rule (instead of
  // the file's or the exact ones). Voxels refuse the key in parse_voxels.
  if (o.type != ObjectType::Polygons && o.type != ObjectType::Voxels)
    opt(j, f, "crease_angle_deg", [&](const json& v, const std::string& ff) {
      if (o.normals_given)
        r.fail(ff, "crease_angle_deg chooses the normals (smoothed across edges sharper than it): leave out \"normals\"");
      o.crease_angle_deg = r.number_in(v, ff, 0, 180);
      o.normals = MeshNormals::Crease;
    });
  if (const std::string e = choose_tessellation(o); !e.empty()) r.fail(f + ".max_edge_length", e);
  return o;
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& name, const std::string& base_dir) {
  // Comments are allowed so shipped scenes can explain themselves.
  const json root = parse_strict_json(text, name, /*comments=*/true);
  Reader r(name);
  Scene s;
  s.name = name;
  r.expect_object(root, "");
  r.check_keys(root, "", {"screen", "camera", "light", "shading", "materials", "objects"});
  parse_screen(r, r.required(root, "", "screen"), s);
  opt(root, "", "camera", [&](const json& v, const std::string&) { parse_camera(r, v, s.camera); });
  opt(root, "", "light", [&](const json& v, const std::string&) { parse_light(r, v, s.light); });
  opt(root, "", "shading", [&](const json& v, const std::string&) { parse_shading(r, v, s.shading); });
  std::map<std::string, Material> mats;
  opt(root, "", "materials", [&](const json& v, const std::string&) { mats = parse_materials(r, v); });
  const json& objs = r.array(r.required(root, "", "objects"), "objects");
  for (size_t i = 0; i < objs.size(); ++i)
    s.objects.push_back(parse_object(r, objs[i], "objects[" + std::to_string(i) + "]",
                                     static_cast<int>(i), mats, base_dir));
  return s;
}

}  // namespace watkins
