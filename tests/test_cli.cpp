// Bad input through the command line: a clear message naming file/line/field, exit code 1, and
// no image written (more in test_cli_hostile.cpp). And the happy path: the embedded default scene renders.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <string>

#include "cli_run.hpp"

namespace {

using watkins::test::CliRun;
CliRun run(const std::string& args) { return watkins::test::run_cli(args); }

bool exists(const std::string& path) {
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

class Cli : public ::testing::Test, protected watkins::test::ScratchDir {
 protected:
  // Renders `scene_text` and expects failure with `message` in the output and no image.
  void expect_rejected(const std::string& scene_text, const std::string& message) {
    const std::string scene = write("scene.json", scene_text);
    const std::string png = dir_ + "/out.png";
    const CliRun r = run("render " + scene + " --out " + png);
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << "expected \"" << message << "\" in:\n" << r.output;
    EXPECT_NE(r.output.find("scene.json"), std::string::npos) << "message must name the file:\n" << r.output;
    EXPECT_FALSE(exists(png)) << "no image may be written for bad input";
  }
  void expect_rejected_strict(const std::string& scene_text, const std::string& message) {
    const std::string scene = write("scene.json", scene_text);
    const CliRun r = run("render " + scene + " --strict --out " + dir_ + "/out.png");
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
    EXPECT_FALSE(exists(dir_ + "/out.png"));
  }
  static std::string triangle(const std::string& v0) {
    return R"({"screen": {"width": 16, "height": 16}, "objects": [{"type": "polygons", "polygons": [
      {"vertices": [)" + v0 + R"(, {"x": 12, "y": 2, "depth": 0.5, "rgb": [1, 2, 3]},
                    {"x": 8, "y": 12, "depth": 0.5, "rgb": [1, 2, 3]}]}]}]})";
  }
};

TEST_F(Cli, DefaultSceneRendersAndReportsError) {
  const std::string png = dir_ + "/default.png";
  const CliRun r = run("render --out " + png);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(exists(png));
  EXPECT_NE(r.output.find("fragments"), std::string::npos);
  EXPECT_NE(r.output.find("vs double"), std::string::npos);
  EXPECT_NE(r.output.find("0 pixels > 1 level"), std::string::npos) << r.output;
}

TEST_F(Cli, MissingFile) {
  const CliRun r = run("render " + dir_ + "/nope.json --out " + dir_ + "/x.png");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("nope.json: cannot open scene file"), std::string::npos) << r.output;
  EXPECT_FALSE(exists(dir_ + "/x.png"));
}

TEST_F(Cli, MalformedJsonNamesLineAndColumn) {
  expect_rejected("{\n  \"screen\": {\"width\": 16,\n  \"height\": }\n}", "scene.json:3:13: malformed JSON");
}

TEST_F(Cli, UnknownKey) {
  expect_rejected(R"({"screen": {"width": 16, "height": 16, "colour": 1}, "objects": []})", "screen: unknown key \"colour\"");
}

TEST_F(Cli, WrongType) {
  expect_rejected(R"({"screen": {"width": "wide", "height": 16}, "objects": []})", "screen.width: expected an integer");
}

TEST_F(Cli, InfiniteAndNanNumbers) {
  expect_rejected(triangle(R"({"x": 1e999, "y": 2, "depth": 0.5, "rgb": [1, 2, 3]})"), "1e999");
  expect_rejected(triangle(R"({"x": NaN, "y": 2, "depth": 0.5, "rgb": [1, 2, 3]})"), "malformed JSON");
}

TEST_F(Cli, DegeneratePolygonWithStrict) {  // skipped without --strict (test_cli_hostile.cpp)
  expect_rejected_strict(R"({"screen": {"width": 16, "height": 16}, "objects": [{"type": "polygons", "polygons": [
      {"vertices": [{"x": 1, "y": 1, "depth": 0.5, "rgb": [0, 0, 0]}, {"x": 5, "y": 5, "depth": 0.5, "rgb": [0, 0, 0]},
                    {"x": 9, "y": 9, "depth": 0.5, "rgb": [0, 0, 0]}]}]}]})",
                  "objects[0].polygons[0]: polygon has zero area");
}

TEST_F(Cli, CoordinateOutsideRepresentableRange) {
  expect_rejected(triangle(R"({"x": 9000, "y": 2, "depth": 0.5, "rgb": [1, 2, 3]})"),
                  "objects[0].polygons[0].vertices[0].x: 9000 is outside the representable range");
}

TEST_F(Cli, ShadeOutOfRange) {
  expect_rejected(triangle(R"({"x": 1, "y": 2, "depth": 0.5, "rgb": [1, 300, 3]})"), "objects[0].polygons[0].vertices[0].rgb");
}

TEST_F(Cli, ActiveEdgeCapacityExceeded) {
  // 40 thin overlapping triangles on the same scan lines: 80 active edges against a capacity of 64.
  std::string polys;
  for (int i = 0; i < 40; ++i) {
    const std::string x = std::to_string(2 + i), x2 = std::to_string(2.5 + i);
    polys += std::string(i ? "," : "") + R"({"vertices": [{"x": )" + x + R"(, "y": 1, "depth": 0.5, "rgb": [9, 9, 9]},
        {"x": )" + x2 + R"(, "y": 1, "depth": 0.5, "rgb": [9, 9, 9]}, {"x": )" + x + R"(, "y": 30, "depth": 0.5, "rgb": [9, 9, 9]}]})";
  }
  expect_rejected(R"({"screen": {"width": 64, "height": 32}, "objects": [{"type": "polygons", "polygons": [)" + polys + "]}]}",
                  "scene needs 80 active edges on scan line");
}

TEST_F(Cli, ScreenTooLarge) {
  expect_rejected(R"({"screen": {"width": 5000, "height": 16}, "objects": []})", "screen.width");
}

TEST_F(Cli, UnknownShadingRuleOnCommandLine) {
  const CliRun r = run("render --rule blinn --out " + dir_ + "/x.png");
  EXPECT_EQ(r.exit_code, 2);  // a wrong option value: usage
  EXPECT_NE(r.output.find("--rule: unknown shading rule \"blinn\""), std::string::npos) << r.output;
  EXPECT_FALSE(exists(dir_ + "/x.png"));
}

TEST_F(Cli, UnknownShadingModeOnCommandLine) {
  const CliRun r = run("render --shading flat --out " + dir_ + "/x.png");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("watkins: usage: --shading: unknown shading mode \"flat\" (gouraud, phong)"),
            std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << "one-line error:\n" << r.output;
  EXPECT_FALSE(exists(dir_ + "/x.png"));
}

TEST_F(Cli, PhongShadingRendersAndReportsTheMode) {
  const std::string png = dir_ + "/phong.png";
  const CliRun r = run("render " WATKINS_SOURCE_DIR "/scenes/sphere.json --shading phong --out " + png);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(exists(png));
  EXPECT_NE(r.output.find("shading phong"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("channel Nx"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("vs double"), std::string::npos) << r.output;
}

TEST_F(Cli, HelpListsShading) {
  const CliRun r = run("render --help");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("--shading"), std::string::npos) << r.output;
}

}  // namespace

namespace {

class CliTruth : public Cli {};

// The analytic truth from the command line: reported and written for eq. (3), refused otherwise.
TEST_F(CliTruth, WrittenForPhongsIlluminationRefusedOtherwise) {
  const std::string png = dir_ + "/s.png", truth = dir_ + "/t.png", diff = dir_ + "/td.png";
  const CliRun r = run("render " WATKINS_SOURCE_DIR "/scenes/sphere.json --shading phong --out " + png + " --truth " +
                       truth + " --truth-diff " + diff);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(exists(truth) && exists(diff));
  EXPECT_NE(r.output.find("vs truth      double reference: max |d|"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("vs truth      fixed model: max |d|"), std::string::npos) << r.output;
  const std::string t2 = dir_ + "/t2.png";
  const CliRun l = run("render " WATKINS_SOURCE_DIR "/scenes/sphere.json --rule lambert --out " + dir_ +
                       "/l.png --truth " + t2);
  EXPECT_EQ(l.exit_code, 1) << l.output;
  EXPECT_NE(l.output.find("t2.png: no analytic truth for"), std::string::npos) << l.output;
  EXPECT_FALSE(exists(dir_ + "/l.png")) << "no output when any part of the run fails";
  EXPECT_NE(l.output.find("eq. (3)"), std::string::npos) << l.output;
  EXPECT_FALSE(exists(t2));
}

}  // namespace
