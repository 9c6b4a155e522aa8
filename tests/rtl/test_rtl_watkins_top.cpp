// rtl/watkins_top.sv end to end against WatkinsTop::render, pixel by pixel: random
// scenes (triangles and quads partly off screen), a jittered quad mesh (shared edges: equal X,
// ties broken by edge id), frames back to back, random edge-stream gaps and pixel back-pressure,
// and an active-edge overflow (sticky flag, the frame still completes). A quick check of the
// top; the full co-simulation is the SystemC bench in testbench/.
#include <gtest/gtest.h>

#include "Vwatkins_top.h"
#include "watkins_top.hpp"
#include "prepare.hpp"
#include "edge_packing.hpp"
#include "random_scene.hpp"
#include "rtl_harness.hpp"
#include "scene.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

constexpr int MaxWidth = 128;      // -GMaxWidth in tests/rtl/CMakeLists.txt
constexpr int MaxActiveEdges = 16;  // -GMaxActiveEdges

// A w x h scene of `polys` random triangles and quads (bow-ties among them), partly off screen.
BuiltScene random_scene(int w, int h, int polys, std::mt19937_64& rng) {
  test::RandomSceneSpec spec;
  spec.min_width = spec.max_width = w;
  spec.min_height = spec.max_height = h;
  spec.min_polygons = spec.max_polygons = polys;
  spec.convex_quads = false;
  return test::random_scene(rng, spec);
}

void pack(VlWide<15>& w, const EdgeRecord& e) {  // the bench's packer (testbench/edge_packing.hpp)
  const tb::EdgeWords x = tb::pack_edge(e);
  for (int i = 0; i < tb::edge_layout::Words; ++i) w[i] = x[i];
}

struct Top {
  Harness<Vwatkins_top> h;
  std::mt19937_64 rng{1};
  Top() {
    h.dut.edge_valid_i = 0;
    h.dut.pixel_ready_i = 0;
    h.reset();
  }
  // Streams one frame; compares to `ref` unless null. Returns the cycles from the first edge
  // beat offered to the last pixel taken.
  // sparse: sparse_i = 1, the beats compared with sparse_stream(*ref) (ref needed).
  std::uint64_t frame(const PreparedScene& p, const Image* ref, int gap_pct, int bp_pct, bool sparse = false) {
    Stalls gaps{rng, gap_pct}, bp{rng, bp_pct};
    auto& d = h.dut;
    d.width_i = p.width;
    d.height_i = p.height;
    d.background_i = (p.background[0] << 16) | (p.background[1] << 8) | p.background[2];
    d.sparse_i = sparse;
    std::vector<SparseBeat> beats;
    if (sparse) beats = sparse_stream(*ref);
    std::size_t next = 0;
    bool eof_sent = false;
    long long pix = 0;
    const long long total = sparse ? static_cast<long long>(beats.size()) : static_cast<long long>(p.width) * p.height;
    const std::uint64_t start = h.cycles;
    int bad = 0;
    while (pix < total || !eof_sent) {
      if (!d.edge_valid_i && !eof_sent && !gaps.stall()) {
        d.edge_eof_i = next == p.edges.size();
        if (!d.edge_eof_i) pack(d.edge_i, p.edges[next]);
        d.edge_valid_i = 1;
      }
      d.pixel_ready_i = !bp.stall();
      d.eval();
      const bool efire = d.edge_valid_i && d.edge_ready_o;
      if (d.pixel_valid_o && d.pixel_ready_i) {
        EXPECT_LT(pix, total) << "pixel beyond the frame";
        if (sparse && pix < total) {
          const SparseBeat& b = beats[std::size_t(pix)];
          const std::uint32_t rgb = (std::uint32_t(b.rgb[0]) << 16) | (std::uint32_t(b.rgb[1]) << 8) | b.rgb[2];
          if ((d.pixel_rgb_o != rgb || bool(d.pixel_covered_o) != b.covered || bool(d.pixel_last_o) != b.last ||
               int(d.pixel_x_o) != b.x || int(d.pixel_y_o) != b.y) &&
              bad++ < 8)
            ADD_FAILURE() << "sparse beat " << pix << ": rtl (" << d.pixel_x_o << "," << d.pixel_y_o << ") " << std::hex
                          << d.pixel_rgb_o << " cov " << int(d.pixel_covered_o) << " last " << int(d.pixel_last_o)
                          << ", model (" << std::dec << b.x << "," << b.y << ") " << std::hex << rgb << " cov "
                          << b.covered << " last " << b.last;
          ++pix;
          h.tick();
          if (efire) {
            if (d.edge_eof_i) eof_sent = true;
            else ++next;
            d.edge_valid_i = 0;
          }
          continue;
        }
        const int x = static_cast<int>(pix % p.width), y = static_cast<int>(pix / p.width);
        const bool last = pix == total - 1;
        EXPECT_EQ(bool(d.pixel_last_o), last) << "pixel " << x << "," << y;
        EXPECT_EQ(int(d.pixel_x_o), x);
        EXPECT_EQ(int(d.pixel_y_o), y);
        if (ref) {
          const std::uint8_t* r = ref->at(x, y);
          const std::uint32_t rgb = (std::uint32_t(r[0]) << 16) | (std::uint32_t(r[1]) << 8) | r[2];
          if ((d.pixel_rgb_o != rgb || bool(d.pixel_covered_o) != ref->is_covered(x, y)) && bad++ < 8)
            ADD_FAILURE() << "pixel (" << x << "," << y << "): rtl " << std::hex << d.pixel_rgb_o << " cov "
                          << int(d.pixel_covered_o) << ", model " << rgb << " cov " << ref->is_covered(x, y);
        }
        ++pix;
      }
      h.tick();
      if (efire) {
        if (d.edge_eof_i) eof_sent = true;
        else ++next;
        d.edge_valid_i = 0;
      }
      if (h.cycles - start > 20ull * total + 100000) {
        ADD_FAILURE() << "hang: " << pix << " of " << total << " pixels, " << next << " edges";
        return 0;
      }
    }
    EXPECT_EQ(bad, 0);
    return h.cycles - start;
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

// Sparse mode: a line costs max(1, covered pixels, fragments + marker) cycles, not the width.
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
