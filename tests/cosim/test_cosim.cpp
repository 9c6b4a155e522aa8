// Co-simulation: the Verilated watkins_top (testbench/rtl_bench.hpp) must produce the bit-exact
// model's image, pixel for pixel, under random input gaps and output back-pressure.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "watkins_top.hpp"
#include "prepare.hpp"
#include "rtl_bench.hpp"
#include "cosim_support.hpp"
#include "random_scene.hpp"
#include "scene.hpp"
#include "scene_builder.hpp"

using namespace watkins;
using namespace watkins::tb;
using namespace watkins::tb::test;
using namespace watkins::test;

namespace {

class RandomScenes : public ::testing::TestWithParam<int> {};

constexpr int ScenesPerBatch = 25;

TEST_P(RandomScenes, MatchTheModel) {
  for (int k = 0; k < ScenesPerBatch; ++k) {
    const std::uint64_t seed = 1000 + static_cast<std::uint64_t>(GetParam()) * ScenesPerBatch + k;
    const BuiltScene scene = random_scene(seed);
    PreparedScene prepared;
    try {
      prepared = prepare(scene);
    } catch (const SceneError& e) {  // too many active edges for the hardware: not a co-simulation case
      continue;
    }
    const RtlOptions o = random_options(seed);
    const RtlResult r = run_rtl(prepared, o);
    const std::string name = scene.name + " (" + std::to_string(scene.width) + "x" +
                             std::to_string(scene.height) + ", " + std::to_string(scene.polygons.size()) +
                             " polygons)";
    expect_clean(name, o, r);
    if (!r.ok()) return;  // one report per batch is enough
    // Every other scene again in sparse output mode, under the next stall pattern.
    if (k % 2 == 0) {
      RtlOptions so = random_options(seed + 1);
      so.sparse = true;
      const RtlResult sr = run_rtl(prepared, so);
      expect_clean(name + " sparse", so, sr);
      if (!sr.ok()) return;
      EXPECT_EQ(sr.frames.at(0).image.rgb, r.frames.at(0).image.rgb) << name << " sparse image";
      EXPECT_EQ(sr.frames.at(0).image.covered, r.frames.at(0).image.covered) << name << " sparse coverage";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Batches, RandomScenes, ::testing::Range(0, 8));  // 8 x 25 = 200 scenes

// ---------------------------------------------------------------- shipped scenes
class ShippedScenes : public ::testing::TestWithParam<std::string> {};

// Each scene in its own shading mode (its file's "shading.mode").
TEST_P(ShippedScenes, MatchTheModelUnderGapsAndStalls) { check_shipped_scene(GetParam(), BuildOptions{}); }

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedScenes, ::testing::ValuesIn(shipped_scenes()), scene_test_name);

// ---------------------------------------------------------------- corner cases
BuiltScene two_triangles(int w, int h, double shift) {
  return screen(w, h,
                {poly({vtx(1 + shift, 1, 0.2, 255, 0, 0), vtx(w - 2.0, 3 + shift, 0.6, 0, 255, 0),
                       vtx(4, h - 1.5, 0.9, 0, 0, 255)}),
                 poly({vtx(w - 1.0, 1, 0.7, 250, 250, 0), vtx(w * 0.6, h - 1.0, 0.1, 0, 250, 250),
                       vtx(2 + shift, h * 0.4, 0.5, 250, 0, 250)})},
                "two triangles", {7, 70, 170});
}

TEST(Cosim, EmptyFrameIsAllBackground) {
  const PreparedScene p = prepare(screen(13, 5, {}, "empty", {1, 2, 3}));
  ASSERT_TRUE(p.edges.empty());
  const RtlOptions o{5, 0.3, 0.3};
  const RtlResult r = run_rtl(p, o);
  expect_clean("empty frame", o, r);
  EXPECT_EQ(r.pixels, 13 * 5);
}

TEST(Cosim, SparseEmptyFrameIsOneTerminatingBeat) {
  // Sparse mode, nothing covered: one beat, not covered, background, at (width-1, height-1),
  // with pixel_last_o (the model's sparse_stream says the same).
  const PreparedScene p = prepare(screen(40, 60, {}, "empty", {9, 8, 7}));
  const Image model = WatkinsTop().render(p);
  const std::vector<SparseBeat> beats = sparse_stream(model);
  ASSERT_EQ(beats.size(), 1u);
  EXPECT_EQ(beats[0].x, 39);
  EXPECT_EQ(beats[0].y, 59);
  EXPECT_FALSE(beats[0].covered);
  EXPECT_TRUE(beats[0].last);
  for (const RtlOptions& base : {RtlOptions{5, 0.0, 0.0}, RtlOptions{6, 0.3, 0.5, 8}}) {
    RtlOptions o = base;
    o.sparse = true;
    const RtlResult r = run_rtl(p, o);
    expect_clean("empty frame, sparse", o, r);
    EXPECT_EQ(r.pixels, 1);
    EXPECT_TRUE(r.frames.at(0).complete);
    EXPECT_EQ(r.frames.at(0).image.rgb, model.rgb);
    // An empty line costs a few cycles (the active-edge list's per-line overhead; the line
    // buffer's read-out of it takes one), far below the width: 40x60 in well under 5 per line.
    if (o.gap == 0 && o.stall == 0) EXPECT_LT(r.cycles, 5 * 60 + 50) << r.cycles << " cycles";
  }
}

TEST(Cosim, SparseLastLineUncovered) {
  // A triangle well inside the frame: the last line has no covered pixel, so the stream ends
  // with the terminating (uncovered) beat; and the first lines are empty too.
  const PreparedScene p = prepare(
      screen(30, 20, {poly({vtx(5, 4, 0.3, 200, 10, 10), vtx(25, 6, 0.5, 10, 200, 10), vtx(12, 14, 0.7, 10, 10, 200)})},
             "inner triangle"));
  const Image model = WatkinsTop().render(p);
  const std::vector<SparseBeat> beats = sparse_stream(model);
  ASSERT_GE(beats.size(), 2u);
  EXPECT_FALSE(beats.back().covered);
  EXPECT_EQ(beats.back().x, 29);
  EXPECT_EQ(beats.back().y, 19);
  for (std::size_t i = 0; i + 1 < beats.size(); ++i) EXPECT_TRUE(beats[i].covered && !beats[i].last);
  for (const RtlOptions& base : {RtlOptions{7, 0.0, 0.0}, RtlOptions{8, 0.2, 0.4}, RtlOptions{9, 0.1, 0.05, 40}}) {
    RtlOptions o = base;
    o.sparse = true;
    const RtlResult r = run_rtl(p, o, &model);
    expect_clean("inner triangle, sparse", o, r);
    EXPECT_EQ(r.pixels, static_cast<long long>(beats.size()));
    EXPECT_EQ(r.frames.at(0).image.rgb, model.rgb);
    EXPECT_EQ(r.frames.at(0).image.covered, model.covered);
  }
}

TEST(Cosim, SparseCheckerNamesTheFirstMismatchingBeat) {
  const PreparedScene p = prepare(two_triangles(20, 10, 0.0));
  Image want = WatkinsTop().render(p);
  int fx = -1, fy = -1;  // the first covered pixel from (7, 3) on
  for (int k = 3 * 20 + 7; k < 20 * 10 && fx < 0; ++k)
    if (want.covered[std::size_t(k)]) fx = k % 20, fy = k / 20;
  ASSERT_GE(fx, 0);
  want.at(fx, fy)[1] ^= 0x10;
  RtlOptions o{52, 0.2, 0.2};
  o.sparse = true;
  const RtlResult r = run_rtl(p, o, &want);
  EXPECT_EQ(r.mismatches, 1);
  EXPECT_FALSE(r.ok());
  const std::string at = "pixel (" + std::to_string(fx) + ", " + std::to_string(fy) + ")";
  EXPECT_NE(r.first_mismatch.find("pixel output: sparse frame 0"), std::string::npos) << r.first_mismatch;
  EXPECT_NE(r.first_mismatch.find(at), std::string::npos) << r.first_mismatch;
  EXPECT_NE(r.first_mismatch.find("model " + at), std::string::npos) << r.first_mismatch;
  EXPECT_TRUE(r.frames.at(0).complete);
}

TEST(Cosim, FramesBackToBackSwitchingModes) {
  const PreparedScene a = prepare(two_triangles(40, 30, 0.0));
  const PreparedScene b = prepare(two_triangles(40, 30, 3.3));
  const PreparedScene c = prepare(two_triangles(23, 41, 1.7));
  const PreparedScene empty = prepare(screen(40, 30, {}, "empty"));
  const std::vector<const PreparedScene*> scenes = {&a, &b, &a, &c, &b, &empty, &a, &empty};
  const std::vector<bool> modes = {false, true, true, false, true, true, false, false};
  for (const RtlOptions& base : {RtlOptions{61, 0.0, 0.0}, RtlOptions{62, 0.3, 0.4}, RtlOptions{63, 0.05, 0.05, 50}}) {
    RtlOptions o = base;
    o.sparse_frames = modes;
    const RtlResult r = run_rtl_frames(scenes, o);
    expect_clean("eight frames back to back, switching modes", o, r);
    ASSERT_EQ(r.frames.size(), scenes.size());
    for (std::size_t f = 0; f < scenes.size(); ++f) {
      EXPECT_TRUE(r.frames[f].complete) << "frame " << f;
      EXPECT_EQ(r.frames[f].sparse, modes[f]) << "frame " << f;
      const Image m = WatkinsTop().render(*scenes[f]);
      EXPECT_EQ(r.frames[f].image.rgb, m.rgb) << "frame " << f;
      EXPECT_EQ(r.frames[f].image.covered, m.covered) << "frame " << f;
      if (modes[f]) EXPECT_EQ(r.frames[f].pixels, static_cast<long long>(sparse_stream(m).size())) << "frame " << f;
    }
  }
}

TEST(Cosim, FramesBackToBack) {
  // Same size: the second frame's edges follow the first frame's end-of-frame beat at once;
  // then a frame of another size (the source waits for the drain before changing width_i).
  const PreparedScene a = prepare(two_triangles(40, 30, 0.0));
  const PreparedScene b = prepare(two_triangles(40, 30, 3.3));
  const PreparedScene c = prepare(two_triangles(23, 41, 1.7));
  for (const RtlOptions& o : {RtlOptions{11, 0.0, 0.0}, RtlOptions{12, 0.3, 0.4}, RtlOptions{13, 0.05, 0.05, 50}}) {
    const RtlResult r = run_rtl_frames({&a, &b, &a, &c, &b}, o);
    expect_clean("five frames back to back", o, r);
    ASSERT_EQ(r.frames.size(), 5u);
    for (const RtlFrame& f : r.frames) EXPECT_TRUE(f.complete);
    EXPECT_EQ(r.pixels, 4 * 40 * 30 + 23 * 41);
    // With no gaps the next frame's first edge goes in within a few cycles of the previous
    // frame's last pixel (the RTL may or may not overlap frames; it must not idle between them).
    if (o.gap == 0 && o.stall == 0)
      for (int f = 1; f < 3; ++f)
        EXPECT_LE(r.frames[f].first_edge_cycle, r.frames[f - 1].last_pixel_cycle + 4)
            << "frame " << f << " did not follow frame " << f - 1 << " at once";
  }
  // And separate runs one after another without a reset in between still match.
  for (int k = 0; k < 3; ++k) {
    RtlOptions o{static_cast<std::uint64_t>(20 + k), 0.2, 0.2};
    o.reset = false;
    expect_clean("consecutive run " + std::to_string(k), o, run_rtl(k % 2 ? b : a, o));
  }
}

TEST(Cosim, ActiveEdgeListOverflowSetsOverflowO) {
  // 40 thin slivers crossing scan line 10: 80 active edges > MaxActiveEdges (64).
  BuiltScene s = screen(96, 20, {}, "overflow");
  for (int k = 0; k < 40; ++k) {
    const double x = 1 + k * 2.3;
    s.polygons.push_back(poly({vtx(x, 2, 0.5, 200, 100, 50), vtx(x + 1.2, 18, 0.5, 200, 100, 50),
                               vtx(x + 0.4, 18, 0.5, 50, 100, 200)}));
  }
  PrepareOptions popt;
  popt.max_active_edges = 1 << 20;  // bypass the software check: the hardware must notice
  PreparedScene p = prepare(s, popt);
  p.config.max_active_edges = fmt::MaxActiveEdges;  // and run it on the default top regardless
  ASSERT_GT(p.needs.max_active_edges, fmt::MaxActiveEdges);
  RtlOptions o;
  o.compare = false;
  o.watchdog = 20000;  // the RTL may drop edges or stop; either way overflow_o must be set
  const RtlResult r = run_rtl(p, o);
  EXPECT_TRUE(r.overflow) << "overflow_o never rose with " << p.needs.max_active_edges << " active edges\n"
                          << r.summary();
  // The bench resets after an overflow: a normal frame afterwards must be clean again.
  const PreparedScene ok = prepare(two_triangles(32, 24, 0.5));
  const RtlOptions o2{31, 0.1, 0.1};
  expect_clean("frame after an overflow", o2, run_rtl(ok, o2));
}

TEST(Cosim, WatchdogNamesTheStuckInterface) {
  // A sink that never takes a pixel: the run must end as a hang that names the pixel output.
  const PreparedScene p = prepare(two_triangles(16, 8, 0.0));
  RtlOptions o;
  o.stall = 1.0;
  o.watchdog = 2000;
  const RtlResult r = run_rtl(p, o);
  EXPECT_TRUE(r.hang);
  EXPECT_NE(r.hang_reason.find("pixel output blocked"), std::string::npos) << r.hang_reason;
  // And the bench recovers (reset) for the next run.
  const RtlOptions o2{41, 0.0, 0.0};
  expect_clean("frame after a hang", o2, run_rtl(p, o2));
}

TEST(Cosim, CheckerNamesTheFirstMismatchingPixel) {
  // The checker itself: an expected image with two pixels changed must give exactly those two
  // mismatches, the first one named with its (x, y) and both values.
  const PreparedScene p = prepare(two_triangles(20, 10, 0.0));
  Image want = WatkinsTop().render(p);
  want.at(7, 3)[1] ^= 0x10;
  want.covered[std::size_t(9) * 20 + 19] ^= 1;
  const RtlOptions o{51, 0.2, 0.2};
  const RtlResult r = run_rtl(p, o, &want);
  EXPECT_EQ(r.mismatches, 2);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.first_mismatch.find("pixel output: frame 0 pixel (7, 3)"), std::string::npos) << r.first_mismatch;
  EXPECT_NE(r.first_mismatch.find("model rgb"), std::string::npos) << r.first_mismatch;
  EXPECT_TRUE(r.frames.at(0).complete);
  EXPECT_FALSE(r.hang);
}

TEST(Cosim, TraceWritesAnFst) {
  const PreparedScene p = prepare(two_triangles(12, 6, 0.0));
  const std::string path = (std::filesystem::temp_directory_path() / "watkins_cosim_trace.fst").string();
  std::filesystem::remove(path);
  RtlOptions o;
  o.trace_path = path;
  expect_clean("traced frame", o, run_rtl(p, o));
  ASSERT_TRUE(std::filesystem::exists(path));
  EXPECT_GT(std::filesystem::file_size(path), 100u);
  // A second traced run in the same process works as well.
  expect_clean("second traced frame", o, run_rtl(p, o));
  EXPECT_GT(std::filesystem::file_size(path), 100u);
  std::filesystem::remove(path);
}

// ---------------------------------------------------------------- stage checker
// The bench compares the three internal stage streams (active_edge_list -> segment_former ->
// segment_interpolator -> scanline_buffer) with the model's, transfer by transfer.

// Items of each model stage stream (every end-of-line marker included).
long long model_stage_items(const PreparedScene& p) {
  long long n = 0;
  PipelineObserver o;
  o.active_edge = [&](int, const ActiveEdge&) { ++n; };
  o.active_edges_end = [&](int) { ++n; };
  o.segment = [&](int, const Segment&) { ++n; };
  o.segments_end = [&](int) { ++n; };
  o.fragment = [&](int, const Fragment&, bool) { n += 2; };  // interpolator and shading outputs
  o.fragments_end = [&](int) { n += 2; };
  WatkinsTop().render(p, o);
  return n;
}

TEST(Cosim, StageCheckerComparesEveryStageTransfer) {
  const PreparedScene p = prepare(two_triangles(40, 30, 0.0));
  const RtlOptions o{61, 0.3, 0.3};
  const RtlResult r = run_rtl(p, o);
  expect_clean("stage-checked frame", o, r);
  EXPECT_TRUE(r.stage_mismatches.empty());
  EXPECT_EQ(r.stage_items, model_stage_items(p));  // every item of every stream, none twice
  // Back to back: the stages of frame f+1 start while frame f drains; each stage keeps its frame.
  const PreparedScene b = prepare(two_triangles(23, 41, 1.7));
  const RtlResult r2 = run_rtl_frames({&p, &b, &p}, o);
  expect_clean("stage-checked frames", o, r2);
  EXPECT_EQ(r2.stage_items, 2 * model_stage_items(p) + model_stage_items(b));
  // Off: nothing compared.
  RtlOptions off = o;
  off.check_stages = false;
  const RtlResult r3 = run_rtl(p, off);
  expect_clean("frame without the stage check", off, r3);
  EXPECT_EQ(r3.stage_items, 0);
}

// The checker itself: the model's expected stream of one stage, corrupted in one item, must give
// exactly one diverging stage -- that one, named with frame, line, item and both values -- while
// the other stages and every pixel still agree (their expected streams are the model's own).
struct Corruption {
  const char* stage;
  std::function<std::string(StageStreams&)> corrupt;  // returns the report text it must produce
};

RtlResult run_corrupted(const std::vector<const PreparedScene*>& frames, int frame, const RtlOptions& base,
                        const std::function<std::string(StageStreams&)>& corrupt, std::string& want) {
  RtlOptions o = base;
  o.edit_stage_streams = [&](int f, StageStreams& s) {
    if (f == frame) want = corrupt(s);
  };
  return run_rtl_frames(frames, o);
}

template <class Item>
std::size_t middle_item(const std::vector<Item>& v) {  // a payload item about half way down
  std::size_t k = v.size() / 2;
  while (k < v.size() && v[k].eol) ++k;
  return k;
}

TEST(Cosim, StageCheckerNamesTheDivergingStage) {
  using ::testing::Test;
  const PreparedScene p = prepare(two_triangles(40, 30, 0.0));
  const std::vector<Corruption> cases = {
      {"active_edge_list",
       [](StageStreams& s) {
         StageEdge& e = s.edges.at(middle_item(s.edges));
         e.value[fmt::ChanX] += 1;
         return "active_edge_list output: frame 0 line " + std::to_string(e.line) + " edge " +
                std::to_string(e.index) + " at cycle ";
       }},
      {"segment_former",
       [](StageStreams& s) {
         StageSegment& g = s.segments.at(middle_item(s.segments));
         g.f[fmt::ChanZ] -= 3;
         return "segment_former output: frame 0 line " + std::to_string(g.line) + " segment " +
                std::to_string(g.index) + " at cycle ";
       }},
      {"segment_interpolator",
       [](StageStreams& s) {
         StageFragment& f = s.fragments.at(middle_item(s.fragments));
         f.material ^= 1;
         return "segment_interpolator output: frame 0 line " + std::to_string(f.line) + " fragment " +
                std::to_string(f.index) + " at cycle ";
       }},
      {"shading",
       [](StageStreams& s) {
         StageFragment& f = s.shaded.at(middle_item(s.shaded));
         f.rgb ^= 0x000100;  // green, lowest bit
         return "shading output: frame 0 line " + std::to_string(f.line) + " fragment " +
                std::to_string(f.index) + " at cycle ";
       }},
  };
  const char* differs[] = {"(differs in x)", "(differs in F.z)", "(differs in material)", "(differs in rgb)"};
  const char* affects[] = {"; affects line ", "; affects pixels (", "; pixel (", "; pixel ("};
  for (std::size_t k = 0; k < cases.size(); ++k) {
    std::string want;
    const RtlOptions o{71 + k, 0.2, 0.2};
    const RtlResult r = run_corrupted({&p}, 0, o, cases[k].corrupt, want);
    SCOPED_TRACE(cases[k].stage);
    Test::RecordProperty(cases[k].stage, r.first_mismatch);  // the report, in --gtest_output=xml
    ASSERT_FALSE(want.empty());
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.first_stage, cases[k].stage) << r.summary();
    ASSERT_EQ(r.stage_mismatches.size(), 1u) << r.summary();
    EXPECT_EQ(r.first_mismatch, r.stage_mismatches[0]);
    EXPECT_EQ(r.first_mismatch.rfind(want, 0), 0u) << "want: " << want << "\ngot:  " << r.first_mismatch;
    EXPECT_NE(r.first_mismatch.find(": RTL "), std::string::npos) << r.first_mismatch;
    EXPECT_NE(r.first_mismatch.find(", model "), std::string::npos) << r.first_mismatch;
    EXPECT_NE(r.first_mismatch.find(differs[k]), std::string::npos) << r.first_mismatch;
    EXPECT_NE(r.first_mismatch.find(affects[k]), std::string::npos) << r.first_mismatch;
    EXPECT_EQ(r.mismatches, 0) << r.summary();  // the pixels themselves agree with the model
    EXPECT_TRUE(r.frames.at(0).complete);
    EXPECT_FALSE(r.hang);
    EXPECT_NE(r.summary().find("stage streams diverge from the model; first: " + want), std::string::npos)
        << r.summary();
  }
}

TEST(Cosim, StageCheckerFollowsFramesAndLostItems) {
  // A fragment missing from frame 1's expected stream: the first fragment after it no longer
  // matches (the RTL's is the missing one), reported in frame 1 at that position.
  const PreparedScene a = prepare(two_triangles(40, 30, 0.0));
  const PreparedScene b = prepare(two_triangles(40, 30, 3.3));
  std::string want;
  const RtlOptions o{81, 0.1, 0.1};
  const RtlResult r = run_corrupted({&a, &b}, 1, o, [](StageStreams& s) {
    const std::size_t k = middle_item(s.fragments);
    const StageFragment f = s.fragments.at(k);
    s.fragments.erase(s.fragments.begin() + static_cast<long>(k));
    return "segment_interpolator output: frame 1 line " + std::to_string(f.line) + " ";
  }, want);
  EXPECT_EQ(r.first_stage, "segment_interpolator") << r.summary();
  EXPECT_EQ(r.first_mismatch.rfind(want, 0), 0u) << "want: " << want << "\ngot:  " << r.first_mismatch;
  EXPECT_EQ(r.stage_mismatches.size(), 1u) << r.summary();
  EXPECT_EQ(r.mismatches, 0);
  // An end-of-line marker where the model has an edge (an active edge the RTL would have lost).
  std::string want2;
  const RtlResult r2 = run_corrupted({&a}, 0, o, [](StageStreams& s) {
    const std::size_t k = middle_item(s.edges);
    StageEdge e = s.edges.at(k);
    s.edges.insert(s.edges.begin() + static_cast<long>(k), e);  // the model "has" one edge more
    return "active_edge_list output: frame 0 line " + std::to_string(e.line) + " ";
  }, want2);
  EXPECT_EQ(r2.first_stage, "active_edge_list") << r2.summary();
  EXPECT_EQ(r2.first_mismatch.rfind(want2, 0), 0u) << "want: " << want2 << "\ngot:  " << r2.first_mismatch;
  EXPECT_NE(r2.first_mismatch.find("model poly"), std::string::npos) << r2.first_mismatch;
  // And a clean run afterwards (the bench resets after the failed runs).
  expect_clean("frame after stage mismatches", o, run_rtl(a, o));
}

}  // namespace
