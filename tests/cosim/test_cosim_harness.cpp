// The default configuration's two benches (RtlHarness in testbench/rtl_bench.hpp): the plain C++
// harness on the speed build's --cc tops (no assertions, no tracing; `watkins render --rtl`) and
// the SystemC bench (assertions, tracing; `--rtl --systemc`) run the same RTL through the same
// drive loop, so they must agree on every cycle count and every pixel.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "cosim_support.hpp"
#include "prepare.hpp"
#include "rtl_bench.hpp"
#include "scene.hpp"

using namespace watkins;
using namespace watkins::tb;
using namespace watkins::tb::test;
using namespace watkins::test;

namespace {

RtlResult run_on(RtlHarness harness, const PreparedScene& p, RtlOptions o) {
  o.harness = harness;
  return run_rtl(p, o);
}

// Every cycle count (the run's, including reset and drain, and each frame's) and every frame.
void expect_same_result(const std::string& what, const RtlResult& a, const RtlResult& b) {
  EXPECT_EQ(a.cycles, b.cycles) << what;
  EXPECT_EQ(a.sim_cycles, b.sim_cycles) << what;
  EXPECT_EQ(a.stage_items, b.stage_items) << what;
  ASSERT_EQ(a.frames.size(), b.frames.size()) << what;
  for (std::size_t f = 0; f < a.frames.size(); ++f) {
    EXPECT_EQ(a.frames[f].first_edge_cycle, b.frames[f].first_edge_cycle) << what << " frame " << f;
    EXPECT_EQ(a.frames[f].last_pixel_cycle, b.frames[f].last_pixel_cycle) << what << " frame " << f;
    EXPECT_EQ(a.frames[f].pixels, b.frames[f].pixels) << what << " frame " << f;
    EXPECT_EQ(a.frames[f].image.rgb, b.frames[f].image.rgb) << what << " frame " << f;
    EXPECT_EQ(a.frames[f].image.covered, b.frames[f].image.covered) << what << " frame " << f;
  }
}

void expect_same_run(const std::string& what, const RtlOptions& o, const RtlResult& fast, const RtlResult& sc) {
  expect_clean(what + " on the plain C++ harness", o, fast);
  expect_clean(what + " on the SystemC bench", o, sc);
  EXPECT_NE(fast.top.find("speed build"), std::string::npos) << fast.top;
  EXPECT_NE(sc.top.find("SystemC bench"), std::string::npos) << sc.top;
  expect_same_result(what, fast, sc);
}

// The default scene and sphere.json, both tops, full-frame and sparse, without and with gaps
// and stalls (random_options: none, light, heavy, all-stall bursts).
TEST(CosimHarness, PlainAndSystemCBenchesAgreeOnEveryCycle) {
  for (const std::string scene_path : {std::string(), std::string(WATKINS_SOURCE_DIR "/scenes/sphere.json")}) {
    for (const ShadingMode shading : {ShadingMode::Gouraud, ShadingMode::Phong}) {
      BuildOptions b;
      b.shading = shading;
      const PreparedScene p = prepare(load_scene_or_default(scene_path, b));
      for (std::uint64_t seed = 0; seed < 4; ++seed) {
        RtlOptions o = random_options(seed);
        o.sparse = seed % 2 == 1;
        const std::string what = (scene_path.empty() ? "default scene" : scene_path) + " " + to_string(shading) +
                                 (o.sparse ? " sparse" : " full-frame");
        expect_same_run(what, o, run_on(RtlHarness::Fast, p, o), run_on(RtlHarness::SystemC, p, o));
      }
    }
  }
}

// Frames back to back (the driver keeps its cycle count between them) on both benches.
TEST(CosimHarness, FramesBackToBackAgree) {
  const PreparedScene a = prepare(load_scene_or_default(""));
  const PreparedScene s = prepare(load_scene_or_default(WATKINS_SOURCE_DIR "/scenes/sphere.json"));
  RtlOptions o = random_options(1);
  o.sparse_frames = {false, true, false};
  RtlOptions fo = o, so = o;
  fo.harness = RtlHarness::Fast;
  so.harness = RtlHarness::SystemC;
  expect_same_run("default, sphere, default", o, run_rtl_frames({&a, &s, &a}, fo), run_rtl_frames({&a, &s, &a}, so));
}

// A run's result never depends on what ran before it in the process (each run resets the top
// first): on each bench the same scene three times, with another scene in the other output mode
// between the first two and a hung run (the sink never ready: a frame left mid-way) between the
// last two, gives the same cycle counts and frames each time; and the two benches agree.
TEST(CosimHarness, RunsDoNotDependOnEarlierRuns) {
  for (const ShadingMode shading : {ShadingMode::Gouraud, ShadingMode::Phong}) {
    BuildOptions b;
    b.shading = shading;
    const PreparedScene a = prepare(load_scene_or_default("", b));
    const PreparedScene s = prepare(load_scene_or_default(WATKINS_SOURCE_DIR "/scenes/sphere.json", b));
    const std::string what = std::string("default scene ") + to_string(shading);
    RtlResult first[2];
    for (const RtlHarness harness : {RtlHarness::Fast, RtlHarness::SystemC}) {
      const std::string on = what + (harness == RtlHarness::Fast ? " on the plain C++ harness" : " on the SystemC bench");
      const RtlOptions o = random_options(1);
      RtlOptions other = random_options(2);
      other.sparse = true;
      RtlOptions stuck;
      stuck.stall = 1.0;
      stuck.watchdog = 500;
      stuck.compare = false;
      const RtlResult r1 = run_on(harness, a, o);
      expect_clean(on + ", first run", o, r1);
      expect_clean("sphere.json sparse in between", other, run_on(harness, s, other));
      const RtlResult r2 = run_on(harness, a, o);
      expect_clean(on + ", second run", o, r2);
      const RtlResult hung = run_on(harness, s, stuck);
      EXPECT_TRUE(hung.hang) << on << ": a sink never ready must hang the run\n" << hung.summary();
      const RtlResult r3 = run_on(harness, a, o);
      expect_clean(on + ", third run", o, r3);
      expect_same_result(on + ": second run against the first", r1, r2);
      expect_same_result(on + ": third run (after a hung one) against the first", r1, r3);
      first[harness == RtlHarness::Fast ? 0 : 1] = r1;
    }
    expect_same_run(what + ", first runs", random_options(1), first[0], first[1]);
  }
}

// A waveform comes from the SystemC bench's traced tops, whichever bench was asked for.
TEST(CosimHarness, TraceRunsOnTheSystemCBench) {
  const ScratchDir dir;
  const PreparedScene p = prepare(load_scene_or_default(WATKINS_SOURCE_DIR "/scenes/sphere.json"));
  RtlOptions o;
  o.harness = RtlHarness::Fast;
  o.trace_path = dir.write("w.fst", "");
  const RtlResult r = run_rtl(p, o);
  EXPECT_TRUE(r.ok()) << r.summary();
  EXPECT_NE(r.top.find("SystemC bench"), std::string::npos) << r.top;
  EXPECT_GT(dir.contents("w.fst").size(), 1000u);
}

// The command line: `render --rtl` (plain C++ harness) and `render --rtl --systemc` name their
// bench, count the same cycles and write the same image, under gaps and stalls, both shadings.
std::string cycles_line(const std::string& out) {
  std::smatch m;
  return std::regex_search(out, m, std::regex("rtl cycles +([0-9]+)")) ? m[1].str() : "";
}

TEST(CosimHarness, CliRtlAndSystemcAgree) {
  const ScratchDir dir;
  const std::string fast_png = dir.write("fast.png", ""), sc_png = dir.write("sc.png", "");
  for (const std::string shading : {"gouraud", "phong"}) {
    const std::string common = "render " WATKINS_SOURCE_DIR "/scenes/sphere.json --shading " + shading +
                               " --rtl --gap 0.1 --stall 0.2 --seed 3";
    const CliRun f = run_cli(common + " --out " + fast_png);
    const CliRun s = run_cli(common + " --systemc --out " + sc_png);
    ASSERT_EQ(f.exit_code, 0) << f.output;
    ASSERT_EQ(s.exit_code, 0) << s.output;
    EXPECT_NE(f.output.find("rtl           Verilated --cc watkins_top built for the default configuration (speed build"), std::string::npos)
        << f.output;
    EXPECT_NE(s.output.find("rtl           SystemC bench"), std::string::npos) << s.output;
    EXPECT_NE(cycles_line(f.output), "") << f.output;
    EXPECT_EQ(cycles_line(f.output), cycles_line(s.output)) << f.output << s.output;
    EXPECT_NE(dir.contents("fast.png").size(), 0u);
    EXPECT_EQ(dir.contents("fast.png"), dir.contents("sc.png")) << shading;
  }
  const CliRun bad = run_cli("render --systemc --out " + fast_png);
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("--systemc needs --rtl"), std::string::npos) << bad.output;
}

}  // namespace
