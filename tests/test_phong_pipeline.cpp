// Phong shading end to end on the model: scene front end (shading.mode, normals, materials),
// prepare (normal channels, material ids, Q2.14 light/eye), the fixed-point pipeline
// (normalizer + phong_shader) against the double reference, and the inputs it must reject.
// Every bound below was measured first (figures in the comments) and is asserted with a margin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "build_options.hpp"
#include "phong_hard_cases.hpp"
#include "test_support.hpp"

using namespace watkins;
using namespace watkins::test;

namespace {

ImageError fixed_vs_double(const BuiltScene& s) { return compare_images(render_fixed(s), render_float_reference(s)); }

int level(const Image& img, int x, int y) { return img.at(x, y)[0]; }

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

// ---- shipped scenes ----------------------------------------------------------------------------

BuiltScene shipped_phong(const std::string& name) {
  return load_scene(WATKINS_SOURCE_DIR "/scenes/" + name, shading_options(ShadingMode::Phong));
}

// Measured: max 2, mean 0.2079, 1 of 37558 pixels > 1 level. The mean is set by Cp's 8-bit
// format (0.95 * 255 = 242.25 -> 242 ...). (The side seen is decided per polygon: vertex normals
// turned towards the eye one by one would give silhouette polygons antipodal normals and errors
// up to 57 levels.)
TEST(PhongPipeline, SphereWithinBoundsOfTheDoubleReference) {
  const ImageError e = fixed_vs_double(shipped_phong("sphere.json"));
  EXPECT_GT(e.compared, 37000);
  EXPECT_LE(e.max_abs, 2);
  EXPECT_LT(e.mean_abs, 0.22);
  EXPECT_LE(e.over_one, 3);
}

// Measured: max 1, mean 0.0541, 0 pixels > 1 level over 12290 pixels.
TEST(PhongPipeline, ConeWithinBoundsOfTheDoubleReference) {
  const ImageError e = fixed_vs_double(shipped_phong("cone.json"));
  EXPECT_GT(e.compared, 12000);
  EXPECT_LE(e.max_abs, 1);
  EXPECT_LT(e.mean_abs, 0.06);
  EXPECT_EQ(e.over_one, 0);
}

// ---- corner cases of the normal ----------------------------------------------------------------

// Opposite vertex normals: each row interpolates N_E to -N_E over 64 pixels, so the normal is
// exactly (0, 0, 0) at the centre of column 32 (alpha = 1/2; the span and the edges are powers of
// two long and the normals multiples of 2^-11, so every step is exact).
// The normalizer returns (0, 0, 0) and the shader then gives cos(i) = 0: the level is exactly
// Cp d = 204 * 64 / 256 = 51, with no specular. The reference treats its (exactly) null normal the
// same way. Measured: 0 levels of difference anywhere (max 0, mean 0).
TEST(PhongPipeline, AntipodalNormalsGiveCpDAtTheNullNormal) {
  const BuiltScene s = antipodal_normals_scene();
  int nulls = 0;
  const PreparedScene p = prepare(s);
  WatkinsTop pipe;
  const Image img = pipe.render(p, [&](int, const Fragment& f, bool) {
    if (f.normal[0] == 0 && f.normal[1] == 0 && f.normal[2] == 0) {
      ++nulls;
      EXPECT_EQ(f.x, 32);
      EXPECT_EQ(f.rgb[0], 51);
      EXPECT_EQ(f.rgb[1], 51);
      EXPECT_EQ(f.rgb[2], 51);
    }
  });
  EXPECT_EQ(nulls, 32);  // every scan line of the quad
  const Image ref = render_float_reference(s);
  for (int y = 0; y < 32; ++y) EXPECT_EQ(level(ref, 32, y), 51) << y;
  const ImageError e = compare_images(img, ref);
  EXPECT_EQ(e.compared, 64 * 32);
  EXPECT_LE(e.max_abs, 1);
  EXPECT_LT(e.mean_abs, 0.01);
}

// Normals almost in the screen plane (|Nz| = 0.001 before normalization), lit from the side:
// the shade depends on Nx, Ny alone. Measured: max 1 level, mean 0.1624, 0 of 4096 pixels > 1.
TEST(PhongPipeline, NormalsNearlyInTheScreenPlane) {
  const BuiltScene s = screen_plane_normals_scene();
  const ImageError e = fixed_vs_double(s);
  EXPECT_EQ(e.compared, 64 * 64);
  EXPECT_LE(e.max_abs, 1);
  EXPECT_LT(e.mean_abs, 0.2);
  EXPECT_EQ(e.over_one, 0);
}

// The light grazes the surface from behind-right, L = (1, 0, 0.1)/|.|: cos(i) changes sign
// inside the quad. Where it is <= 0 the level must be Cp d exactly (51): with L.E < 0,
// cos(s) = 2 (N.L)(N.E) - L.E stays positive there, so an ungated specular would leak about
// 0.8 * 0.0995 * 255 = 20 levels. Measured: max 1 level, mean 0.0938, 0 of 2048 pixels > 1 vs
// double; 1376 pixels have cos(i) < 0, all exactly 51.
TEST(PhongPipeline, GrazingLightHasNoSpecularLeak) {
  const BuiltScene s = grazing_light_scene();
  const Image img = render_fixed(s), ref = render_float_reference(s);
  int dark = 0, lit = 0;
  for (int y = 4; y < 36; ++y)
    for (int x = 4; x < 68; ++x) {
      const double alpha = (x + 0.5 - 4) / 64.0;
      const double nx = -0.3 + 0.6 * alpha;  // same direction as the interpolated normal
      const double ndl = (nx * 1 + -1 * 0.1) / std::sqrt(1.01);
      if (ndl < -1e-3) {
        ++dark;
        EXPECT_EQ(level(img, x, y), 51) << x << "," << y;
      } else if (ndl > 1e-3) {
        ++lit;
        EXPECT_GT(level(img, x, y), 51 + 15) << x << "," << y;  // the specular is there when lit
      }
    }
  EXPECT_GT(dark, 1000);
  EXPECT_GT(lit, 500);
  const ImageError e = compare_images(img, ref);
  EXPECT_LE(e.max_abs, 1);
  EXPECT_LT(e.mean_abs, 0.12);
}

// ---- interior highlight: what Phong shading is for ---------------------------------------------

// scenes/highlight.json: one 200 x 200 pixel quad at Z = 4 (an OBJ face, so both pipelines get the
// same geometry from the scene front end), corner normals tilted outwards by 0.5, light at the
// eye: the mirror direction is met only at the centre. Phong: measured 255 at the centre. Gouraud
// with the phong vertex rule interpolates the corner shades (cos(s)^64 ~ 0 there): measured max 131.
TEST(PhongPipeline, InteriorHighlightOnlyWithPhong) {
  const PhongVsGouraud opt = phong_vs_gouraud();
  const BuiltScene sp = load_scene(WATKINS_SOURCE_DIR "/scenes/highlight.json", opt.phong);
  const BuiltScene sg = load_scene(WATKINS_SOURCE_DIR "/scenes/highlight.json", opt.gouraud);
  ASSERT_EQ(sp.polygons.size(), 1u);
  const Image ip = render_fixed(sp), ig = render_fixed(sg);
  auto max_level = [](const Image& img, int x0, int x1) {
    int m = 0;
    for (int y = x0; y < x1; ++y)
      for (int x = x0; x < x1; ++x) m = std::max(m, int(img.at(x, y)[0]));
    return m;
  };
  EXPECT_GE(max_level(ip, 118, 138), 250);  // near the centre (128, 128)
  EXPECT_LE(max_level(ig, 0, 256), 135);    // nowhere near it with vertex shading
  EXPECT_GE(max_level(ig, 0, 256), 125);
  // The corners agree: both evaluate eq. (3) with the corner normal there.
  EXPECT_NEAR(level(ip, 29, 29), level(ig, 29, 29), 2);
  const ImageError e = fixed_vs_double(sp);
  EXPECT_LE(e.max_abs, 4);  // measured 3, mean 0.0835, 158 of 40000 pixels > 1 level (n = 64)
  EXPECT_LT(e.mean_abs, 0.1);
  EXPECT_LE(e.over_one, 200);
}

// ---- the specular exponent ---------------------------------------------------------------------

// n from 0 to 255 (the whole ShininessBits range) on a quad with an off-centre highlight; Cp,
// d and W are exact in their formats, so the error is the normal's and the power's. It grows
// with n: d(level)/d(cos s) = 255 W n cos(s)^(n-1), and cos(s) carries the Q2.14 unit normal's
// error (about 2^-14 per component, times 4). Measured (max, mean, pixels > 1 of 16384):
//   n    0: 0 0.0000   0     n  10: 2 0.1877   4     n 128: 4 0.0837 105
//   n    1: 1 0.0192   0     n  32: 2 0.1146  40     n 255: 5 0.0710  78
//   n    2: 1 0.1174   0     n  64: 2 0.0942  59
//   n    5: 1 0.2231   0
TEST(PhongPipeline, ShininessSweepWithinBoundsOfTheDoubleReference) {
  struct Bound {
    int n, max_abs;
    double mean_abs;
    int over_one;
  };
  for (const Bound b : {Bound{0, 0, 0.01, 0}, Bound{1, 1, 0.03, 0}, Bound{2, 1, 0.13, 0}, Bound{5, 1, 0.24, 0},
                        Bound{10, 2, 0.2, 10}, Bound{32, 3, 0.13, 60}, Bound{64, 3, 0.11, 80},
                        Bound{128, 5, 0.1, 130}, Bound{255, 6, 0.085, 100}}) {
    const BuiltScene s = shininess_scene(b.n);
    const ImageError e = fixed_vs_double(s);
    EXPECT_EQ(e.compared, 128 * 128) << "n = " << b.n;
    EXPECT_LE(e.max_abs, b.max_abs) << "n = " << b.n;
    EXPECT_LT(e.mean_abs, b.mean_abs) << "n = " << b.n;
    EXPECT_LE(e.over_one, b.over_one) << "n = " << b.n;
  }
}

TEST(PhongPipeline, ShininessRangeInTheSceneFile) {
  auto scene = [](const std::string& n) {
    return R"({"screen": {"width": 16, "height": 16}, "shading": {"mode": "phong"},
      "materials": {"m": {"color": [1, 1, 1], "n": )" + n + R"(}},
      "objects": [{"type": "sphere", "center": [0, 0, 5], "radius": 1, "material": "m"}]})";
  };
  EXPECT_EQ(load_scene_text(scene("255"), "s.json", ".").materials.at(0).n, 255);
  EXPECT_EQ(load_scene_text(scene("0"), "s.json", ".").materials.at(0).n, 0);
  EXPECT_EQ(error_of([&] { load_scene_text(scene("256"), "s.json", "."); }),
            "s.json: materials.m.n: Phong shading needs an integer in [0, 255], got 256");
  EXPECT_EQ(error_of([&] { load_scene_text(scene("2.5"), "s.json", "."); }),
            "s.json: materials.m.n: Phong shading needs an integer in [0, 255], got 2.5");
  // Gouraud does not use n: any value the parser accepts is kept.
  const BuildOptions g = shading_options(ShadingMode::Gouraud);
  EXPECT_NO_THROW(load_scene_text(scene("300"), "s.json", ".", g));
}

// ---- scene front end ---------------------------------------------------------------------------

TEST(PhongScene, BuildFillsMaterialsLightEyeAndTurnedNormals) {
  const std::string text = R"({"screen": {"width": 64, "height": 64}, "shading": {"mode": "phong"},
    "light": {"type": "eye"},
    "materials": {"a": {"color": [1, 0, 0], "n": 3}, "b": {"color": [0, 1, 0]}, "unused": {"color": [0, 0, 1]}},
    "objects": [{"type": "sphere", "center": [0, 0, 5], "radius": 1, "material": "b"},
                {"type": "sphere", "center": [1, 0, 6], "radius": 1, "material": "a"},
                {"type": "sphere", "center": [-1, 0, 6], "radius": 1, "material": "b"}]})";
  const BuiltScene s = load_scene_text(text, "s.json", ".");
  EXPECT_EQ(s.shading, ShadingMode::Phong);
  ASSERT_EQ(s.materials.size(), 2u);  // b, a: only materials in use, in order of first use
  EXPECT_EQ(s.materials[0].cp[1], 1.0);
  EXPECT_EQ(s.materials[1].n, 3);
  EXPECT_EQ(s.light[2], -1.0);  // an eye light shines along E
  EXPECT_EQ(s.eye[2], -1.0);
  for (const ScreenPolygon& p : s.polygons) {
    EXPECT_EQ(p.material, p.object == 1 ? 1 : 0);
    // The sphere's own normals (N = (P - C)/r), not turned vertex by vertex; every emitted
    // polygon is a front face, so its normals face the eye at the origin on the whole: sum N.(-P) > 0.
    const glm::dvec3 c = p.object == 0 ? glm::dvec3(0, 0, 5) : glm::dvec3(p.object == 1 ? 1 : -1, 0, 6);
    double seen = 0;
    for (const ScreenVertex& v : p.v) {
      const double Z = v.eye_z, X = (v.x - 32) * Z / 32, Y = (32 - v.y) * Z / 32;
      const glm::dvec3 n = glm::normalize(glm::dvec3(X, Y, Z) - c);
      EXPECT_NEAR(v.normal[0], n.x, 1e-6);
      EXPECT_NEAR(v.normal[1], n.y, 1e-6);
      EXPECT_NEAR(v.normal[2], n.z, 1e-6);
      seen -= v.normal[0] * X + v.normal[1] * Y + v.normal[2] * Z;
    }
    EXPECT_GT(seen, 0);
  }
  const PreparedScene prep = prepare(s, PrepareOptions{1024});
  EXPECT_EQ(prep.shading, ShadingMode::Phong);
  ASSERT_EQ(prep.materials.size(), 2u);
  EXPECT_EQ(prep.materials[0].cp[1], 255);
  EXPECT_EQ(prep.materials[0].d, 51);   // round(0.2 * 256)
  EXPECT_EQ(prep.materials[0].w, 128);  // round(0.5 * 256)
  EXPECT_EQ(prep.eye[2], -(1 << fmt::UnitFracBits));
  for (const EdgeRecord& e : prep.edges) EXPECT_EQ(e.material, s.polygons[std::size_t(e.poly)].material);
  // The same scene in Gouraud mode carries material id 0 and the shades, as before.
  const BuildOptions g = shading_options(ShadingMode::Gouraud);
  const PreparedScene pg = prepare(load_scene_text(text, "s.json", ".", g), PrepareOptions{1024});
  for (const EdgeRecord& e : pg.edges) EXPECT_EQ(e.material, 0);
}

TEST(PhongScene, ScreenPolygonsCarryNormalsAndTheirMaterial) {
  const std::string text = R"({"screen": {"width": 32, "height": 32}, "shading": {"mode": "phong"},
    "materials": {"m": {"color": [0.5, 0.5, 0.5], "d": 1, "W": 0}},
    "objects": [{"type": "polygons", "material": "m", "polygons": [{"vertices": [
      {"x": 2, "y": 2, "depth": 0.5, "normal": [0, 0, -2]}, {"x": 30, "y": 2, "depth": 0.5, "normal": [0, 0, -1]},
      {"x": 16, "y": 30, "depth": 0.5, "normal": [0, 0, -1]}]}]}]})";
  const BuiltScene s = load_scene_text(text, "s.json", ".");
  ASSERT_EQ(s.polygons.size(), 1u);
  EXPECT_EQ(s.polygons[0].v[0].normal[2], -1.0);  // normalized
  const Image img = render_fixed(s);
  EXPECT_EQ(level(img, 16, 10), 128);  // d = 1, W = 0: the level is Cp = round(0.5 * 255)
}

// ---- bad input ---------------------------------------------------------------------------------

TEST(PhongScene, ScreenVertexWithoutNormalIsRejectedUnderPhong) {
  const std::string text = R"({"screen": {"width": 32, "height": 32}, "shading": {"mode": "phong"},
    "objects": [{"type": "polygons", "polygons": [{"vertices": [
      {"x": 2, "y": 2, "depth": 0.5, "normal": [0, 0, -1]}, {"x": 30, "y": 2, "depth": 0.5, "rgb": [1, 2, 3]},
      {"x": 16, "y": 30, "depth": 0.5, "normal": [0, 0, -1]}]}]}]})";
  EXPECT_EQ(error_of([&] { load_scene_text(text, "s.json", "."); }),
            "s.json: objects[0].polygons[0].vertices[1]: missing key \"normal\" (Phong shading interpolates "
            "vertex normals)");
  // Gouraud needs the shades instead.
  const BuildOptions g = shading_options(ShadingMode::Gouraud);
  EXPECT_EQ(error_of([&] { load_scene_text(text, "s.json", ".", g); }),
            "s.json: objects[0].polygons[0].vertices[0]: missing key \"rgb\" (Gouraud shading interpolates "
            "vertex shades)");
}

TEST(PhongScene, SeventeenMaterialsExceedTheMaterialId) {
  std::string mats, objs;
  for (int i = 0; i < 17; ++i) {
    const std::string k = std::to_string(i);
    mats += std::string(i ? "," : "") + "\"m" + k + "\": {\"color\": [0.5, 0.5, 0.5]}";
    objs += std::string(i ? "," : "") + R"({"type": "polygons", "material": "m)" + k + R"(", "polygons": [{"vertices": [
      {"x": 1, "y": )" + k + R"(, "depth": 0.5, "normal": [0, 0, -1], "rgb": [1, 1, 1]},
      {"x": 30, "y": )" + k + R"(, "depth": 0.5, "normal": [0, 0, -1], "rgb": [1, 1, 1]},
      {"x": 16, "y": 31, "depth": 0.5, "normal": [0, 0, -1], "rgb": [1, 1, 1]}]}]})";
  }
  const std::string text = R"({"screen": {"width": 32, "height": 32}, "shading": {"mode": "phong"},
    "materials": {)" + mats + R"(}, "objects": [)" + objs + "]}";
  const BuiltScene s = load_scene_text(text, "s.json", ".");
  EXPECT_EQ(s.materials.size(), 17u);
  EXPECT_EQ(error_of([&] { prepare(s, PrepareOptions{1024}); }),
            "s.json: scene needs 17 materials; the material id is 4 bits and holds 16 (merge materials, or raise "
            "MaterialIdBits in model/twins/formats.hpp and the RTL to match)");
  // Gouraud does not carry material ids: the same scene prepares.
  const BuildOptions g = shading_options(ShadingMode::Gouraud);
  EXPECT_NO_THROW(prepare(load_scene_text(text, "s.json", ".", g), PrepareOptions{1024}));
}

TEST(PhongScene, InvalidShadingModeAndMaterialRanges) {
  auto scene = [](const std::string& shading, const std::string& mat) {
    return R"({"screen": {"width": 16, "height": 16}, "shading": )" + shading + R"(,
      "materials": {"m": )" + mat + R"(}, "objects": []})";
  };
  const std::string ok = R"({"color": [1, 1, 1]})";
  EXPECT_EQ(error_of([&] { load_scene_text(scene(R"({"mode": "phon"})", ok), "s.json", "."); }),
            "s.json: shading.mode: expected \"gouraud\" or \"phong\", got \"phon\"");
  EXPECT_EQ(error_of([&] { load_scene_text(scene(R"({"mode": 1})", ok), "s.json", "."); }),
            "s.json: shading.mode: expected a string, got 1");
  EXPECT_EQ(error_of([&] { load_scene_text(scene(R"({"mode": "phong"})", R"({"color": [1, 1, 1], "W": 2})"),
                                           "s.json", "."); }),
            "s.json: materials.m.W: expected a number in [0, 1.99609], got 2");
  EXPECT_EQ(error_of([&] { load_scene_text(scene(R"({"mode": "phong"})", R"({"color": [1, 1, 1], "d": 1.5})"),
                                           "s.json", "."); }),
            "s.json: materials.m.d: expected a number in [0, 1], got 1.5");
  EXPECT_NO_THROW(load_scene_text(scene(R"({"mode": "phong"})", R"({"color": [1, 1, 1], "W": 1.99609375})"),
                                  "s.json", "."));
}

TEST(PhongScene, PrepareRejectsNormalsThatAreNotUnit) {
  BuiltScene s = phong_scene(16, 16, {poly({nvtx(1, 1, 0, 0, -1), nvtx(15, 1, 0, 0, -1), nvtx(8, 15, 0, 0, -1)})},
                             material(1, 0.2, 0.5, 10));
  s.polygons[0].v[2].normal[0] = 1.5;
  EXPECT_EQ(error_of([&] { prepare(s); }),
            "test: polygon 0 vertex 2: vertex normal component 1.5 is outside [-1, 1] (expected a unit vector)");
  s.polygons[0].v[2].normal[0] = NAN;
  EXPECT_NE(error_of([&] { prepare(s); }).find("vertex normal component NaN"), std::string::npos);
}

}  // namespace
