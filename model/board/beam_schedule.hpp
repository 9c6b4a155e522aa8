// The beam schedule of a board top (docs/reference/board.md): when each rendered line is complete
// in the line buffer against the pixel-clock edge at which the video starts showing it.
//
// The ULX3S: clocks from one VCO, in ticks of 1/1260 us, all rising at tick 0: clk_pixel (an edge
// every ticks_per_pixel), clk_pipe (every ticks_per_pipe). The iCEBreaker: one clock, the pixel
// clock, which also runs the pipeline (a tick is its period, no synchronizer: zero stages). The video timing runs from reset: the pixel
// edge video_start + m samples the state (h, v) = (m mod 800, (m div 800) mod 525) of video frame
// m div 420000.
// A flip-flop samples the value from before its edge: an edge coinciding with the sender's
// samples the old value. From that:
//  - frame request k: the toggle flips at the pixel edge of (639, 479) of video frame k; two
//    pipeline flip-flops and the edge detector make the start pulse, high in the clock sampled
//    at the pipeline edge first_edge_after(request) + sync_stages (one clock: a register makes
//    the pulse, sync_stages 0);
//  - frame_player begins at that pulse, or at the clock after the previous frame's last pixel
//    was taken when that is later, and offers the first edge beat start_to_first_beat clocks
//    after it begins; watkins_top then runs as the cycle model clocks it, from idle, with
//    pixel_ready_i = (w - r_sync) < line_slots (signed, line_count_bits);
//  - w counts the lines whose last pixel was taken (edge that takes it); r counts the lines
//    released: pixel edge of h = 639 on video line D y + D - 1 of every video frame after the
//    first request; each count is visible to the other domain from edge
//    first_edge_after(its tick) + count_stages on (two flip-flops and gray_sync's binary register;
//    one clock: count_stages 0, the counts are read where they are kept);
//  - rendered line y of frame k is started (and checked) at the pixel edge of h = 799 on video
//    line D y - 1 of video frame k + 1 (y = 0: v = 524 of video frame k): it is missed unless
//    its completion is visible there.
#pragma once

#include <cstddef>
#include <vector>

#include "config.hpp"
#include "frame.hpp"

namespace watkins::board {

// 640 x 480 at 60 Hz: 800 x 525 pixel clocks per frame.
constexpr int HTotal = 800, VTotal = 525, HVisible = 640, VVisible = 480;
constexpr long long FramePixelClocks = static_cast<long long>(HTotal) * VTotal;

// The boards the beam schedule knows (docs/reference/board.md).
enum class Board { Ulx3s, Icebreaker };

struct BoardTiming {
  int doubling = 2;            // D (1 or 2): rendered line y on video lines D y .. D y + D - 1
  int line_slots = 2;          // S: the line buffer's slots (a power of two)
  int ticks_per_pixel = 50;    // clk_pixel period (25.2 MHz)
  int ticks_per_pipe = 16;     // clk_pipe period (78.75 MHz)
  int sync_stages = 2;         // flip-flops of toggle_sync (the frame request)
  int count_stages = 3;        // gray_sync: two flip-flops and the binary register (the line counts)
  int line_count_bits = 12;    // LineCountBits: the counts compared as signed differences
  // The scene bank's read width: 0, a whole record a read (the ULX3S's block RAM: frame_player
  // offers the records back to back); 64, the iCEBreaker's SPRAMs (spram_frame_player: a record in
  // Parts = ceil(EdgeBits / 64) reads, at the pace CycleOptions::edge_interval = Parts,
  // edge_gap = 2).
  int bank_read_bits = 0;
  // The frame player's clocks from the start pulse to the first edge beat offered; -1: its
  // contract's, 11 + 2^MaterialIdBits of the configuration (frame_player), or 10 +
  // 2^MaterialIdBits + Parts with bank_read_bits (spram_frame_player).
  int start_to_first_beat = -1;
  int frames = 3;              // K rendered frames simulated (at least 3)
  // The pixel edge that samples the video's first state (0, 0): the pixel domain's reset leaves
  // its two-flip-flop synchronizer at edge 2 on the ULX3S top (every video event 2 clocks later);
  // on the iCEBreaker the video starts after the scene's copy from the flash
  // (icebreaker_video_start, flash_image.hpp), which the slack does not depend on.
  int video_start = 2;
  double ticks_per_us = 1260;  // the tick's rate, for reporting the clocks in MHz
};

// A board's timing (its clocks and synchronizers) at the defaults above for the rest: the ULX3S
// is BoardTiming{}; the iCEBreaker runs one 25.125 MHz clock (ticks_per_pixel = ticks_per_pipe =
// 1, sync_stages = count_stages = 0, ticks_per_us 25.125) and reads its bank from the SPRAMs
// (bank_read_bits 64).
BoardTiming board_timing(Board board);

// The first edge of a clock of `period` ticks (rising at tick 0) strictly after tick `tick`:
// where a flip-flop on it first samples a value registered at `tick`.
long long first_edge_after(long long tick, long long period);
// The edge whose clock first reads a value registered at `tick` through `stages` flip-flops.
long long visible_from(long long tick, long long period, int stages);
// r_sync at pipeline edge `edge`: the released lines the pipeline domain reads in the clock that
// edge samples (releases from the first request on, each visible_from its pixel edge's tick).
long long releases_seen(const BoardTiming& t, long long edge);
// frame_player's StartToFirstBeat at a configuration: 11 + 2^MaterialIdBits.
int start_to_first_beat(const Config& cfg);
// spram_frame_player's: 10 + 2^MaterialIdBits + parts, a record in `parts` reads.
int spram_start_to_first_beat(const Config& cfg, int parts);

struct LineSlack {
  int frame = 0, y = 0;
  long long completion = 0;   // pipeline edge that takes the line's last pixel (edge 0 at tick 0)
  long long check = 0;        // pixel edge at which the video starts the line
  long long deadline = 0;     // the last pipeline edge whose completion the check sees
  long long slack = 0;        // deadline - completion, pipeline clocks (negative: missed)
  bool missed = false;
};

struct FrameRun {
  long long request = 0;      // pixel edge of the frame request (the toggle flips)
  long long start_pulse = 0;  // pipeline edge sampling the start pulse
  long long begin = 0;        // pipeline edge frame_player begins (the pulse, or after the last frame left)
  long long first_beat = 0;   // pipeline edge of the first edge beat offered (the cycle model's cycle 0)
  long long last_pixel = 0;   // pipeline edge that takes the frame's last pixel
  long long cycles() const { return last_pixel - first_beat + 1; }
};

struct BeamSchedule {
  BoardTiming timing;         // as run (start_to_first_beat resolved)
  int width = 0, height = 0;  // the rendered frame
  std::vector<FrameRun> frames;
  std::vector<LineSlack> lines;  // frame by frame, y = 0 .. height - 1
  long long missed = 0;
  std::size_t worst = 0;      // index in `lines` of the least slack (the first of equals)
  // Pipeline clocks per rendered line: D video lines.
  double budget_per_line() const;
};

// Runs `timing.frames` rendered frames of `frame` (prepared for `cfg`) on the board from reset.
// Throws std::invalid_argument for a doubling other than 1 or 2, slots not a power of two, fewer
// than 3 frames, a clock period under one tick or a negative synchronizer depth, or a frame that is not 640/D x 480/D (naming the field); CapacityError as the
// cycle model does.
BeamSchedule beam_schedule(const Frame& frame, const Config& cfg, const BoardTiming& timing = {});

}  // namespace watkins::board
