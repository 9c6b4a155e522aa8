// rtl/watkins_top.sv end to end against WatkinsTop::render, pixel by pixel: random
// scenes (triangles and quads partly off screen), a jittered quad mesh (shared edges: equal X,
// ties broken by edge id), frames back to back, random edge-stream gaps and pixel back-pressure,
// and an active-edge overflow (sticky flag, the frame still completes). A quick check of the
// top at small sizes; the full co-simulation is the SystemC bench in testbench/, and both drive
// the top with the same loop (testbench/frame_driver.hpp).
#include <gtest/gtest.h>

#include "Vwatkins_top.h"
#include "cc_top_pins.hpp"
#include "frame_driver.hpp"
#include "prepare.hpp"
#include "random_scene.hpp"
#include "watkins_top.hpp"
#include "rtl_harness.hpp"
#include "scene.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

// The top's parameters as tests/rtl/CMakeLists.txt built it (PARAMS of watkins_rtl_unit).
constexpr int MaxWidth = WATKINS_RTL_PARAM_MaxWidth;
constexpr int MaxActiveEdges = WATKINS_RTL_PARAM_MaxActiveEdges;

// A w x h scene of `polys` random triangles and quads (bow-ties among them), partly off screen.
BuiltScene random_scene(int w, int h, int polys, std::mt19937_64& rng) {
  test::RandomSceneSpec spec;
  spec.min_width = spec.max_width = w;
  spec.min_height = spec.max_height = h;
  spec.min_polygons = spec.max_polygons = polys;
  spec.convex_quads = false;
  return test::random_scene(rng, spec);
}

// The bench's drive loop (testbench/frame_driver.hpp) on this top: the edge source with its
// gaps, the pixel sink with its back-pressure, and the checks of every pixel (raster order and
// pixel_x_o/pixel_y_o, pixel_last_o on the last, RGB and coverage against the model) or, in
// sparse mode, of every beat against sparse_stream(*ref); no pixel after the frame; a watchdog.
struct Top {
  Harness<Vwatkins_top> h;
  tb::detail::CcTopPins<Vwatkins_top, tb::detail::NoTrace> pins{h.dut};
  // overflow_o is sticky until reset: the driver must not reset after an overflowing frame.
  tb::detail::FrameDriver driver{pins, tb::detail::FrameDriver::Policy{false}};
  std::uint64_t seed = 1;
  // Streams one frame; compares to `ref` unless null. Returns the cycles from the first edge
  // beat offered to the last pixel taken. gap_pct / bp_pct: percent of cycles with a gap in
  // the edge stream / with pixel_ready_i low.
  // sparse: sparse_i = 1, the beats compared with sparse_stream(*ref) (ref needed).
  std::uint64_t frame(const PreparedScene& p, const Image* ref, int gap_pct, int bp_pct, bool sparse = false) {
    tb::RtlOptions opt;
    opt.seed = seed++;
    opt.gap = gap_pct / 100.0;
    opt.stall = bp_pct / 100.0;
    opt.sparse = sparse;
    opt.reset = false;  // frames after frames on one top without a reset (overflow_o stays set)
    tb::RtlResult r;
    driver.run({&p}, {ref}, {}, opt, r);
    EXPECT_TRUE(r.assertion.empty()) << r.assertion;
    EXPECT_FALSE(r.hang) << "hang: " << r.hang_reason;
    EXPECT_TRUE(r.protocol_error.empty()) << r.protocol_error;
    EXPECT_EQ(r.mismatches, 0) << r.first_pixel_mismatch;
    EXPECT_TRUE(r.frames.at(0).complete) << r.summary();
    // A top that still moves but crawls is a failure too: at most 20 cycles a pixel (or sparse
    // beat) plus a fixed allowance, as the frame's whole budget.
    const std::uint64_t total = sparse ? sparse_stream(*ref).size() : std::uint64_t(p.width) * p.height;
    const auto cycles = static_cast<std::uint64_t>(r.frames.at(0).cycles());
    EXPECT_LE(cycles, 20ull * total + 100000) << "frame too slow: " << cycles << " cycles for " << total << " pixels";
    return cycles;
  }
};

bool prepare_ok(const BuiltScene& s, PreparedScene& p, bool verbose = false) {
  try {
    p = prepare(s, PrepareOptions{MaxActiveEdges});
    return true;
  } catch (const SceneError& e) {
    if (verbose) std::printf("prepare: %s\n", e.what());
    return false;
  }
}

}  // namespace

// 24 random frames back to back with alternating gap and back-pressure rates; `sparse(frame)`
// picks the output mode of each frame.
template <class SparseOf>
void random_frames(std::uint64_t seed, SparseOf sparse) {
  Top t;
  std::mt19937_64 rng(seed);
  int frames = 0;
  while (frames < 24) {
    const int w = 1 + static_cast<int>(rng() % MaxWidth), h = 1 + static_cast<int>(rng() % 70);
    PreparedScene p;
    if (!prepare_ok(random_scene(w, h, static_cast<int>(rng() % 7), rng), p)) continue;
    WatkinsTop pipe(MaxActiveEdges);
    const Image ref = pipe.render(p);
    t.frame(p, &ref, frames % 2 ? 40 : 10, frames % 3 ? 40 : 0, sparse(frames));
    ++frames;
  }
  EXPECT_FALSE(t.h.dut.overflow_o);
}

TEST(RtlTop, RandomScenesGapsAndBackPressure) {
  random_frames(11, [](int) { return false; });
}

TEST(RtlTop, SharedEdgeMesh) {
  Top t;
  std::mt19937_64 rng(12);
  for (int i = 0; i < 4; ++i) {
    PreparedScene p;
    ASSERT_TRUE(prepare_ok(test::mesh_scene(rng, 96, 64, 3, 5), p, true));
    WatkinsTop pipe(MaxActiveEdges);
    const Image ref = pipe.render(p);
    t.frame(p, &ref, 20 * i, 20 * i);
  }
  EXPECT_FALSE(t.h.dut.overflow_o);
}

// Cycles per frame with no stalls: per line the pixel stream (width) or the fragments (+ marker),
// whichever is larger, plus the last line's read-out and the pipeline's fill latency.
TEST(RtlTop, CyclesPerFrame) {
  Top t;
  std::mt19937_64 rng(13);
  for (int i = 0; i < 6; ++i) {
    PreparedScene p;
    const BuiltScene s = i < 3 ? test::mesh_scene(rng, MaxWidth, 48, 3 + i, 3) : random_scene(MaxWidth, 48, 6, rng);
    if (!prepare_ok(s, p)) continue;
    WatkinsTop pipe(MaxActiveEdges);
    std::vector<std::uint64_t> per_line(p.height, 0);
    const Image ref = pipe.render(p, [&](int y, const Fragment&, bool) { ++per_line[y]; });
    // The two line buffers overlap line y's fragments (and its marker) with line y-1's pixels.
    std::uint64_t bound = 0;
    for (int y = 0; y < p.height; ++y) bound += std::max<std::uint64_t>(p.width, per_line[y] + 1);
    const std::uint64_t cycles = t.frame(p, &ref, 0, 0);
    std::printf("top: %dx%d, %zu edges, %lld fragments, %llu cycles (width*height %d)\n", p.width, p.height,
                p.edges.size(), pipe.stats().fragments, static_cast<unsigned long long>(cycles), p.width * p.height);
    // Plus the last line's read-out and the pipeline's fill latency.
    EXPECT_LT(cycles, bound + p.width + 2ull * p.height + 100) << "per-line bound " << bound;
  }
}

TEST(RtlTop, SparseRandomScenesAndModeSwitches) {
  random_frames(15, [](int frame) { return frame % 4 != 3; });
}

// Sparse mode: a line costs max(1, covered pixels, fragments + marker) cycles (plus one for the line
// buffer's swap where its reader sets the pace; the slack below holds 3 per line), not the width.
TEST(RtlTop, SparseCyclesPerFrame) {
  Top t;
  std::mt19937_64 rng(16);
  for (int i = 0; i < 4; ++i) {
    PreparedScene p;
    if (!prepare_ok(random_scene(MaxWidth, 48, 1 + i, rng), p)) continue;
    WatkinsTop pipe(MaxActiveEdges);
    std::vector<std::uint64_t> per_line(p.height, 0);
    const Image ref = pipe.render(p, [&](int y, const Fragment&, bool) { ++per_line[y]; });
    std::uint64_t bound = 0;
    for (int y = 0; y < p.height; ++y) {
      std::uint64_t cov = 0;
      for (int x = 0; x < p.width; ++x) cov += ref.is_covered(x, y);
      bound += std::max<std::uint64_t>({1, cov, per_line[y] + 1});
    }
    const std::uint64_t cycles = t.frame(p, &ref, 0, 0, true);
    std::printf("top sparse: %dx%d, %lld fragments, %llu cycles (bound %llu)\n", p.width, p.height,
                pipe.stats().fragments, static_cast<unsigned long long>(cycles), static_cast<unsigned long long>(bound));
    EXPECT_LT(cycles, bound + p.width + 3ull * p.height + 100) << "per-line bound " << bound;
  }
}

// More polygons on a line than the list holds: overflow_o rises and stays, the frame still
// delivers every pixel (what is drawn is undefined), and the next frame runs.
TEST(RtlTop, OverflowIsStickyAndNeverHangs) {
  Top t;
  std::mt19937_64 rng(14);
  PreparedScene big;
  big = prepare(test::mesh_scene(rng, 96, 32, 12, 2), PrepareOptions{1024});
  ASSERT_GT(big.needs.max_active_edges, MaxActiveEdges);
  t.frame(big, nullptr, 10, 10);
  EXPECT_TRUE(t.h.dut.overflow_o);
  PreparedScene small;
  ASSERT_TRUE(prepare_ok(random_scene(40, 20, 3, rng), small));
  WatkinsTop pipe(MaxActiveEdges);
  const Image ref = pipe.render(small);
  t.frame(small, &ref, 10, 10);
  EXPECT_TRUE(t.h.dut.overflow_o) << "sticky until reset";
}
