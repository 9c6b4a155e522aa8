// `watkins synth` refuses bad input before it runs any tool: one line naming the option and the
// value (and the names it accepts), exit code 2 for a wrong option value (usage), 1 for a bad
// configuration file, no work folder. (The place-and-route itself is
// the ctests synth_smoke and synth_seeds, label synth: tests/synth/smoke.py and seeds.py.)
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_run.hpp"

namespace {

class CliSynth : public ::testing::Test, protected watkins::test::ScratchDir {
 protected:
  // code 2: a wrong option value ("watkins: usage: "); 1: a bad file ("watkins: error: ").
  void expect_refused(const std::string& args, const std::string& message, int code = 2) {
    const std::string work = dir_ + "/work";
    const watkins::test::CliRun r = watkins::test::run_cli("synth " + args + " --work " + work);
    EXPECT_EQ(r.exit_code, code) << r.output;
    EXPECT_NE(r.output.find((code == 2 ? "watkins: usage: " : "watkins: error: ") + message), std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << "expected one line:\n" << r.output;
    EXPECT_FALSE(std::filesystem::exists(work)) << "nothing may run for bad input";
  }
};

TEST_F(CliSynth, UnknownDesignListsTheDesigns) {
  expect_refused("--designs edge_incrementer,nope", "--designs: unknown design \"nope\" (edge_incrementer, ");
}

TEST_F(CliSynth, UnknownTargetListsTheTargets) {
  expect_refused("--targets ice40-lp1k", "--targets: unknown target \"ice40-lp1k\" (ice40-up5k, ice40-hx8k, ecp5-85)");
}

TEST_F(CliSynth, MissingConfigurationFile) {
  expect_refused("--config " + dir_ + "/nope.json", dir_ + "/nope.json: cannot open configuration file", 1);
}

TEST_F(CliSynth, InvalidConfigurationNamesTheField) {
  const std::string cfg = write("narrow.json", R"({"max_width": 0})");
  expect_refused("--config " + cfg, "", 1);
  const watkins::test::CliRun r = watkins::test::run_cli("synth --config " + cfg + " --work " + dir_ + "/w");
  EXPECT_NE(r.output.find("max_width"), std::string::npos) << r.output;
}

TEST_F(CliSynth, EmptyListItemsAreRefused) {
  expect_refused("--designs edge_incrementer,,segment_former", "--designs: empty item in \"edge_incrementer,,segment_former\"");
  expect_refused("--targets ecp5-85,", "--targets: empty item in \"ecp5-85,\"");
  expect_refused("--config ,default", "--config: empty item in \",default\"");
}

TEST_F(CliSynth, JobsMustBePositive) {
  expect_refused("--jobs 0", "--jobs: expected an integer in [1, 256], got \"0\"");
  expect_refused("--timeout 0", "--timeout: expected an integer in [1, 1073741824], got \"0\"");
}

// nextpnr's --seed is an int: 1 .. 2^31 - 1, each once (a repeated seed would be the same run).
TEST_F(CliSynth, SeedsMustBePositiveDistinctIntegers) {
  const std::string range = " is not a seed (a decimal integer from 1 to 2147483647)";
  expect_refused("--seeds 0", "--seeds: \"0\"" + range);
  expect_refused("--seeds x", "--seeds: \"x\"" + range);
  expect_refused("--seeds 1,2147483648", "--seeds: \"2147483648\"" + range);
  expect_refused("--seeds 1,,2", "--seeds: empty item in \"1,,2\"");
  expect_refused("--seeds 3,3", "--seeds: seed 3 given twice");
}

}  // namespace
