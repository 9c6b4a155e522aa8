// watkins board sim: the virtual board. The Verilated board top built for the shading (the
// scene's shading.mode or --shading; testbench/board/: ulx3s_top, Gouraud or Phong; icebreaker_top,
// Gouraud compact or pipelined, or Phong where the build has it) runs the scene from reset on the
// board's clocks, the ULX3S's bank 0 loaded with the scene's bank image, the iCEBreaker's copied
// from its SPI flash model; every video frame is captured from the pins and written as it is
// drawn, DIR/frame_NNN.png (640 x 480 as shown; NNN the rendered frame, the first video frame
// shows none), with one report line per frame: the lines the deadline check finds missed, whether
// the frame equals the model's image as the board shows it (on the iCEBreaker, the Pmod's 12-bit
// levels), the simulated clocks and the wall time. The scene must fit the configuration the top
// was built for (the default scene's sized one at that shading; refused in one line naming what
// does not fit). There is no window: the frames are PNG files. The tops exist only in a build
// with the RTL and the tests (WATKINS_RTL and WATKINS_TESTS); elsewhere the subcommand says so.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace watkins::board_command {

// Exit code when a frame differs from the model's image with no line missed (an RTL bug).
constexpr int SimMismatchExit = 3;

struct SimArgs {
  std::string scene;           // scene file; the embedded default scene when empty
  std::string board = "ulx3s";
  std::string top;             // icebreaker: "compact" (default) or "pipelined"; ulx3s: pipelined only
  std::string shading;         // "gouraud" or "phong": the top built for it; empty: the scene's shading.mode
  int frames = 2;              // rendered frames to show
  std::string out = "board-sim";  // the folder of the PNG frames
};

// Registers `sim` under the `board` subcommand; returns it.
CLI::App* add_sim_command(CLI::App* board, SimArgs& args);
// Runs the virtual board; returns the exit code (0; MissedExit when a line misses its deadline;
// SimMismatchExit when a frame differs from the model otherwise). Bad input throws (one line).
int run_sim(const SimArgs& args);

}  // namespace watkins::board_command
