// The board bench: rtl/board/ulx3s_top Verilated (--cc, the PLL and the DDR outputs as the
// stand-ins of testbench/board/primitives/), clocked on the board's time base
// (docs/reference/board.md, "Clocks": one tick = 1/1260 us; clk_tmds toggles every 5 ticks,
// clk_pixel every 25, clk_pipe every 8, all rising at tick 0; edges that coincide are one
// eval()). The bench drives the stand-in PLL's outputs through its public variables, LOCK high
// and btn[0] up from tick 0, and records, per clock:
//   - at the TMDS encoders' inputs (after each pixel-clock edge): de, hsync, vsync, and the pixel
//     of every visible position, so the video timing and the frames can be checked;
//   - in the pipeline domain (the values each rising edge samples): the start pulses and every
//     line's last pixel taken, so each rendered line's completion is known in pipeline clocks
//     from its frame's start pulse;
//   - in the pixel domain: every line the deadline check finds missed.
// Pipeline clock n is the rising edge of clk_pipe at tick 16 n; pixel clock m the rising edge of
// clk_pixel at tick 50 m.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "image.hpp"
#include "shading_mode.hpp"

class VerilatedContext;

namespace watkins::board_tb {

constexpr int VideoWidth = 640, VideoHeight = 480;
constexpr int LineClocks = 800, FrameLines = 525;
constexpr long long FrameClocks = static_cast<long long>(LineClocks) * FrameLines;  // pixel clocks

struct BoardRun;

struct BoardOptions {
  std::string bank_file;     // +watkins_bank=FILE (empty: the BankFile the top was built with)
  int video_frames = 3;      // video frames from the first visible pixel after reset
  bool tmds_clock = true;    // toggle clk_tmds (false: hold it low; the serializers idle)
  // The FT231X's transmit line (ftdi_txd) at a time in seconds from tick 0, set before every
  // eval() (e.g. UartLine::level, uart_line.hpp); empty: held high (idle).
  std::function<bool(double)> ftdi_txd;
  bool record_video = true;  // keep BoardRun::video (false: the frames and the records only)
  // Called after the last pixel clock of each captured video frame (frames.back()), with the
  // records, the clocks, the evals, missed_count and wall_seconds so far; it may release the
  // frames it has read and clear the records (the run only appends to them).
  std::function<void(BoardRun&)> on_frame;
};

// A pixel clock's signals at the encoders' inputs.
struct VideoSample {
  bool de = false, hsync_n = true, vsync_n = true;
};

struct LineDone {
  long long line = 0;         // global rendered-line number (w before the increment)
  long long pipe_clock = 0;   // the clk_pipe edge that takes its last pixel
  long long from_start = -1;  // pipe_clock minus its frame's start pulse clock (-1: no start yet)
};

struct MissedLine {
  long long line = 0;          // global rendered-line number (s before the increment)
  long long pixel_clock = 0;   // the clk_pixel edge that starts it
};

struct BoardRun {
  // The encoders' inputs of every pixel clock after reset, from the first visible pixel on.
  std::vector<VideoSample> video;
  long long first_visible = -1;      // pixel clock at which `video` starts
  std::vector<Image> frames;         // the 640 x 480 visible pixels of each captured video frame
  std::vector<long long> start_clocks;  // pipe clock of each start pulse
  std::vector<long long> begin_clocks;  // pipe clock at which the frame player begins each frame
  std::vector<long long> request_pixel_clocks;  // pixel clock of each frame request
  std::vector<LineDone> lines;
  std::vector<MissedLine> missed;
  int missed_count = 0;  // the RTL's counter at the end
  int link_frames = 0, link_errors = 0;  // the host link's good and dropped packets at the end
  std::vector<int> begin_banks;          // the bank each begun frame reads (after the begin's edge)
  bool overflow = false;
  long long pixel_clocks = 0, pipe_clocks = 0, evals = 0;
  double wall_seconds = 0;
};

// The three Verilated board tops (testbench/board/CMakeLists.txt): the default scene's sized
// configuration doubled (Vulx3s_top: Doubling 2, bank 0 from the build's default_bank.mem); a
// 640 x 480 native configuration (Vulx3s_top_native: tests/board/native.gouraud.json, Doubling
// 1, bank 0 from +watkins_bank only); the default scene's sized Phong configuration doubled
// (Vulx3s_top_phong: scenes/sized/default.phong.json, Phong = 1, Doubling 2, bank 0 from
// +watkins_bank only).
enum class BoardTop { Default, Native, Phong };

// What a Verilated top was built for: the configuration file its -G list came from (its path in
// the source tree), the shading its Phong parameter draws, its Doubling and its BankWords.
struct TopBuild {
  std::string config;
  ShadingMode shading = ShadingMode::Gouraud;
  int doubling = 2;
  int bank_words = 512;
};
TopBuild top_build(BoardTop top);

class BoardBench {
 public:
  explicit BoardBench(BoardTop top = BoardTop::Default);
  ~BoardBench();
  // A fresh model from reset for every run.
  BoardRun run(const BoardOptions& options);

 private:
  BoardTop top_;
  std::unique_ptr<VerilatedContext> context_;
};

// The expected encoder inputs of position k of the 800 x 525 raster (k = v * 800 + h).
VideoSample expected_video(long long k);

// The frame as the video shows it: each pixel repeated `doubling` times across and down.
Image doubled(const Image& frame, int doubling);

}  // namespace watkins::board_tb
