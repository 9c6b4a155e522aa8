// The ULX3S board top on its Verilated bench (testbench/board/board_bench.hpp), frame by frame:
// the default scene at its sized configuration (scenes/sized/default.gouraud.json) from bank 0,
// 320 x 240 doubled to 640 x 480 at 60 Hz. Two video frames after the first request equal the
// model's image bit for bit and each other, the encoders' inputs follow the 800 x 525 timing on
// every pixel clock, and no line misses its deadline; the same scene shaded by Phong on the Phong
// top (scenes/sized/default.phong.json) equals the model's Phong image. A 640 x 480 native scene
// built to miss (tests/board/miss.json at tests/board/native.gouraud.json, Doubling 1) shows
// missed lines, the same ones every frame, and the model's pixels on every other line; one whose
// frame outlasts a video frame (tests/board/slow.json) makes the frame player wait for the frame
// before to leave. The runs equal the cycle model's beam schedule line for line (completion edges, missed lines).
// WATKINS_BOARD_PNG=FILE writes the captured frame of the default scene as a PNG
// (docs/results/images/board_default.png); WATKINS_BOARD_LINES=FILE writes every rendered line's
// completion (pipeline clocks from its frame's start pulse) and every missed line as CSV.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "board_bench.hpp"
#include "beam_schedule.hpp"
#include "board_image.hpp"
#include "config_file.hpp"
#include "image_io.hpp"
#include "prepare.hpp"
#include "scene.hpp"
#include "watkins_top.hpp"

namespace watkins::board_tb {
namespace {

constexpr int Doubling = WATKINS_BOARD_DOUBLING;
constexpr int BankWords = WATKINS_BOARD_BANK_WORDS;
constexpr int LineSlots = 2;  // both tops' line buffer

struct Scene {
  PreparedScene frame;
  Image model;
};

Scene prepare_scene(const std::string& path, const std::string& config_path, const BuildOptions& opt = {}) {
  const Config config = load_config(config_path);
  Scene s;
  s.frame = prepare(load_scene(path, opt), config);
  s.model = WatkinsTop(config).render(s.frame);
  return s;
}

// Writes the scene's bank image to `path` (through a temporary, so a reader never sees half).
void write_bank(const Scene& s, const std::string& path) {
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  board::write_readmemh_file(tmp, board::bank_image(s.frame, s.frame.config, BankWords));
  ASSERT_EQ(std::rename(tmp.c_str(), path.c_str()), 0) << path;
}

// Every pixel clock from the first visible one on against the 800 x 525 raster; returns the
// number of clocks that differ (the first one reported).
long long timing_mismatches(const BoardRun& r) {
  long long bad = 0;
  for (std::size_t k = 0; k < r.video.size(); ++k) {
    const VideoSample want = expected_video(static_cast<long long>(k)), got = r.video[k];
    if (want.de != got.de || want.hsync_n != got.hsync_n || want.vsync_n != got.vsync_n) {
      if (bad++ == 0)
        ADD_FAILURE() << "video timing: clock " << k << " (h " << k % LineClocks << ", v "
                      << (k / LineClocks) % FrameLines << "): de/hsync_n/vsync_n " << got.de << got.hsync_n
                      << got.vsync_n << ", want " << want.de << want.hsync_n << want.vsync_n;
    }
  }
  return bad;
}

// Compares the first `rendered_frames` frames' requests, start pulses and begins, and every line
// the RTL completed in the run (the lines of those frames, or fewer when the frames lag the video);
// the missed lines among them but the last LineSlots (their checks may come after the run).
void expect_model_schedule(const BoardRun& r, const board::BeamSchedule& b, int rendered_frames) {
  ASSERT_GE(b.frames.size(), std::size_t(rendered_frames));
  for (int f = 0; f < rendered_frames; ++f) {
    EXPECT_EQ(r.request_pixel_clocks.at(f), b.frames[f].request) << "request " << f;
    EXPECT_EQ(r.start_clocks.at(f), b.frames[f].start_pulse) << "start pulse " << f;
    EXPECT_EQ(r.begin_clocks.at(f), b.frames[f].begin) << "begin " << f;
  }
  const std::size_t lines = std::min(r.lines.size(), std::size_t(rendered_frames) * b.height);
  ASSERT_GE(lines, std::size_t(b.height)) << "not one frame done";
  long long differ = 0;
  for (std::size_t i = 0; i < lines; ++i) {
    if (r.lines[i].pipe_clock != b.lines[i].completion && differ++ == 0)
      ADD_FAILURE() << "line " << i << " done at pipeline edge " << r.lines[i].pipe_clock << ", the model's "
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

long long pixel_mismatches(const Image& got, const Image& want) {
  long long bad = 0;
  for (std::size_t i = 0; i < want.rgb.size(); ++i) bad += got.rgb[i] != want.rgb[i];
  return bad;
}

void write_lines_csv(const char* path, const std::string& scene, const BoardRun& r, int height, bool append) {
  std::ofstream out(path, append ? std::ios::app : std::ios::trunc);
  if (!append) out << "scene,event,line,frame,y,clock,from_start\n";
  for (const LineDone& l : r.lines)
    out << scene << ",done," << l.line << ',' << l.line / height << ',' << l.line % height << ',' << l.pipe_clock << ','
        << l.from_start << '\n';
  for (const MissedLine& m : r.missed)
    out << scene << ",missed," << m.line << ',' << m.line / height << ',' << m.line % height << ',' << m.pixel_clock
        << ",\n";
}

std::string run_summary(const BoardRun& r) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%lld pixel clocks, %lld pipeline clocks, %lld evals in %.2f s (%.0f pixel clocks/s)",
                r.pixel_clocks, r.pipe_clocks, r.evals, r.wall_seconds, r.pixel_clocks / r.wall_seconds);
  return buf;
}

TEST(Board, DefaultSceneFrameByFrame) {
  const Scene s =
      prepare_scene(WATKINS_SOURCE_DIR "/scenes/default.json", WATKINS_SOURCE_DIR "/scenes/sized/default.gouraud.json");
  ASSERT_EQ(s.frame.width * Doubling, VideoWidth);
  ASSERT_EQ(s.frame.height * Doubling, VideoHeight);
  write_bank(s, WATKINS_BOARD_BANK_FILE);  // the file the top was built to read
  BoardBench bench;
  BoardOptions opt;
  const BoardRun r = bench.run(opt);
  std::printf("board bench: %s\n", run_summary(r).c_str());

  // Reset, then the first visible pixel; the first frame request at its frame's last visible
  // pixel; frames 1 and 2 are the scene's.
  ASSERT_EQ(r.frames.size(), 3u);
  ASSERT_GE(r.request_pixel_clocks.size(), 2u);
  // The encoders' inputs show a state a clock late: the request flips on the edge after the
  // state h = 639, v = 479.
  EXPECT_EQ(r.request_pixel_clocks[0], r.first_visible + 479LL * LineClocks + 639);
  EXPECT_EQ(timing_mismatches(r), 0);
  const Image want = doubled(s.model, Doubling);
  EXPECT_EQ(pixel_mismatches(r.frames[1], want), 0) << "video frame 1 against the model";
  EXPECT_EQ(pixel_mismatches(r.frames[2], want), 0) << "video frame 2 against the model";
  EXPECT_EQ(r.frames[1].rgb, r.frames[2].rgb) << "consecutive frames differ";
  EXPECT_EQ(r.missed_count, 0);
  EXPECT_TRUE(r.missed.empty());
  EXPECT_FALSE(r.overflow);

  // Every rendered line of the two frames done, in order, after its frame's start pulse; one
  // start pulse per frame request, each frame begun on its pulse.
  ASSERT_GE(r.start_clocks.size(), 2u);
  EXPECT_EQ(r.begin_clocks, r.start_clocks);
  ASSERT_GE(r.lines.size(), 2u * s.frame.height);
  for (std::size_t i = 0; i < r.lines.size(); ++i) {
    EXPECT_EQ(r.lines[i].line, static_cast<long long>(i));
    EXPECT_GT(r.lines[i].from_start, 0) << "line " << i;
  }
  // Every line's completion and the deadline checks exactly as the beam schedule has them.
  expect_model_schedule(r, board::beam_schedule(s.frame, s.frame.config), 2);
  if (const char* png = std::getenv("WATKINS_BOARD_PNG")) {
    const std::vector<unsigned char> bytes = encode_png(r.frames[1]);
    std::ofstream(png, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                               static_cast<std::streamsize>(bytes.size()));
  }
  if (const char* csv = std::getenv("WATKINS_BOARD_LINES")) write_lines_csv(csv, "default", r, s.frame.height, false);
}

// The default scene shaded by Phong's eq. (3) at its sized Phong configuration on the Phong top
// (Vulx3s_top_phong, bank 0 from +watkins_bank): the light, the eye and the material table from
// the bank's header, each rendered frame the model's image bit for bit, every line on time and
// done when the beam schedule has it.
TEST(Board, PhongDefaultSceneFrameByFrame) {
  BuildOptions phong;
  phong.shading = ShadingMode::Phong;
  const Scene s = prepare_scene(WATKINS_SOURCE_DIR "/scenes/default.json",
                                WATKINS_SOURCE_DIR "/scenes/sized/default.phong.json", phong);
  ASSERT_EQ(s.frame.shading, ShadingMode::Phong);
  ASSERT_EQ(top_build(BoardTop::Phong).shading, ShadingMode::Phong);
  const std::string bank = std::string(WATKINS_BOARD_WORK_DIR) + "/phong_bank." + std::to_string(::getpid()) + ".mem";
  write_bank(s, bank);
  BoardBench bench(BoardTop::Phong);
  BoardOptions opt;
  opt.bank_file = bank;
  opt.record_video = false;
  const BoardRun r = bench.run(opt);
  std::remove(bank.c_str());
  std::printf("board bench (Phong): %s\n", run_summary(r).c_str());
  ASSERT_EQ(r.frames.size(), 3u);
  const Image want = doubled(s.model, Doubling);
  EXPECT_EQ(pixel_mismatches(r.frames[1], want), 0) << "video frame 1 against the model";
  EXPECT_EQ(pixel_mismatches(r.frames[2], want), 0) << "video frame 2 against the model";
  EXPECT_EQ(r.missed_count, 0);
  EXPECT_TRUE(r.missed.empty());
  EXPECT_FALSE(r.overflow);
  expect_model_schedule(r, board::beam_schedule(s.frame, s.frame.config), 2);
}

TEST(Board, SceneThatMissesItsDeadline) {
  const Scene s =
      prepare_scene(WATKINS_SOURCE_DIR "/tests/board/miss.json", WATKINS_SOURCE_DIR "/tests/board/native.gouraud.json");
  ASSERT_EQ(s.frame.width, VideoWidth);
  ASSERT_EQ(s.frame.height, VideoHeight);
  const std::string bank = std::string(WATKINS_BOARD_WORK_DIR) + "/miss_bank.mem";
  write_bank(s, bank);
  BoardBench bench(BoardTop::Native);
  BoardOptions opt;
  opt.bank_file = bank;
  opt.tmds_clock = false;  // the video timing is checked on the default scene
  const BoardRun r = bench.run(opt);
  std::printf("board bench: %s; %d lines missed\n", run_summary(r).c_str(), r.missed_count);

  EXPECT_GT(r.missed_count, 0);
  EXPECT_EQ(r.missed_count, static_cast<int>(r.missed.size()));
  EXPECT_FALSE(r.overflow);
  // The same lines of every frame miss, from the heavy band (lines 200..209) on.
  std::set<long long> per_frame[2];
  for (const MissedLine& m : r.missed) {
    const long long frame = m.line / s.frame.height, y = m.line % s.frame.height;
    EXPECT_GE(y, 200) << "line " << m.line;
    if (frame < 2) per_frame[frame].insert(y);
  }
  EXPECT_FALSE(per_frame[0].empty());
  EXPECT_EQ(per_frame[0], per_frame[1]);
  // Every line that made its deadline shows the model's pixels (video frame f + 1 shows
  // rendered frame f).
  ASSERT_EQ(r.frames.size(), 3u);
  const std::size_t row = std::size_t(VideoWidth) * 3;
  for (int f = 0; f < 2; ++f) {
    for (int y = 0; y < VideoHeight; ++y) {
      if (per_frame[f].count(y)) continue;
      EXPECT_TRUE(std::equal(s.model.rgb.begin() + y * row, s.model.rgb.begin() + (y + 1) * row,
                             r.frames[f + 1].rgb.begin() + y * row))
          << "frame " << f << " line " << y;
    }
  }
  board::BoardTiming timing;
  timing.doubling = 1;
  expect_model_schedule(r, board::beam_schedule(s.frame, s.frame.config, timing), 2);
  if (const char* csv = std::getenv("WATKINS_BOARD_LINES")) write_lines_csv(csv, "miss", r, s.frame.height, true);
}

TEST(Board, FrameLongerThanAVideoFrame) {
  const Scene s =
      prepare_scene(WATKINS_SOURCE_DIR "/tests/board/slow.json", WATKINS_SOURCE_DIR "/tests/board/native.gouraud.json");
  const std::string bank = std::string(WATKINS_BOARD_WORK_DIR) + "/slow_bank.mem";
  write_bank(s, bank);
  BoardBench bench(BoardTop::Native);
  BoardOptions opt;
  opt.bank_file = bank;
  opt.tmds_clock = false;
  const BoardRun r = bench.run(opt);
  std::printf("board bench: %s; %d lines missed\n", run_summary(r).c_str(), r.missed_count);
  // The second start pulse comes while the first frame is in the pipeline: the frame player
  // begins it later, the clock after that frame's last pixel is taken.
  ASSERT_GE(r.start_clocks.size(), 2u);
  ASSERT_GE(r.begin_clocks.size(), 2u);
  EXPECT_EQ(r.begin_clocks[0], r.start_clocks[0]);
  EXPECT_GT(r.begin_clocks[1], r.start_clocks[1]);
  EXPECT_GT(r.missed_count, 0);
  EXPECT_FALSE(r.overflow);
  board::BoardTiming timing;
  timing.doubling = 1;
  expect_model_schedule(r, board::beam_schedule(s.frame, s.frame.config, timing), 2);
}

}  // namespace
}  // namespace watkins::board_tb
