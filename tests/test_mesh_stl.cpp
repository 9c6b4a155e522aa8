// STL import (ASCII and binary, welding, bad input), crease-angle normals and face splitting by
// edge length: the mesh becomes polygons like any other, so the pipelines need nothing new.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>

#include "cli_run.hpp"
#include "mesh_obj.hpp"
#include "mesh_stl.hpp"
#include "scene_types.hpp"
#include "shipped_scenes.hpp"
#include "stl_export.hpp"
#include "test_support.hpp"

namespace {

using watkins::IndexedMesh;
using watkins::MeshNormals;
using watkins::SceneError;
using watkins::SceneObject;
using watkins::test::CliRun;
using watkins::test::run_cli;
using watkins::test::ScratchDir;

const std::string kScenes = std::string(WATKINS_SOURCE_DIR) + "/scenes/";

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

SceneObject stl_object(double crease = -1) {
  SceneObject o;
  o.type = watkins::ObjectType::Mesh;
  o.file = "m.stl";
  if (crease >= 0) {
    o.normals = MeshNormals::Crease;
    o.crease_angle_deg = crease;
  }
  return o;
}

IndexedMesh stl(const std::string& bytes, const SceneObject& o, int* degenerate = nullptr, bool strict = false) {
  int d = 0;
  IndexedMesh m = watkins::stl_mesh_from_bytes(bytes, o, "h.json: objects[0].file", 100000, strict, d);
  if (degenerate) *degenerate = d;
  return m;
}

std::string stl_error(const std::string& bytes, bool strict = false, std::size_t max_faces = 100000,
                      const SceneObject& o = stl_object()) {
  try {
    int d = 0;
    watkins::stl_mesh_from_bytes(bytes, o, "h.json: objects[0].file", max_faces, strict, d);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

using Tri = std::array<glm::dvec3, 3>;

// The facets of an ASCII STL written by hand here (cube.stl's text is parsed by the reader
// under test, so the binary twin is made from these independent numbers).
std::vector<Tri> cube_triangles() {
  const glm::dvec3 v[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                           {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const int q[6][4] = {{4, 5, 6, 7}, {0, 3, 2, 1}, {1, 2, 6, 5}, {0, 4, 7, 3}, {3, 7, 6, 2}, {0, 1, 5, 4}};
  std::vector<Tri> t;
  for (const auto& f : q) {
    t.push_back({v[f[0]], v[f[1]], v[f[2]]});
    t.push_back({v[f[0]], v[f[2]], v[f[3]]});
  }
  return t;
}

void put32(std::string& b, std::uint32_t x) {
  for (int k = 0; k < 4; ++k) b.push_back(char((x >> (8 * k)) & 0xff));
}
void put_float(std::string& b, float f) {
  std::uint32_t x;
  std::memcpy(&x, &f, 4);
  put32(b, x);
}

std::string binary_stl(const std::vector<Tri>& tris, const std::string& header = "binary") {
  std::string b = header;
  b.resize(80, ' ');
  put32(b, std::uint32_t(tris.size()));
  for (const Tri& t : tris) {
    for (int c = 0; c < 3; ++c) put_float(b, 0);  // facet normal: ignored
    for (const glm::dvec3& p : t)
      for (int c = 0; c < 3; ++c) put_float(b, float(p[c]));
    b += std::string(2, '\0');
  }
  return b;
}

std::string ascii_stl(const std::vector<Tri>& tris) {
  std::ostringstream s;
  s.precision(17);
  s << "solid t\n";
  for (const Tri& t : tris) {
    s << " facet normal 0 0 0\n  outer loop\n";
    for (const glm::dvec3& p : t) s << "   vertex " << p.x << " " << p.y << " " << p.z << "\n";
    s << "  endloop\n endfacet\n";
  }
  s << "endsolid t\n";
  return s.str();
}

// Positions as exact doubles: vertices split by their normals still share them.
using Key = std::tuple<double, double, double>;
Key key(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

// Every undirected edge (by position) used exactly twice, once in each direction: closed, no
// T-junction, consistently wound.
void expect_watertight(const IndexedMesh& m) {
  std::map<std::pair<Key, Key>, int> directed;
  for (const auto& f : m.faces)
    for (int k = 0; k < f.n; ++k) ++directed[{key(m.position[f.idx[k]]), key(m.position[f.idx[(k + 1) % f.n]])}];
  for (const auto& [e, count] : directed) {
    EXPECT_EQ(count, 1) << "an edge used twice in one direction";
    auto back = directed.find({e.second, e.first});
    EXPECT_TRUE(back != directed.end() && back->second == 1) << "an edge with no face on its other side";
  }
}

std::set<Key> distinct_positions(const IndexedMesh& m) {
  std::set<Key> s;
  for (const auto& p : m.position) s.insert(key(p));
  return s;
}

TEST(Stl, AsciiAndBinaryCubeGiveTheSameMesh) {
  for (double crease : {-1.0, 80.0}) {
    const IndexedMesh a = stl(file_bytes(kScenes + "cube.stl"), stl_object(crease));
    const IndexedMesh b = stl(binary_stl(cube_triangles()), stl_object(crease));
    ASSERT_EQ(a.faces.size(), 12u);
    ASSERT_EQ(a.position.size(), b.position.size());
    ASSERT_EQ(a.faces.size(), b.faces.size());
    for (std::size_t k = 0; k < a.position.size(); ++k) {
      EXPECT_EQ(a.position[k], b.position[k]);
      EXPECT_EQ(a.normal[k], b.normal[k]);
    }
    for (std::size_t f = 0; f < a.faces.size(); ++f) {
      EXPECT_EQ(a.faces[f].n, 3);
      EXPECT_EQ(a.faces[f].idx, b.faces[f].idx);
    }
  }
}

TEST(Stl, BinaryIsDetectedBySizeEvenWithASolidHeader) {
  const std::string b = binary_stl(cube_triangles(), "solid cube exported as binary");
  EXPECT_TRUE(watkins::is_binary_stl(b));
  EXPECT_EQ(stl(b, stl_object()).faces.size(), 12u);
  EXPECT_FALSE(watkins::is_binary_stl(file_bytes(kScenes + "cube.stl")));
  EXPECT_TRUE(watkins::is_binary_stl(file_bytes(kScenes + "cylinder.stl")));
}

TEST(Stl, WeldedCubeHasEightVerticesAndEveryEdgeSharedByTwoFaces) {
  // Averaged normals: one vertex per position.
  const IndexedMesh m = stl(binary_stl(cube_triangles()), stl_object());
  EXPECT_EQ(m.position.size(), 8u);
  expect_watertight(m);
  // Corners a little off (as a float export of computed points is): welded within the default
  // tolerance, 1e-6 of the diagonal (3.5e-6 here); kept apart when the tolerance is 0 (exact).
  std::vector<Tri> jittered = cube_triangles();
  for (std::size_t t = 0; t < jittered.size(); ++t) jittered[t][0].x += (t % 2 ? 1e-7 : -1e-7);
  const std::string text = ascii_stl(jittered);
  EXPECT_EQ(stl(text, stl_object()).position.size(), 8u);
  SceneObject exact = stl_object();
  exact.weld_tolerance = 0;
  EXPECT_GT(stl(text, exact).position.size(), 8u);
  // A tolerance larger than an edge collapses faces: zero area, skipped and counted.
  SceneObject coarse = stl_object();
  coarse.weld_tolerance = 0.01;
  std::vector<Tri> small = cube_triangles();
  small.push_back({glm::dvec3(0, 0, 0), glm::dvec3(0.001, 0, 0), glm::dvec3(0, 0.001, 0)});
  int degenerate = 0;
  EXPECT_EQ(stl(ascii_stl(small), coarse, &degenerate).faces.size(), 12u);
  EXPECT_EQ(degenerate, 1);
}

TEST(Stl, ZeroAreaFacetsAreSkippedAndCountedOrAnErrorWhenStrict) {
  std::vector<Tri> t = cube_triangles();
  t.insert(t.begin() + 2, Tri{glm::dvec3(0, 0, 0), glm::dvec3(1, 1, 1), glm::dvec3(2, 2, 2)});  // in a line
  t.push_back(Tri{glm::dvec3(1, 1, 1), glm::dvec3(1, 1, 1), glm::dvec3(0, 0, 0)});  // two corners one vertex
  int degenerate = 0;
  EXPECT_EQ(stl(binary_stl(t), stl_object(), &degenerate).faces.size(), 12u);
  EXPECT_EQ(degenerate, 2);
  EXPECT_EQ(stl_error(binary_stl(t), true),
            "h.json: objects[0].file: STL file \"m.stl\": facet 3: facet of zero area (its corners weld together or "
            "lie in a line; skipped without --strict)");
  EXPECT_NE(stl_error(ascii_stl(t), true).find("STL file \"m.stl\": line 16: facet of zero area"), std::string::npos)
      << stl_error(ascii_stl(t), true);
}

TEST(Stl, TruncatedOrMiscountedBinaryIsRefused) {
  const std::string b = binary_stl(cube_triangles());
  EXPECT_EQ(stl_error(b.substr(0, b.size() - 7)),
            "h.json: objects[0].file: STL file \"m.stl\": neither ASCII STL (it does not start with \"solid\") nor "
            "binary STL (its header gives 12 facets, 84 + 50 x 12 = 684 bytes, but the file has 677: truncated?)");
  std::string more = b;
  more[80] = 13;  // the count says 13, the file holds 12
  EXPECT_NE(stl_error(more).find("its header gives 13 facets, 84 + 50 x 13 = 734 bytes, but the file has 684"),
            std::string::npos);
  EXPECT_NE(stl_error(b.substr(0, 50)).find("50 bytes, shorter than the 84-byte header"), std::string::npos);
  // A truncated binary file whose header starts with "solid" is read as ASCII and stops at its NUL bytes.
  const std::string s = binary_stl(cube_triangles(), "solid x");
  EXPECT_NE(stl_error(s.substr(0, s.size() - 1)).find("line 1: NUL byte (not ASCII STL; nor binary STL: its size, 683 bytes"),
            std::string::npos) << stl_error(s.substr(0, s.size() - 1));
  std::string none = binary_stl({});
  EXPECT_NE(stl_error(none).find("binary STL with no facets"), std::string::npos);
  EXPECT_NE(stl_error(b, false, 11).find("has 12 facets, more than the 11 faces left for it"), std::string::npos);
}

TEST(Stl, NonFiniteAndHugeNumbersAreRefusedNamingTheFacet) {
  std::vector<Tri> t = cube_triangles();
  t[2][1].y = NAN;
  EXPECT_EQ(stl_error(binary_stl(t)),
            "h.json: objects[0].file: STL file \"m.stl\": facet 3: vertex 2: expected a finite number, got NaN");
  t[2][1].y = INFINITY;
  EXPECT_NE(stl_error(binary_stl(t)).find("facet 3: vertex 2: expected a finite number, got inf"), std::string::npos);
  t[2][1].y = 1e20;
  EXPECT_NE(stl_error(binary_stl(t)).find("facet 3: vertex 2: expected a number of magnitude at most 1e9"),
            std::string::npos);
  const std::string text = "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 nan 0\nvertex 0 1 0\n"
                           "endloop\nendfacet\nendsolid a\n";
  EXPECT_EQ(stl_error(text), "h.json: objects[0].file: STL file \"m.stl\": line 5: vertex: expected a finite number, got \"nan\"");
  std::string big = text;
  big.replace(big.find("nan"), 3, "1e999");
  EXPECT_NE(stl_error(big).find("line 5: vertex: expected a finite number, got \"1e999\""), std::string::npos);
  big.replace(big.find("1e999"), 5, "2e9");
  EXPECT_NE(stl_error(big).find("line 5: vertex: expected a number of magnitude at most 1e9"), std::string::npos);
}

TEST(Stl, MalformedAsciiIsRefusedNamingTheLine) {
  const std::string head = "solid a\nfacet normal 0 0 1\n";
  const std::string loop = "outer loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n";
  auto err = [&](const std::string& t) { return stl_error(t); };
  EXPECT_EQ(err(head + loop + "endfacet\nendsolid a\n"), "");
  EXPECT_EQ(err(head + loop + "ENDFACET\nEndSolid\n"), "") << "keywords in any case";
  EXPECT_NE(err(head + "vertex 0 0 0\n").find("line 3: expected \"outer loop\", got \"vertex\""), std::string::npos);
  EXPECT_NE(err(head + "outer loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid\n")
                .find("line 6: a facet has 3 vertices, got 2"), std::string::npos);
  EXPECT_NE(err(head + "outer loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\nendloop\nendfacet\nendsolid\n")
                .find("line 7: a facet has 3 vertices (STL facets are triangles), got a 4th"), std::string::npos);
  EXPECT_NE(err(head + "outer loop\nvertex 0 0\n").find("line 4: \"vertex\": expected 3 numbers, got 2 tokens after it"),
            std::string::npos);
  EXPECT_NE(err(head + loop + "endsolid\n").find("line 8: expected \"endfacet\", got \"endsolid\""), std::string::npos);
  EXPECT_NE(err(head + loop).find("the file ends where \"endfacet\" was expected (truncated?)"), std::string::npos);
  EXPECT_NE(err(head + loop + "endfacet\n").find("the file ends before \"endsolid\" (truncated?)"), std::string::npos);
  EXPECT_NE(err(head + loop + "endfacet\nendsolid\nsolid b\n").find("line 10: text after \"endsolid\" (line 9; one solid per file)"),
            std::string::npos);
  EXPECT_NE(err("solid a\nfacet 0 0 1\n").find("line 2: expected \"facet normal\", got \"facet\""), std::string::npos);
  EXPECT_NE(err("solid a\nfacet normal 0 1\n").find("line 2: \"facet normal\": expected 3 numbers, got 2 tokens after it"),
            std::string::npos);
  EXPECT_NE(err("solid a\nfacet normal 0 1 0 1\n").find("line 2: \"facet normal\": expected 3 numbers, got 4 tokens"),
            std::string::npos);
  EXPECT_NE(err("solid a\nvertex 0 0 0\n").find("line 2: expected \"facet normal\" or \"endsolid\", got \"vertex\""),
            std::string::npos);
  EXPECT_NE(err("solid a\nendsolid a\n").find("has no facets"), std::string::npos);
  EXPECT_NE(err("").find("0 bytes, shorter than the 84-byte header"), std::string::npos);
}

// The cube in ASCII with each keyword spelt as given (lower case: ascii_stl's text) and each facet
// normal's three tokens as given.
std::string ascii_cube(const std::array<const char*, 9>& kw, const std::string& normal) {
  std::ostringstream s;
  s.precision(17);
  s << kw[0] << " cube\n";
  for (const Tri& t : cube_triangles()) {
    s << " " << kw[1] << " " << kw[2] << " " << normal << "\n  " << kw[3] << " " << kw[4] << "\n";
    for (const glm::dvec3& p : t) s << "   " << kw[5] << " " << p.x << " " << p.y << " " << p.z << "\n";
    s << "  " << kw[6] << "\n " << kw[7] << "\n";
  }
  s << kw[8] << " cube\n";
  return s.str();
}

const std::array<const char*, 9> kLower = {"solid", "facet", "normal", "outer", "loop", "vertex", "endloop", "endfacet",
                                           "endsolid"};

// The same faces on the same positions as the lower-case cube with numeric normals.
void expect_same_cube(const IndexedMesh& m, const std::string& what) {
  const IndexedMesh ref = stl(ascii_cube(kLower, "0 0 1"), stl_object());
  ASSERT_EQ(ref.faces.size(), 12u);
  ASSERT_EQ(m.faces.size(), ref.faces.size()) << what;
  ASSERT_EQ(m.position.size(), ref.position.size()) << what;
  for (std::size_t k = 0; k < m.position.size(); ++k) EXPECT_EQ(m.position[k], ref.position[k]) << what;
  for (std::size_t f = 0; f < m.faces.size(); ++f) EXPECT_EQ(m.faces[f].idx, ref.faces[f].idx) << what;
}

TEST(Stl, KeywordsAreReadInAnyCaseAndSolidIsSniffedInAnyCase) {
  const std::array<const char*, 9> upper = {"SOLID", "FACET", "NORMAL", "OUTER", "LOOP", "VERTEX", "ENDLOOP",
                                            "ENDFACET", "ENDSOLID"};
  const std::array<const char*, 9> mixed = {"Solid", "Facet", "Normal", "Outer", "Loop", "VeRtEx", "EndLoop",
                                            "endFacet", "EndSolid"};
  expect_same_cube(stl(ascii_cube(upper, "0 0 1"), stl_object()), "upper case");
  expect_same_cube(stl(ascii_cube(mixed, "0 0 1"), stl_object()), "mixed case");
  // A file not named .stl is STL when its first word is "solid" in any case (else OBJ).
  ScratchDir dir;
  for (const auto& kw : {upper, mixed, kLower}) {
    SceneObject o = stl_object();
    o.file = dir.write("cube.mesh", ascii_cube(kw, "0 0 1"));
    int d = 0;
    expect_same_cube(watkins::load_mesh_file(o, "w", 1000, false, d), std::string("sniffed: ") + kw[0]);
  }
  // "solid" as the start of a longer first word is not the keyword: read as OBJ, which refuses it.
  SceneObject o = stl_object();
  o.file = dir.write("cube.mesh", "solidity 1 2 3\n");
  int d = 0;
  try {
    watkins::load_mesh_file(o, "w", 1000, false, d);
    FAIL() << "\"solidity\" read as a mesh";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("OBJ"), std::string::npos) << e.what();
  }
}

TEST(Stl, FacetNormalsAreSkippedWhateverTheirText) {
  for (const char* normal : {"nan nan nan", "NaN -nan inf", "1e999 -1e999 0", "x y z", "0 0 1e-400"})
    expect_same_cube(stl(ascii_cube(kLower, normal), stl_object()), normal);
  // Binary: the normal's floats are not read, NaN and inf included.
  std::string b = binary_stl(cube_triangles());
  const float weird[3] = {NAN, INFINITY, -INFINITY};
  for (std::size_t f = 0; f < 12; ++f)
    for (int c = 0; c < 3; ++c) std::memcpy(&b[84 + 50 * f + 4 * std::size_t(c)], &weird[c], 4);
  const IndexedMesh m = stl(b, stl_object());
  const IndexedMesh ref = stl(binary_stl(cube_triangles()), stl_object());
  ASSERT_EQ(m.faces.size(), 12u);
  ASSERT_EQ(m.position.size(), 8u);
  for (std::size_t k = 0; k < m.position.size(); ++k) {
    EXPECT_EQ(m.position[k], ref.position[k]);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(std::fabs(m.position[k][c]), 1.0);  // the cube's corners
  }
  for (std::size_t f = 0; f < m.faces.size(); ++f) EXPECT_EQ(m.faces[f].idx, ref.faces[f].idx);
  // Three tokens it must still be.
  EXPECT_NE(stl_error(ascii_cube(kLower, "nan nan")).find("line 2: \"facet normal\": expected 3 numbers, got 2 tokens"),
            std::string::npos);
}

TEST(Stl, FileNormalsAreRefusedAndWeldToleranceIsForStlOnly) {
  SceneObject o = stl_object();
  o.normals_given = true;  // "normals": "file"
  EXPECT_NE(stl_error(file_bytes(kScenes + "cube.stl"), false, 100000, o).find("has no vertex normals (its facet normals are not used"),
            std::string::npos);
  SceneObject obj;
  obj.type = watkins::ObjectType::Mesh;
  obj.file = kScenes + "cube.obj";
  obj.weld_tolerance = 0;
  int d = 0;
  try {
    watkins::load_mesh_file(obj, "w", 1000, false, d);
    FAIL() << "weld_tolerance accepted on an OBJ file";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("weld_tolerance applies to STL files"), std::string::npos) << e.what();
  }
}

// ---- crease-angle normals --------------------------------------------------------------------

SceneObject obj_object(const std::string& file, MeshNormals normals, double crease = 0) {
  SceneObject o;
  o.type = watkins::ObjectType::Mesh;
  o.file = kScenes + file;
  o.normals = normals;
  o.crease_angle_deg = crease;
  return o;
}

glm::dvec3 face_normal(const IndexedMesh& m, const IndexedMesh::Face& f) {
  const glm::dvec3 &a = m.position[f.idx[0]], &b = m.position[f.idx[1]], &c = m.position[f.idx[2]];
  return glm::normalize(glm::cross(b - a, c - a));
}

TEST(Crease, CubeAt80KeepsFlatFacesAndAt180AveragesTheCorners) {
  int d = 0;
  for (const char* file : {"cube.obj", "cube.stl"}) {
    const IndexedMesh sharp = watkins::load_mesh_file(obj_object(file, MeshNormals::Crease, 80), "w", 1000, false, d);
    EXPECT_EQ(sharp.position.size(), 24u) << file << ": each corner split three ways";
    for (const auto& f : sharp.faces) {
      // Left-handed after the z mirror: the cross product of a front face points inwards.
      const glm::dvec3 n = -face_normal(sharp, f);
      for (int k = 0; k < f.n; ++k) EXPECT_LT(glm::length(sharp.normal[f.idx[k]] - n), 1e-12) << file;
    }
    const IndexedMesh smooth = watkins::load_mesh_file(obj_object(file, MeshNormals::Crease, 180), "w", 1000, false, d);
    EXPECT_EQ(smooth.position.size(), 8u) << file;
    for (std::size_t k = 0; k < smooth.position.size(); ++k)
      EXPECT_LT(glm::length(smooth.normal[k] - smooth.position[k] / std::sqrt(3.0)), 1e-12) << file;
  }
  // cube.obj's quads: the corner angles and the areas of its faces agree, so 180 is "average".
  const IndexedMesh avg = watkins::load_mesh_file(obj_object("cube.obj", MeshNormals::Average), "w", 1000, false, d);
  const IndexedMesh c180 = watkins::load_mesh_file(obj_object("cube.obj", MeshNormals::Crease, 180), "w", 1000, false, d);
  ASSERT_EQ(avg.position.size(), c180.position.size());
  for (std::size_t k = 0; k < avg.position.size(); ++k) {
    EXPECT_EQ(avg.position[k], c180.position[k]);
    EXPECT_LT(glm::length(avg.normal[k] - c180.normal[k]), 1e-15);
  }
  // The STL cube's triangles: by area, a corner meeting one triangle of a side and two of another
  // leans to the second; by angle (what crease_angle_deg uses) it is the diagonal, as above.
  const IndexedMesh stl_avg = watkins::load_mesh_file(obj_object("cube.stl", MeshNormals::Average), "w", 1000, false, d);
  double worst = 0;
  for (std::size_t k = 0; k < stl_avg.position.size(); ++k)
    worst = std::max(worst, glm::length(stl_avg.normal[k] - stl_avg.position[k] / std::sqrt(3.0)));
  EXPECT_GT(worst, 0.05);
}

TEST(Crease, CylinderSidesSmoothAndRimsSharpAt80FlatAt0) {
  int d = 0;
  const IndexedMesh m = watkins::load_mesh_file(obj_object("cylinder.stl", MeshNormals::Crease, 80), "w", 1000, false, d);
  ASSERT_EQ(m.faces.size(), 96u);
  int side = 0, cap = 0;
  for (std::size_t k = 0; k < m.position.size(); ++k) {
    const glm::dvec3 &p = m.position[k], &n = m.normal[k];
    if (std::fabs(std::fabs(n.y) - 1) < 1e-12) {
      ++cap;  // a cap's vertex: the cap's normal, not bent towards the side
    } else {
      ++side;  // a side's vertex: horizontal and radial (the exact cylinder normal)
      EXPECT_LT(std::fabs(n.y), 1e-12);
      EXPECT_LT(glm::length(n - glm::normalize(glm::dvec3(p.x, 0, p.z))), 1e-6);  // the file's floats
    }
  }
  EXPECT_EQ(side, 48);     // each rim vertex once for the side...
  EXPECT_EQ(cap, 48 + 2);  // ...and once for its cap, plus the caps' centres
  const IndexedMesh flat = watkins::load_mesh_file(obj_object("cylinder.stl", MeshNormals::Crease, 0), "w", 1000, false, d);
  for (const auto& f : flat.faces)
    for (int k = 0; k < f.n; ++k) EXPECT_LT(glm::length(flat.normal[f.idx[k]] + face_normal(flat, f)), 1e-6);
}

// The cube's two visible faces meet on a vertical edge near the middle of the picture: the step
// between each pixel of the middle row and the next (the largest over the channels), -1 where
// either is not covered.
std::vector<int> middle_row_steps(const std::string& crease, const char* mode) {
  const std::string text = R"({"screen": {"width": 160, "height": 120},
    "camera": {"type": "gouraud", "focal": 1.2, "near": 0.5, "far": 100},
    "light": {"type": "directional", "direction": [0.5, 0.6, -2]},
    "shading": {"mode": ")" + std::string(mode) + R"(", "rule": "lambert"},
    "objects": [{"type": "mesh", "file": "cube.stl", "crease_angle_deg": )" + crease + R"(,
                 "scale": 0.8, "rotate_deg": [-25, 35, 0], "translate": [0, 0, 5]}]})";
  const watkins::BuiltScene s = watkins::load_scene_text(text, "c.json", kScenes);
  const watkins::Image img = watkins::test::render_fixed(s);
  const int y = s.height / 2;
  std::vector<int> step(std::size_t(s.width), -1);
  for (int x = 0; x + 1 < s.width; ++x) {
    if (!img.is_covered(x, y) || !img.is_covered(x + 1, y)) continue;
    for (int c = 0; c < 3; ++c) step[x] = std::max(step[x], std::abs(int(img.at(x, y)[c]) - int(img.at(x + 1, y)[c])));
  }
  return step;
}

TEST(Crease, ShadeJumpsAcrossASharpEdgeAt80AndNotAt180) {
  for (const char* mode : {"gouraud", "phong"}) {
    const std::vector<int> sharp = middle_row_steps("80", mode), smooth = middle_row_steps("180", mode);
    // At 80 degrees each face is flat: one shade per face, and a jump where they meet.
    const std::size_t edge = std::size_t(std::max_element(sharp.begin(), sharp.end()) - sharp.begin());
    EXPECT_GT(sharp[edge], 50) << mode;
    int flat = 0;
    for (std::size_t x = 0; x < sharp.size(); ++x) flat += x != edge && sharp[x] > 0;
    EXPECT_EQ(flat, 0) << mode;
    // At 180 the same edge is smoothed over: the shade varies along the row, but crosses the edge
    // by no more than a few levels (8 levels a pixel is the gradient elsewhere on this row).
    EXPECT_GE(smooth[edge], 0) << mode;
    EXPECT_LE(smooth[edge], 6) << mode;
    EXPECT_GT(*std::max_element(smooth.begin(), smooth.end()), 0) << mode;
  }
}

// ---- splitting by edge length ----------------------------------------------------------------

TEST(Split, CubeFacesSplitWatertightWithShortEdges) {
  for (double L : {0.5, 0.7, 1.5, 3.0}) {
    SceneObject o = stl_object();
    o.max_edge_length = L;
    const IndexedMesh m = stl(binary_stl(cube_triangles()), o);
    expect_watertight(m);
    double area = 0, longest = 0, longest_cube_edge = 0;
    for (const auto& f : m.faces) {
      ASSERT_EQ(f.n, 3);
      const glm::dvec3 &a = m.position[f.idx[0]], &b = m.position[f.idx[1]], &c = m.position[f.idx[2]];
      area += 0.5 * glm::length(glm::cross(b - a, c - a));
      for (const auto& [p, q] : {std::pair(a, b), std::pair(b, c), std::pair(c, a)}) {
        const double len = glm::length(q - p);
        longest = std::max(longest, len);
        // On a cube edge: two coordinates at +-1 shared by both ends.
        int on = 0;
        for (int k = 0; k < 3; ++k) on += p[k] == q[k] && std::fabs(p[k]) == 1;
        if (on == 2) longest_cube_edge = std::max(longest_cube_edge, len);
      }
    }
    EXPECT_NEAR(area, 24, 1e-9) << L;
    EXPECT_LE(longest_cube_edge, L) << L;
    EXPECT_LT(longest, 1.5 * L) << L;  // inside a face, the stitch to the grid may be a little longer
    if (L < 2) EXPECT_GT(m.faces.size(), 12u);
    if (L == 3.0) EXPECT_EQ(m.faces.size(), 12u);  // nothing longer than 2*sqrt(2)
  }
}

TEST(Split, ThinAndObtuseFacesStayWatertight) {
  // The cylinder's sides are 2 x 0.26 slivers, its caps fans of thin triangles around a centre.
  int d = 0;
  for (double L : {0.1, 0.13, 0.4, 0.9}) {
    for (double crease : {0.0, 80.0}) {
      SceneObject o = obj_object("cylinder.stl", MeshNormals::Crease, crease);
      o.max_edge_length = L;
      const IndexedMesh m = watkins::load_mesh_file(o, "w", 1000000, false, d);
      expect_watertight(m);
      double area = 0;
      for (const auto& f : m.faces) {
        const glm::dvec3 &a = m.position[f.idx[0]], &b = m.position[f.idx[1]], &c = m.position[f.idx[2]];
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
        EXPECT_GT(glm::length(glm::cross(b - a, c - a)), 0) << "a zero-area piece at L = " << L;
      }
      // 24 side rectangles 2 x (2 sin(7.5 deg)) and two 24-gons of (24/2) sin(15 deg).
      EXPECT_NEAR(area, 24 * 2 * 2 * std::sin(M_PI / 24) + 2 * 12 * std::sin(M_PI / 12), 1e-5) << L;
    }
  }
  EXPECT_EQ(d, 0);
}

// The lesson's control: splitting changes the tessellation, not the surface's normals, so the
// Phong picture stays (nearly) the same while Gouraud's comes closer to it.
TEST(Split, GouraudApproachesPhongAsTheCylinderIsSplit) {
  auto render = [](const char* mode, const std::string& split) {
    const std::string text = R"({"screen": {"width": 160, "height": 120},
      "camera": {"type": "gouraud", "focal": 1.2, "near": 0.5, "far": 100},
      "light": {"type": "directional", "direction": [0.5, 0.6, -2]},
      "shading": {"mode": ")" + std::string(mode) + R"(", "rule": "phong"},
      "materials": {"m": {"color": [0.3, 0.8, 0.75], "n": 20}},
      "objects": [{"type": "mesh", "file": "cylinder.stl", "crease_angle_deg": 80, "material": "m")" + split + R"(,
                   "scale": 1.2, "rotate_deg": [-30, 0, 15], "translate": [0, 0, 5]}]})";
    return watkins::test::render_fixed(watkins::load_scene_text(text, "c.json", kScenes));
  };
  // Mean |difference| over pixels both images cover.
  auto mean_diff = [](const watkins::Image& a, const watkins::Image& b) {
    double sum = 0;
    int n = 0;
    for (std::size_t i = 0; i < a.covered.size(); ++i)
      if (a.covered[i] && b.covered[i]) {
        for (int c = 0; c < 3; ++c) sum += std::abs(int(a.rgb[3 * i + c]) - int(b.rgb[3 * i + c]));
        ++n;
      }
    return sum / (3.0 * n);
  };
  const watkins::Image phong = render("phong", ""), gouraud = render("gouraud", "");
  const watkins::Image phong_split = render("phong", R"(, "max_edge_length": 0.15)");
  const watkins::Image gouraud_split = render("gouraud", R"(, "max_edge_length": 0.15)");
  EXPECT_LT(mean_diff(phong_split, phong), 0.5);
  const double before = mean_diff(gouraud, phong), after = mean_diff(gouraud_split, phong);
  EXPECT_GT(before, 0.5);  // measured: 0.82 before, 0.37 after, Phong split vs unsplit 0.25
  EXPECT_LT(after, 0.5 * before) << before << " -> " << after;
}

TEST(Split, QuadsWithFileNormalsKeepThemAndShortFacesStayQuads) {
  SceneObject o = obj_object("cube.obj", MeshNormals::File);
  o.max_edge_length = 0.6;
  int d = 0;
  const IndexedMesh m = watkins::load_mesh_file(o, "w", 100000, false, d);
  expect_watertight(m);
  for (const auto& f : m.faces) {
    const glm::dvec3 n = -face_normal(m, f);
    for (int k = 0; k < f.n; ++k) EXPECT_LT(glm::length(m.normal[f.idx[k]] - n), 1e-12);
  }
  o.max_edge_length = 2;  // every edge fits: the quads stay
  const IndexedMesh q = watkins::load_mesh_file(o, "w", 100000, false, d);
  EXPECT_EQ(q.faces.size(), 6u);
  EXPECT_EQ(q.faces[0].n, 4);
  o.max_edge_length = 1e-3;
  try {
    watkins::load_mesh_file(o, "h.json: objects[0].file", 100000, false, d);
    FAIL() << "a split past the face limit";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("max_edge_length 0.001 splits the faces into"), std::string::npos) << e.what();
  }
}

TEST(Split, SplitCubeRendersWithoutCracks) {
  for (const char* split : {"", R"(, "max_edge_length": 0.3)"}) {
    const std::string text = R"({"screen": {"width": 160, "height": 120},
      "camera": {"type": "gouraud", "focal": 1.2, "near": 0.5, "far": 100},
      "objects": [{"type": "mesh", "file": "cube.stl", "crease_angle_deg": 80)" + std::string(split) + R"(,
                   "scale": 0.8, "rotate_deg": [-25, 35, 0], "translate": [0, 0, 5]}]})";
    const watkins::BuiltScene s = watkins::load_scene_text(text, "c.json", kScenes);
    std::vector<int> hits;
    watkins::test::render_fixed(s, &hits);
    int covered = 0;
    for (int y = 1; y + 1 < s.height; ++y)
      for (int x = 1; x + 1 < s.width; ++x) {
        const int h = hits[std::size_t(y) * s.width + x];
        EXPECT_LE(h, 1) << "overlap at " << x << "," << y;
        covered += h;
        const bool inside = hits[std::size_t(y) * s.width + x - 1] && hits[std::size_t(y) * s.width + x + 1] &&
                            hits[std::size_t(y - 1) * s.width + x] && hits[std::size_t(y + 1) * s.width + x];
        EXPECT_TRUE(h || !inside) << "crack at " << x << "," << y << split;
      }
    EXPECT_GT(covered, 1500);
  }
}

// ---- scenes and the command line -------------------------------------------------------------

TEST(StlScene, BuildsAndCountsItsPolygons) {
  const watkins::BuiltScene s = watkins::load_scene(kScenes + "stl.json");
  // The cube shows 3 of 12 triangles' sides (6 triangles), the cylinder about half of its 96.
  EXPECT_EQ(s.degenerate, 0);
  EXPECT_GT(s.polygons.size(), 40u);
  EXPECT_EQ(s.polygons.size() + std::size_t(s.culled_backfaces), 12u + 96u);
}

TEST(StlScene, SceneKeysAreChecked) {
  auto err = [](const std::string& obj) {
    try {
      watkins::load_scene_text(R"({"screen": {"width": 8, "height": 8}, "objects": [)" + obj + "]}", "k.json", kScenes);
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(err(R"({"type": "mesh", "file": "cube.obj", "normals": "file", "crease_angle_deg": 80})"),
            "k.json: objects[0].crease_angle_deg: crease_angle_deg chooses the normals (smoothed across edges sharper "
            "than it): leave out \"normals\"");
  EXPECT_NE(err(R"({"type": "mesh", "file": "cube.obj", "crease_angle_deg": 181})").find("expected a number in [0, 180]"),
            std::string::npos);
  EXPECT_NE(err(R"({"type": "mesh", "file": "cube.obj", "max_edge_length": 0})").find("objects[0].max_edge_length: expected a positive number"),
            std::string::npos);
  EXPECT_NE(err(R"({"type": "mesh", "file": "cube.stl", "weld_tolerance": -1})").find("objects[0].weld_tolerance"),
            std::string::npos);
  EXPECT_NE(err(R"({"type": "mesh", "file": "cube.stl", "normals": "file"})")
                .find("k.json: objects[0].file: STL file \"" + kScenes + "cube.stl\": has no vertex normals"),
            std::string::npos);
  EXPECT_EQ(err(R"({"type": "mesh", "file": "cube.stl", "weld_tolerance": 0, "max_edge_length": 1, "crease_angle_deg": 30,
                    "translate": [0, 0, 5]})"), "");
}

TEST(StlCli, BadStlFileExitsOneAndWritesNothing) {
  ScratchDir dir;
  std::string b = binary_stl(cube_triangles());
  const std::string folder = std::filesystem::path(dir.write("t.stl", b.substr(0, b.size() - 10))).parent_path();
  dir.write("t.json", R"({"screen": {"width": 32, "height": 32},
    "objects": [{"type": "mesh", "file": "t.stl", "translate": [0, 0, 5]}]})");
  const CliRun r = run_cli("render t.json --out o.png", folder);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("t.json: objects[0].file: STL file \"t.stl\": neither ASCII STL"),
            std::string::npos) << r.output;
  EXPECT_FALSE(dir.has("o.png"));
}

// Every file export-stl writes for a shipped scene, ASCII and binary, reads back through the mesh
// reader facet for facet: the same facets in the same order at the same corners (within the weld
// tolerance and float32), less those the welding makes zero-area (counted as degenerate).
TEST(StlExport, EveryShippedSceneReadsBackFacetForFacet) {
  int exported = 0, refused = 0;
  for (const std::string& path : watkins::test::shipped_scene_paths()) {
    const watkins::BuiltScene s = watkins::load_scene(path);
    const std::string name = std::filesystem::path(path).stem().string();
    bool world = false;
    for (const SceneObject& o : s.source->objects) world = world || o.type != watkins::ObjectType::Polygons;
    if (!world) {
      EXPECT_NE(watkins::test::error_of([&] { watkins::export_stl(*s.source, std::size_t{1} << 22); })
                    .find(path + ": no world-space surfaces to export ("),
                std::string::npos) << name;
      ++refused;
      continue;
    }
    const watkins::StlExport e = watkins::export_stl(*s.source, std::size_t{1} << 22);
    ASSERT_FALSE(e.facets.empty()) << name;
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const watkins::StlFacet& f : e.facets)
      for (const glm::dvec3& p : f.v) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const double tol = 2e-6 * glm::length(hi - lo) + 1e-6 * std::max(glm::length(lo), glm::length(hi));
    const std::vector<unsigned char> bin = watkins::stl_binary(e, "watkins export-stl " + name);
    for (const std::string& bytes : {watkins::stl_ascii(e, name), std::string(bin.begin(), bin.end())}) {
      const bool binary = watkins::is_binary_stl(bytes);
      int degenerate = 0;
      const IndexedMesh m = watkins::stl_mesh_from_bytes(bytes, stl_object(), name, std::size_t{1} << 22, false, degenerate);
      EXPECT_EQ(m.faces.size() + std::size_t(degenerate), e.facets.size()) << name << (binary ? " binary" : " ASCII");
      EXPECT_LE(degenerate * 100, int(e.facets.size())) << name;  // measured: 0 on every shipped scene
      // Walk the facets in order: each face read is the next facet with its corners (the reader
      // negates z back), the facets passed over are the degenerate ones.
      std::size_t next = 0;
      int passed = 0, mismatched = 0;
      for (const auto& f : m.faces) {
        auto matches = [&](const watkins::StlFacet& sf) {
          for (int k = 0; k < 3; ++k) {
            const glm::dvec3 p(sf.v[k].x, sf.v[k].y, -sf.v[k].z), q = m.position[std::size_t(f.idx[k])];
            if (glm::length(p - q) > tol) return false;
          }
          return true;
        };
        while (next < e.facets.size() && !matches(e.facets[next])) ++next, ++passed;
        if (next == e.facets.size()) {
          ++mismatched;
          break;
        }
        ++next;
      }
      EXPECT_EQ(mismatched, 0) << name << (binary ? " binary" : " ASCII");
      EXPECT_EQ(passed + int(e.facets.size() - next), degenerate) << name << (binary ? " binary" : " ASCII");
    }
    ++exported;
  }
  EXPECT_GE(exported, 15);
  EXPECT_GE(refused, 1);  // coplanar, overdraw, screen_polygons: command lists only
}

TEST(StlCli, ExportOfOnlyScreenPolygonsExitsOneAndWritesNothing) {
  ScratchDir dir;
  const std::string out = std::filesystem::path(dir.write("empty", "")).parent_path().string() + "/s.stl";
  for (const char* ascii : {"", " --ascii"}) {
    const CliRun r = run_cli("export-stl " + kScenes + "screen_polygons.json --out " + out + ascii);
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_EQ(r.output, "watkins: error: " + kScenes + "screen_polygons.json: no world-space surfaces to export (1 "
                        "screen-space polygons object(s) have no world geometry)\n");
    EXPECT_FALSE(dir.has("s.stl"));
  }
}

TEST(StlCli, RtlRendersTheStlSceneBitExact) {
  ScratchDir dir;
  const std::string folder = std::filesystem::path(dir.write("empty", "")).parent_path();
  for (const char* mode : {"gouraud", "phong"}) {
    const CliRun r = run_cli("render " + kScenes + "stl.json --shading " + mode + " --rtl --out o.png", folder);
    if (r.output.find("this build has no RTL simulation") != std::string::npos) GTEST_SKIP() << r.output;
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("rtl vs model  0 mismatching pixels"), std::string::npos) << r.output;
    EXPECT_TRUE(dir.has("o.png"));
  }
}

}  // namespace

// max_edge_length is in world units for meshes as for the analytic surfaces: the cube (side 2 in
// its file) scaled by 2 is split as the same cube of side 4 would be, and no cube edge is longer
// than the limit once scaled; a non-uniform scale measures each edge along its own axes.
TEST(Split, LimitIsInWorldUnitsAfterTheScale) {
  SceneObject scaled = stl_object();
  scaled.transform.scale = glm::dvec3(2.0);
  scaled.max_edge_length = 1.5;
  const IndexedMesh m = stl(binary_stl(cube_triangles()), scaled);
  SceneObject plain = stl_object();
  plain.max_edge_length = 0.75;  // the same limit in the file's units
  EXPECT_EQ(m.faces.size(), stl(binary_stl(cube_triangles()), plain).faces.size());
  EXPECT_GT(m.faces.size(), 12u * 9);  // edges of 4 world units in 3 pieces at least
  expect_watertight(m);
  for (const auto& f : m.faces)
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 p = m.position[f.idx[k]], q = m.position[f.idx[(k + 1) % 3]];
      int on = 0;
      for (int c = 0; c < 3; ++c) on += p[c] == q[c] && std::fabs(p[c]) == 1;
      if (on == 2) EXPECT_LE(glm::length(2.0 * (q - p)), 1.5 + 1e-12);
    }
  // Stretched along x only: the x edges are split, the y and z edges (2 world units) are not.
  SceneObject stretched = stl_object();
  stretched.transform.scale = glm::dvec3(4, 1, 1);
  stretched.max_edge_length = 2.5;
  const IndexedMesh s = stl(binary_stl(cube_triangles()), stretched);
  std::set<Key> on_x_edges, on_y_edges;  // positions (a split point has a vertex per face normal)
  for (const glm::dvec3& p : s.position) {
    if (std::fabs(p.y) == 1 && std::fabs(p.z) == 1 && std::fabs(p.x) < 1) on_x_edges.insert(key(p));
    if (std::fabs(p.x) == 1 && std::fabs(p.z) == 1 && std::fabs(p.y) < 1) on_y_edges.insert(key(p));
  }
  EXPECT_EQ(on_x_edges.size(), 4u * 3);  // 8 world units in 4 pieces: 3 new points on each of the 4 x edges
  EXPECT_EQ(on_y_edges.size(), 0u) << "the y edges (2 world units) stay whole";
}
