// watkins board: the pipeline on an FPGA board racing the beam (docs/reference/board.md).
// `board check` sizes a scene, prepares its frame and runs the board's beam schedule
// (model/board/beam_schedule.hpp): the worst line's slack and the lines that miss their deadline.
// Every subcommand takes --shading gouraud|phong (the scene's shading.mode when not given): the
// pipeline the frame is prepared, sized, timed and built for.
// `board image` writes the frame's scene bank; `board build` checks the deadline, then builds the
// bitstream through the shared FPGA flow (board_build.hpp) and reports resources and clocks;
// `board stream` sends frames to the board's host link (board_stream.hpp); `board sim` runs the
// Verilated board top on a scene, frame by frame (board_sim.hpp).
#pragma once

#include <string>

#include "board_sim.hpp"
#include "board_stream.hpp"

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
  std::string top;            // "compact" or "pipelined"; empty: the board's (icebreaker: compact,
                              // ulx3s: pipelined; a --config file: its own "compact")
  std::string shading;        // "gouraud" or "phong"; empty: the scene's shading.mode
};

// `board image`: the scene bank's $readmemh file, as the board build initializes bank 0.
struct ImageArgs {
  CheckArgs target;           // the scene and the board it is prepared for
  std::string out;            // the $readmemh file; default <scene stem>.bank.hex
  int bank_words = 0;         // 0: the smallest power of two (at least 512) that holds the frame
};

// `board build`: size, check the deadline, the bank image, yosys, nextpnr, ecppack (ulx3s) or
// icepack (icebreaker), report.
struct BuildArgs {
  CheckArgs target;
  std::string work = "board-build";  // yosys's and nextpnr's folder (scripts, netlist, logs, reports)
  std::string out;                   // the bitstream; default <scene stem>.<board>.bit (.bin: icebreaker)
  std::string md;                    // the report as markdown (none when empty)
  std::string rtl_dir;               // default: the source tree's rtl/
  int seed = 0;                      // nextpnr --seed; 0: none
  int timeout = 3600;                // seconds per tool
};

struct BoardArgs {
  CheckArgs check;
  ImageArgs image;
  BuildArgs build;
  StreamArgs stream;  // `board stream` (board_stream.hpp)
  SimArgs sim;        // `board sim` (board_sim.hpp)
  CLI::App* board_app = nullptr;
  CLI::App* check_app = nullptr;
  CLI::App* image_app = nullptr;
  CLI::App* build_app = nullptr;
  CLI::App* stream_app = nullptr;
  CLI::App* sim_app = nullptr;
};

// Registers `watkins board` and its subcommands on `app`; returns the `board` subcommand.
CLI::App* add_board_command(CLI::App& app, BoardArgs& args);
// The checks of the command line that need no file: UsageError (exit code 2) naming the option.
void check_board(const BoardArgs& args);
// Runs the subcommand given; returns the exit code. Bad input throws (one line).
int run_board(const BoardArgs& args);

}  // namespace watkins::board_command
