// Voxel objects (model/scene/voxels.hpp, Herman and Liu 1978): boundary-face extraction, winding and
// outward normals, averaged normals, anisotropic spacing, raw files and their bad-input
// discipline, the phantoms' analytic truth, and the shipped phantom scenes on the default hardware.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>

#include "analytic_truth.hpp"
#include "cli_run.hpp"
#include "error_stats.hpp"
#include "prepare.hpp"
#include "scene.hpp"
#include "scene_types.hpp"
#include "smoother.hpp"
#include "surfaces.hpp"
#include "voxels.hpp"
#include "watkins_top.hpp"

using namespace watkins;

namespace {

std::string scene_text(const std::string& objects) {
  return R"({"screen": {"width": 64, "height": 64},
    "camera": {"type": "lookat", "eye": [0, 0, -40], "target": [0, 0, 0], "fov_deg": 30, "near": 1, "far": 200},
    "light": {"type": "eye"}, "shading": {"mode": "phong", "rule": "phong"},
    "materials": {"m": {"color": [0.5, 0.5, 0.5], "d": 0.2, "W": 0.25, "n": 10}},
    "objects": [)" + objects + "]}";
}

VoxelGrid grid(std::array<int, 3> dims, std::initializer_list<std::array<int, 3>> in, glm::dvec3 spacing = glm::dvec3(1.0)) {
  VoxelGrid g(dims, spacing);
  for (const auto& v : in) g.set(v[0], v[1], v[2], true);
  return g;
}

glm::dvec3 newell(const IndexedMesh& m, const IndexedMesh::Face& f) {
  glm::dvec3 n(0.0);
  for (int k = 0; k < f.n; ++k) n += glm::cross(m.position[std::size_t(f.idx[k])], m.position[std::size_t(f.idx[(k + 1) % f.n])]);
  return n;
}

glm::dvec3 centroid(const IndexedMesh& m, const IndexedMesh::Face& f) {
  glm::dvec3 c(0.0);
  for (int k = 0; k < f.n; ++k) c += m.position[std::size_t(f.idx[k])] / double(f.n);
  return c;
}

// A scratch folder whose path the test needs (a raw file is named relative to the scene's folder).
struct Scratch : test::ScratchDir {
  const std::string& dir() const { return dir_; }
};

std::string message_of(const std::string& text, const std::string& base_dir = ".") {
  try {
    load_scene_text(text, "t", base_dir);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Voxels, OneVoxelHasSixOutwardFacesWoundFrontFromOutside) {
  const VoxelGrid g = grid({3, 3, 3}, {{{1, 1, 1}}});
  EXPECT_EQ(g.boundary_faces(), 6u);
  const IndexedMesh m = voxel_surface(g, false, false);
  ASSERT_EQ(m.faces.size(), 6u);
  std::set<std::tuple<int, int, int>> normals;
  for (const auto& f : m.faces) {
    ASSERT_EQ(f.n, 4);
    const glm::dvec3 n = m.normal[std::size_t(f.idx[0])];
    normals.insert({int(n.x), int(n.y), int(n.z)});
    // Outward: from the voxel's centre (the grid's centre, the origin) towards the face.
    EXPECT_GT(glm::dot(n, centroid(m, f)), 0.49);
    // Left-handed world: a front face's Newell normal points inward (docs/guide/scene-format.md).
    EXPECT_LT(glm::dot(newell(m, f), n), 0);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(m.normal[std::size_t(f.idx[k])], n);  // flat: the face's own normal
  }
  EXPECT_EQ(normals.size(), 6u);
}

TEST(Voxels, TwoAdjacentVoxelsShareNoFaceAndTenRemain) {
  for (int axis = 0; axis < 3; ++axis) {
    std::array<int, 3> b{1, 1, 1};
    b[std::size_t(axis)] = 2;
    const VoxelGrid g = grid({4, 4, 4}, {{{1, 1, 1}}, b});
    EXPECT_EQ(g.boundary_faces(), 10u) << axis;
    EXPECT_EQ(voxel_surface(g, false, true).faces.size(), 20u) << axis;  // split: two triangles each
  }
  // Touching along an edge only: nothing is shared, 12 faces.
  EXPECT_EQ(grid({4, 4, 4}, {{{1, 1, 1}}, {{2, 2, 1}}}).boundary_faces(), 12u);
}

TEST(Voxels, AHoleInsideIsASecondSurfaceFacingIntoTheHole) {
  VoxelGrid g({5, 5, 5}, glm::dvec3(1.0));
  for (int k = 1; k < 4; ++k)
    for (int j = 1; j < 4; ++j)
      for (int i = 1; i < 4; ++i) g.set(i, j, k, !(i == 2 && j == 2 && k == 2));
  // 6 x 9 outer faces and 6 around the empty centre voxel.
  EXPECT_EQ(g.boundary_faces(), 54u + 6u);
  const IndexedMesh m = voxel_surface(g, false, false);
  int inner = 0;
  for (const auto& f : m.faces) {
    const glm::dvec3 c = centroid(m, f), n = m.normal[std::size_t(f.idx[0])];
    if (glm::length(c) < 0.6) {
      ++inner;
      EXPECT_LT(glm::dot(n, c), 0);  // outward from the solid is towards the hole's centre
    }
    EXPECT_LT(glm::dot(newell(m, f), n), 0);
  }
  EXPECT_EQ(inner, 6);
}

TEST(Voxels, AnisotropicSpacingScalesTheFacesAndCentresTheGrid) {
  const VoxelGrid g = grid({2, 2, 2}, {{{1, 1, 1}}}, {1.04, 1.04, 1.68});
  EXPECT_EQ(g.corner(0, 0, 0), glm::dvec3(-1.04, -1.04, -1.68));
  EXPECT_EQ(g.corner(2, 2, 2), glm::dvec3(1.04, 1.04, 1.68));
  const IndexedMesh m = voxel_surface(g, false, false);
  for (const auto& f : m.faces) {
    const glm::dvec3 n = m.normal[std::size_t(f.idx[0])];
    // Face area: the product of the two spacings across its normal.
    const double area = glm::length(newell(m, f)) / 2;
    const double expect = n.z != 0 ? 1.04 * 1.04 : 1.04 * 1.68;
    EXPECT_NEAR(area, expect, 1e-12);
  }
}

TEST(Voxels, AveragedNormalsShareCornersAndPointOutward) {
  const VoxelGrid g = grid({3, 3, 3}, {{{1, 1, 1}}});
  const IndexedMesh m = voxel_surface(g, true, false);
  EXPECT_EQ(m.position.size(), 8u);  // one vertex per corner of the cube
  for (std::size_t v = 0; v < m.position.size(); ++v) {
    // A cube corner: the normalized sum of its three faces' normals, along the diagonal.
    EXPECT_NEAR(glm::dot(m.normal[v], glm::normalize(m.position[v])), 1.0, 1e-12);
  }
  // Two voxels touching along an edge: at the two shared corners the six face normals cancel, so
  // those faces keep their own normals there (no zero normal reaches the pipeline).
  const IndexedMesh e = voxel_surface(grid({4, 4, 4}, {{{1, 1, 1}}, {{2, 2, 1}}}), true, false);
  for (const glm::dvec3& n : e.normal) EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
}

TEST(Voxels, PhantomsAreSampledAtVoxelCentres) {
  const Phantom p = make_phantom(PhantomShape::Ellipsoid, {4, 3, 2});
  EXPECT_TRUE(p.contains({3.99, 0, 0}));
  EXPECT_FALSE(p.contains({0, 3.01, 0}));
  const VoxelGrid g = voxelize(p, {10, 8, 6}, glm::dvec3(1.0));
  // Voxel centres at half-integers; inside where x^2/16 + y^2/9 + z^2/4 <= 1.
  std::size_t expect = 0;
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 10; ++i) {
        const double x = i - 4.5, y = j - 3.5, z = k - 2.5;
        expect += x * x / 16 + y * y / 9 + z * z / 4 <= 1;
      }
  EXPECT_EQ(g.inside_count(), expect);
  const Phantom b = make_phantom(PhantomShape::BeadedSphere, glm::dvec3(1.0));
  EXPECT_EQ(b.balls.size(), 15u);
  EXPECT_TRUE(b.contains({0, 0, 0.99}));   // a bead on +Z, beyond the body's radius 0.8
  EXPECT_FALSE(b.contains({0.7, 0.7, 0}));  // between beads, outside the body
  EXPECT_NEAR(b.extent, 1.0, 1e-12);
}

TEST(Voxels, SceneObjectDrawsExactlyTheFacesTurnedToTheEye) {
  const BuiltScene s = load_scene_text(scene_text(R"({"type": "voxels", "phantom": "ellipsoid", "dims": [6, 6, 6],
    "material": "m"})"), "t", ".");
  const VoxelGrid& g = *s.source->objects.at(0).voxels;
  // The eye at (0, 0, -40) (the scene's look-at camera, object untransformed): a face is drawn
  // when its outward normal points to the eye's side of its plane, culled when away, degenerate
  // (zero projected area) when the eye is in its plane.
  int front = 0, edge_on = 0;
  const IndexedMesh m = voxel_surface(g, false, false);
  for (const auto& f : m.faces) {
    const double d = glm::dot(m.normal[std::size_t(f.idx[0])], glm::dvec3(0, 0, -40) - centroid(m, f));
    front += d > 0;
    edge_on += d == 0;
  }
  EXPECT_EQ(s.polygons.size(), std::size_t(front));
  EXPECT_EQ(s.degenerate, edge_on);
  EXPECT_EQ(s.polygons.size() + std::size_t(s.culled_backfaces) + std::size_t(s.degenerate), g.boundary_faces());
  EXPECT_GT(front, 0);
}

TEST(Voxels, RawFileIsThresholdedU8AndU16) {
  Scratch dir;
  // 2 x 1 x 1 voxels: densities 10 and 200 (u8); 256 and 16 (u16, little-endian: bytes 00 01, 10 00).
  dir.write("a.raw", std::string("\x0a\xc8", 2));
  dir.write("b.raw", std::string("\x00\x01\x10\x00", 4));
  auto obj = [](const std::string& file, const std::string& format, int threshold) {
    return R"({"type": "voxels", "file": ")" + file + R"(", "format": ")" + format + R"(", "dims": [2, 1, 1], "threshold": )" +
           std::to_string(threshold) + "}";
  };
  const Scene a = parse_scene(scene_text(obj("a.raw", "u8", 100)), "t", dir.dir());
  EXPECT_FALSE(a.objects[0].voxels->inside(0, 0, 0));
  EXPECT_TRUE(a.objects[0].voxels->inside(1, 0, 0));
  EXPECT_FALSE(a.objects[0].has_phantom);
  const Scene b = parse_scene(scene_text(obj("b.raw", "u16", 200)), "t", dir.dir());
  EXPECT_TRUE(b.objects[0].voxels->inside(0, 0, 0));  // little-endian 0x0100 = 256
  EXPECT_FALSE(b.objects[0].voxels->inside(1, 0, 0));
}

TEST(Voxels, BadInputNamesTheField) {
  Scratch dir;
  dir.write("a.raw", std::string(5, '\x80'));
  auto with = [&](const std::string& keys) {
    return message_of(scene_text(R"({"type": "voxels", )" + keys + "}"), dir.dir());
  };
  EXPECT_EQ(with(R"("file": "a.raw", "dims": [2, 2, 2], "threshold": 1)"),
            "t: objects[0].file: \"" + dir.dir() + "/a.raw\" holds 5 bytes; dims [2, 2, 2] of u8 need 8");
  EXPECT_EQ(with(R"("file": "a.raw", "dims": [5, 1, 1], "threshold": 256)"),
            "t: objects[0].threshold: expected a number in [0, 255], got 256");
  EXPECT_EQ(with(R"("file": "a.raw", "dims": [5, 1, 1], "threshold": 200)"),
            "t: objects[0].threshold: no voxel is inside: the surface is empty");
  EXPECT_EQ(with(R"("file": "a.raw", "dims": [5, 1, 1])"), "t: objects[0]: missing required key \"threshold\"");
  EXPECT_EQ(with(R"("file": "a.raw", "format": "s8", "dims": [5, 1, 1], "threshold": 1)"),
            "t: objects[0].format: expected \"u8\" or \"u16\" (little-endian), got \"s8\"");
  EXPECT_EQ(with(R"("file": "none.raw", "dims": [5, 1, 1], "threshold": 1)"),
            "t: objects[0].file: \"" + dir.dir() + "/none.raw\" is not a readable regular file");
  EXPECT_EQ(with(R"("phantom": "ellipsoid", "file": "a.raw", "dims": [5, 1, 1])"),
            "t: objects[0]: give exactly one of \"file\" (a raw density volume) or \"phantom\"");
  EXPECT_EQ(with(R"("phantom": "cube", "dims": [5, 1, 1])"),
            "t: objects[0].phantom: expected \"ellipsoid\", \"beaded_sphere\" or \"two_lobed\", got \"cube\"");
  EXPECT_EQ(with(R"("phantom": "ellipsoid", "dims": [5, 1, 1], "threshold": 3)"),
            "t: objects[0].threshold: applies to a raw \"file\" only, not to a phantom");
  EXPECT_EQ(with(R"("phantom": "ellipsoid", "dims": [4, 4, 4], "crease_angle_deg": 45)"),
            "t: objects[0].crease_angle_deg: voxel faces meet at 90 degrees: choose \"normals\": \"face\" or \"average\"");
  EXPECT_EQ(with(R"("phantom": "ellipsoid", "dims": [5, 0, 1])"),
            "t: objects[0].dims[1]: expected an integer in [1, 1024], got 0");
  EXPECT_EQ(with(R"("phantom": "ellipsoid", "dims": [5, 1])"),
            "t: objects[0].dims: expected an array of 3 integers [nx, ny, nz], got [5,1]");
  EXPECT_EQ(with(R"("phantom": "ellipsoid", "dims": [4, 4, 4], "spacing": [1, -1, 1])"),
            "t: objects[0].spacing[1]: expected a positive number (at least 1e-09), got -1");
  // A 256^3 ball: about 6 * 0.9^2 * 128^2 * pi/... faces, over the 65536 polygons the pipeline holds.
  const std::string big = with(R"("phantom": "ellipsoid", "dims": [256, 256, 256])");
  EXPECT_EQ(big.rfind("t: objects[0].dims: the surface has ", 0), 0u) << big;
  EXPECT_NE(big.find("voxel faces, over the pipeline's 65536 polygons"), std::string::npos) << big;
}

TEST(Voxels, TruthHitsThePhantomNotTheVoxelFaces) {
  // Eye light along +Z: the centre pixel's ray meets the phantom head on, where its normal faces the eye.
  for (const char* ph : {"ellipsoid", "beaded_sphere", "two_lobed"}) {
    const BuiltScene s = load_scene_text(scene_text(std::string(R"({"type": "voxels", "phantom": ")") + ph +
                                                    R"(", "dims": [16, 16, 16], "material": "m"})"),
                                         "t", ".");
    const AnalyticTruth t = render_analytic_truth(s);
    ASSERT_TRUE(t.unavailable.empty()) << ph << ": " << t.unavailable;
    EXPECT_EQ(t.surfaces, 1);
    long long covered = 0;
    for (char c : t.image.covered) covered += c != 0;
    EXPECT_GT(covered, 300) << ph;
    // Brightest at the centre for the ellipsoid: the normal there is (0, 0, -1), the light's direction.
    if (std::string(ph) == "ellipsoid") {
      const std::uint8_t* centre = t.image.at(32, 32);
      const std::uint8_t* off = t.image.at(32 + 8, 32);
      EXPECT_TRUE(t.image.covered[32 * 64 + 32]);
      EXPECT_GT(int(centre[0]), int(off[0]));
    }
  }
  // A file volume has no closed form: no truth, said so.
  Scratch dir;
  dir.write("a.raw", std::string(8, '\x80'));
  const BuiltScene f = load_scene_text(
      scene_text(R"({"type": "voxels", "file": "a.raw", "dims": [2, 2, 2], "threshold": 1})"), "t", dir.dir());
  EXPECT_FALSE(render_analytic_truth(f).unavailable.empty());
}

TEST(Voxels, PhantomScenesFitTheDefaultHardwareAndApproachTheTruth) {
  // The shipped scenes: within 64 active edges and 1024 pixels of span (the default hardware), and
  // the Phong pipeline on averaged normals closer to the exact surface than flat faces.
  for (const char* name : {"voxel_ellipsoid", "voxel_beaded", "voxel_two_lobed"}) {
    const std::string path = std::string(WATKINS_SOURCE_DIR) + "/scenes/" + name + ".json";
    double mean[2] = {0, 0};
    for (int phong = 0; phong < 2; ++phong) {
      BuildOptions opt;
      opt.shading = phong ? ShadingMode::Phong : ShadingMode::Gouraud;
      opt.flat = !phong;
      const BuiltScene s = load_scene(path, opt);
      const PreparedScene p = prepare(s);
      EXPECT_LE(p.needs.max_active_edges, fmt::MaxActiveEdges) << name;
      EXPECT_GT(s.polygons.size(), 150u) << name;
      WatkinsTop top(Config{});
      const Image img = top.render(p);
      const AnalyticTruth t = render_analytic_truth(s);
      ASSERT_TRUE(t.unavailable.empty()) << name;
      const ImageError e = compare_with_truth(s, img, t);
      EXPECT_GT(e.compared, 10000) << name;
      mean[phong] = e.mean_abs;
    }
    EXPECT_LT(mean[1], mean[0]) << name << ": phong " << mean[1] << " vs flat " << mean[0];
  }
}

TEST(Voxels, MachBandMeanAveragesTheJumpsAtPolygonEdges) {
  // One row: polygon 0 at level 10, polygon 1 at level 20, then polygon 2 at level 20. The step at
  // 0|1 jumps 10 on both sides; 1|2 is no step (0, 0): mean 5, max 10.
  Image img(12, 1);
  const int level[12] = {10, 10, 10, 10, 20, 20, 20, 20, 20, 20, 20, 20};
  const int poly[12] = {0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2};
  for (int x = 0; x < 12; ++x) {
    for (int c = 0; c < 3; ++c) img.at(x, 0)[c] = static_cast<std::uint8_t>(level[x]);
    img.covered[std::size_t(x)] = 1;
    img.owner[std::size_t(x)] = poly[x];
  }
  EXPECT_DOUBLE_EQ(mach_band(img, img.owner), 10.0);
  EXPECT_DOUBLE_EQ(mach_band_mean(img, img.owner), 5.0);
}

TEST(Voxels, SmoothingTheFlatPhantomWeakensItsBandsButNotItsError) {
  // Herman and Liu's Fig. 4 against Fig. 2 on the ellipsoid phantom, as README's table has it:
  // W = 0.8 cuts the mean band across face boundaries about 10x, and leaves the error against the
  // exact surface within 15 % of flat's (the face interiors keep their three orientations).
  BuildOptions opt;
  opt.flat = true;
  opt.shading = ShadingMode::Gouraud;
  const BuiltScene s = load_scene(std::string(WATKINS_SOURCE_DIR) + "/scenes/voxel_ellipsoid.json", opt);
  const PreparedScene p = prepare(s);
  WatkinsTop top(Config{});
  const Image flat = top.render(p);
  const Image smooth = Smoother(quantize_smooth_weight(0.8)).apply(flat);
  const AnalyticTruth t = render_analytic_truth(s);
  ASSERT_TRUE(t.unavailable.empty());
  const Image flat_obj = by_object(s, flat), smooth_obj = by_object(s, smooth);  // owners as the truth's
  const double band_flat = mach_band_mean(flat_obj, flat.owner, &t.image);
  const double band_smooth = mach_band_mean(smooth_obj, flat.owner, &t.image);
  EXPECT_GT(band_flat, 40);
  EXPECT_LT(band_smooth * 8, band_flat);
  const ImageError ef = compare_with_truth(s, flat, t), es = compare_with_truth(s, smooth, t);
  EXPECT_LT(es.mean_abs, ef.mean_abs);
  EXPECT_GT(es.mean_abs, 0.85 * ef.mean_abs);  // measured: 51.57 against 57.14
}

namespace {

// Every vertex's shade and normal of a built scene, in polygon order.
std::vector<double> vertex_values(const BuiltScene& s) {
  std::vector<double> v;
  for (const ScreenPolygon& p : s.polygons)
    for (const ScreenVertex& x : p.v) v.insert(v.end(), {x.x, x.y, x.rgb[0], x.normal[0], x.normal[1], x.normal[2]});
  return v;
}

}  // namespace

TEST(Voxels, NormalsOverrideGivesWhatItNamesWhateverTheScene) {
  // voxel-compare's rows: the override sets the voxel normals, whether the scene says "face", says
  // nothing (face, the default) or says "average".
  const std::string body = R"({"type": "voxels", "phantom": "ellipsoid", "dims": [10, 10, 10], "rotate_deg": [20, 30, 0],
    "material": "m")";
  const std::string unsaid = scene_text(body + "}"), face = scene_text(body + R"(, "normals": "face"})"),
                    average = scene_text(body + R"(, "normals": "average"})");
  BuildOptions gouraud, flat;
  gouraud.shading = flat.shading = ShadingMode::Gouraud;
  flat.flat = true;
  const BuiltScene avg_plain = load_scene_text(average, "a", ".", gouraud);
  const BuiltScene face_plain = load_scene_text(face, "f", ".", gouraud);
  ASSERT_NE(vertex_values(avg_plain), vertex_values(face_plain));
  for (const std::string& text : {unsaid, face, average}) {
    BuildOptions g = gouraud, f = gouraud;
    g.voxel_normals = VoxelNormals::Average;
    f.voxel_normals = VoxelNormals::Face;
    const BuiltScene sg = load_scene_text(text, "t", ".", g), sf = load_scene_text(text, "t", ".", f);
    EXPECT_EQ(vertex_values(sg), vertex_values(avg_plain));
    EXPECT_EQ(vertex_values(sf), vertex_values(face_plain));
    EXPECT_EQ(sg.source->objects.at(0).normals, MeshNormals::Average);  // the source is the scene as built
    EXPECT_EQ(sf.source->objects.at(0).normals, MeshNormals::Face);
    // Gouraud on averaged normals is not the flat picture; on face normals it is (one normal per
    // face, light and eye at infinity: every vertex of a face gets the face's shade).
    BuildOptions fl = flat;
    fl.voxel_normals = VoxelNormals::Face;
    WatkinsTop top(Config{});
    const Image flat_img = top.render(prepare(load_scene_text(text, "t", ".", fl)));
    const Image g_img = top.render(prepare(sg)), f_img = top.render(prepare(sf));
    int g_differs = 0, f_differs = 0, covered = 0;
    for (int y = 0; y < flat_img.height; ++y)
      for (int x = 0; x < flat_img.width; ++x) {
        covered += flat_img.covered[std::size_t(y) * std::size_t(flat_img.width) + std::size_t(x)];
        for (int c = 0; c < 3; ++c) {
          g_differs += std::abs(int(g_img.at(x, y)[c]) - int(flat_img.at(x, y)[c])) > 1;
          f_differs += std::abs(int(f_img.at(x, y)[c]) - int(flat_img.at(x, y)[c])) > 1;
        }
      }
    EXPECT_GT(covered, 500);
    EXPECT_GT(g_differs, covered / 2) << "Gouraud on averaged normals";
    EXPECT_EQ(f_differs, 0) << "Gouraud on face normals";
  }
}

TEST(Voxels, CompareCommandRendersWhatEachRowSays) {
  // voxel_smoothed.json gives its phantom face normals: the Gouraud and Phong rows still shade
  // averaged normals, so their error against the truth is not the flat row's.
  const test::CliRun r =
      test::run_cli(std::string("voxel-compare ") + WATKINS_SOURCE_DIR + "/scenes/voxel_smoothed.json --weights 0.8");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto trim = [](const std::string& c) {
    const std::size_t b = c.find_first_not_of(' '), e = c.find_last_not_of(' ');
    return b == std::string::npos ? std::string() : c.substr(b, e - b + 1);
  };
  std::map<std::string, double> truth_mean;  // "vs truth mean" by the row's shading label
  std::istringstream lines(r.output);
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> cell;  // "", scene, shading, polygons, ..., vs truth mean (8), ...
    std::istringstream cells(line);
    for (std::string c; std::getline(cells, c, '|');) cell.push_back(trim(c));
    if (cell.size() > 8 && cell[1] == "voxel_smoothed") truth_mean[cell[2]] = std::stod(cell[8]);
  }
  ASSERT_EQ(truth_mean.size(), 4u) << r.output;
  const double flat = truth_mean.at("flat (Fig. 2)");
  for (const char* label : {"Gouraud, averaged normals (Fig. 3)", "Phong, averaged normals"})
    EXPECT_LT(truth_mean.at(label), flat - 5) << label << "\n" << r.output;
}
