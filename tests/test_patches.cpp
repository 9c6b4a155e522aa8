// Patch objects (model/scene/patches.hpp, scene key "patches"): the uniform B-spline basis change
// against the B-spline itself, shared boundaries (bit-identical in the patches and in the
// tessellation), poles, Newell's teapot as shipped, k_u / k_v, and bad input naming its field.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "analytic_truth.hpp"
#include "build_options.hpp"
#include "float_reference.hpp"
#include "patches.hpp"
#include "scene_types.hpp"
#include "surfaces.hpp"

using namespace watkins;

namespace {

// The uniform cubic B-spline basis at u in [0, 1] (the segment's four weights).
void bspline_basis(double u, double b[4]) {
  const double w = 1 - u;
  b[0] = w * w * w / 6;
  b[1] = (3 * u * u * u - 6 * u * u + 4) / 6;
  b[2] = (-3 * u * u * u + 3 * u * u + 3 * u + 1) / 6;
  b[3] = u * u * u / 6;
}

// Patch (a, b) of a rows x cols net evaluated as a B-spline (indices wrap where closed).
glm::dvec3 bspline_point(const std::vector<glm::dvec3>& net, int rows, int cols, int a, int b, double s, double t) {
  double bs[4], bt[4];
  bspline_basis(s, bs);
  bspline_basis(t, bt);
  glm::dvec3 p(0.0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p += bt[i] * bs[j] * net[std::size_t(((a + i) % rows) * cols + (b + j) % cols)];
  return p;
}

std::vector<glm::dvec3> random_net(int rows, int cols, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-2, 2);
  std::vector<glm::dvec3> net;
  for (int k = 0; k < rows * cols; ++k) net.emplace_back(d(rng), d(rng), d(rng));
  return net;
}

// A scene of one object (its JSON), Gouraud's camera; the object sits at Z = 6.
std::string one_object(const std::string& object) {
  return R"({"screen": {"width": 160, "height": 120}, "camera": {"type": "gouraud", "focal": 1},
    "objects": [)" + object + "]}";
}

Scene parse(const std::string& object) { return parse_scene(one_object(object), "t.json", "."); }

// The message of the SceneError the object raises ("" if none).
std::string error_of(const std::string& object) {
  try {
    parse(object);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

const char* kFlat16 = R"([[0,0,0],[1,0,0],[2,0,0],[3,0,0],[0,1,0],[1,1,0],[2,1,0],[3,1,0],
                         [0,2,0],[1,2,0],[2,2,0],[3,2,0],[0,3,0],[1,3,0],[2,3,0],[3,3,0]])";

Scene shipped(const std::string& name) {
  return parse_scene(read_scene_text(WATKINS_SOURCE_DIR "/scenes/" + name), name, WATKINS_SOURCE_DIR "/scenes");
}

Scene teapot(int uv) {
  std::string text = read_scene_text(WATKINS_SOURCE_DIR "/scenes/teapot.json");
  const std::string key = R"("u": 4, "v": 4)";
  const std::size_t at = text.find(key);
  EXPECT_NE(at, std::string::npos);
  text.replace(at, key.size(), "\"u\": " + std::to_string(uv) + ", \"v\": " + std::to_string(uv));
  return parse_scene(text, "teapot.json", WATKINS_SOURCE_DIR "/scenes");
}

// Edges (vertex index pairs) used by exactly one face of the mesh.
int open_edges(const IndexedMesh& m) {
  std::map<std::pair<int, int>, int> uses;
  for (const IndexedMesh::Face& f : m.faces)
    for (int k = 0; k < f.n; ++k) {
      const int a = f.idx[std::size_t(k)], b = f.idx[std::size_t((k + 1) % f.n)];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  int open = 0;
  for (const auto& e : uses) open += e.second == 1;
  return open;
}

}  // namespace

// The Bezier form of every patch is the B-spline patch itself: at random (s, t) the two agree to
// 1e-12 (control points in [-2, 2]), on an open net and on a net closed in both directions.
TEST(Patches, BsplineBasisChangeAgreesWithTheBspline) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (const bool closed : {false, true}) {
    SCOPED_TRACE(closed ? "closed" : "open");
    const int rows = 5, cols = 6;
    const std::vector<glm::dvec3> net = random_net(rows, cols, 3);
    const std::vector<BicubicPatch> patches = bspline_patches(net, rows, cols, closed, closed);
    const int pv = closed ? rows : rows - 3, pu = closed ? cols : cols - 3;
    ASSERT_EQ(patches.size(), std::size_t(pv * pu));
    double worst = 0;
    for (int a = 0; a < pv; ++a)
      for (int b = 0; b < pu; ++b)
        for (int k = 0; k < 20; ++k) {
          const double s = unit(rng), t = unit(rng);
          glm::dvec3 p, ds, dt;
          bezier_point(patches[std::size_t(a * pu + b)], s, t, p, ds, dt);
          worst = std::max(worst, glm::length(p - bspline_point(net, rows, cols, a, b, s, t)));
        }
    EXPECT_LT(worst, 1e-12);
    EXPECT_GT(worst, 0);  // evaluated two different ways, not the same doubles
  }
}

// Neighbouring B-spline patches hold their shared boundary as the same doubles: the same points
// along it (bit for bit, as the same control points evaluated the same way), the same tangent
// along it, and cross-boundary tangents that agree (C1; C2 in exact arithmetic) to 1e-12.
TEST(Patches, BsplineNeighboursShareBoundaryPointsAndTangents) {
  const int rows = 6, cols = 7;
  const std::vector<glm::dvec3> net = random_net(rows, cols, 11);
  for (const bool closed_u : {false, true}) {
    SCOPED_TRACE(closed_u ? "closed_u" : "open");
    const std::vector<BicubicPatch> patches = bspline_patches(net, rows, cols, closed_u, false);
    const int pv = rows - 3, pu = closed_u ? cols : cols - 3;
    int compared = 0;
    for (int a = 0; a < pv; ++a)
      for (int b = 0; b < pu; ++b)
        for (int k = 0; k <= 8; ++k) {
          const double x = k / 8.0;
          glm::dvec3 p0, s0, t0, p1, s1, t1;
          // Along s: patch (a, b) at s = 1 against (a, b + 1) at s = 0 (the first patch when closed).
          if (b + 1 < pu || closed_u) {
            bezier_point(patches[std::size_t(a * pu + b)], 1, x, p0, s0, t0);
            bezier_point(patches[std::size_t(a * pu + (b + 1) % pu)], 0, x, p1, s1, t1);
            EXPECT_EQ(p0, p1);
            EXPECT_EQ(t0, t1);
            EXPECT_LT(glm::length(s0 - s1), 1e-12);
            ++compared;
          }
          // Along t: patch (a, b) at t = 1 against (a + 1, b) at t = 0.
          if (a + 1 < pv) {
            bezier_point(patches[std::size_t(a * pu + b)], x, 1, p0, s0, t0);
            bezier_point(patches[std::size_t((a + 1) * pu + b)], x, 0, p1, s1, t1);
            EXPECT_EQ(p0, p1);
            EXPECT_EQ(s0, s1);
            EXPECT_LT(glm::length(t0 - t1), 1e-12);
            ++compared;
          }
        }
    EXPECT_GT(compared, 100);
  }
}

// The shipped B-spline sheet tessellates watertight: its 12 patches' grids are welded into one
// vertex array, so every edge but the sheet's border is used by two faces, and each shared
// boundary vertex is one entry (one position and one normal for both sides).
TEST(Patches, ShippedBsplineTessellationIsWelded) {
  const Scene s = shipped("bspline.json");
  ASSERT_EQ(s.objects.size(), 1u);
  const SceneObject& o = s.objects[0];
  ASSERT_EQ(o.patches.size(), 12u);  // 6 x 7 net: 3 x 4 patches
  const IndexedMesh m = tessellate_surface(o);
  const int u = o.u, v = o.v;  // 5, 6
  EXPECT_EQ(m.faces.size(), std::size_t(12 * u * v));
  // One grid over the whole sheet: (4u + 1) x (3v + 1) vertices.
  EXPECT_EQ(m.position.size(), std::size_t((4 * u + 1) * (3 * v + 1)));
  EXPECT_EQ(open_edges(m), 2 * (4 * u + 3 * v));
  for (const glm::dvec3& n : m.normal) EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
}

// A lone bezier_patch is patches[0] of its object, exactly its control points.
TEST(Patches, BezierPatchIsItsObjectsOnlyPatch) {
  const Scene s = shipped("patch.json");
  ASSERT_EQ(s.objects.size(), 1u);
  ASSERT_EQ(s.objects[0].patches.size(), 1u);
  EXPECT_EQ(s.objects[0].patches[0][0], glm::dvec3(-1.5, 1.5, 0.0));
  EXPECT_EQ(s.objects[0].patches[0][5], glm::dvec3(-0.5, 0.5, -2.2));
  EXPECT_EQ(s.objects[0].patches[0][15], glm::dvec3(1.5, -1.5, 0.0));
}

// Newell's teapot as shipped: 32 patches on 294 distinct control points (the quarters and halves
// freeglut stores, mirrored, shared points merged), every patch's control points listed by index;
// the surface's extent, measured on a fine tessellation, is the teapot's: z from the bottom's pole
// (0) to the knob's (3.15), the handle's back at x = -3, the spout's lip at x = 3.43, the body
// 2 wide at most (|y| <= 2).
TEST(Patches, TeapotCountsAndExtent) {
  const Scene s = teapot(24);
  ASSERT_EQ(s.objects.size(), 1u);
  const SceneObject& o = s.objects[0];
  ASSERT_EQ(o.patches.size(), 32u);
  std::set<std::vector<double>> distinct;
  for (const BicubicPatch& cp : o.patches)
    for (const glm::dvec3& c : cp) distinct.insert({c.x, c.y, c.z});
  EXPECT_EQ(distinct.size(), 294u);
  const IndexedMesh m = tessellate_surface(o);
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::dvec3& p : m.position) lo = glm::min(lo, p), hi = glm::max(hi, p);
  EXPECT_NEAR(lo.z, 0.0, 1e-12);
  EXPECT_NEAR(hi.z, 3.15, 1e-12);
  EXPECT_NEAR(lo.x, -3.0, 0.01);
  EXPECT_NEAR(hi.x, 3.43, 0.01);
  EXPECT_NEAR(hi.y, 2.0, 0.01);
  EXPECT_NEAR(lo.y, -2.0, 0.01);
}

// The teapot's poles: the bottom's collapsed row and the knob's top have the normals of the
// surface's limit there, straight down and straight up (object space, z up), and no normal of the
// tessellation is not a number.
TEST(Patches, TeapotPolesHaveTheLimitNormals) {
  const Scene s = teapot(8);
  const IndexedMesh m = tessellate_surface(s.objects[0]);
  int bottom = 0, top = 0;
  for (std::size_t k = 0; k < m.position.size(); ++k) {
    const glm::dvec3 &p = m.position[k], &n = m.normal[k];
    ASSERT_TRUE(std::isfinite(n.x + n.y + n.z)) << k;
    if (std::hypot(p.x, p.y) < 1e-12 && p.z < 1e-12) {
      ++bottom;
      EXPECT_NEAR(n.z, -1.0, 1e-9);
    }
    if (std::hypot(p.x, p.y) < 0.003 && p.z > 3.15 - 1e-6) {
      ++top;
      EXPECT_NEAR(n.z, 1.0, 1e-6);
    }
  }
  EXPECT_EQ(bottom, 1);  // the 4 bottom patches' pole, welded into one vertex
  EXPECT_GE(top, 1);
  // patch_normal at a collapsed boundary point itself: the limit, not (0, 0, 0).
  for (const BicubicPatch& cp : s.objects[0].patches) {
    const glm::dvec3 n = patch_normal(cp, 0.5, 0);
    EXPECT_GT(glm::length(n), 0);
  }
}

// The analytic truth ray-casts every patch: at a fine tessellation (16 x 16 per patch) the double
// reference's Phong render of the teapot and of the B-spline sheet agree with it closely.
TEST(Patches, TruthAgreesWithAFineTessellation) {
  const BuildOptions phong = test::shading_options(ShadingMode::Phong);
  for (const std::string name : {"teapot", "bspline"}) {
    SCOPED_TRACE(name);
    std::string text = read_scene_text(WATKINS_SOURCE_DIR "/scenes/" + name + ".json");
    const std::string key = name == "teapot" ? R"("u": 4, "v": 4)" : R"("u": 5, "v": 6)";
    text.replace(text.find(key), key.size(), R"("u": 16, "v": 16)");
    const BuiltScene scene = load_scene_text(text, name, WATKINS_SOURCE_DIR "/scenes", phong);
    const AnalyticTruth truth = render_analytic_truth(scene);
    ASSERT_TRUE(truth.unavailable.empty()) << truth.unavailable;
    const ImageError e = compare_with_truth(scene, render_float_reference(scene), truth);
    EXPECT_GT(e.compared, 10000);
    EXPECT_LT(e.mean_abs, 0.5);
    EXPECT_LE(e.coverage_differs, e.compared / 200);
  }
}

// k_u, k_v: a count of equal parts or a list of parameters; stored on the object, and not grid
// lines of the tessellation (they are Whitted's interior edges, for drawing by curves).
TEST(Patches, InteriorEdgesParseAndLeaveTheTessellation) {
  const std::string cps = kFlat16;
  const Scene a = parse(R"({"type": "bezier_patch", "u": 4, "v": 2, "k_u": 3, "k_v": [0.25, 0.5], "control_points": )" + cps + "}");
  const SceneObject& o = a.objects[0];
  EXPECT_EQ(o.k_u, (std::vector<double>{1.0 / 3, 2.0 / 3}));
  EXPECT_EQ(o.k_v, (std::vector<double>{0.25, 0.5}));
  // Whitted's interior edges are the curves' only: the tessellation is the u x v grid.
  EXPECT_EQ(tessellate_surface(o).faces.size(), std::size_t(4 * 2));
  const Scene b = parse(R"({"type": "patches", "basis": "bezier", "k_u": 1, "patches": [)" + cps + "]}");
  EXPECT_TRUE(b.objects[0].k_u.empty());
  EXPECT_TRUE(b.objects[0].k_v.empty());
  EXPECT_EQ(b.objects[0].u, 8);  // the patches default
  // And the errors, naming the field.
  const std::string patch = R"({"type": "bezier_patch", "control_points": )" + cps;
  EXPECT_NE(error_of(patch + R"(, "k_u": [0.5, 0.5]})").find("objects[0].k_u[1]: must be greater than the one before (0.5)"),
            std::string::npos);
  EXPECT_NE(error_of(patch + R"(, "k_v": [0, 0.5]})").find("objects[0].k_v[0]: expected a parameter in (0, 1), got 0"),
            std::string::npos);
  EXPECT_NE(error_of(patch + R"(, "k_u": 0})").find("objects[0].k_u: expected an integer in [1, 65], got 0"), std::string::npos);
  EXPECT_NE(error_of(patch + R"(, "k_u": "four"})").find("objects[0].k_u: expected a count of equal parts"), std::string::npos);
}

// Bad input names the field and what is wrong.
TEST(Patches, BadInputNamesTheField) {
  const std::string cps = kFlat16;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"type": "patches", "patches": [)" + cps + "]}", R"(objects[0]: missing required key "basis")"},
      {R"({"type": "patches", "basis": "nurbs", "patches": []})", R"(objects[0].basis: expected "bezier" or "bspline", got "nurbs")"},
      {R"({"type": "patches", "basis": "bezier"})", R"(objects[0]: missing required key "patches")"},
      {R"({"type": "patches", "basis": "bezier", "patches": []})", "objects[0].patches: expected 1 to 4096 patches, got 0"},
      {R"({"type": "patches", "basis": "bezier", "patches": [[1, 2, 3]]})", "objects[0].patches[0]: expected 16 control point indices or 16 points"},
      {R"({"type": "patches", "basis": "bezier", "patches": [[0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15]]})",
       R"(objects[0].patches[0]: indices need "control_points")"},
      {R"({"type": "patches", "basis": "bezier", "control_points": [[0,0,0],[1,0,0]], "patches": [[0,1,1,0,0,1,1,0,0,1,1,0,0,1,1,2]]})",
       "objects[0].patches[0][15]: expected an integer in [0, 1], got 2"},
      {R"({"type": "patches", "basis": "bezier", "control_points": [[0,0,0]], "patches": [[0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0.5]]})",
       "objects[0].patches[0][15]: expected an integer, got 0.5"},
      {R"({"type": "patches", "basis": "bezier", "patches": [)" + std::string(cps).replace(cps.find("[3,3,0]"), 7, "[3,3]") + "]}",
       "objects[0].patches[0][15]: expected an array of 3 numbers"},
      {R"({"type": "patches", "basis": "bezier", "closed_u": true, "patches": [)" + cps + "]}",
       R"(objects[0].closed_u: applies to "basis": "bspline" only)"},
      {R"({"type": "patches", "basis": "bspline", "patches": [)" + cps + "]}",
       R"(objects[0].patches: applies to "basis": "bezier" only)"},
      {R"({"type": "patches", "basis": "bspline", "control_net": [[[0,0,0],[1,0,0],[2,0,0],[3,0,0]],
          [[0,1,0],[1,1,0],[2,1,0],[3,1,0]], [[0,2,0],[1,2,0],[2,2,0],[3,2,0]]]})",
       "objects[0].control_net: expected 4 to 1024 rows, got 3"},
      {R"({"type": "patches", "basis": "bspline", "control_net": [[[0,0,0],[1,0,0],[2,0,0],[3,0,0]],
          [[0,1,0],[1,1,0],[2,1,0]], [[0,2,0],[1,2,0],[2,2,0],[3,2,0]], [[0,3,0],[1,3,0],[2,3,0],[3,3,0]]]})",
       "objects[0].control_net[1]: every row has as many points as the first (4), got 3"},
      {R"({"type": "patches", "basis": "bspline", "control_net": [[[0,0,0],[1,0,0],[2,0,0]], [[0,1,0],[1,1,0],[2,1,0]],
          [[0,2,0],[1,2,0],[2,2,0]], [[0,3,0],[1,3,0],[2,3,0]]]})",
       "objects[0].control_net[0]: expected 4 to 1024 points in a row, got 3"},
      {R"({"type": "patches", "basis": "bspline", "closed_u": 1, "control_net": []})", "objects[0].closed_u: expected true or false"},
      {R"({"type": "patches", "basis": "bezier", "u": 1, "patches": [)" + cps + "]}", "objects[0].u: expected an integer in [2, 1024], got 1"},
      {R"({"type": "patches", "basis": "bezier", "twist": 1, "patches": [)" + cps + "]}", R"(objects[0]: unknown key "twist")"},
  };
  for (const auto& [object, message] : cases) {
    const std::string e = error_of(object);
    EXPECT_NE(e.find("t.json: " + message), std::string::npos) << object << "\n  gave: " << e;
  }
  // A grid too fine for many patches is refused before it is sampled: 20 flat 3 x 3 patches at
  // 3/950 need 950 segments each way, 20 x 951^2 grid points (over 2^24).
  std::string twenty;
  for (int k = 0; k < 20; ++k) twenty += std::string(k ? ", " : "") + cps;
  EXPECT_NE(error_of(R"({"type": "patches", "basis": "bezier", "max_edge_length": 0.0031579, "patches": [)" + twenty + "]}")
                .find("objects[0].max_edge_length: 0.0031579 needs more than 16777216 grid points over the object's patches"),
            std::string::npos);
  // A closed direction needs 3 points: a 3 x 3 net closed both ways is 9 patches.
  const Scene s = parse(R"({"type": "patches", "basis": "bspline", "closed_u": true, "closed_v": true, "control_net":
      [[[1,0,0],[0,1,0],[-1,0,0]], [[1,0,1],[0,1,1],[-1,0,1]], [[1,0,2],[0,1,2],[-1,0,2]]]})");
  EXPECT_EQ(s.objects[0].patches.size(), 9u);
}
