// `watkins board check` as users run it: the default scene's report and exit 0, a native scene
// too heavy for the beam named line by line with exit 4, either micro-architecture on either
// board, --shading on every board subcommand, and sizes and options refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cli_run.hpp"

using namespace watkins::test;

namespace {

// `layers` quads over the whole 640 x 480 screen, stacked: layers x 640 fragments a line.
std::string stacked_scene(int layers) {
  std::string polys;
  for (int i = 0; i < layers; ++i) {
    const std::string z = std::to_string(0.2 + 0.1 * i), c = std::to_string(40 * i);
    polys += std::string(i ? "," : "") + "{\"vertices\": [" + "{\"x\": 0, \"y\": 0, \"depth\": " + z + ", \"rgb\": [" + c +
             ", 90, 30]}, {\"x\": 640, \"y\": 0, \"depth\": " + z + ", \"rgb\": [" + c +
             ", 90, 30]}, {\"x\": 640, \"y\": 480, \"depth\": " + z + ", \"rgb\": [" + c +
             ", 90, 30]}, {\"x\": 0, \"y\": 480, \"depth\": " + z + ", \"rgb\": [" + c + ", 90, 30]}]}";
  }
  return "{\"screen\": {\"width\": 640, \"height\": 480, \"background\": [0, 0, 0]}, \"objects\": [{\"type\": "
         "\"polygons\", \"polygons\": [" + polys + "]}]}";
}

TEST(CliBoard, DefaultSceneMakesEveryLine) {
  const CliRun r = run_cli("board check " WATKINS_SOURCE_DIR "/scenes/default.json --board ulx3s");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("clk_pipe 78.75 MHz (25/8 of clk_pixel)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("doubling 2, 2 line slots"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("budget        5000 pipeline clocks per rendered line"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("worst line    frame "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("missed        0 lines"), std::string::npos) << r.output;
}

TEST(CliBoard, HeavyNativeSceneMissesWithExitFour) {
  ScratchDir dir;
  const std::string heavy = dir.write("stacked.json", stacked_scene(5));
  const CliRun r = run_cli("board check " + heavy);
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("doubling 1"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("budget        2500 pipeline clocks"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("missed        "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(" lines: frame 0 line "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("slack -"), std::string::npos) << r.output;
}

// The frame alone: the same fragments on both tops; the pipelined top's cycles are the pixel
// read-out's H(W + 1) + 6 when no line is fragment-bound, the compact top's at least its own
// empty frame's H(W + 1) + 10.
TEST(CliBoard, EitherTopOnEitherBoard) {
  const std::string scene = WATKINS_SOURCE_DIR "/scenes/default.json";
  CliRun r = run_cli("board check " + scene + " --board icebreaker --top pipelined");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("pipelined top, edge record 184 bits"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("alone         76846 cycles a frame, 15845 fragments (0.206 per clock)"), std::string::npos)
      << r.output;
  r = run_cli("board check " + scene + " --board ulx3s --top compact");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("compact top, edge record 184 bits"), std::string::npos) << r.output;
  const std::size_t at = r.output.find("alone         ");
  ASSERT_NE(at, std::string::npos) << r.output;
  const long long cycles = std::stoll(r.output.substr(at + 14));
  EXPECT_GE(cycles, 240LL * 321 + 10) << r.output;
  EXPECT_NE(r.output.find(" cycles a frame, 15845 fragments ("), std::string::npos) << r.output;
  r = run_cli("board check " + scene + " --board icebreaker");
  EXPECT_NE(r.output.find("compact top"), std::string::npos) << r.output;
  // The compact top has no smoother: a configuration that smooths is refused for it, by name.
  r = run_cli("board check " + scene + " --config " WATKINS_SOURCE_DIR
              "/scenes/sized/voxel_smoothed_64.gouraud.json --top compact");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("the compact top has no smoother"), std::string::npos) << r.output;
}

// overdraw (2,548 fragments a line) on the iCEBreaker: one lane misses lines, so the sized
// compact configuration takes two and meets every line; a --config file says for itself.
TEST(CliBoard, OverdrawTakesTwoLanesOnTheIcebreaker) {
  const std::string scene = WATKINS_SOURCE_DIR "/scenes/overdraw.json";
  CliRun r = run_cli("board check " + scene + " --board icebreaker");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("compact top (2 fragment lanes), edge record"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("missed        0 lines"), std::string::npos) << r.output;
  ScratchDir dir;
  const std::string one = dir.write("one.json", "{\"smoothing\": false, \"compact\": true, \"max_width\": 320}");
  r = run_cli("board check " + scene + " --board icebreaker --config " + one);
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("compact top, edge record"), std::string::npos) << r.output;
  // The default scene needs one lane.
  r = run_cli("board check " WATKINS_SOURCE_DIR "/scenes/default.json --board icebreaker");
  EXPECT_NE(r.output.find("compact top, edge record"), std::string::npos) << r.output;
}

// --shading on the board subcommands: the default scene shaded by Phong is sized, banked, timed
// and packed as Phong (190-bit edge records, the material table); on the iCEBreaker's compact top
// the scene is sized as `watkins size --compact` sizes it (the narrow Phong formats) and the
// deadline proven by the compact cycle model where that model times Phong frames, refused in one
// line naming why where it does not. A name that is no pipeline is one line, exit
// 2, and no file written, on every subcommand.
TEST(CliBoard, ShadingOnEverySubcommand) {
  ScratchDir dir;
  const std::string probe = dir.write("probe", "");
  const std::string here = probe.substr(0, probe.rfind('/'));
  const std::string scene = WATKINS_SOURCE_DIR "/scenes/default.json";
  CliRun r = run_cli("board check " + scene + " --shading phong");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("shading phong, 79 polygons"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("pipelined top, edge record 190 bits"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("no smoother, the model's Phong formats"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("missed        0 lines"), std::string::npos) << r.output;
  r = run_cli("board image " + scene + " --shading phong -o phong.hex", here);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("words of 190 bits (278 edge records, 2 materials)"), std::string::npos) << r.output;
  r = run_cli("board stream " + scene + " --shading phong --port packets.bin", here);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("edge record 190 bits"), std::string::npos) << r.output;
  EXPECT_TRUE(dir.has("packets.bin"));
  r = run_cli("board check " + scene + " --shading phong --board icebreaker");
  if (r.exit_code == 1) {
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_NE(r.output.find("shading phong on the icebreaker board's compact top: no line deadline can be proven"),
              std::string::npos)
        << r.output;
  } else {
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("shading phong, 79 polygons"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("compact top"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("narrow Phong formats"), std::string::npos) << r.output;  // as `size --compact`
  }
  for (const char* sub : {"check", "image -o bad.out", "build -o bad.out --work bad.work", "stream --port bad.out",
                          "sim --out bad.out"}) {
    r = run_cli("board " + std::string(sub) + " " + scene + " --shading flat", here);
    EXPECT_EQ(r.exit_code, 2) << sub << ": " << r.output;
    EXPECT_EQ(r.output, "watkins: usage: --shading: unknown shading mode \"flat\" (gouraud, phong)\n") << sub;
    EXPECT_FALSE(dir.has("bad.out")) << sub;
    EXPECT_FALSE(dir.has("bad.work")) << sub;
  }
}

TEST(CliBoard, RefusesOtherSizesAndOptions) {
  ScratchDir dir;
  const std::string scene = WATKINS_SOURCE_DIR "/scenes/default.json";
  CliRun r = run_cli("board check " + scene + " --doubling 1");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("screen.width 320"), std::string::npos) << r.output;
  const std::string odd = dir.write("odd.json", "{\"screen\": {\"width\": 320, \"height\": 200}, \"objects\": []}");
  r = run_cli("board check " + odd);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("screen.height 200"), std::string::npos) << r.output;
  for (const char* bad : {"--slots 3", "--slots 0", "--doubling 3", "--board icestick", "--top tiny"}) {
    r = run_cli("board check " + scene + " " + bad);
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.output;
    EXPECT_NE(r.output.find(std::string(bad).substr(0, std::string(bad).find(' '))), std::string::npos) << r.output;
  }
  r = run_cli("board");
  EXPECT_EQ(r.exit_code, 2) << r.output;
}

}  // namespace
