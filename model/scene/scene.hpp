// Scene front end: JSON scene files (documented in README), OBJ meshes, analytic surfaces,
// cameras, lights and the vertex shading rules. Produces screen-space polygons for prepare.cpp.
// Every error names the file, and the line/column or the JSON field, and what is wrong.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "depth_tie.hpp"
#include "scene_error.hpp"
#include "screen_curve.hpp"
#include "screen_polygon.hpp"
#include "shading_mode.hpp"
#include "whitted_edges.hpp"

namespace watkins {

// Vertex shading rules of the Gouraud pipeline. Phong is Phong's eq. (3) evaluated at each vertex
// (light and eye at infinity), what Gouraud interpolates when compared with Phong shading.
enum class ShadingRule { Gouraud, Lambert, Warnock, Romney, Phong };
enum class DepthMode { InverseZ, Z };  // Gouraud's eq. (1): interpolate 1/Z; eq. (2): interpolate Z
// How the Gouraud pipeline shades between vertices: Eq1 interpolates S itself (Gouraud's eq. (1));
// Eq2 interpolates S·Z and Z and divides per pixel (his eq. (2), the top's shade divider). Eq2
// carries Z in the depth channel as Z/far (proportional to Z, so the quotient is his), never 1/Z.
enum class Interpolation { Eq1, Eq2 };

const char* to_string(ShadingRule r);
const char* to_string(DepthMode m);
std::optional<ShadingRule> parse_shading_rule(const std::string& s);  // "gouraud", ..., "phong"
std::optional<DepthMode> parse_depth_mode(const std::string& s);      // "inverse-z", "z"
const char* to_string(Interpolation i);
std::optional<Interpolation> parse_interpolation(const std::string& s);  // "eq1", "eq2"
const char* to_string(ShadingMode m);
std::optional<ShadingMode> parse_shading_mode(const std::string& s);  // "gouraud", "phong"
const char* to_string(DepthTie t);
std::optional<DepthTie> parse_depth_tie(const std::string& s);        // "arrival", "submission"

struct Scene;  // parsed scene, defined in scene_types.hpp

// A voxel object's normals (scene-format.md, "voxels"): each face its own, or averaged at the corners.
enum class VoxelNormals { Face, Average };

// Options given on the command line override the scene file's own settings.
struct BuildOptions {
  std::optional<ShadingRule> rule;
  std::optional<DepthMode> depth;
  std::optional<Interpolation> interpolation;
  std::optional<bool> cull_backfaces;
  std::optional<ShadingMode> shading;
  std::optional<bool> flat;  // flat shading (see BuiltScene::flat)
  std::optional<DepthTie> depth_tie;
  std::optional<double> smooth;  // Herman & Liu's W (BuiltScene::smooth)
  std::optional<bool> patches_as_curves;  // patch objects: Whitted's curves (true) or polygons (false)
  // Every voxel object's normals, whatever its "normals" says (voxel-compare renders one phantom
  // both ways); BuiltScene::source holds the objects as built.
  std::optional<VoxelNormals> voxel_normals;
  // Zero-area polygons are skipped and counted (BuiltScene::degenerate), as GL skips them; with
  // strict, a zero-area polygon of a "polygons" command list is an error naming it.
  bool strict = false;
  // Faces the scene's objects may tessellate into (and OBJ files hold) before culling, estimated
  // before anything is allocated: a 1 KB scene asking for 10^9 polygons is refused at once.
  std::size_t max_faces = std::size_t{1} << 22;
};

// A material as Phong's eq. (3) uses it: S = Cp [cos(i)(1 - d) + d] + W cos(s)^n.
struct PhongMaterial {
  double cp[3] = {1, 1, 1};  // reflectance per channel, [0, 1]
  double d = 0.2, W = 0.5;   // d in [0, 1], W in [0, 511/256]
  int n = 10;                // 0..255
};

// The scene as the pipeline sees it: screen size, background and screen-space polygons.
struct BuiltScene {
  std::string name;
  int width = 0, height = 0;
  double background[3] = {0, 0, 0};  // 8-bit levels
  ShadingRule rule = ShadingRule::Gouraud;
  DepthMode depth = DepthMode::InverseZ;
  Interpolation interpolation = Interpolation::Eq1;  // Eq2: depth is Z/far, and depth == Z
  ShadingMode shading = ShadingMode::Gouraud;
  // Equal depth at a pixel (depth_tie.hpp): Submission keeps the polygon that comes first in
  // `polygons`, which hold the scene's polygons in submission order -- objects in file order, each
  // object's polygons or faces in its own order (an OBJ file's faces in file order, a face of more
  // than 4 vertices as consecutive triangles) -- with culled, near-clipped and zero-area ones left
  // out (the others keep their relative order).
  DepthTie depth_tie = DepthTie::Arrival;
  // Herman & Liu's 3x3 image smoothing after the scan-line buffer with weight W (0: off);
  // preparation rounds it to the smoother's format (Frame::smooth_w).
  double smooth = 0.0;
  // Flat shading (Gouraud pipeline only): every polygon gets one shade, the vertex rule evaluated
  // at its centroid with its plane's normal, given to all its vertices — the faceted picture of
  // Warnock and Romney that Gouraud's interpolation removes (the depth still varies per vertex).
  bool flat = false;
  // Phong: camera-space unit vectors towards the light and towards the eye (both at infinity,
  // eye = (0, 0, -1)), and the materials ScreenPolygon::material indexes.
  double light[3] = {0, 0, -1};
  double eye[3] = {0, 0, -1};
  std::vector<PhongMaterial> materials;
  std::vector<ScreenPolygon> polygons;
  // Curved surfaces drawn by Whitted's method (screen_curve.hpp): their edges, and how many
  // regions they pair in (preparation gives region r the polygon id polygons.size() + r).
  std::vector<ScreenCurve> curves;
  int curve_regions = 0;
  // How the curves were made (Newton iterations, silhouettes, Whitted's defaults), and the most
  // curve crossings on one scan line (the curved edges active at once; line max_curve_line).
  EdgeStats curve_stats;
  int max_curve_crossings = 0, max_curve_line = 0;
  bool cull_backfaces = true;  // the setting the polygons were built with (the truth hides back sides too)
  int culled_backfaces = 0;   // dropped by back-face culling
  int near_clipped = 0;       // dropped: a vertex behind the camera's near plane
  int degenerate = 0;         // dropped: zero projected area (the pole quads of a sphere, zero-area
                              // polygons of a command list)
  // The parsed scene it was built from (for the analytic truth, which ray-casts the exact
  // surfaces); null for scenes assembled in code.
  std::shared_ptr<const Scene> source;
};

// A scene file's text (at most 16 MiB; SceneError naming the file when it cannot be read).
std::string read_scene_text(const std::string& path);
// Load and validate a scene file (JSON). Relative mesh and volume file paths (OBJ, STL, raw) are
// resolved against its folder.
BuiltScene load_scene(const std::string& path, const BuildOptions& opt = {});
// Same, from text; `name` is used in messages and `base_dir` for mesh and volume file paths.
BuiltScene load_scene_text(const std::string& text, const std::string& name,
                           const std::string& base_dir, const BuildOptions& opt = {});
// The same in two steps, so a caller learns every file the scene reads before building it: the
// scene file parsed and validated (parse_scene_file; the embedded default scene when path is
// empty), then built with the command line's options.
Scene parse_scene_file(const std::string& path);
BuiltScene build_scene(const Scene& parsed, const BuildOptions& opt = {});
// A file a parsed scene reads besides the scene file itself: the object that names it
// ("objects[2]"), what it is ("mesh file", "raw volume") and its path, resolved against the
// scene's folder.
struct SceneFile {
  std::string field, kind, path;
};
std::vector<SceneFile> files_read(const Scene& parsed);
// The scene compiled into the binary, used when `watkins render` gets no file.
const std::string& default_scene_text();
// load_scene(path), or the embedded default scene when path is empty.
BuiltScene load_scene_or_default(const std::string& path, const BuildOptions& opt = {});

}  // namespace watkins
