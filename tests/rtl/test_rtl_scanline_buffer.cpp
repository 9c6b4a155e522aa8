// rtl/scanline_buffer.sv against ScanlineBuffer: random fragment streams per line (same x back
// to back, equal depths, empty lines, full lines), end-of-line markers, several frames, under
// random valid gaps and pixel back-pressure; every pixel, its coverage, position and the last
// flag. Sparse mode (sparse_i): only the covered pixels (ScanlineBuffer::next_covered), plus the
// terminating uncovered beat at (width-1, height-1) when the last line has no covered pixel.
#include <gtest/gtest.h>

#include <deque>
#include <sstream>
#include <string>

#include "Vscanline_buffer.h"
#include "rtl_harness.hpp"
#include "scanline_buffer.hpp"
#include "stream_bench.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

constexpr int MaxWidth = WATKINS_RTL_PARAM_MaxWidth;  // PARAMS in tests/rtl/CMakeLists.txt

struct In {
  bool eol;
  Fragment f;
};
struct Px {
  std::uint32_t rgb;
  bool covered, last;
  int x, y;
};

// sparse: 0 full frames, 1 sparse frames, 2 alternating (frame by frame).
void run(int frames, int gap_pct, int bp_pct, std::uint64_t seed, int sparse = 0) {
  Harness<Vscanline_buffer> h;
  std::mt19937_64 rng(seed);
  StreamBench<Px> b(rng, gap_pct, bp_pct);
  b.max_cycles = 1000000;
  b.until_expected = true;  // the frame ends with its last pixel; every input must be in by then
  const StreamPorts ports{h.dut.frag_valid_i, h.dut.frag_ready_o, h.dut.pixel_valid_o, h.dut.pixel_ready_i};
  reset_stream(h, ports);
  for (int fr = 0; fr < frames; ++fr) {
    const int width = (fr % 3 == 0) ? MaxWidth : 1 + static_cast<int>(rng() % MaxWidth);
    const int height = 1 + static_cast<int>(rng() % 12);
    const std::array<std::uint8_t, 3> bg{std::uint8_t(rng()), std::uint8_t(rng()), std::uint8_t(rng())};
    h.dut.width_i = width;
    h.dut.height_i = height;
    h.dut.background_i = (bg[0] << 16) | (bg[1] << 8) | bg[2];
    const bool sp = sparse == 1 || (sparse == 2 && fr % 2 == 1);
    h.dut.sparse_i = sp;
    bool last_line_covered = false;
    // Stimulus and expected pixels of the whole frame, line by line, from the model.
    std::deque<In> in;
    std::deque<Px>& want = b.expect;
    ScanlineBuffer model(width, bg);
    for (int y = 0; y < height; ++y) {
      model.clear();
      const int n = (rng() % 5 == 0) ? 0 : static_cast<int>(rng() % (3 * width));
      const std::uint32_t depth_range = (rng() % 2) ? 4 : (1u << 24);  // few depths: many ties
      int x = static_cast<int>(rng() % width);
      for (int i = 0; i < n; ++i) {
        Fragment f;
        if (rng() % 3) x = static_cast<int>(rng() % width);  // else the same x again
        f.x = x;
        f.depth = static_cast<std::uint32_t>(rng() % depth_range);
        if (depth_range == (1u << 24) && rng() % 16 == 0) f.depth = (1u << 24) - 1;
        for (auto& c : f.rgb) c = static_cast<std::uint8_t>(rng());
        model.write(f);
        in.push_back({false, f});
      }
      in.push_back({true, Fragment{}});
      auto pack = [](const std::array<std::uint8_t, 3>& p) {
        return (std::uint32_t(p[0]) << 16) | (std::uint32_t(p[1]) << 8) | p[2];
      };
      if (sp) {
        for (int px = model.next_covered(0); px < width; px = model.next_covered(px + 1)) {
          want.push_back({pack(model.pixel(px)), true, false, px, y});
          last_line_covered = y == height - 1;
        }
        if (y == height - 1) {
          if (!last_line_covered) want.push_back({pack(bg), false, false, width - 1, y});
          want.back().last = true;
        }
      } else {
        for (int px = 0; px < width; ++px)
          want.push_back({pack(model.pixel(px)), model.covered(px), y == height - 1 && px == width - 1, px, y});
      }
    }
    const bool ran = b.run(
        h, ports, [&] { return !in.empty(); },
        [&] {
          const In& i = in.front();
          h.dut.frag_eol_i = i.eol;
          h.dut.frag_x_i = i.f.x;
          h.dut.frag_depth_i = i.f.depth;
          h.dut.frag_rgb_i = (std::uint32_t(i.f.rgb[0]) << 16) | (std::uint32_t(i.f.rgb[1]) << 8) | i.f.rgb[2];
          return true;
        },
        [&](std::deque<Px>&) { in.pop_front(); },
        [&](const Px& w) {
          if (h.dut.pixel_rgb_o == w.rgb && h.dut.pixel_covered_o == w.covered && h.dut.pixel_last_o == w.last &&
              int(h.dut.pixel_x_o) == w.x && int(h.dut.pixel_y_o) == w.y)
            return std::string();
          std::ostringstream diff;
          diff << "frame " << fr << (sp ? " (sparse)" : "") << ": rtl (" << h.dut.pixel_x_o << ", "
               << h.dut.pixel_y_o << ") " << std::hex << h.dut.pixel_rgb_o << " cov " << int(h.dut.pixel_covered_o)
               << " last " << int(h.dut.pixel_last_o) << "; model (" << std::dec << w.x << ", " << w.y << ") "
               << std::hex << w.rgb << " cov " << w.covered << " last " << w.last;
          return diff.str();
        });
    ASSERT_TRUE(ran);
    ASSERT_TRUE(in.empty());
    h.tick();
    ASSERT_FALSE(h.dut.pixel_valid_o) << "extra pixel after the frame";
  }
  EXPECT_EQ(b.mismatches, 0u);
}

}  // namespace

TEST(RtlScanlineBuffer, FullRate) { run(60, 0, 0, 1); }
TEST(RtlScanlineBuffer, GapsAndBackPressure) { run(60, 40, 40, 2); }
TEST(RtlScanlineBuffer, HeavyBackPressure) { run(30, 5, 80, 3); }
TEST(RtlScanlineBuffer, SparseFullRate) { run(60, 0, 0, 4, 1); }
TEST(RtlScanlineBuffer, SparseGapsAndBackPressure) { run(60, 40, 40, 5, 1); }
TEST(RtlScanlineBuffer, SparseHeavyBackPressure) { run(30, 5, 80, 6, 1); }
TEST(RtlScanlineBuffer, AlternatingModes) { run(60, 20, 30, 7, 2); }
