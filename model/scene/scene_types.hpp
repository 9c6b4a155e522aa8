// The parsed, validated scene (scene_parse.cpp fills it, scene_build.cpp consumes it).
// Everything here is already range-checked, so the builder never has to re-validate input.
// World coordinates are left-handed: +X right, +Y up, +Z away from the observer, which is
// the frame of Watkins and Gouraud ("observer at the origin looking in the Z direction").
#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene.hpp"
#include "screen_polygon.hpp"
#include "voxels.hpp"

namespace watkins {

// Object -> world: scale, then rotate about X, then Y, then Z, then translate.
struct Transform {
  glm::dvec3 translate{0.0};
  glm::dvec3 rotate_deg{0.0};
  glm::dvec3 scale{1.0};  // every component > 0 (a mirror would flip the winding)
};

// Reflectance in [0,1] per channel; d, W, n are Phong's coefficients (eq. 3). n is checked
// against the Phong formats (an integer 0..255) only when a Phong rule or pipeline uses it.
struct Material {
  std::string name;  // key in "materials"; empty for the default white material
  glm::dvec3 color{1.0};
  double d = 0.2, W = 0.5, n = 10.0;
};

struct Camera {
  enum class Type { Gouraud, LookAt } type = Type::Gouraud;
  double focal = 1.0;  // f in x_s = W/2 + f*(W/2)*X/Z; for lookat, 1/tan(fov/2)
  glm::dvec3 eye{0.0}, target{0.0, 0.0, 1.0}, up{0.0, 1.0, 0.0};  // lookat only
  double near = 0.1, far = 1000.0;
};

struct Light {
  enum class Type { Directional, Eye } type = Type::Eye;
  glm::dvec3 towards{0.0, 0.0, -1.0};  // directional: unit vector from the scene to the light (world)
};

struct Shading {
  ShadingRule rule = ShadingRule::Gouraud;
  DepthMode depth = DepthMode::InverseZ;
  Interpolation interpolation = Interpolation::Eq1;  // "interpolation": eq1 or eq2 (depth then z)
  bool cull_backfaces = true;
  double specular_m = 8.0;
  ShadingMode mode = ShadingMode::Gouraud;  // "mode": which pipeline shades
  bool flat = false;                         // "flat": one shade per polygon (BuiltScene::flat)
  DepthTie depth_tie = DepthTie::Arrival;    // "depth_tie": equal-depth rule (BuiltScene::depth_tie)
  double smooth = 0.0;                       // "smooth": Herman & Liu's W (BuiltScene::smooth)
};

enum class ObjectType { Sphere, Cone, QuarterTorus, HyperbolicParaboloid, BezierPatch, CrossVault, Pier, Portico, Mesh,
                        Polygons, Voxels, Patches };

// One bicubic Bezier patch: control point [4*row + col], object space; s runs along a row, t from
// row to row, and dP/ds x dP/dt is the front side's normal (patches.hpp evaluates it).
using BicubicPatch = std::array<glm::dvec3, 16>;

// File: the OBJ file's normals (analytic surfaces: the exact ones); Average: averaged over the
// faces at a vertex; Crease: averaged over the faces within crease_angle_deg; Face: each face its
// own (voxels).
enum class MeshNormals { File, Average, Crease, Face };

struct SceneObject {
  ObjectType type = ObjectType::Sphere;
  std::string field;  // "objects[3]", used in messages
  Material material;
  Transform transform;
  bool triangles = false;  // split every quad into two triangles
  int u = 24, v = 12;      // tessellation

  glm::dvec3 center{0.0};         // sphere centre; cone base centre
  double radius = 1.0;            // sphere; cone base radius
  double height = 1.0;            // cone: apex at center + (0, height, 0)
  bool cap = true;                // cone: close the base with a triangle fan
  double major_radius = 2.0;      // quarter torus
  double minor_radius = 0.5;
  double c = 1.0, size = 1.0;     // hyperbolic paraboloid z = (x^2 - y^2)/c, |x|,|y| <= size
  // "bezier_patch" (one) and "patches" (B-spline nets converted by the basis change): every patch
  // of the object in Bezier form, object space, before the object's transform.
  std::vector<BicubicPatch> patches;
  // Whitted's interior edges of every patch: f(k, t) for k in k_u, f(s, k) for k in k_v; ascending,
  // in (0, 1). Used only when drawn by curves: the tessellation is the u x v grid.
  // "draw": "curves" draws the patches by Whitted's edge description (model/curves) instead of
  // polygons, with k_u, k_v as his interior edges (subpatches).
  bool draw_curves = false;
  std::vector<double> k_u, k_v;
  int cap_rings = 1;              // cone: rings of the base cap (more only under max_edge_length)
  // Cross vault / portico bay: plan size (x, z) of a bay, crown height above the springing line;
  // the two barrels are half ellipses of that rise (surfaces.hpp, cross_vault).
  double span_x = 4.0, span_z = 4.0, rise = 2.0;
  // Pier (a box column, base centre `center`) and the portico's piers: plan section and height.
  double pier_x = 0.5, pier_z = 0.5, pier_height = 4.0;
  int bays = 1;                   // portico: bays in a row along +X
  std::array<int, 3> box_segments{1, 1, 1};  // pier faces: segments along x, y, z
  std::string file;               // mesh: OBJ or STL; voxels: the raw volume; resolved against the scene's folder
  MeshNormals normals = MeshNormals::File;  // analytic surfaces: File = exact normals, or Crease
  bool normals_given = false;     // mesh: "normals" was in the scene (an STL file has no normals)
  double crease_angle_deg = 0;    // MeshNormals::Crease: faces further apart are not smoothed
  double max_edge_length = 0;     // split edges longer than this (world units, after scale); 0: never
  double weld_tolerance = -1;     // STL: weld corners this close (file units); < 0: 1e-6 x bbox diagonal
  // Voxels: the thresholded volume or the sampled phantom (voxels.hpp), made by the parser, and the
  // phantom itself when there is one (the analytic truth ray-casts it).
  std::shared_ptr<const VoxelGrid> voxels;
  bool has_phantom = false;
  Phantom phantom;
  std::vector<ScreenPolygon> polygons;  // "polygons": screen-space, validated, passed through
  // "polygons": the first vertex without "rgb" / "normal" (field path, empty when none); which
  // one is an error depends on the shading mode, known only once the command line is applied.
  std::string vertex_without_rgb, vertex_without_normal;
};

struct Scene {
  std::string name;  // file name (or given name) used in messages
  int width = 320, height = 240;
  double background[3] = {0, 0, 0};
  Camera camera;
  Light light;
  Shading shading;
  std::vector<SceneObject> objects;
};

// JSON text -> Scene. Throws SceneError naming `name` and the offending field.
Scene parse_scene(const std::string& text, const std::string& name, const std::string& base_dir);

}  // namespace watkins
