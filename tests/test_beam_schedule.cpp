// The board's beam schedule (model/board/beam_schedule.hpp): the cycle model under the line
// buffer's back-pressure against the video's deadlines, on scenes light and heavy, and the
// clock-crossing edges where two domains' edges coincide.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "beam_schedule.hpp"
#include "prepare.hpp"
#include "scene_builder.hpp"

using namespace watkins;
using namespace watkins::board;
using namespace watkins::test;

namespace {

// One small triangle on a 320 x 240 frame.
PreparedScene light_scene() {
  return prepare(screen(320, 240, {poly({vtx(100, 50, 0.3, 200, 10, 10), vtx(220, 60, 0.5, 10, 200, 10),
                                          vtx(150, 180, 0.7, 10, 10, 200)})}, "light"));
}

// `layers` quads across the whole of a 640 x 480 frame, stacked: every line is layers x 640
// fragments, more than the 2,500 pipeline clocks of a native video line from four on.
PreparedScene stacked_scene(int layers) {
  std::vector<ScreenPolygon> quads;
  for (int i = 0; i < layers; ++i) {
    const double z = 0.2 + 0.1 * i;
    quads.push_back(poly({vtx(-1, -1, z, 40 * i, 90, 30), vtx(641, -1, z, 40 * i, 90, 30),
                          vtx(641, 481, z, 40 * i, 90, 30), vtx(-1, 481, z, 40 * i, 90, 30)}));
  }
  return prepare(screen(640, 480, quads, "stacked"));
}

TEST(BeamSchedule, LightSceneHasSlackOnEveryLine) {
  const PreparedScene p = light_scene();
  const BeamSchedule s = beam_schedule(p, Config{});
  EXPECT_EQ(s.timing.doubling, 2);
  const int lead = 11 + (1 << id_bits(Config{}.max_materials));  // frame_player: 11 + 2^MaterialIdBits
  EXPECT_EQ(s.timing.start_to_first_beat, lead);
  EXPECT_DOUBLE_EQ(s.budget_per_line(), 5000);
  ASSERT_EQ(s.lines.size(), 3u * 240);
  ASSERT_EQ(s.frames.size(), 3u);
  EXPECT_EQ(s.missed, 0);
  for (const LineSlack& l : s.lines) {
    ASSERT_FALSE(l.missed) << l.frame << " " << l.y;
    // The two slots hold the pipeline about two lines ahead of the beam: a line is written once
    // the line two before it is released, more than a rendered line (5,000 clocks) before its start.
    ASSERT_GT(l.slack, 4000) << "frame " << l.frame << " line " << l.y;
  }
  // Every frame starts at its request's pulse, StartToFirstBeat before its first beat; the video and the
  // pipeline repeat every frame (1,312,500 pipeline clocks), so frames 1 and 2 run alike.
  for (const FrameRun& f : s.frames) {
    EXPECT_EQ(f.begin, f.start_pulse);
    EXPECT_EQ(f.first_beat - f.begin, lead);
  }
  EXPECT_EQ(s.frames[2].start_pulse - s.frames[1].start_pulse, 1312500);
  EXPECT_EQ(s.frames[2].cycles(), s.frames[1].cycles());
  for (int y = 0; y < 240; ++y)
    ASSERT_EQ(s.lines[std::size_t(2 * 240 + y)].slack, s.lines[std::size_t(240 + y)].slack) << y;
}

TEST(BeamSchedule, StackedNativeSceneMissesAndNamesItsLines) {
  BoardTiming t;
  t.doubling = 1;
  const PreparedScene light = stacked_scene(2);  // 1,280 fragments a line: in time
  const BeamSchedule ok = beam_schedule(light, Config{}, t);
  EXPECT_EQ(ok.missed, 0);
  EXPECT_DOUBLE_EQ(ok.budget_per_line(), 2500);
  const PreparedScene heavy = stacked_scene(5);  // 3,200 a line: falls behind the beam
  const BeamSchedule s = beam_schedule(heavy, Config{}, t);
  EXPECT_GT(s.missed, 0);
  const LineSlack& worst = s.lines.at(s.worst);
  EXPECT_TRUE(worst.missed);
  EXPECT_LT(worst.slack, 0);
  long long missed = 0;
  for (const LineSlack& l : s.lines) {
    missed += l.missed;
    EXPECT_EQ(l.missed, l.slack < 0);
    EXPECT_GE(l.slack, worst.slack);
  }
  EXPECT_EQ(missed, s.missed);
  // Line 0 is written after the request, far ahead of its start; the lines fall behind by
  // ~700 clocks each, so the first misses come early in the frame.
  EXPECT_FALSE(s.lines[0].missed);
  EXPECT_TRUE(s.lines[100].missed);
}

TEST(BeamSchedule, LateFirstBeatMissesTheFirstLines) {
  BoardTiming t;
  // Frame 0's request is 36,160 pixel clocks (113,000 pipeline clocks) before line 0's start.
  t.start_to_first_beat = 120000;
  const BeamSchedule s = beam_schedule(light_scene(), Config{}, t);
  EXPECT_TRUE(s.lines[0].missed);
  EXPECT_EQ(s.lines[s.worst].frame, 0);
  EXPECT_EQ(s.lines[s.worst].y, 0);
  EXPECT_GT(s.missed, 0);
  t.start_to_first_beat = 100000;
  EXPECT_EQ(beam_schedule(light_scene(), Config{}, t).missed, 0);
}

TEST(BeamSchedule, CoincidentEdgesSampleTheOldValue) {
  // Pipeline edge 50 and pixel edge 16 are both at tick 800: a pipeline flip-flop samples a
  // pixel register loaded at tick 800 at edge 51, one loaded at tick 799 at edge 50.
  EXPECT_EQ(first_edge_after(800, 16), 51);
  EXPECT_EQ(first_edge_after(799, 16), 50);
  EXPECT_EQ(first_edge_after(400, 50), 9);  // pipeline edge 25 = pixel edge 8
  EXPECT_EQ(visible_from(800, 16, 2), 53);
  EXPECT_EQ(visible_from(801, 16, 2), 53);

  // The first release: h = 639 on video line 1 (D = 2) of video frame 1, pixel edge 421,439,
  // tick 21,071,950 = pipeline edge 1,316,996.875: sampled at 1,316,997, read from 1,316,999.
  // (The video's first state at pixel edge 0 here; the board top's is at edge 2, below.)
  BoardTiming t;
  t.video_start = 0;
  t.count_stages = 2;  // the counts read from the second flip-flop here; the board top's add a register
  const long long m = 420000 + 800 + 639;
  EXPECT_EQ(releases_seen(t, 1316998), 0);
  EXPECT_EQ(releases_seen(t, 1316999), 1);
  EXPECT_EQ(releases_seen(t, 1316999 + 5000), 2);  // the next rendered line, two video lines on
  // Video frame 0 releases nothing: the counts are armed by its request.
  EXPECT_EQ(releases_seen(t, 1316000), 0);

  // Clocks of one period: every edge coincides. The release at pixel edge m is sampled at
  // pipeline edge m + 1 (not m), read from m + 3; a request's pulse three edges after it; a
  // line's last chance is the edge three before its check (sampled at check - 2, read at check).
  BoardTiming same = t;
  same.ticks_per_pixel = same.ticks_per_pipe = 16;
  EXPECT_EQ(releases_seen(same, m + 2), 0);
  EXPECT_EQ(releases_seen(same, m + 3), 1);
  const BeamSchedule s = beam_schedule(light_scene(), Config{}, same);
  EXPECT_EQ(s.frames[0].start_pulse, s.frames[0].request + 3);
  for (const LineSlack& l : s.lines) ASSERT_EQ(l.deadline, l.check - 3);
  // At the board's clocks the request (pixel edge 383,839, tick 19,191,950) is sampled at
  // pipeline edge 1,199,497 and pulses in the clock of edge 1,199,499.
  const BeamSchedule b = beam_schedule(light_scene(), Config{}, t);
  EXPECT_EQ(b.frames[0].request, 383839);
  EXPECT_EQ(b.frames[0].start_pulse, 1199499);
  // Line 0's check: h = 799, v = 524 of video frame 0 (pixel edge 419,999); its w_sync reads the
  // pixel edge 419,997's sample, tick 20,999,850: the last pipeline edge strictly before it is
  // 1,312,490.
  EXPECT_EQ(b.lines[0].check, 419999);
  EXPECT_EQ(b.lines[0].deadline, 1312490);
  // The board top's video starts at pixel edge 2 (its reset synchronizer): every video event two
  // pixel clocks later, the request (tick 19,192,050) pulsing at pipeline edge 1,199,506.
  BoardTiming board;
  const BeamSchedule late = beam_schedule(light_scene(), Config{}, board);
  EXPECT_EQ(late.frames[0].request, 383841);
  EXPECT_EQ(late.frames[0].start_pulse, 1199506);
  EXPECT_EQ(late.lines[0].check, 420001);
  // Its counts cross through gray_sync's three registers: line 0's completion must be sampled by
  // pixel edge 420,001 - 3 (tick 20,999,900): the last pipeline edge strictly before it, 1,312,493.
  EXPECT_EQ(late.lines[0].deadline, 1312493);
  EXPECT_EQ(releases_seen(board, visible_from(50LL * (420000 + 800 + 639 + 2), 16, 3) - 1), 0);
  EXPECT_EQ(releases_seen(board, visible_from(50LL * (420000 + 800 + 639 + 2), 16, 3)), 1);
}

TEST(BeamSchedule, RefusesAFrameOfAnotherSize) {
  BoardTiming t;
  t.doubling = 1;
  try {
    beam_schedule(light_scene(), Config{}, t);
    FAIL() << "a 320 x 240 frame at doubling 1";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("width 320"), std::string::npos) << e.what();
  }
  t.doubling = 3;
  EXPECT_THROW(beam_schedule(light_scene(), Config{}, t), std::invalid_argument);
}

}  // namespace
