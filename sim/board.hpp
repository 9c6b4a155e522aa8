// watkins board: the pipeline on an FPGA board racing the beam (docs/reference/board.md).
// `board check` sizes a scene, prepares its frame and runs the board's beam schedule
// (model/board/beam_schedule.hpp): the worst line's slack and the lines that miss their deadline.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace watkins::board_command {

// Exit code of `board check` when a line misses its deadline (docs/guide/cli.md).
constexpr int MissedExit = 4;

struct CheckArgs {
  std::string scene;          // scene file; the embedded default scene when empty
  std::string board = "ulx3s";
  int doubling = 0;           // 1 or 2; 0: from the scene's size (320x240: 2, 640x480: 1)
  int slots = 2;              // the line buffer's slots
  std::string config;         // a configuration file instead of sizing the scene (`watkins size`, bound 1)
};

struct BoardArgs {
  CheckArgs check;
  CLI::App* board_app = nullptr;
  CLI::App* check_app = nullptr;
};

// Registers `watkins board` and its subcommands on `app`; returns the `board` subcommand.
CLI::App* add_board_command(CLI::App& app, BoardArgs& args);
// The checks of the command line that need no file: UsageError (exit code 2) naming the option.
void check_board(const BoardArgs& args);
// Runs the subcommand given; returns the exit code. Bad input throws (one line).
int run_board(const BoardArgs& args);

}  // namespace watkins::board_command
