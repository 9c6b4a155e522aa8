// Hostile and careless input: the scene parser and the OBJ reader refuse it with one
// message naming the file, line or field; nothing recurses on input, nothing allocates before
// the size is known, nothing non-finite gets through.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>

#include "mesh_obj.hpp"
#include "mesh_stl.hpp"
#include "scene.hpp"
#include "scene_types.hpp"

namespace {

using watkins::SceneError;

// The message load_scene_text throws for `text`, or "" when it loads.
std::string error_of(const std::string& text, const watkins::BuildOptions& opt = {}) {
  try {
    watkins::load_scene_text(text, "h.json", "/nonexistent", opt);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

#define EXPECT_MESSAGE(text, needle)                                                         \
  do {                                                                                       \
    const std::string m_ = error_of(text);                                                   \
    EXPECT_NE(m_.find(needle), std::string::npos) << "expected \"" << (needle) << "\" in: " << m_; \
    EXPECT_EQ(m_.rfind("h.json", 0), 0u) << "names the file: " << m_;                        \
  } while (0)

const std::string kScreen = R"("screen": {"width": 32, "height": 32})";

std::string triangle(const std::string& extra, double x2 = 8, double y2 = 12) {
  return "{" + kScreen + R"(, "objects": [{"type": "polygons", "polygons": [{"vertices": [
      {"x": 2, "y": 2, "depth": 0.5, "rgb": [1, 2, 3])" + extra + R"(},
      {"x": 12, "y": 2, "depth": 0.5, "rgb": [1, 2, 3]},
      {"x": )" + std::to_string(x2) + R"(, "y": )" + std::to_string(y2) + R"(, "depth": 0.5, "rgb": [1, 2, 3]}]}]}]})";
}

TEST(HostileJson, DeepNestingIsRefusedWithItsPositionNotACrash) {
  // 10^5 levels crashed the message path (a recursive dump); the text scan refuses them first.
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_MESSAGE(deep, "h.json:1:65: malformed JSON: arrays and objects nested deeper than 64 levels");
  std::string objects;
  for (int i = 0; i < 100000; ++i) objects += "{\"a\":";
  objects += "1" + std::string(100000, '}');
  EXPECT_MESSAGE(objects, "nested deeper than 64 levels");
  // Inside a value of a real field, on line 2.
  EXPECT_MESSAGE("{" + kScreen + ",\n \"objects\": " + std::string(70, '[') + std::string(70, ']') + "}",
                 "h.json:2:76:");
  // Brackets in strings and comments are not nesting.
  EXPECT_EQ(error_of("{" + kScreen + ", // " + std::string(100, '[') + "\n \"objects\": []}"), "");
  EXPECT_MESSAGE("{" + kScreen + ", \"objects\": [], \"" + std::string(100, '{') + "\": 1}", "unknown key");
}

TEST(HostileJson, LongValuesAreShownCut) {
  std::string big = "[";
  for (int i = 0; i < 200000; ++i) big += (i ? "," : "") + std::to_string(i);
  big += "]";
  const std::string m = error_of(R"({"screen": {"width": )" + big + R"(, "height": 8}, "objects": []})");
  EXPECT_NE(m.find("screen.width: expected an integer, got [0,1,2,"), std::string::npos) << m;
  EXPECT_LT(m.size(), 120u) << m;
}

TEST(HostileJson, DuplicateKeysAreRefusedNamingTheKeyAndItsObject) {
  EXPECT_MESSAGE(R"({"screen": {"width": 8, "height": 8, "width": 16}, "objects": []})",
                 "h.json: screen: duplicate key \"width\"");
  EXPECT_MESSAGE("{" + kScreen + R"(, "objects": [], "objects": []})", "h.json: duplicate key \"objects\"");
  EXPECT_MESSAGE("{" + kScreen + R"(, "objects": [{"type": "sphere", "radius": 1},
                 {"type": "sphere", "radius": 1, "center": [0, 0, 5], "radius": 2}]})",
                 "h.json: objects[1]: duplicate key \"radius\"");
  EXPECT_MESSAGE("{" + kScreen + R"(, "materials": {"red": {"color": [1, 0, 0], "d": 0.1, "d": 0.2}}, "objects": []})",
                 "h.json: materials.red: duplicate key \"d\"");
  // The same key in two objects is fine.
  EXPECT_EQ(error_of("{" + kScreen + R"(, "objects": [{"type": "sphere", "radius": 1, "center": [0, 0, 5]},
                 {"type": "sphere", "radius": 1, "center": [0, 0, 9]}]})"), "");
}

TEST(HostileJson, ControlCharactersInKeysAndNamesAreEscaped) {
  const std::string m = error_of(R"({"screen": {"width": 8, "height": 8, "a\u001b[31mb\u0007": 1}, "objects": []})");
  EXPECT_NE(m.find(R"(screen: unknown key "a\u001b[31mb\u0007")"), std::string::npos) << m;
  for (char c : m) EXPECT_GE(static_cast<unsigned char>(c), 0x20) << "raw control character in: " << m;
  const std::string mat = error_of("{" + kScreen + R"(, "objects": [{"type": "sphere", "radius": 1, "material": "x\ny"}]})");
  EXPECT_NE(mat.find(R"(unknown material "x\u000ay")"), std::string::npos) << mat;
  EXPECT_EQ(mat.find('\n'), std::string::npos) << mat;
}

TEST(HostileJson, FiniteNumbersWhoseProductsOverflowAreRefusedNamingTheField) {
  EXPECT_MESSAGE("{" + kScreen + R"(, "light": {"type": "directional", "direction": [1e200, 0, 0]}, "objects": []})",
                 "light.direction[0]: expected a number of magnitude at most 1e+09, got 1e+200");
  EXPECT_MESSAGE("{" + kScreen + R"(, "camera": {"type": "lookat", "eye": [0, 1e200, -5], "target": [0, 0, 0]},
                 "objects": []})", "camera.eye[1]: expected a number of magnitude at most");
  EXPECT_MESSAGE(triangle(R"(, "normal": [1e200, 1e200, 0])"), "objects[0].polygons[0].vertices[0].normal[0]");
  EXPECT_MESSAGE("{" + kScreen + R"(, "objects": [{"type": "sphere", "radius": 1, "center": [0, 0, 5],
                 "scale": [1, 1e-300, 1]}]})", "objects[0].scale[1]: expected a positive number (at least 1e-09)");
  EXPECT_MESSAGE("{" + kScreen + R"(, "objects": [{"type": "sphere", "radius": 1e-300}]})", "objects[0].radius");
}

TEST(HostileJson, NanIsSpelledOneWay) {
  EXPECT_EQ(watkins::number_text(std::nan("")), "NaN");
  EXPECT_EQ(watkins::number_text(-std::nan("")), "NaN");
}

TEST(HostileJson, ZeroAreaPolygonsAreSkippedAndCountedFatalOnlyWhenStrict) {
  const std::string text = "{" + kScreen + R"(, "objects": [{"type": "polygons", "polygons": [
      {"vertices": [{"x": 1, "y": 1, "depth": 0.5, "rgb": [0, 0, 0]}, {"x": 5, "y": 5, "depth": 0.5, "rgb": [0, 0, 0]},
                    {"x": 9, "y": 9, "depth": 0.5, "rgb": [0, 0, 0]}]},
      {"vertices": [{"x": 1, "y": 1, "depth": 0.5, "rgb": [0, 0, 0]}, {"x": 9, "y": 1, "depth": 0.5, "rgb": [0, 0, 0]},
                    {"x": 1, "y": 9, "depth": 0.5, "rgb": [0, 0, 0]}]}]}]})";
  const watkins::BuiltScene s = watkins::load_scene_text(text, "h.json", ".");
  EXPECT_EQ(s.polygons.size(), 1u);
  EXPECT_EQ(s.degenerate, 1);
  EXPECT_EQ(s.polygons[0].v[1].x, 9);  // the one with area is the one kept
  watkins::BuildOptions strict;
  strict.strict = true;
  EXPECT_EQ(error_of(text, strict), "h.json: objects[0].polygons[0]: polygon has zero area (skipped without --strict)");
}

TEST(HostileJson, SizeIsEstimatedBeforeAllocating) {
  // 1 KB asking for 40 spheres of 1024 x 1024: refused at once, naming the object that crosses.
  std::string objs;
  for (int i = 0; i < 40; ++i) objs += std::string(i ? "," : "") + R"({"type": "sphere", "radius": 1, "u": 1024, "v": 1024})";
  const auto t0 = std::chrono::steady_clock::now();
  const std::string m = error_of("{" + kScreen + ", \"objects\": [" + objs + "]}");
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_NE(m.find("h.json: objects[3].u: the objects up to here make about"), std::string::npos) << m;
  EXPECT_NE(m.find("over the limit of 4194304"), std::string::npos) << m;
  EXPECT_LT(s, 0.5) << "refused before tessellating";
}

TEST(HostileJson, TooManyPolygonsNameTheObjectThatCrossesTheLimit) {
  const std::string m = error_of("{" + kScreen + R"(, "camera": {"type": "lookat", "eye": [0, 0, -5], "target": [0, 0, 0]},
      "objects": [{"type": "sphere", "radius": 1, "u": 16, "v": 8},
                  {"type": "sphere", "radius": 1, "u": 512, "v": 512}]})");
  EXPECT_EQ(m, "h.json: objects[1]: the scene has more than 65536 polygons up to this object; the pipeline's polygon "
               "id is 16 bits (at most 65536)");
}

// ---- OBJ reader -------------------------------------------------------------------------------

watkins::SceneObject mesh_object(watkins::MeshNormals normals = watkins::MeshNormals::Average) {
  watkins::SceneObject o;
  o.type = watkins::ObjectType::Mesh;
  o.file = "m.obj";
  o.normals = normals;
  return o;
}

std::string obj_error(const std::string& text, std::size_t max_faces = 1000) {
  try {
    watkins::obj_mesh_from_text(text, mesh_object(), "h.json: objects[0].file", max_faces);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

TEST(HostileObj, FacesOfMoreThan255VerticesAreReadRight) {
  for (int n : {255, 256, 300, 1000}) {
    std::string text;
    for (int k = 0; k < n; ++k) {
      const double a = 2 * M_PI * k / n;
      text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    }
    text += "f";
    for (int k = 1; k <= n; ++k) text += " " + std::to_string(k);
    text += "\n";
    const watkins::IndexedMesh m = watkins::obj_mesh_from_text(text, mesh_object(), "w", 10000);
    ASSERT_EQ(m.faces.size(), static_cast<size_t>(n - 2)) << n;  // a fan over all n vertices
    ASSERT_EQ(m.position.size(), static_cast<size_t>(n));
    for (size_t f = 0; f < m.faces.size(); ++f) {
      EXPECT_EQ(m.faces[f].n, 3);
      EXPECT_EQ(m.faces[f].idx[0], 0);
      EXPECT_EQ(m.faces[f].idx[1], static_cast<int>(f + 1));
      EXPECT_EQ(m.faces[f].idx[2], static_cast<int>(f + 2));
    }
    // Vertex k is the file's vertex k (z mirrored): the last triangle closes on vertex n - 1.
    EXPECT_NEAR(m.position[n - 1].x, std::cos(2 * M_PI * (n - 1) / n), 1e-6);
  }
}

TEST(HostileObj, QuadsStayQuadsAndRelativeIndicesResolve) {
  const watkins::IndexedMesh m =
      watkins::obj_mesh_from_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4 -3 -2 -1\nf 1/1 2/2 3/3\nvt 0 0\n", mesh_object(), "w", 10);
  ASSERT_EQ(m.faces.size(), 2u);
  EXPECT_EQ(m.faces[0].n, 4);
  EXPECT_EQ(m.faces[1].n, 3);
}

TEST(HostileObj, NotANumberIsRefusedNamingTheLine) {
  EXPECT_EQ(obj_error("v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n"),
            "h.json: objects[0].file: OBJ file \"m.obj\": line 2: v: expected a finite number, got \"nan\"");
  EXPECT_NE(obj_error(kTriangle + "v inf 0 0\nf 1 2 3\n").find("line 4: v: expected a finite number, got \"inf\""),
            std::string::npos);
  EXPECT_NE(obj_error("v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n").find("got \"zero\""), std::string::npos);
  EXPECT_NE(obj_error("v 0 0 0\nv 1 0 0x\nv 0 1 0\nf 1 2 3\n").find("got \"0x\""), std::string::npos);
  EXPECT_NE(obj_error(kTriangle + "vn 0 0 1e999\nf 1 2 3\n").find("line 4: vn: expected a finite number"), std::string::npos);
  EXPECT_NE(obj_error("v 0 0 1e200\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").find("line 1: v: expected a number of magnitude at most 1e9"),
            std::string::npos);
  EXPECT_NE(obj_error("v 0 0\n").find("line 1: v: expected 3 coordinates"), std::string::npos);
}

TEST(HostileObj, IndicesPast2To63AreRefusedNotWrapped) {
  EXPECT_NE(obj_error(kTriangle + "f 1 2 9223372036854775808\n").find("line 4: f: vertex index \"9223372036854775808\" is out of range"),
            std::string::npos) << obj_error(kTriangle + "f 1 2 9223372036854775808\n");
  EXPECT_NE(obj_error(kTriangle + "f 1 2 18446744073709551619\n").find("is out of range"), std::string::npos);
  EXPECT_NE(obj_error(kTriangle + "f 1 2 -9223372036854775808\n").find("is before the first one"), std::string::npos);
  EXPECT_NE(obj_error(kTriangle + "f 1 2 9223372036854775807\n").find("line 4: f: vertex index 9223372036854775807 is past the last vertex (3)"),
            std::string::npos) << obj_error(kTriangle + "f 1 2 9223372036854775807\n");
  EXPECT_NE(obj_error(kTriangle + "f 1 2 0\n").find("index 0 (OBJ indices start at 1)"), std::string::npos);
  EXPECT_NE(obj_error(kTriangle + "f 1 2 3x\n").find("vertex index \"3x\" is not an integer"), std::string::npos);
  EXPECT_NE(obj_error(kTriangle + "f 1 2\n").find("f: a face needs at least 3 vertices, got 2"), std::string::npos);
  EXPECT_NE(obj_error(kTriangle + "f 1//9 2//9 3//9\n").find("normal index 9 is past the last normal (0)"), std::string::npos);
}

TEST(HostileObj, FaceCountIsBoundedWhileReading) {
  std::string text = kTriangle;
  for (int i = 0; i < 20; ++i) text += "f 1 2 3\n";
  EXPECT_NE(obj_error(text, 10).find("line 14: f: the file makes more than 10 faces"), std::string::npos) << obj_error(text, 10);
  EXPECT_EQ(obj_error(text, 20), "");
}

TEST(HostileObj, BinaryAndDevicesAreRefusedUnread) {
  EXPECT_NE(obj_error(std::string("v 0 0 0\0\0\0", 10)).find("line 1: NUL byte"), std::string::npos);
  EXPECT_NE(obj_error("").find("has no faces"), std::string::npos);
  watkins::SceneObject o = mesh_object();
  o.file = "/dev/zero";
  try {
    int degenerate = 0;
    watkins::load_mesh_file(o, "h.json: objects[0].file", 1000, false, degenerate);
    FAIL() << "/dev/zero loaded";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(), "h.json: objects[0].file: mesh file \"/dev/zero\" is not a regular file");
  }
}

}  // namespace
