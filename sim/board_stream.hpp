// watkins board stream: frames of an animation sent to the board's host link
// (docs/reference/board.md, "Host link"). Every frame -- each scene given, or the first turned
// on a turntable -- is prepared at the board's configuration (the first scene's sized one, or
// --config: the one the bitstream was built with), checked against the bank (BankWords words, as
// `board build` sizes it from the first scene, or --bank-words) and the beam deadline, and packed
// (model/board/frame_packet.hpp) before anything is sent; a frame that does not fit is refused
// with one line naming it. Every frame is shaded as the bitstream was built: --shading, or the
// first scene's shading.mode, which the others must share. A serial port (a tty) is set raw 8N1
// at 3,000,000 baud and the frames are written at --fps, once or --loop'ed; any other file (a
// regular file, a FIFO) gets the packets once, back to back, all or nothing.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace watkins::board_command {

struct StreamArgs {
  std::vector<std::string> scenes;  // scene files; the first sets the size and the sized configuration
  std::string port;                 // a serial port (tty) or a file
  std::string config;               // the bitstream's configuration instead of sizing the first scene
  int turntable = 0;                // N > 0: N frames of the (single) scene, 360/N degrees apart
  double fps = 30;                  // frames a second on a serial port
  bool loop = false;                // repeat the frames until interrupted (a serial port only)
  int bank_words = 0;               // the board's BankWords; 0: as `board build` sizes the first scene's
  int slots = 2;                    // the line buffer's slots (the beam check)
  std::string shading;              // "gouraud" or "phong" for every frame; empty: each scene's shading.mode
};

// Registers `stream` under the `board` subcommand; returns it.
CLI::App* add_stream_command(CLI::App* board, StreamArgs& args);
// Prepares, checks and sends the frames; returns the exit code. Bad input throws (one line).
int run_stream(const StreamArgs& args);

}  // namespace watkins::board_command
