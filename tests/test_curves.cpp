// Whitted's edge description and intersection processor (model/curves), the builder's curve path
// and the double reference drawing curves. Bounds were measured first (figures in the comments)
// and are asserted with a margin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "analytic_truth.hpp"
#include "cli_run.hpp"
#include "camera.hpp"
#include "float_reference.hpp"
#include "newton_fixed.hpp"
#include "newton_scan.hpp"
#include "scene_types.hpp"
#include "patches.hpp"
#include "surfaces.hpp"
#include "test_support.hpp"
#include "whitted_edges.hpp"

using namespace watkins;

namespace {

std::string patch_text() { return read_scene_text(std::string(WATKINS_SOURCE_DIR) + "/scenes/patch.json"); }

// patch.json with n x n subpatches (k = 1/n, ..., (n-1)/n) and an n x n tessellation, Phong shading.
BuiltScene patch_scene(int n, bool curves, bool cull = false) {
  std::string ks;
  for (int k = 1; k < n; ++k) ks += (k > 1 ? ", " : "") + std::to_string(double(k) / n);
  std::string text = patch_text();
  const std::string uv = "\"u\": 16, \"v\": 16, \"k_u\": 8, \"k_v\": 8";  // as shipped
  const std::size_t at = text.find(uv);
  EXPECT_NE(at, std::string::npos);
  text.replace(at, uv.size(), "\"u\": " + std::to_string(n) + ", \"v\": " + std::to_string(n) + ", \"k_u\": [" + ks +
                                  "], \"k_v\": [" + ks + "]");
  BuildOptions o;
  o.shading = ShadingMode::Phong;
  o.patches_as_curves = curves;
  o.cull_backfaces = cull;
  return load_scene_text(text, "patch.json", ".", o);
}

// The builder's camera-space patch function for a scene's bezier_patch object.
struct CameraPatch {
  BicubicPatch cp;
  ObjectToCamera xf;
  CameraPatch(const Scene& sc, const SceneObject& o)
      : cp(o.patches.at(0)), xf(make_view(sc.camera), o.transform) {}
  PatchPoint fn() const {
    return [this](double u, double v, glm::dvec3& p, glm::dvec3& pu, glm::dvec3& pv) {
      bezier_point(cp, u, v, p, pu, pv);
      p = xf.linear * p + xf.offset, pu = xf.linear * pu, pv = xf.linear * pv;
    };
  }
};

// A half cylinder along Y (a cubic Bezier half circle of radius 1 in X-Z, bulging towards the eye)
// at Z = 5: its silhouettes are the rulings where the line of sight grazes it, u = const.
PatchPoint half_cylinder(BicubicPatch& cp) {
  const double xz[4][2] = {{-1, 0}, {-1, -4.0 / 3}, {1, -4.0 / 3}, {1, 0}};
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) cp[std::size_t(4 * row + col)] = {xz[col][0], 1.5 - row, 5 + xz[col][1]};
  return [&cp](double u, double v, glm::dvec3& p, glm::dvec3& pu, glm::dvec3& pv) { bezier_point(cp, u, v, p, pu, pv); };
}

const Projection kProj{160, 120, 1.2};

// patch.json with 8 x 8 subpatches drawn by curves, its camera-space patch and its edge description.
struct DescribedPatch {
  BuiltScene s = patch_scene(8, true);
  CameraPatch cam{*s.source, s.source->objects.at(0)};
  PatchPoint f = cam.fn();
  EdgeStats st;
  PatchEdges e = describe();

 private:
  PatchEdges describe() {
    const SceneObject& o = s.source->objects.at(0);
    WhittedOptions wo;
    wo.k_u = o.k_u, wo.k_v = o.k_v, wo.line_hi = s.height;
    return describe_patch(f, kProj, wo, st);
  }
};

}  // namespace

// Newton on E_y(t) = y_n: every crossing of the shipped patch (8 x 8 subpatches, and whole) within
// 1e-9 px of its scan line, the first-order start converging in under 2 iterations on average.
// Measured: 1583 crossings at 8 x 8, 1.916 iterations each (5e-10 px tolerance), 20 by brute
// force; 1380 of 1408 stepped crossings within 1/1024 px after one iteration.
TEST(Curves, NewtonConvergesOnEveryCrossingOfThePatch) {
  const BuiltScene s = patch_scene(8, true);
  ASSERT_TRUE(s.source);
  for (bool subpatches : {false, true}) {
    const SceneObject& o = s.source->objects.at(0);
    const CameraPatch cam(*s.source, o);
    const PatchPoint f = cam.fn();
    WhittedOptions wo;
    if (subpatches) wo.k_u = o.k_u, wo.k_v = o.k_v;
    wo.line_hi = s.height;
    EdgeStats st;
    const PatchEdges e = describe_patch(f, kProj, wo, st);
    ASSERT_GT(st.newton.crossings, 300);
    long long checked = 0;
    for (const EdgePiece& p : e.pieces)
      for (std::size_t k = 0; k < p.lines.size(); ++k) {
        EXPECT_LT(std::fabs(p.lines[k].y - (p.y0 + int(k) + 0.5)), 1e-9) << "piece at line " << p.y0 << " + " << k;
        ++checked;
      }
    EXPECT_GE(checked, st.newton.crossings);  // a side or silhouette bounding two regions is stepped once
    EXPECT_LT(st.newton.mean_iterations(), 2.0);
    // Whitted's "usually in the first iteration": at pixel precision (1/1024 px) nearly always;
    // the exceptions are lines next to an extremum of E_y, where E'_y is small.
    EXPECT_GT(st.newton.one_iteration_close, 0.95 * double(st.newton.stepped));
    EXPECT_EQ(st.newton.no_convergence, 0);
    // Brute force only where an iterate leaves its piece (a piece starting at an extremum of E_y).
    EXPECT_LT(st.newton.brute_force(), st.newton.crossings / 20);
  }
}

// The brute-force path: E_y = 100 t^2 starts with E'_y = 0, so the first estimate leaves [0, 1];
// bisection on the monotonic piece still finds every crossing.
TEST(Curves, BruteForceWhenTheEstimateLeavesThePiece) {
  const EdgeY ey = [](double t, double& y, double& dy) { y = 100 * t * t, dy = 200 * t; };
  NewtonStats st;
  int first = -1;
  const std::vector<double> ts = scan_line_crossings(ey, 0, 1, 0, 1000, first, st);
  EXPECT_EQ(first, 0);
  ASSERT_EQ(ts.size(), 100u);  // lines 0..99: 0 <= n + 0.5 < 100
  EXPECT_GE(st.left_piece, 1);
  EXPECT_EQ(st.brute_force(), st.left_piece + st.no_convergence);
  for (std::size_t n = 0; n < ts.size(); ++n) EXPECT_LT(std::fabs(100 * ts[n] * ts[n] - (n + 0.5)), 1e-9);
  // Reversed parameter direction: t from 1 (top) to 0 gives the same lines.
  const EdgeY down = [](double t, double& y, double& dy) { y = 100 * (1 - t) * (1 - t), dy = -200 * (1 - t); };
  NewtonStats st2;
  const std::vector<double> ts2 = scan_line_crossings(down, 1, 0, 0, 1000, first, st2);
  ASSERT_EQ(ts2.size(), 100u);
  EXPECT_NEAR(ts2[10], 1 - std::sqrt(0.105), 1e-9);
}

// y-monotonic split: an iso-line whose camera-space Y is 2 (u - 1/2)^2 - 0.1 at constant Z has
// its only extremum of E_y at u = 1/2; the edge becomes two pieces, each crossing its lines once.
TEST(Curves, EdgeSplitAtItsExtremumInY) {
  const PatchPoint f = [](double u, double v, glm::dvec3& p, glm::dvec3& pu, glm::dvec3& pv) {
    p = {u - 0.5, 2 * (u - 0.5) * (u - 0.5) - 0.1 + 0.3 * v, 2.0};
    pu = {1, 4 * (u - 0.5), 0}, pv = {0, 0.3, 0};
  };
  ParamCurve c;
  c.a = {0, 0}, c.b = {1, 0};
  const ScreenEdge e(f, kProj, c);
  const std::vector<double> ext = e.y_extrema();
  ASSERT_EQ(ext.size(), 1u);
  EXPECT_NEAR(ext[0], 0.5, 1e-12);
  WhittedOptions wo;
  wo.line_hi = 240;
  EdgeStats st;
  const std::vector<EdgePiece> pieces = scan_edge(f, kProj, c, 0, 1, wo, st);
  EXPECT_EQ(st.y_splits, 1);
  ASSERT_EQ(pieces.size(), 2u);
  // y_s = 120 - (1.2 * 160) Y / 2: 81.6 at the ends, 129.6 at u = 1/2 (the bottom); centres
  // 82.5 .. 129.5, 48 lines on each piece.
  for (const EdgePiece& p : pieces) {
    EXPECT_EQ(p.y0, 82);
    EXPECT_EQ(p.lines.size(), 48u);
  }
}

// Silhouette of a half cylinder seen from the front: split at k_u = 1/2, each subpatch holds one
// silhouette ruling; Whitted's Hermite ends on N.(P - eye) = 0 and, the surface being ruled, lies on
// the silhouette everywhere (the uv-space chord is the ruling itself).
TEST(Curves, HalfCylinderSilhouette) {
  BicubicPatch cp;
  const PatchPoint f = half_cylinder(cp);
  WhittedOptions wo;
  wo.k_u = {0.5};
  wo.line_hi = 240;
  EdgeStats st;
  const PatchEdges e = describe_patch(f, kProj, wo, st);
  EXPECT_EQ(st.silhouettes, 2);
  EXPECT_EQ(st.default_one + st.default_many + st.default_side_twice + st.default_inside, 0);
  ASSERT_EQ(e.silhouettes.size(), 2u);
  for (const ParamCurve& s : e.silhouettes) {
    EXPECT_LT(std::fabs(silhouette_cosine(f, s.a.x, s.a.y)), 1e-9);
    EXPECT_LT(std::fabs(silhouette_cosine(f, s.b.x, s.b.y)), 1e-9);
    for (int k = 0; k <= 20; ++k) {
      const glm::dvec2 uv = s.at(k / 20.0);
      EXPECT_LT(std::fabs(silhouette_cosine(f, uv.x, uv.y)), 1e-9);
    }
  }
  EXPECT_EQ(e.regions.size(), 4u);  // each subpatch: a front part and a back part
  // Culling keeps the front parts only.
  wo.cull = true;
  EdgeStats st2;
  const PatchEdges front = describe_patch(f, kProj, wo, st2);
  EXPECT_EQ(front.regions.size(), 2u);
  EXPECT_EQ(st2.culled_regions, 2);
  // Without k_u the patch holds both silhouettes: four boundary crossings, Whitted's default.
  wo.k_u.clear();
  EdgeStats st3;
  describe_patch(f, kProj, wo, st3);
  EXPECT_EQ(st3.default_many, 1);
  EXPECT_EQ(st3.silhouettes, 0);
}

// On the shipped patch (8 x 8) the Hermite is the surface curve over the uv chord: it ends on
// the silhouette and stays near it. Measured: the nearest true silhouette point along v = const is
// at most 0.63 px away on screen (asserted < 1 px).
TEST(Curves, PatchSilhouetteNearTheTrueOne) {
  const DescribedPatch d;
  const BuiltScene& s = d.s;
  const PatchPoint& f = d.f;
  const PatchEdges& e = d.e;
  ASSERT_GE(e.silhouettes.size(), 4u);
  double worst = 0;
  for (const ParamCurve& sil : e.silhouettes) {
    EXPECT_LT(std::fabs(silhouette_cosine(f, sil.a.x, sil.a.y)), 1e-9);
    EXPECT_LT(std::fabs(silhouette_cosine(f, sil.b.x, sil.b.y)), 1e-9);
    for (int k = 1; k < 16; ++k) {
      const glm::dvec2 uv = sil.at(k / 16.0);
      // The true silhouette along v = const: the sign change of N.P nearest to u.
      auto g = [&](double u) { return silhouette_cosine(f, u, uv.y); };
      double best = 1e9;
      for (int dir : {-1, 1}) {
        double a = uv.x, ga = g(a);
        for (double step = 1e-3; step < 0.3; step += 1e-3) {
          const double b = uv.x + dir * step;
          if (b < 0 || b > 1) break;
          if ((g(b) < 0) != (ga < 0)) {
            double lo = b - dir * 1e-3, hi = b;
            for (int it = 0; it < 60; ++it) {
              const double m = 0.5 * (lo + hi);
              ((g(m) < 0) == (g(lo) < 0) ? lo : hi) = m;
            }
            glm::dvec3 p0, p1, d;
            f(uv.x, uv.y, p0, d, d);
            f(lo, uv.y, p1, d, d);
            best = std::min(best, std::hypot(kProj.x(p0) - kProj.x(p1), kProj.y(p0) - kProj.y(p1)));
            break;
          }
        }
      }
      if (best < 1e9) worst = std::max(worst, best);
    }
  }
  EXPECT_LT(worst, 1.0) << "Hermite silhouette vs true silhouette, px";
  RecordProperty("silhouette_px", std::to_string(worst));
}

// Every region's crossings pair on every scan line (an even count), and the builder's curves
// carry the interface's promises (y0 >= 0, regions numbered 0..curve_regions - 1).
TEST(Curves, RegionsPairOnEveryLine) {
  const BuiltScene s = patch_scene(8, true);
  EXPECT_TRUE(s.polygons.empty());
  ASSERT_GT(s.curve_regions, 64);
  std::map<std::pair<int, int>, int> count;  // (region, line) -> crossings
  for (const ScreenCurve& c : s.curves) {
    ASSERT_GE(c.y0, 0);
    ASSERT_FALSE(c.lines.empty());
    ASSERT_LT(c.region, s.curve_regions);
    for (std::size_t k = 0; k < c.lines.size(); ++k) ++count[{c.region, c.y0 + int(k)}];
  }
  for (const auto& rc : count) EXPECT_EQ(rc.second % 2, 0) << "region " << rc.first.first << " line " << rc.first.second;
  EXPECT_GT(s.max_curve_crossings, 4);
}

// Whitted against tessellation, both against the exact patch ray-cast, at the same subdivision
// (8 x 8 subpatches against 8 x 8 quads, Phong). Measured: curves mean 0.680 levels, 0 pixels of
// changed coverage; polygons mean 1.175, 92 pixels.
TEST(Curves, ReferenceBeatsTessellationAgainstTheTruth) {
  const BuiltScene curves = patch_scene(8, true), polys = patch_scene(8, false);
  const AnalyticTruth truth = render_analytic_truth(curves);
  ASSERT_TRUE(truth.unavailable.empty()) << truth.unavailable;
  const ImageError ec = compare_with_truth(curves, render_float_reference(curves), truth);
  const ImageError ep = compare_with_truth(polys, render_float_reference(polys), truth);
  EXPECT_GT(ec.compared, 14000);
  EXPECT_LT(ec.mean_abs, 0.75 * ep.mean_abs) << "curves " << ec.mean_abs << ", polygons " << ep.mean_abs;
  EXPECT_LT(ec.coverage_differs, ep.coverage_differs / 4 + 1)
      << "curves " << ec.coverage_differs << ", polygons " << ep.coverage_differs;
}

// Scene keys: "draw", "k_u", "k_v" and their errors; "polygons" (the default) keeps the image.
TEST(Curves, SceneKeys) {
  std::string text = patch_text();
  const BuiltScene base = load_scene_text(text, "p", ".");
  EXPECT_TRUE(base.curves.empty());
  EXPECT_EQ(base.polygons.size(), 256u);
  auto with = [&](const std::string& keys) {  // in place of the shipped interior edges
    std::string t = text;
    const std::string shipped = "\"k_u\": 8, \"k_v\": 8, ";
    t.erase(t.find(shipped), shipped.size());
    const std::size_t at = t.find("\"u\": 16");
    t.insert(at, keys + ", ");
    return t;
  };
  const BuiltScene drawn = load_scene_text(with(R"("draw": "curves", "k_u": [0.5])"), "p", ".");
  EXPECT_TRUE(drawn.polygons.empty());
  EXPECT_FALSE(drawn.curves.empty());
  BuildOptions back;
  back.patches_as_curves = false;
  EXPECT_EQ(load_scene_text(with(R"("draw": "curves")"), "p", ".", back).polygons.size(), 256u);
  for (const char* bad : {R"("draw": "lines")", R"("k_u": [0.5, 0.5])", R"("k_v": [1])", R"("k_u": 0.5)"})
    EXPECT_THROW(load_scene_text(with(bad), "p", "."), SceneError) << bad;
}

// Whitted's shading rule is eq. (3) with d = 0.25 and n = 60: the material preset sets them.
TEST(Curves, WhittedMaterialRule) {
  std::string text = patch_text();
  const std::string cyan = R"("cyan": {"color": [0.3, 0.85, 0.9]})";
  const std::size_t at = text.find(cyan);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, cyan.size(), R"("cyan": {"color": [0.3, 0.85, 0.9], "rule": "whitted", "W": 0.7})");
  BuildOptions o;
  o.shading = ShadingMode::Phong;
  const BuiltScene s = load_scene_text(text, "p", ".", o);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].d, 0.25);
  EXPECT_EQ(s.materials[0].n, 60);
  EXPECT_EQ(s.materials[0].W, 0.7);
  std::string bad = text;
  bad.replace(bad.find("\"rule\": \"whitted\""), 17, "\"rule\": \"whitted\", \"n\": 5");
  EXPECT_THROW(load_scene_text(bad, "p", ".", o), SceneError);
}

// The Newton option in fixed point, one iteration per line with an N-bit reciprocal, on Whitted's
// screen-space cubics per piece, against the double Newton on the exact edges (patch.json, 8 x 8
// subpatches). Measured (x, px), any N from 8 to 20 bits: total max 0.81, mean 0.0068; the cubic
// fit alone max 0.71; the one-iteration stepping alone max 0.82, mean 0.0016, on 16 of 2864 lines
// over 1/16 px (a piece of a shared edge counts per region).
TEST(Curves, FixedPointNewtonAgainstTheDouble) {
  const DescribedPatch d;
  const BuiltScene& s = d.s;
  const PatchPoint& f = d.f;
  const PatchEdges& e = d.e;
  std::vector<FixedNewtonError> by_bits;
  for (int bits : {8, 12, 16, 20}) {
    FixedNewtonFormat fmt;
    fmt.recip_bits = bits;
    FixedNewtonError all;
    for (const EdgePiece& p : e.pieces) all.add(fixed_newton_error(f, kProj, p, fmt));
    std::printf("fixed Newton, %2d-bit reciprocal: x max %.4f mean %.5f px, y left %.4f px; cubic fit alone %.4f px, "
                "stepping alone max %.4f mean %.5f px, %lld of %lld lines over 1/16 px\n", bits, all.max_x, all.mean_x,
                all.max_y, all.max_x_cubic, all.max_x_step, all.mean_x_step, all.step_over_16th, all.lines);
    by_bits.push_back(all);
  }
  EXPECT_GT(by_bits[0].lines, 2000);
  // The reciprocal's width hardly matters (Newton corrects its own step: an error in 1 / y' is
  // first order in a residual that is already small); one iteration does, next to an extremum of
  // E_y, where y' is small and a residual in y is a large one in x.
  EXPECT_LT(std::fabs(by_bits[0].mean_x_step - by_bits[3].mean_x_step), 0.01 * by_bits[3].mean_x_step);
  EXPECT_LT(by_bits[1].mean_x_step, 0.005);
  EXPECT_LT(by_bits[1].step_over_16th, by_bits[1].lines / 50);
  EXPECT_GT(by_bits[1].max_x_step, 0.25);  // the exceptions are real: one iteration is not enough there
  EXPECT_LT(by_bits[1].max_x_cubic, 1.0);
  EXPECT_EQ(FixedNewtonError::multipliers, 21);
}

// A patches object (Newell's teapot as shipped: 32 Bezier patches, culling on) drawn by curves
// with its 4 x 4 subpatches per patch (k_u, k_v) against its 4 x 4 tessellation, Phong. Measured:
// curves mean 2.23 levels, 9 pixels of changed coverage; polygons 4.83, 377. Every region still
// pairs on every line.
TEST(Curves, TeapotByCurves) {
  const std::string text = read_scene_text(std::string(WATKINS_SOURCE_DIR) + "/scenes/teapot.json");
  BuildOptions o;
  o.shading = ShadingMode::Phong;
  o.patches_as_curves = true;
  const BuiltScene curves = load_scene_text(text, "teapot.json", ".", o);
  o.patches_as_curves = false;
  const BuiltScene polys = load_scene_text(text, "teapot.json", ".", o);
  EXPECT_EQ(curves.curve_stats.cells, 32 * 16);
  // 32 patches x 65 x 65 subpatches is over the 2^15 the builder allows an object drawn as curves.
  std::string many = text;
  const std::string k4 = "\"k_u\": 4, \"k_v\": 4";
  many.replace(many.find(k4), k4.size(), "\"k_u\": 65, \"k_v\": 65");
  o.patches_as_curves = true;
  EXPECT_THROW(load_scene_text(many, "teapot.json", ".", o), SceneError);
  o.patches_as_curves = false;
  EXPECT_GT(curves.curve_stats.culled_regions, 100);
  std::map<std::pair<int, int>, int> count;
  for (const ScreenCurve& c : curves.curves)
    for (std::size_t k = 0; k < c.lines.size(); ++k) ++count[{c.region, c.y0 + int(k)}];
  for (const auto& rc : count) ASSERT_EQ(rc.second % 2, 0) << "region " << rc.first.first << " line " << rc.first.second;
  const AnalyticTruth truth = render_analytic_truth(curves);
  ASSERT_TRUE(truth.unavailable.empty()) << truth.unavailable;
  const ImageError ec = compare_with_truth(curves, render_float_reference(curves), truth);
  const ImageError ep = compare_with_truth(polys, render_float_reference(polys), truth);
  EXPECT_LT(ec.mean_abs, 0.6 * ep.mean_abs) << "curves " << ec.mean_abs << ", polygons " << ep.mean_abs;
  EXPECT_LT(ec.coverage_differs, ep.coverage_differs / 10)
      << "curves " << ec.coverage_differs << ", polygons " << ep.coverage_differs;
}

// `watkins render --patches curves` draws the patch by curves (no polygons) and reports them;
// a bad value is refused.
TEST(Curves, CliPatchesOption) {
  watkins::test::ScratchDir dir;
  const std::string folder = std::filesystem::path(dir.write("placeholder", "")).parent_path().string();
  const std::string scene = std::string(WATKINS_SOURCE_DIR) + "/scenes/patch.json";
  const auto r = watkins::test::run_cli("render " + scene + " --model float --patches curves --out " +
                                        folder + "/c.png");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(dir.has("c.png"));
  EXPECT_NE(r.output.find("polygons      0 "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("curves        "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("newton        "), std::string::npos) << r.output;
  EXPECT_NE(watkins::test::run_cli("render " + scene + " --patches lines --out " + folder + "/d.png").exit_code, 0);
}

namespace {

// Curves are not clipped: a patch drawn by curves that reaches in front of the near plane is
// refused, the message naming the scene, the object and its field (drawn as polygons it is clipped).
TEST(Curves, NearPlaneRefusalNamesTheObject) {
  std::string text = patch_text();
  const std::string at = "\"translate\": [0, 0, 4.5]";
  ASSERT_NE(text.find(at), std::string::npos);
  text.replace(text.find(at), at.size(), "\"translate\": [0, 0, 1.2]");
  BuildOptions o;
  o.patches_as_curves = true;
  try {
    load_scene_text(text, "near.json", ".", o);
    FAIL() << "a patch through the near plane was drawn by curves";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("objects[0].draw: the patch reaches outside the camera's [near, far)"),
              std::string::npos)
        << e.what();
  }
  o.patches_as_curves = false;
  EXPECT_GT(load_scene_text(text, "near.json", ".", o).near_clipped, 0);
}

}  // namespace
