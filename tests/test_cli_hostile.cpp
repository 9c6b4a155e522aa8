// Hostile and careless command lines: exit codes 0 ok, 1 bad input, 2 usage, 3 internal
// error or RTL mismatch; one line naming the file, field or option; no output file, not even a
// partial one or a temporary, unless the whole run succeeded.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "cli_run.hpp"

namespace {

using watkins::test::CliRun;
using watkins::test::run_cli;

class CliHostile : public ::testing::Test, protected watkins::test::ScratchDir {
 protected:
  // Files in the scratch folder: nothing but what the test wrote may be left (no temporaries).
  size_t files() const {
    size_t n = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir_)) n += e.is_regular_file();
    return n;
  }
  // `watkins ARGS`: expects `code`, `needle` in a one-line error, no a.png.
  CliRun expect(const std::string& args, int code, const std::string& needle) {
    const CliRun r = run_cli(args, dir_);
    EXPECT_EQ(r.exit_code, code) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(needle), std::string::npos) << "expected \"" << needle << "\" in:\n" << r.output;
    EXPECT_FALSE(has("a.png")) << args;
    return r;
  }
  static std::string sphere() { return WATKINS_SOURCE_DIR "/scenes/sphere.json"; }
};

TEST_F(CliHostile, NonFiniteGapAndStallAreUsageErrors) {
  expect("render --out a.png --gap nan", 2, "--gap: expected a finite number, got \"nan\"");
  expect("render --out a.png --stall nan", 2, "--stall: expected a finite number, got \"nan\"");
  expect("render --out a.png --stall inf", 2, "--stall");
  expect("render --out a.png --gap 1.5", 2, "--gap");
}

TEST_F(CliHostile, SeedOutOfRangeIsAUsageError) {
  expect("render --out a.png --seed -1", 2, "--seed: expected an integer in [0, 18446744073709551615], got \"-1\"");
  expect("render --out a.png --seed 18446744073709551616", 2, "got \"18446744073709551616\"");
  expect("render --out a.png --seed 12abc", 2, "--seed");
  const CliRun ok = run_cli("render --out a.png --seed 18446744073709551615", dir_);
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

TEST_F(CliHostile, EmptySceneNameIsAnErrorNotTheBuiltInScene) {
  const CliRun r = expect("render \"\" --out a.png", 2, "watkins: usage: the scene file name is empty");
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

TEST_F(CliHostile, UnknownOptionIsAUsageError) { expect("render --out a.png --frobnicate", 2, "--frobnicate"); }

TEST_F(CliHostile, OutputOverAnInputIsRefused) {
  std::ifstream in(sphere());
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  write("s.json", text);
  expect("render s.json --out s.json", 2, "--out s.json is the scene file; refusing to overwrite it");
  expect("render s.json --out a.png --diff ./s.json", 2, "--diff ./s.json is the scene file");
  expect("render s.json --out a.png --diff a.png", 2, "--diff and --out name the same file a.png");
  EXPECT_EQ(contents("s.json"), text) << "the scene is untouched";
  // Nor the OBJ file a scene reads.
  write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write("m.json", R"({"screen": {"width": 16, "height": 16}, "objects": [{"type": "mesh", "file": "m.obj",
      "normals": "average", "translate": [0, 0, 5]}]})");
  expect("render m.json --out m.obj", 2, "--out m.obj is the mesh file of objects[0]");
  EXPECT_EQ(contents("m.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  // Nor an STL file.
  const std::string stl = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                          "endloop\nendfacet\nendsolid t\n";
  write("m.stl", stl);
  write("n.json", R"({"screen": {"width": 16, "height": 16}, "objects": [{"type": "mesh", "file": "m.stl",
      "translate": [0, 0, 5]}]})");
  expect("render n.json --out m.stl", 2, "--out m.stl is the mesh file of objects[0]");
  EXPECT_EQ(contents("m.stl"), stl);
}

TEST_F(CliHostile, PngWriteErrorsAreReported) {
  const CliRun r = run_cli("render " + sphere() + " --out /dev/full", dir_);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("watkins: error: /dev/full: cannot write: No space left on device"), std::string::npos) << r.output;
  const CliRun d = run_cli("render " + sphere() + " --out " + dir_ + "/no/such/folder/a.png", dir_);
  EXPECT_EQ(d.exit_code, 1) << d.output;
  EXPECT_NE(d.output.find("no/such/folder/a.png: cannot write: its folder "), std::string::npos) << d.output;
  EXPECT_NE(d.output.find("No such file or directory"), std::string::npos) << d.output;
}

TEST_F(CliHostile, NoPartialOutputsWhenAnyWriteFails) {
  // --out fails: --diff is not written either, and no temporary is left.
  const CliRun r = run_cli("render " + sphere() + " --diff d.png --out /dev/full", dir_);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_FALSE(has("d.png"));
  const CliRun f = run_cli("render " + sphere() + " --diff d.png --out missing/a.png", dir_);
  EXPECT_EQ(f.exit_code, 1) << f.output;
  EXPECT_FALSE(has("d.png"));
  EXPECT_EQ(files(), 0u) << "no temporaries left";
}

TEST_F(CliHostile, NoOutputWhenTheTruthFailsAfterTheImage) {
  const CliRun r = run_cli("render " + sphere() + " --rule lambert --out a.png --diff d.png --truth t.png", dir_);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("--truth t.png: no analytic truth for"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(nothing written)"), std::string::npos) << r.output;
  EXPECT_EQ(files(), 0u);
}

// The RTL's waveform streams out during the run: under a temporary name, renamed with the other
// outputs only when everything succeeded, removed when anything failed.
TEST_F(CliHostile, RtlTraceIsWrittenAllOrNothing) {
  const CliRun r = run_cli("render " + sphere() + " --rule lambert --rtl --trace w.fst --out a.png --truth t.png", dir_);
  if (r.output.find("this build has no RTL simulation") != std::string::npos) GTEST_SKIP() << r.output;
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("rtl vs model  0 mismatching pixels"), std::string::npos) << r.output;  // it ran
  EXPECT_NE(r.output.find("(nothing written)"), std::string::npos) << r.output;
  EXPECT_EQ(files(), 0u) << "no trace and no temporary";
  const CliRun ok = run_cli("render " + sphere() + " --rtl --trace w.fst --out a.png", dir_);
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  ASSERT_TRUE(has("w.fst") && has("a.png"));
  EXPECT_GT(std::filesystem::file_size(dir_ + "/w.fst"), 1000u);
  EXPECT_EQ(files(), 2u);
}

TEST_F(CliHostile, SuccessWritesEveryOutputAndNoTemporary) {
  const CliRun r = run_cli("render " + sphere() + " --shading phong --out a.png --diff d.png --truth t.png", dir_);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(has("a.png") && has("d.png") && has("t.png"));
  EXPECT_EQ(files(), 3u);
  EXPECT_NE(r.output.find("wrote         a.png, d.png, t.png"), std::string::npos) << r.output;
  // An existing output is replaced whole.
  const CliRun again = run_cli("render " + sphere() + " --out a.png", dir_);
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(files(), 3u);
}

TEST_F(CliHostile, BadInputFilesGiveOneLineAndExitOne) {
  write("deep.json", std::string(100000, '[') + std::string(100000, ']'));
  expect("render deep.json --out a.png", 1, "deep.json:1:65: malformed JSON: arrays and objects nested deeper than 64 levels");
  expect("render /dev/zero --out a.png", 1, "/dev/zero: scene file is larger than 16 MiB (the limit)");
  write("z.json", R"({"screen": {"width": 16, "height": 16}, "objects": [{"type": "mesh", "file": "/dev/zero",
      "normals": "average"}]})");
  expect("render z.json --out a.png", 1, "z.json: objects[0].file: mesh file \"/dev/zero\" is not a regular file");  // no .obj or .stl: told by content
  write("d.json", R"({"screen": {"width": 16, "height": 16, "height": 8}, "objects": []})");
  const CliRun r = expect("render d.json --out a.png", 1, "watkins: error: d.json: screen: duplicate key \"height\"");
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  write("n.json", R"({"screen": {"width": 16, "height": 16}, "light": {"type": "directional", "direction": [1e200, 1, 0]},
      "objects": []})");
  expect("render n.json --out a.png", 1, "n.json: light.direction[0]: expected a number of magnitude at most");
}

TEST_F(CliHostile, ConfigurationFilesAreReadAsStrictlyAsScenes) {
  write("deep.json", std::string(100000, '{') + std::string(100000, '}'));
  expect("render --config deep.json --out a.png", 1, "deep.json:1:65: malformed JSON: arrays and objects nested deeper than 64");
  write("dup.json", R"({"shade": {"frac_bits": 8, "frac_bits": 9}})");
  expect("render --config dup.json --out a.png", 1, "dup.json: shade: duplicate key \"frac_bits\"");
  write("ctl.json", R"({"shade": {"\u001b[2J": 9}})");
  const CliRun r = expect("render --config ctl.json --out a.png", 1, R"(ctl.json: shade: unknown key "\u001b[2J")");
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << "no raw escape sequence reaches the terminal";
  expect("render --config /dev/zero --out a.png", 1, "/dev/zero: configuration file is larger than 1 MiB");
}

TEST_F(CliHostile, ZeroAreaCommandListPolygonsAreSkippedUnlessStrict) {
  write("z.json", R"({"screen": {"width": 16, "height": 16}, "objects": [{"type": "polygons", "polygons": [
      {"vertices": [{"x": 1, "y": 1, "depth": 0.5, "rgb": [0, 0, 0]}, {"x": 5, "y": 5, "depth": 0.5, "rgb": [0, 0, 0]},
                    {"x": 9, "y": 9, "depth": 0.5, "rgb": [0, 0, 0]}]},
      {"vertices": [{"x": 1, "y": 1, "depth": 0.5, "rgb": [9, 9, 9]}, {"x": 9, "y": 1, "depth": 0.5, "rgb": [9, 9, 9]},
                    {"x": 1, "y": 9, "depth": 0.5, "rgb": [9, 9, 9]}]}]}]})");
  const CliRun r = run_cli("render z.json --out a.png", dir_);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("polygons      1 (culled 0 back faces, 0 clipped, 1 degenerate"), std::string::npos) << r.output;
  std::filesystem::remove(dir_ + "/a.png");
  expect("render z.json --strict --out a.png", 1, "z.json: objects[0].polygons[0]: polygon has zero area");
}

}  // namespace
