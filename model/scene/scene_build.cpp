// Scene -> screen-space polygons: object and camera transforms, projection, near/far
// rejection, degenerate and back-face removal, and the per-vertex shading rules.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "camera.hpp"
#include "formats.hpp"
#include "illumination.hpp"
#include "mesh_polygons.hpp"
#include "mesh_stl.hpp"
#include "patches.hpp"
#include "scene.hpp"
#include "scene_types.hpp"
#include "surfaces.hpp"
#include "whitted_edges.hpp"

namespace watkins {

const std::string& default_scene_text() {
  static const std::string s =
#include "default_scene.inc"
      ;
  return s;
}

BuiltScene load_scene_or_default(const std::string& path, const BuildOptions& opt) {
  return path.empty() ? load_scene_text(default_scene_text(), "<default scene>", ".", opt)
                      : load_scene(path, opt);
}

namespace {

constexpr double kCoordLimit = fmt::VertexLimit;
constexpr size_t kMaxPolygons = fmt::MaxPolygons;  // the pipeline's polygon id is PolyIdBits
constexpr size_t kMaxCurveCells = size_t{1} << 15;  // subpatches of one object drawn as curves

// An object in camera space, ready to project and shade.
struct CamObject {
  const SceneObject* src = nullptr;
  int index = 0;
  IndexedMesh mesh;                 // position/normal replaced by camera-space values
  std::vector<char> kept;           // per face: survived near/far rejection
};

// The normal of the side the observer sees: n, or -n when it faces away from the eye.
glm::dvec3 facing(const glm::dvec3& p, const glm::dvec3& n) {
  const glm::dvec3 to_eye = -p / glm::length(p);
  return glm::dot(n, to_eye) < 0 ? -n : n;
}

// The builder's material table: one PhongMaterial per distinct material a polygon uses, so
// ScreenPolygon::material indexes BuiltScene::materials. Phong's n must fit the shader's 8 bits.
class MaterialTable {
 public:
  MaterialTable(const std::string& scene, bool phong, std::vector<PhongMaterial>& out)
      : scene_(scene), phong_(phong), out_(out) {}
  int index(const Material& m) {
    auto it = ids_.find(m.name);
    if (it != ids_.end()) return it->second;
    if (phong_ && !(m.n == std::floor(m.n) && m.n >= 0 && m.n <= 255))
      throw SceneError(scene_ + ": materials." + field_key(m.name) + ".n: Phong shading needs an integer in [0, 255], got " +
                       number_text(m.n));
    out_.push_back(phong_material(m));
    return ids_[m.name] = static_cast<int>(out_.size() - 1);
  }

 private:
  const std::string& scene_;
  bool phong_;
  std::vector<PhongMaterial>& out_;
  std::map<std::string, int> ids_;
};

double signed_area(const ScreenPolygon& p) {
  double a2 = 0;
  for (size_t k = 0; k < p.v.size(); ++k) {
    const ScreenVertex& a = p.v[k];
    const ScreenVertex& b = p.v[(k + 1) % p.v.size()];
    a2 += a.x * b.y - b.x * a.y;
  }
  return 0.5 * a2;
}

BuiltScene build(Scene sc, const BuildOptions& opt) {
  if (opt.voxel_normals)
    for (SceneObject& o : sc.objects)
      if (o.type == ObjectType::Voxels)
        o.normals = *opt.voxel_normals == VoxelNormals::Average ? MeshNormals::Average : MeshNormals::Face;
  BuiltScene out;
  out.name = sc.name;
  out.source = std::make_shared<const Scene>(sc);
  out.width = sc.width;
  out.height = sc.height;
  for (int c = 0; c < 3; ++c) out.background[c] = sc.background[c];
  out.rule = opt.rule.value_or(sc.shading.rule);
  out.depth = opt.depth.value_or(sc.shading.depth);
  out.interpolation = opt.interpolation.value_or(sc.shading.interpolation);
  if (out.interpolation == Interpolation::Eq2) {
    if (out.depth == DepthMode::InverseZ && opt.depth)
      throw SceneError(sc.name + ": --depth inverse-z contradicts interpolation eq2, which divides by the "
                       "interpolated Z");
    out.depth = DepthMode::Z;
  }
  out.shading = opt.shading.value_or(sc.shading.mode);
  out.flat = opt.flat.value_or(sc.shading.flat);
  out.depth_tie = opt.depth_tie.value_or(sc.shading.depth_tie);
  out.smooth = opt.smooth.value_or(sc.shading.smooth);
  if (out.interpolation == Interpolation::Eq2 && out.shading == ShadingMode::Phong)
    throw SceneError(sc.name + ": shading.interpolation: eq2 is a mode of the gouraud pipeline (its shade "
                     "divider); the phong pipeline shades every pixel");
  if (out.flat && out.shading == ShadingMode::Phong)
    throw SceneError(sc.name + ": shading.flat: flat shading gives one shade per polygon to the gouraud pipeline; "
                     "the phong pipeline shades every pixel");
  const bool cull = opt.cull_backfaces.value_or(sc.shading.cull_backfaces);
  out.cull_backfaces = cull;
  const Camera& cam = sc.camera;
  const View view = make_view(cam);
  const glm::dvec3 light_cam = view.dir(sc.light.towards);
  // Phong (pipeline or vertex rule): light and eye at infinity; an "eye" light shines along E.
  const glm::dvec3 eye_dir(0, 0, -1);
  const glm::dvec3 light_inf = sc.light.type == Light::Type::Eye ? eye_dir : glm::normalize(light_cam);
  for (int c = 0; c < 3; ++c) out.light[c] = light_inf[c], out.eye[c] = eye_dir[c];
  MaterialTable materials(sc.name, out.shading == ShadingMode::Phong || out.rule == ShadingRule::Phong,
                          out.materials);

  // Before anything is tessellated: the faces the surfaces will make, against the budget (OBJ files
  // are counted as they are read, against what the budget has left).
  std::size_t faces = 0;
  for (const SceneObject& o : sc.objects) {
    faces += estimated_faces(o);
    if (faces > opt.max_faces)
      throw SceneError(sc.name + ": " + o.field + (o.type == ObjectType::Polygons ? ".polygons" : ".u") +
                       ": the objects up to here make about " + std::to_string(faces) +
                       " faces before culling, over the limit of " + std::to_string(opt.max_faces) +
                       " (the pipeline holds " + std::to_string(kMaxPolygons) + " polygons)");
  }

  // Pass 1: geometry into camera space; reject polygons reaching outside [near, far).
  std::vector<CamObject> objs;
  double zmin = INFINITY, rmin = INFINITY;
  for (size_t i = 0; i < sc.objects.size(); ++i) {
    const SceneObject& o = sc.objects[i];
    if (o.type == ObjectType::Polygons) continue;
    CamObject co;
    co.src = &o;
    co.index = static_cast<int>(i);
    co.mesh = object_mesh(o, sc.name + ": " + o.field + ".file", opt.max_faces - std::min(faces, opt.max_faces),
                          opt.strict, out.degenerate);
    if (o.type == ObjectType::Mesh) faces += co.mesh.faces.size();  // files are counted as read
    const glm::dmat3 rot = rotation(o.transform.rotate_deg);
    const glm::dvec3 s = o.transform.scale;
    for (size_t k = 0; k < co.mesh.position.size(); ++k) {
      // Each vertex is transformed once, so every polygon sharing it sees the same doubles.
      co.mesh.position[k] = view.point(rot * (s * co.mesh.position[k]) + o.transform.translate);
      // Inverse transpose of rot*diag(s) is rot*diag(1/s).
      co.mesh.normal[k] = glm::normalize(view.dir(rot * (co.mesh.normal[k] / s)));
      // The parser bounds every number, so this holds; a NaN here would be a silent empty frame.
      const glm::dvec3 &p = co.mesh.position[k], &n = co.mesh.normal[k];
      if (!std::isfinite(p.x + p.y + p.z) || !std::isfinite(n.x + n.y + n.z))
        throw SceneError(sc.name + ": " + o.field + ": a vertex or its normal is not finite in camera space "
                         "(check the object's transform and the camera)");
    }
    co.kept.assign(co.mesh.faces.size(), 0);
    for (size_t f = 0; f < co.mesh.faces.size(); ++f) {
      const auto& face = co.mesh.faces[f];
      bool inside = true;
      for (int k = 0; k < face.n; ++k) {
        double z = co.mesh.position[face.idx[k]].z;
        inside = inside && z >= cam.near && z < cam.far;
      }
      if (!inside) {
        ++out.near_clipped;
        continue;
      }
      co.kept[f] = 1;
      for (int k = 0; k < face.n; ++k) {
        const glm::dvec3& p = co.mesh.position[face.idx[k]];
        zmin = std::min(zmin, p.z);
        rmin = std::min(rmin, glm::length(p));
      }
    }
    objs.push_back(std::move(co));
  }

  // Pass 2: project and shade every vertex of a kept polygon, then emit the polygons.
  const double half_w = 0.5 * sc.width, half_h = 0.5 * sc.height;
  // n is already turned towards the eye (facing): the side that is seen is shaded.
  auto shade = [&](const glm::dvec3& p, const glm::dvec3& n, const Material& mat, double rgb[3]) {
    const double R = glm::length(p);
    const glm::dvec3 to_eye = -p / R;
    if (out.rule == ShadingRule::Phong) {
      const auto lv = phong_levels(phong_material(mat), {n.x, n.y, n.z}, out.light, out.eye);
      std::copy(lv.begin(), lv.end(), rgb);
      return;
    }
    const glm::dvec3 L = sc.light.type == Light::Type::Eye ? to_eye : light_cam;
    const double cs = glm::dot(n, L);
    double diff = 0, spec = 0;
    switch (out.rule) {
      case ShadingRule::Gouraud: diff = cs * cs * (zmin / p.z); break;
      case ShadingRule::Lambert: diff = std::max(0.0, cs); break;
      case ShadingRule::Warnock:
        diff = std::fabs(cs) * (rmin / R);
        spec = std::pow(std::fabs(cs), sc.shading.specular_m) * (rmin / R);
        break;
      case ShadingRule::Romney: diff = cs * cs * std::pow(rmin / R, 4); break;
      case ShadingRule::Phong: break;  // handled above
    }
    for (int c = 0; c < 3; ++c) rgb[c] = std::clamp(255.0 * (mat.color[c] * diff + spec), 0.0, 255.0);
  };

  // The depth a vertex or a curve crossing carries at camera-space Z (eq. (1) or (2)); eq. (2)'s
  // divider needs it proportional to Z: Z/far.
  auto depth_of = [&](double z) {
    const double d = out.interpolation == Interpolation::Eq2 ? z / cam.far
                     : out.depth == DepthMode::InverseZ    ? 1.0 - cam.near / z
                                                           : (z - cam.near) / (cam.far - cam.near);
    return std::min(d, std::nextafter(1.0, 0.0));  // rounding only; Z < far already holds
  };

  // A patch object drawn by Whitted's method: its edge curves crossed with every scan line
  // (model/curves), one region per subpatch or per side of a silhouette.
  auto add_curves = [&](const SceneObject& o, int index, const CamObject& co) {
    if (out.flat)
      throw SceneError(sc.name + ": " + o.field + ".draw: flat shading gives one shade per polygon; a patch drawn as "
                       "curves has no polygons (draw it as polygons)");
    // The tessellation's vertices lie on the surface: one outside [near, far) means the patch is cut.
    for (char k : co.kept)
      if (!k)
        throw SceneError(sc.name + ": " + o.field + ".draw: the patch reaches outside the camera's [near, far); "
                         "curves are not clipped (draw it as polygons, or move it)");
    // Each subpatch is a few hundred point evaluations before any scan line: bounded like faces.
    const std::size_t cells = o.patches.size() * (o.k_u.size() + 1) * (o.k_v.size() + 1);
    if (cells > kMaxCurveCells)
      throw SceneError(sc.name + ": " + o.field + ".k_u: drawn as curves the object has " + std::to_string(cells) +
                       " subpatches (patches x (k_u + 1) x (k_v + 1)), over the limit of " +
                       std::to_string(kMaxCurveCells));
    const ObjectToCamera xf(view, o.transform);
    const Projection proj{half_w, half_h, cam.focal};
    WhittedOptions wo;
    wo.k_u = o.k_u, wo.k_v = o.k_v, wo.cull = cull;
    wo.line_lo = 0, wo.line_hi = sc.height;
    const int material = materials.index(o.material);
    const glm::dmat3 normal_to_camera = glm::transpose(glm::inverse(xf.linear));
    for (const BicubicPatch& cp : o.patches) {
      const PatchPoint f = [&](double u, double v, glm::dvec3& p, glm::dvec3& pu, glm::dvec3& pv) {
        bezier_point(cp, u, v, p, pu, pv);
        p = xf.linear * p + xf.offset;  // a proper linear map: dP/du x dP/dv keeps its side
        pu = xf.linear * pu;
        pv = xf.linear * pv;
      };
      // The patch's own normal (its limit at a pole, as the tessellation and the truth take it).
      wo.normal = [&](double u, double v) { return normal_to_camera * patch_normal(cp, u, v); };
      const PatchEdges edges = describe_patch(f, proj, wo, out.curve_stats);
      for (const EdgePiece& piece : edges.pieces) {
        const bool front = edges.regions[std::size_t(piece.region)].front;
        ScreenCurve c;
        c.region = out.curve_regions + piece.region;
        c.object = index;
        c.material = material;
        c.y0 = piece.y0;
        for (std::size_t k = 0; k < piece.lines.size(); ++k) {
          const EdgeCrossing& e = piece.lines[k];
          if (!(e.x >= -kCoordLimit && e.x < kCoordLimit))
            throw SceneError(sc.name + ": " + o.field + ": an edge of the patch projects to x=" + number_text(e.x) +
                             ", outside the representable range [" + number_text(-kCoordLimit) + ", " +
                             number_text(kCoordLimit) + ") pixels; move the camera or reduce focal");
          ScreenVertex v;
          v.x = e.x;
          v.y = piece.y0 + int(k) + 0.5;  // the scan line's centre (E_y(t) within the Newton tolerance)
          v.depth = depth_of(e.p.z);
          v.eye_z = e.p.z;
          // Phong: the side the region shows, turned as a whole (as a back polygon's normals are).
          for (int a = 0; a < 3; ++a) v.normal[a] = front ? e.normal[a] : -e.normal[a];
          shade(e.p, facing(e.p, e.normal), o.material, v.rgb);
          c.lines.push_back(v);
        }
        out.curves.push_back(std::move(c));
      }
      out.curve_regions += int(edges.regions.size());
    }
  };

  size_t next_obj = 0;
  std::string crossed;  // the object at which the polygon count passed kMaxPolygons
  for (size_t i = 0; i < sc.objects.size(); ++i) {
    const SceneObject& o = sc.objects[i];
    if (o.type == ObjectType::Polygons) {
      // A hardware user's command list: already in screen space, never culled or reshaded.
      const bool phong = out.shading == ShadingMode::Phong;
      const std::string& missing = phong ? o.vertex_without_normal : o.vertex_without_rgb;
      if (!missing.empty())
        throw SceneError(sc.name + ": " + missing + ": missing key \"" + (phong ? "normal" : "rgb") + "\" (" +
                         (phong ? "Phong shading interpolates vertex normals" : "Gouraud shading interpolates vertex shades") +
                         ")");
      for (size_t k = 0; k < o.polygons.size(); ++k) {
        ScreenPolygon p = o.polygons[k];
        if (std::fabs(signed_area(p)) < 1e-9) {  // as GL does: nothing to draw, skipped and counted
          if (opt.strict)
            throw SceneError(sc.name + ": " + o.field + ".polygons[" + std::to_string(k) +
                             "]: polygon has zero area (skipped without --strict)");
          ++out.degenerate;
          continue;
        }
        p.material = materials.index(o.material);
        out.polygons.push_back(std::move(p));
      }
      if (out.polygons.size() > kMaxPolygons) {
        crossed = o.field;
        break;
      }
      continue;
    }
    const CamObject& co = objs[next_obj++];
    if ((o.type == ObjectType::BezierPatch || o.type == ObjectType::Patches) &&
        opt.patches_as_curves.value_or(o.draw_curves)) {
      add_curves(o, int(i), co);
      continue;
    }
    const IndexedMesh& m = co.mesh;
    std::vector<ScreenVertex> sv(m.position.size());
    std::vector<char> done(m.position.size(), 0);
    auto vertex = [&](int k) -> const ScreenVertex& {
      if (done[k]) return sv[k];
      const glm::dvec3& p = m.position[k];
      ScreenVertex& v = sv[k];
      v.x = half_w + cam.focal * half_w * p.x / p.z;
      v.y = half_h - cam.focal * half_w * p.y / p.z;
      for (int axis = 0; axis < 2; ++axis) {
        const double c = axis == 0 ? v.x : v.y;
        if (!(c >= -kCoordLimit && c < kCoordLimit))
          throw SceneError(sc.name + ": " + o.field + ": vertex projects to " + (axis == 0 ? "x=" : "y=") + number_text(c) +
                           ", outside the representable range [" + number_text(-kCoordLimit) + ", " +
                           number_text(kCoordLimit) + ") pixels; move the camera or reduce focal");
      }
      v.depth = depth_of(p.z);
      v.eye_z = p.z;
      // Phong gets the surface normal as it is: the side seen is decided per polygon below, since
      // near a silhouette a front face's vertex normals may point slightly away from the eye and
      // turning those alone would make the interpolated normal pass through zero. Gouraud's
      // vertex rules shade the side each vertex shows.
      for (int c = 0; c < 3; ++c) v.normal[c] = m.normal[k][c];
      shade(p, facing(p, m.normal[k]), o.material, v.rgb);
      done[k] = 1;
      return v;
    };
    for (size_t f = 0; f < m.faces.size(); ++f) {
      if (!co.kept[f]) continue;
      const auto& face = m.faces[f];
      ScreenPolygon poly;
      poly.object = static_cast<int>(i);
      for (int k = 0; k < face.n; ++k) poly.v.push_back(vertex(face.idx[k]));
      // Front faces look counter-clockwise on the display; with y down that is a negative
      // shoelace area.
      const double a = signed_area(poly);
      if (std::fabs(a) < 1e-9) {
        ++out.degenerate;
      } else if (cull && a > 0) {
        ++out.culled_backfaces;
      } else {
        if (a > 0)  // a back face (culling off): its back is what is seen, so Phong shades that side
          for (ScreenVertex& v : poly.v)
            for (double& c : v.normal) c = -c;
        poly.material = materials.index(o.material);  // only materials of emitted polygons count
        if (out.flat) {
          // One shade per polygon: the rule at the centroid, with the plane's normal (Newell's
          // method, so non-planar quads get their best-fit plane), turned like the vertex normals.
          glm::dvec3 centroid(0.0), plane(0.0), vertex_normals(0.0);
          for (int k = 0; k < face.n; ++k) {
            const glm::dvec3& a = m.position[face.idx[k]];
            const glm::dvec3& b = m.position[face.idx[(k + 1) % face.n]];
            centroid += a / double(face.n);
            plane += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
            vertex_normals += m.normal[face.idx[k]];
          }
          plane = glm::normalize(plane);
          if (glm::dot(plane, vertex_normals) < 0) plane = -plane;  // outward, as the surface's normals
          double rgb[3];
          shade(centroid, facing(centroid, plane), o.material, rgb);
          for (ScreenVertex& v : poly.v) std::copy(rgb, rgb + 3, v.rgb);
        }
        out.polygons.push_back(std::move(poly));
        if (out.polygons.size() > kMaxPolygons) break;  // refused below, before more is built
      }
    }
    if (out.polygons.size() > kMaxPolygons) {
      crossed = o.field;
      break;
    }
  }
  // Curve crossings per scan line: the curved edges active at once.
  if (!out.curves.empty()) {
    std::vector<int> per_line(std::size_t(std::max(sc.height, 1)), 0);
    for (const ScreenCurve& c : out.curves)
      for (std::size_t k = 0; k < c.lines.size(); ++k) ++per_line[std::size_t(c.y0) + k];
    const auto most = std::max_element(per_line.begin(), per_line.end());
    out.max_curve_crossings = *most;
    out.max_curve_line = int(most - per_line.begin());
  }
  if (out.polygons.size() > kMaxPolygons)
    throw SceneError(sc.name + ": " + crossed + ": the scene has more than " + std::to_string(kMaxPolygons) +
                     " polygons up to this object; the pipeline's polygon id is " + std::to_string(fmt::PolyIdBits) +
                     " bits (at most " + std::to_string(kMaxPolygons) + ")");
  return out;
}

}  // namespace

BuiltScene load_scene_text(const std::string& text, const std::string& name, const std::string& base_dir,
                           const BuildOptions& opt) {
  return build(parse_scene(text, name, base_dir), opt);
}

std::string read_scene_text(const std::string& path) {
  if (path.empty()) throw SceneError("scene file name is empty");
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw SceneError(path + ": cannot open scene file: " + std::strerror(errno));
  // Read at most one byte past the limit: /dev/zero or a stray multi-gigabyte file is refused
  // after 16 MiB, not after the allocator gives up.
  constexpr size_t kMaxSceneBytes = size_t{16} << 20;
  std::string text;
  char buf[65536];
  size_t n;
  while (text.size() <= kMaxSceneBytes && (n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
  const bool bad = std::ferror(f);
  const int err = errno;
  std::fclose(f);
  if (bad) throw SceneError(path + ": cannot read scene file: " + std::strerror(err));
  if (text.size() > kMaxSceneBytes)
    throw SceneError(path + ": scene file is larger than " + std::to_string(kMaxSceneBytes >> 20) + " MiB (the limit)");
  return text;
}

Scene parse_scene_file(const std::string& path) {
  if (path.empty()) return parse_scene(default_scene_text(), "<default scene>", ".");
  return parse_scene(read_scene_text(path), path, std::filesystem::path(path).parent_path().string());
}

BuiltScene build_scene(const Scene& parsed, const BuildOptions& opt) { return build(parsed, opt); }

std::vector<SceneFile> files_read(const Scene& parsed) {
  std::vector<SceneFile> out;
  for (const SceneObject& o : parsed.objects)
    if (!o.file.empty()) out.push_back({o.field, o.type == ObjectType::Voxels ? "raw volume" : "mesh file", o.file});
  return out;
}

BuiltScene load_scene(const std::string& path, const BuildOptions& opt) {
  return load_scene_text(read_scene_text(path), path, std::filesystem::path(path).parent_path().string(), opt);
}

}  // namespace watkins
