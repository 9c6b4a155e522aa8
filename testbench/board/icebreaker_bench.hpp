// The iCEBreaker bench: rtl/board/icebreaker_top Verilated (--cc, the PLL, the I/O cells and the
// SPRAMs as the stand-ins of testbench/board/primitives/), each top at the default scene's sized
// configuration, Doubling 2, the scene bank copied from the SPI flash model (spi_flash.hpp) holding
// the options' flash image at SpramBank::FlashAddress: Vicebreaker_top built compact
// (tests/configs/compact_default.gouraud.json: Compact = 1, what the UP5K holds),
// Vicebreaker_top_pipelined (scenes/sized/default.gouraud.json: the pipelined blocks, the same
// board logic around another timing) and, where the build names its configuration,
// Vicebreaker_top_phong (IcebreakerTop::Phong). One clock (docs/reference/board.md, "iCEBreaker"):
// clock m is its m-th rising edge, the first at m = 0; each clock is two eval()s, the rising edge
// and the falling edge (where dvi_clk rises). LOCK is high and the button up from the start. The
// bench records, per clock:
//   - at the Pmod's pins after each rising edge: dvi_de, dvi_hsync, dvi_vsync, and the 12-bit
//     pixel of every visible position (each 4-bit channel c shown as the 8-bit level c << 4), and
//     dvi_clk after both edges (low after the rising edge, high after the falling one);
//   - the values each rising edge samples: the start pulses, the frame player's begins, every
//     line's last pixel taken and every line the deadline check finds missed.
// The records are the ULX3S bench's (board_bench.hpp: BoardRun), with one clock for both of its
// domains (pixel_clocks = pipe_clocks).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "board_bench.hpp"

class VerilatedContext;

namespace watkins::board_tb {

// Phong: icebreaker_top with Phong = 1 at the configuration file the build names
// (WATKINS_BOARD_ICEBREAKER_PHONG_CONFIG, testbench/board/CMakeLists.txt; its "compact" says
// which blocks), Vicebreaker_top_phong; a build that names none has no such top (top_built).
enum class IcebreakerTop { Compact, Pipelined, Phong };

struct IcebreakerOptions {
  std::vector<std::uint8_t> flash;  // the flash's bytes from SpramBank::FlashAddress on (flash_image)
  int video_frames = 3;             // video frames from the first visible pixel on the pins
  bool record_video = true;         // keep BoardRun::video (false: the frames and the records only)
  // Called after the last clock of each captured video frame (run.frames.back()), as
  // BoardOptions::on_frame.
  std::function<void(BoardRun&)> on_frame;
};

struct IcebreakerRun {
  BoardRun run;             // video, frames, requests, starts, begins, lines, missed (clocks as above)
  long long dvi_clk_bad = 0;  // clocks whose dvi_clk was not low after the rising edge and high after the falling
  long long flash_bits = 0;   // bits the flash put out
  long long flash_bad_commands = 0;  // commands other than Read Data and Release Power-down
};

// Whether this build has the top (Compact and Pipelined always; Phong when the build names its
// configuration).
bool top_built(IcebreakerTop top);
// The configuration file, shading, Doubling and BankWords the top was built with
// (std::logic_error for a top not built).
TopBuild top_build(IcebreakerTop top);

class IcebreakerBench {
 public:
  explicit IcebreakerBench(IcebreakerTop top = IcebreakerTop::Compact);
  ~IcebreakerBench();
  // A fresh model from reset for every run.
  IcebreakerRun run(const IcebreakerOptions& options);

 private:
  IcebreakerTop top_;
  std::unique_ptr<VerilatedContext> context_;
};

}  // namespace watkins::board_tb
