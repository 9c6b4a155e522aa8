// `watkins render --config F`: a narrower configuration renders and says so; a bad file or a
// configuration too narrow for the scene is one clear line, exit code 1, no image.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <string>

#include "cli_run.hpp"

namespace {

using watkins::test::CliRun;
CliRun run(const std::string& args) { return watkins::test::run_cli(args); }

class CliConfig : public ::testing::Test, protected watkins::test::ScratchDir {
 protected:
  bool exists(const std::string& path) {
    struct stat st;
    return stat(path.c_str(), &st) == 0;
  }
};

TEST_F(CliConfig, NarrowConfigurationRenders) {
  const std::string cfg = write("narrow.json", R"({"x": {"int_bits": 11, "frac_bits": 8}, "shade": {"int_bits": 9, "frac_bits": 8}})");
  const std::string png = dir_ + "/out.png";
  const CliRun r = run("render " WATKINS_SOURCE_DIR "/scenes/sphere.json --config " + cfg + " --out " + png);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("config        " + cfg + ": x 11.8"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("edge records  590 (270 bits each)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("group shade  values need 17 bits: int 9 of 9, frac 8"), std::string::npos) << r.output;
  EXPECT_TRUE(exists(png));
}

TEST_F(CliConfig, BadFileIsOneLineNamingTheField) {
  const std::string cfg = write("bad.json", R"({"shade": {"frac_bits": 2.5}})");
  const std::string png = dir_ + "/out.png";
  const CliRun r = run("render --config " + cfg + " --out " + png);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.output, "watkins: error: " + cfg + ": shade.frac_bits: expected an integer, got 2.5\n");
  EXPECT_FALSE(exists(png));
}

TEST_F(CliConfig, TooNarrowForTheSceneIsRefused) {
  const std::string cfg = write("narrow.json", R"({"depth": {"int_bits": 20}})");
  const std::string png = dir_ + "/out.png";
  const CliRun r = run("render " WATKINS_SOURCE_DIR "/scenes/sphere.json --config " + cfg + " --out " + png);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("edge values of channel Z need 41 signed bits; the configuration's depth word is 36 "
                          "(depth.int_bits 20, needs 25)"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(exists(png));
}

// A scene that smooths on a configuration without the smoother ("smoothing": false): one line
// naming the field, exit code 1, no image; on the model and on the RTL (scenes/sized/default.gouraud.json
// has no smoother: the default scene never smooths), whether or not this build has that top (the
// RTL case is left out in a build without the RTL).
TEST_F(CliConfig, SmoothingOnAConfigurationWithoutTheSmootherIsRefused) {
  const std::string cfg = write("nosmooth.json", R"({"smoothing": false})");
  const std::string sized = WATKINS_SOURCE_DIR "/scenes/sized/default.gouraud.json";
  const std::string png = dir_ + "/out.png";
  const std::string line = ": smoothing: the scene smooths (W = 102/128, shading.smooth or --smooth); the configuration "
                           "has smoothing false (no smoother)\n";
  for (const std::string& args :
       {"render " WATKINS_SOURCE_DIR "/scenes/cone.json --smooth 0.8 --config " + cfg + " --out " + png,
        "render --shading gouraud --smooth 0.8 --rtl --config " + sized + " --out " + png}) {
    SCOPED_TRACE(args);
    const CliRun r = run(args);
    if (r.output.find("this build has no RTL simulation") != std::string::npos) continue;  // model-only build
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_EQ(r.output.rfind("watkins: error: ", 0), 0u) << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << "one line: " << r.output;
    EXPECT_NE(r.output.find(line), std::string::npos) << r.output;
    EXPECT_FALSE(exists(png));
  }
  // Without --smooth the same configuration renders.
  const CliRun ok = run("render " WATKINS_SOURCE_DIR "/scenes/cone.json --config " + cfg + " --out " + png);
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_TRUE(exists(png));
}

// A configuration no Verilated top was built for (WATKINS_RTL_CONFIGS) is refused in one line.
TEST_F(CliConfig, RtlRefusesAConfigurationWithoutATop) {
  const std::string cfg = write("narrow.json", R"({"shade": {"frac_bits": 8}})");
  const CliRun r = run("render --rtl --config " + cfg + " --out " + dir_ + "/out.png");
  EXPECT_EQ(r.exit_code, 2) << r.output;  // a usage error (README: exit codes)
  // Either this build has no RTL, or none built for this configuration.
  EXPECT_TRUE(r.output.find("--rtl --config " + cfg + ": no Verilated watkins_top for this configuration") !=
                  std::string::npos ||
              r.output.find("--rtl: this build has no RTL simulation") != std::string::npos)
      << r.output;
}

}  // namespace
