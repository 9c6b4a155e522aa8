// The iCEBreaker board top on its Verilated bench (testbench/board/icebreaker_bench.hpp), built
// compact (tests/configs/compact_default.gouraud.json, what the UP5K holds) and pipelined
// (scenes/sized/default.gouraud.json: the same board logic around another timing), and with
// Phong = 1 where the build names its configuration (its frames the model's Phong image): the
// default scene at the sized configuration, 320 x 240 doubled to 640 x 480 at 60 Hz on the 12-bit DVI Pmod,
// one 25.125 MHz clock, the scene copied into the SPRAMs from the SPI flash model holding the bank
// as `watkins board build` writes it (the whole bank read, no other command). Two video frames after the
// first request equal the model's image, each 8-bit level truncated to its top four bits as the
// Pmod shows it, bit for bit, and each other; the pins follow the 800 x 525 timing on every clock
// and dvi_clk is the clock inverted; no line misses its deadline. A scene built to miss
// (tests/board/miss_doubled.json) shows missed lines, the same ones every frame, and the model's
// pixels on every other line. Every run equals the beam schedule of the iCEBreaker's timing
// (board::board_timing(Board::Icebreaker): the cycle model of the top as built, the records at
// the SPRAM frame player's pace, the video from the clock after the flash's copy) line for line:
// requests, start pulses, begins, every line's completion clock and the missed lines.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "beam_schedule.hpp"
#include "board_image.hpp"
#include "config_file.hpp"
#include "flash_image.hpp"
#include "icebreaker_bench.hpp"
#include "prepare.hpp"
#include "scene.hpp"
#include "watkins_top.hpp"

namespace watkins::board_tb {
namespace {

constexpr int Doubling = 2;
constexpr int BankWords = WATKINS_ICEBREAKER_BANK_WORDS;
constexpr int LineSlots = 2;
// The pins show the video state of clock m - PinLatency - video_start after rising edge m: the
// state's Pmod register, then the I/O cell's output register.
constexpr long long PinLatency = 1;

struct Scene {
  PreparedScene frame;
  Image model;  // as the Pmod shows it: each 8-bit level's top four bits
};

// The scene shaded as the top was built (its configuration and its Phong parameter).
Scene prepare_scene(const std::string& path, IcebreakerTop top) {
  const TopBuild built = top_build(top);
  const Config config = load_config(built.config);
  BuildOptions opt;
  opt.shading = built.shading;
  Scene s;
  s.frame = prepare(load_scene(path, opt), config);
  s.model = board::pmod_levels(WatkinsTop(config).render(s.frame));
  return s;
}

// The flash's bytes at the scene's address: the bank, as `watkins board build` writes it.
std::vector<std::uint8_t> flash_of(const Scene& s) {
  return board::flash_image(board::bank_image(s.frame, s.frame.config, BankWords), BankWords);
}

int parts_of(const Scene& s) { return board::spram_parts(s.frame.config.edge_record_bits(s.frame.shading)); }

board::BeamSchedule schedule(const Scene& s) {
  board::BoardTiming t = board::board_timing(board::Board::Icebreaker);
  t.doubling = Doubling;
  t.line_slots = LineSlots;
  t.video_start = board::icebreaker_video_start(BankWords, parts_of(s));
  return board::beam_schedule(s.frame, s.frame.config, t);
}

// Requests, start pulses and begins of the first two frames, every line the RTL completed in
// them, and the missed lines among them but the last LineSlots (their checks may come after the
// run), against the beam schedule.
void expect_model_schedule(const BoardRun& r, const board::BeamSchedule& b) {
  for (int f = 0; f < 2; ++f) {
    EXPECT_EQ(r.request_pixel_clocks.at(f), b.frames[f].request) << "request " << f;
    EXPECT_EQ(r.start_clocks.at(f), b.frames[f].start_pulse) << "start pulse " << f;
    EXPECT_EQ(r.begin_clocks.at(f), b.frames[f].begin) << "begin " << f;
  }
  const std::size_t lines = std::min(r.lines.size(), std::size_t(2) * b.height);
  ASSERT_GE(lines, std::size_t(b.height)) << "not one frame done";
  long long differ = 0;
  for (std::size_t i = 0; i < lines; ++i) {
    EXPECT_EQ(r.lines[i].line, static_cast<long long>(i));
    if (r.lines[i].pipe_clock != b.lines[i].completion && differ++ == 0)
      ADD_FAILURE() << "line " << i << " done at clock " << r.lines[i].pipe_clock << ", the model's "
                    << b.lines[i].completion;
  }
  EXPECT_EQ(differ, 0);
  const long long checked = static_cast<long long>(lines) - LineSlots;
  std::set<long long> rtl_missed, model_missed;
  for (long long i = 0; i < checked; ++i)
    if (b.lines[static_cast<std::size_t>(i)].missed) model_missed.insert(i);
  for (const MissedLine& m : r.missed)
    if (m.line < checked) rtl_missed.insert(m.line);
  EXPECT_EQ(rtl_missed, model_missed) << "missed lines: RTL " << rtl_missed.size() << ", model " << model_missed.size();
}

long long timing_mismatches(const BoardRun& r) {
  long long bad = 0;
  for (std::size_t k = 0; k < r.video.size(); ++k) {
    const VideoSample want = expected_video(static_cast<long long>(k)), got = r.video[k];
    if (want.de != got.de || want.hsync_n != got.hsync_n || want.vsync_n != got.vsync_n) {
      if (bad++ == 0)
        ADD_FAILURE() << "video timing: clock " << k << " (h " << k % LineClocks << ", v "
                      << (k / LineClocks) % FrameLines << "): de/hsync/vsync " << got.de << got.hsync_n << got.vsync_n
                      << ", want " << want.de << want.hsync_n << want.vsync_n;
    }
  }
  return bad;
}

long long pixel_mismatches(const Image& got, const Image& want) {
  long long bad = 0;
  for (std::size_t i = 0; i < want.rgb.size(); ++i) bad += got.rgb[i] != want.rgb[i];
  return bad;
}

std::string summary(const BoardRun& r) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%lld clocks, %lld evals in %.2f s (%.0f clocks/s)", r.pixel_clocks, r.evals,
                r.wall_seconds, r.pixel_clocks / r.wall_seconds);
  return buf;
}

void default_scene_frame_by_frame(IcebreakerTop top) {
  const Scene s = prepare_scene(WATKINS_SOURCE_DIR "/scenes/default.json", top);
  ASSERT_EQ(s.frame.width * Doubling, VideoWidth);
  IcebreakerBench bench(top);
  IcebreakerOptions opt;
  opt.flash = flash_of(s);
  const IcebreakerRun out = bench.run(opt);
  const BoardRun& r = out.run;
  std::printf("icebreaker bench: %s\n", summary(r).c_str());
  // The loader read the whole bank from the flash (and nothing more) before the video started.
  EXPECT_EQ(out.flash_bits, static_cast<long long>(opt.flash.size()) * 8);
  EXPECT_EQ(out.flash_bad_commands, 0);

  ASSERT_EQ(r.frames.size(), 3u);
  ASSERT_GE(r.request_pixel_clocks.size(), 2u);
  const board::BeamSchedule b = schedule(s);
  // The pins show state 0 (the first visible pixel) after rising edge video_start + PinLatency.
  EXPECT_EQ(r.first_visible, b.timing.video_start + PinLatency);
  EXPECT_EQ(r.request_pixel_clocks[0], r.first_visible - PinLatency + 479LL * LineClocks + 639);
  EXPECT_EQ(timing_mismatches(r), 0);
  EXPECT_EQ(out.dvi_clk_bad, 0);
  const Image want = doubled(s.model, Doubling);
  EXPECT_EQ(pixel_mismatches(r.frames[1], want), 0) << "video frame 1 against the model";
  EXPECT_EQ(pixel_mismatches(r.frames[2], want), 0) << "video frame 2 against the model";
  EXPECT_EQ(r.frames[1].rgb, r.frames[2].rgb) << "consecutive frames differ";
  EXPECT_EQ(r.missed_count, 0);
  EXPECT_TRUE(r.missed.empty());
  EXPECT_FALSE(r.overflow);
  EXPECT_EQ(b.missed, 0);
  ASSERT_GE(r.start_clocks.size(), 2u);
  EXPECT_EQ(r.begin_clocks, r.start_clocks);
  expect_model_schedule(r, b);
  const board::LineSlack& w = b.lines[b.worst];
  std::printf("icebreaker bench: worst line frame %d line %d, slack %lld clocks\n", w.frame, w.y, w.slack);
}

void scene_that_misses_its_deadline(IcebreakerTop top) {
  const Scene s = prepare_scene(WATKINS_SOURCE_DIR "/tests/board/miss_doubled.json", top);
  IcebreakerBench bench(top);
  IcebreakerOptions opt;
  opt.flash = flash_of(s);
  const IcebreakerRun out = bench.run(opt);
  const BoardRun& r = out.run;
  std::printf("icebreaker bench: %s; %d lines missed\n", summary(r).c_str(), r.missed_count);

  EXPECT_GT(r.missed_count, 0);
  EXPECT_EQ(r.missed_count, static_cast<int>(r.missed.size()));
  EXPECT_FALSE(r.overflow);
  // The same lines of every frame miss, from the band (lines 100..105) on.
  std::set<long long> per_frame[2];
  for (const MissedLine& m : r.missed) {
    const long long frame = m.line / s.frame.height, y = m.line % s.frame.height;
    EXPECT_GE(y, 100) << "line " << m.line;
    if (frame < 2) per_frame[frame].insert(y);
  }
  EXPECT_FALSE(per_frame[0].empty());
  EXPECT_EQ(per_frame[0], per_frame[1]);
  // Every line that made its deadline shows the model's pixels, doubled (video frame f + 1 shows
  // rendered frame f).
  ASSERT_EQ(r.frames.size(), 3u);
  const Image want = doubled(s.model, Doubling);
  const std::size_t row = std::size_t(VideoWidth) * 3;
  for (int f = 0; f < 2; ++f) {
    for (int y = 0; y < VideoHeight; ++y) {
      if (per_frame[f].count(y / Doubling)) continue;
      EXPECT_TRUE(std::equal(want.rgb.begin() + y * row, want.rgb.begin() + (y + 1) * row,
                             r.frames[f + 1].rgb.begin() + y * row))
          << "frame " << f << " video line " << y;
    }
  }
  expect_model_schedule(r, schedule(s));
}

TEST(Icebreaker, CompactDefaultSceneFrameByFrame) { default_scene_frame_by_frame(IcebreakerTop::Compact); }
TEST(Icebreaker, CompactSceneThatMissesItsDeadline) { scene_that_misses_its_deadline(IcebreakerTop::Compact); }
TEST(Icebreaker, PipelinedDefaultSceneFrameByFrame) { default_scene_frame_by_frame(IcebreakerTop::Pipelined); }
TEST(Icebreaker, PipelinedSceneThatMissesItsDeadline) { scene_that_misses_its_deadline(IcebreakerTop::Pipelined); }
// The Phong top, where the build has one (WATKINS_BOARD_ICEBREAKER_PHONG_CONFIG).
TEST(Icebreaker, PhongDefaultSceneFrameByFrame) {
  if (!top_built(IcebreakerTop::Phong)) GTEST_SKIP() << "this build has no Verilated iCEBreaker Phong top";
  default_scene_frame_by_frame(IcebreakerTop::Phong);
}

}  // namespace
}  // namespace watkins::board_tb
