// `watkins render --depth-tie arrival|submission` and the scene's shading.depth_tie: the rule is
// reported, it changes the image of scenes/coplanar.json, the option overrides the scene, and a
// bad value is one line naming the option (exit 2) or the field (exit 1) with no image written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "cli_run.hpp"

namespace {

using watkins::test::CliRun;
using watkins::test::run_cli;

class CliDepthTie : public ::testing::Test, protected watkins::test::ScratchDir {
 protected:
  static int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }
  static std::string coplanar() { return WATKINS_SOURCE_DIR "/scenes/coplanar.json"; }
};

TEST_F(CliDepthTie, RuleIsReportedAndChangesTheImage) {
  const CliRun scene = run_cli("render " + coplanar() + " --out scene.png", dir_);
  ASSERT_EQ(scene.exit_code, 0) << scene.output;
  EXPECT_NE(scene.output.find("depth-tie submission"), std::string::npos) << scene.output;  // the scene's
  const CliRun arr = run_cli("render " + coplanar() + " --depth-tie arrival --out arrival.png", dir_);
  ASSERT_EQ(arr.exit_code, 0) << arr.output;
  EXPECT_NE(arr.output.find("depth-tie arrival"), std::string::npos) << arr.output;
  const CliRun sub = run_cli("render " + coplanar() + " --depth-tie submission --out submission.png", dir_);
  ASSERT_EQ(sub.exit_code, 0) << sub.output;
  EXPECT_EQ(contents("scene.png"), contents("submission.png"));
  EXPECT_NE(contents("arrival.png"), contents("submission.png"));
  // The built-in scene keeps the default rule.
  const CliRun def = run_cli("render --out default.png", dir_);
  ASSERT_EQ(def.exit_code, 0) << def.output;
  EXPECT_NE(def.output.find("depth-tie arrival"), std::string::npos) << def.output;
}

TEST_F(CliDepthTie, BadOptionValueIsOneUsageLine) {
  for (const std::string v : {"bogus", "Submission", "\"\""}) {
    const CliRun r = run_cli("render " + coplanar() + " --depth-tie " + v + " --out a.png", dir_);
    EXPECT_EQ(r.exit_code, 2) << v << "\n" << r.output;
    EXPECT_EQ(lines(r.output), 1) << r.output;
    EXPECT_NE(r.output.find("--depth-tie: unknown rule"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("(arrival, submission)"), std::string::npos) << r.output;
    EXPECT_FALSE(has("a.png")) << v;
  }
  const CliRun missing = run_cli("render " + coplanar() + " --out a.png --depth-tie", dir_);
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_FALSE(has("a.png"));
}

TEST_F(CliDepthTie, BadSceneValueNamesTheField) {
  const std::string path = write("tie.json", R"({"screen": {"width": 8, "height": 8},
    "shading": {"depth_tie": "sideways"}, "objects": []})");
  const CliRun r = run_cli("render " + path + " --out a.png", dir_);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(lines(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("shading.depth_tie: expected \"arrival\" or \"submission\", got \"sideways\""),
            std::string::npos) << r.output;
  EXPECT_FALSE(has("a.png"));
  // The option overrides the scene's value only when the scene is valid: still an error.
  EXPECT_EQ(run_cli("render " + path + " --depth-tie arrival --out a.png", dir_).exit_code, 1);
}

TEST_F(CliDepthTie, HelpDocumentsTheOption) {
  const CliRun r = run_cli("render --help", dir_);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("--depth-tie"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("submission"), std::string::npos) << r.output;
}

}  // namespace
