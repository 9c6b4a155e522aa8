// rtl/scanline_buffer.sv against ScanlineBuffer: random fragment streams per line (same x back
// to back, equal depths, empty lines, full lines), end-of-line markers, several frames, under
// random valid gaps and pixel back-pressure; every pixel, its coverage, position and the last
// flag. Sparse mode (sparse_i): only the covered pixels (ScanlineBuffer::next_covered), plus the
// terminating uncovered beat at (width-1, height-1) when the last line has no covered pixel.
// Equal-depth rule (tie_submission_i): random frames under each rule and alternating, with few
// depths and few polygon ids so that ties are common; and a directed line of equal depths sent
// back to back to one x (the forwarded depth word carries the id), pixels asserted by hand.
#include <gtest/gtest.h>

#include <deque>
#include <sstream>
#include <string>
#include <vector>

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

using Line = std::vector<Fragment>;

// One frame of the stream bench: lines[y] are line y's fragments. The frame's pixels as the model
// gives them (appended to `frame_pixels` when given); false when the run stopped early.
struct FrameSpec {
  int width = 1;
  std::array<std::uint8_t, 3> bg{};
  bool sparse = false;
  DepthTie tie = DepthTie::Arrival;
  std::vector<Line> lines;
};

bool run_frame(Harness<Vscanline_buffer>& h, StreamBench<Px>& b, const StreamPorts& ports, int fr,
               const FrameSpec& spec, std::vector<std::array<std::uint8_t, 3>>* frame_pixels = nullptr) {
  const int width = spec.width;
  const int height = static_cast<int>(spec.lines.size());
  const std::array<std::uint8_t, 3>& bg = spec.bg;
  const bool sp = spec.sparse;
  h.dut.width_i = width;
  h.dut.height_i = height;
  h.dut.background_i = (bg[0] << 16) | (bg[1] << 8) | bg[2];
  h.dut.sparse_i = sp;
  h.dut.tie_submission_i = spec.tie == DepthTie::Submission;
  {
    bool last_line_covered = false;
    // Stimulus and expected pixels of the whole frame, line by line, from the model.
    std::deque<In> in;
    std::deque<Px>& want = b.expect;
    ScanlineBuffer model(width, bg, spec.tie);
    for (int y = 0; y < height; ++y) {
      model.clear();
      for (const Fragment& f : spec.lines[y]) {
        model.write(f);
        in.push_back({false, f});
      }
      in.push_back({true, Fragment{}});
      if (frame_pixels)
        for (int px = 0; px < width; ++px) frame_pixels->push_back(model.pixel(px));
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
          h.dut.frag_poly_i = i.f.poly;
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
    EXPECT_TRUE(ran);
    EXPECT_TRUE(in.empty());
    h.tick();
    EXPECT_FALSE(h.dut.pixel_valid_o) << "extra pixel after the frame";
    return ran && in.empty() && !h.dut.pixel_valid_o;
  }
}

// sparse: 0 full frames, 1 sparse frames, 2 alternating (frame by frame); tie: 0 arrival,
// 1 submission, 2 alternating (frame by frame, out of step with sparse).
void run(int frames, int gap_pct, int bp_pct, std::uint64_t seed, int sparse = 0, int tie = 0) {
  Harness<Vscanline_buffer> h;
  std::mt19937_64 rng(seed);
  StreamBench<Px> b(rng, gap_pct, bp_pct);
  b.max_cycles = 1000000;
  b.until_expected = true;  // the frame ends with its last pixel; every input must be in by then
  const StreamPorts ports{h.dut.frag_valid_i, h.dut.frag_ready_o, h.dut.pixel_valid_o, h.dut.pixel_ready_i};
  reset_stream(h, ports);
  for (int fr = 0; fr < frames; ++fr) {
    FrameSpec spec;
    spec.width = (fr % 3 == 0) ? MaxWidth : 1 + static_cast<int>(rng() % MaxWidth);
    const int height = 1 + static_cast<int>(rng() % 12);
    spec.bg = {std::uint8_t(rng()), std::uint8_t(rng()), std::uint8_t(rng())};
    spec.sparse = sparse == 1 || (sparse == 2 && fr % 2 == 1);
    spec.tie = (tie == 1 || (tie == 2 && fr % 4 >= 2)) ? DepthTie::Submission : DepthTie::Arrival;
    const int width = spec.width;
    for (int y = 0; y < height; ++y) {
      Line line;
      const int n = (rng() % 5 == 0) ? 0 : static_cast<int>(rng() % (3 * width));
      const std::uint32_t depth_range = (rng() % 2) ? 4 : (1u << 24);  // few depths: many ties
      const int poly_range = (rng() % 2) ? 6 : 65536;                   // few ids: equal ids too
      int x = static_cast<int>(rng() % width);
      for (int i = 0; i < n; ++i) {
        Fragment f;
        if (rng() % 3) x = static_cast<int>(rng() % width);  // else the same x again
        f.x = x;
        f.depth = static_cast<std::uint32_t>(rng() % depth_range);
        if (depth_range == (1u << 24) && rng() % 16 == 0) f.depth = (1u << 24) - 1;
        f.poly = static_cast<int>(rng() % poly_range);
        for (auto& c : f.rgb) c = static_cast<std::uint8_t>(rng());
        line.push_back(f);
      }
      spec.lines.push_back(line);
    }
    ASSERT_TRUE(run_frame(h, b, ports, fr, spec));
  }
  EXPECT_EQ(b.mismatches, 0u);
}

Fragment frag(int x, std::uint32_t depth, int poly, std::uint8_t shade) {
  Fragment f;
  f.x = x;
  f.depth = depth;
  f.poly = poly;
  f.rgb[0] = f.rgb[1] = f.rgb[2] = shade;
  return f;
}

// Equal depths back to back to one x (each tested against the word written the clock before,
// forwarded), then a nearer fragment and a tie with it, under both rules, at full rate and under
// gaps and back-pressure. The shade of fragment k is 10 * k + 10.
void directed(int gap_pct, int bp_pct) {
  Harness<Vscanline_buffer> h;
  std::mt19937_64 rng(11);
  StreamBench<Px> b(rng, gap_pct, bp_pct);
  b.max_cycles = 100000;
  b.until_expected = true;
  const StreamPorts ports{h.dut.frag_valid_i, h.dut.frag_ready_o, h.dut.pixel_valid_o, h.dut.pixel_ready_i};
  reset_stream(h, ports);
  const Line line{frag(5, 7, 9, 10),  frag(5, 7, 3, 20), frag(5, 7, 5, 30), frag(5, 7, 1, 40),  // x 5: ties
                  frag(2, 4, 2, 50),  frag(2, 4, 6, 60), frag(2, 3, 8, 70), frag(2, 3, 7, 80),  // x 2
                  frag(6, 9, 4, 90),  frag(6, 9, 4, 100)};  // x 6: equal depth, equal id: first stays
  for (DepthTie tie : {DepthTie::Submission, DepthTie::Arrival, DepthTie::Submission}) {
    FrameSpec spec;
    spec.width = 8;
    spec.tie = tie;
    spec.lines = {line, line};
    std::vector<std::array<std::uint8_t, 3>> px;
    ASSERT_TRUE(run_frame(h, b, ports, 0, spec, &px));
    const bool sub = tie == DepthTie::Submission;
    // Submission: the smallest id among the nearest; arrival: the first of the nearest.
    EXPECT_EQ(px.at(5)[0], sub ? 40 : 10) << (sub ? "submission" : "arrival");
    EXPECT_EQ(px.at(2)[0], sub ? 80 : 70) << (sub ? "submission" : "arrival");
    EXPECT_EQ(px.at(6)[0], 90) << (sub ? "submission" : "arrival");
    EXPECT_EQ(px.at(8 + 5)[0], sub ? 40 : 10) << "second line";
  }
  EXPECT_EQ(b.mismatches, 0u);
  EXPECT_GT(b.checked, 0u);
}

}  // namespace

TEST(RtlScanlineBuffer, FullRate) { run(60, 0, 0, 1); }
TEST(RtlScanlineBuffer, GapsAndBackPressure) { run(60, 40, 40, 2); }
TEST(RtlScanlineBuffer, HeavyBackPressure) { run(30, 5, 80, 3); }
TEST(RtlScanlineBuffer, SparseFullRate) { run(60, 0, 0, 4, 1); }
TEST(RtlScanlineBuffer, SparseGapsAndBackPressure) { run(60, 40, 40, 5, 1); }
TEST(RtlScanlineBuffer, SparseHeavyBackPressure) { run(30, 5, 80, 6, 1); }
TEST(RtlScanlineBuffer, AlternatingModes) { run(60, 20, 30, 7, 2); }
TEST(RtlScanlineBuffer, TieSubmissionFullRate) { run(60, 0, 0, 8, 0, 1); }
TEST(RtlScanlineBuffer, TieSubmissionGapsAndBackPressure) { run(60, 40, 40, 9, 0, 1); }
TEST(RtlScanlineBuffer, TieRulesAlternatingSparse) { run(60, 20, 30, 10, 2, 2); }
TEST(RtlScanlineBuffer, TieBackToBackOneX) { directed(0, 0); }
TEST(RtlScanlineBuffer, TieBackToBackOneXStalled) { directed(30, 50); }
