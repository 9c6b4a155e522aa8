// rtl/board/video_timing.sv over two frames and a line from reset: h and v count 0..799 and
// 0..524; de, hsync and vsync are those of the same (h, v) on every clock; per frame 307,200
// visible pixels in 480 runs of 640, 525 hsync pulses of 96 clocks starting at h = 656, one vsync
// pulse of 2 lines (1,600 clocks) starting at v = 490, h = 0; both syncs active low.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "Vvideo_timing.h"
#include "rtl_harness.hpp"

using namespace watkins::rtl;

namespace {

struct State {
  int h, v;
  bool de, hsync_n, vsync_n;
};

State read(const Vvideo_timing& d) { return {d.h_o, d.v_o, d.de_o != 0, d.hsync_no != 0, d.vsync_no != 0}; }

// A pulse (or visible run) of a signal: the clock it starts and how many clocks it lasts.
struct Run {
  std::uint64_t start, length;
};
template <class F>
std::vector<Run> runs(const std::vector<State>& s, F active) {
  std::vector<Run> r;
  for (std::uint64_t t = 0; t < s.size(); ++t) {
    if (!active(s[t])) continue;
    if (t > 0 && active(s[t - 1])) {
      ++r.back().length;
    } else {
      r.push_back({t, 1});
    }
  }
  return r;
}

constexpr int HTotal = 800, VTotal = 525;
constexpr std::uint64_t Frame = std::uint64_t{HTotal} * VTotal;

TEST(RtlVideoTiming, TwoFrames) {
  Harness<Vvideo_timing> h;
  h.dut.rst_ni = 0;
  h.tick();
  h.tick();
  // In reset: h = v = 0, the first visible pixel, syncs high.
  State s0 = read(h.dut);
  EXPECT_EQ(s0.h, 0);
  EXPECT_EQ(s0.v, 0);
  EXPECT_TRUE(s0.de);
  EXPECT_TRUE(s0.hsync_n);
  EXPECT_TRUE(s0.vsync_n);
  h.dut.rst_ni = 1;
  // trace[t]: the outputs during clock t after reset (t = 0 is the reset state).
  std::vector<State> trace{s0};
  const std::uint64_t clocks = 2 * Frame + HTotal;
  while (trace.size() < clocks) {
    h.tick();
    trace.push_back(read(h.dut));
  }
  std::uint64_t bad = 0;
  for (std::uint64_t t = 0; t < trace.size(); ++t) {
    const State& s = trace[t];
    const int hh = static_cast<int>(t % HTotal), vv = static_cast<int>((t / HTotal) % VTotal);
    const bool ok = s.h == hh && s.v == vv && s.de == (hh < 640 && vv < 480) &&
                    s.hsync_n == !(hh >= 656 && hh < 752) && s.vsync_n == !(vv >= 490 && vv < 492);
    if (!ok && ++bad <= 5)
      ADD_FAILURE() << "clock " << t << ": h " << s.h << " v " << s.v << " de " << s.de << " hs " << s.hsync_n
                    << " vs " << s.vsync_n << ", expected h " << hh << " v " << vv;
  }
  EXPECT_EQ(bad, 0u);

  // The pulses counted and measured over exactly two frames.
  const std::vector<State> two(trace.begin(), trace.begin() + static_cast<std::ptrdiff_t>(2 * Frame));
  const auto de = runs(two, [](const State& s) { return s.de; });
  const auto hs = runs(two, [](const State& s) { return !s.hsync_n; });
  const auto vs = runs(two, [](const State& s) { return !s.vsync_n; });
  ASSERT_EQ(de.size(), 2u * 480u);
  ASSERT_EQ(hs.size(), 2u * 525u);
  ASSERT_EQ(vs.size(), 2u);
  std::uint64_t visible = 0;
  for (std::size_t i = 0; i < de.size(); ++i) {
    const std::uint64_t frame = i / 480, line = i % 480;
    EXPECT_EQ(de[i].start, frame * Frame + line * HTotal);
    EXPECT_EQ(de[i].length, 640u);
    visible += de[i].length;
  }
  EXPECT_EQ(visible, 2u * 640u * 480u);
  for (std::size_t i = 0; i < hs.size(); ++i) {
    EXPECT_EQ(hs[i].start, i * HTotal + 656);
    EXPECT_EQ(hs[i].length, 96u);
  }
  for (std::size_t i = 0; i < vs.size(); ++i) {
    EXPECT_EQ(vs[i].start, i * Frame + 490u * HTotal);
    EXPECT_EQ(vs[i].length, 2u * HTotal);
  }
  // Porches: 16 clocks from the end of the visible line to hsync, 48 from its end to the line's end;
  // 10 lines from the last visible line to vsync, 33 after it.
  EXPECT_EQ(hs[0].start - (de[0].start + de[0].length), 16u);
  EXPECT_EQ(HTotal - (hs[0].start + hs[0].length), 48u);
  EXPECT_EQ(vs[0].start - 480u * HTotal, 10u * HTotal);
  EXPECT_EQ(Frame - (vs[0].start + vs[0].length), 33u * HTotal);
}

// A reset in mid-frame returns to h = v = 0 on the next clock and the count goes on from there.
TEST(RtlVideoTiming, ResetMidFrame) {
  Harness<Vvideo_timing> h;
  h.reset();
  for (int i = 0; i < 12345; ++i) h.tick();
  EXPECT_EQ(h.dut.h_o, 12345 % HTotal);
  EXPECT_EQ(h.dut.v_o, 12345 / HTotal);
  h.dut.rst_ni = 0;
  h.tick();
  EXPECT_EQ(h.dut.h_o, 0);
  EXPECT_EQ(h.dut.v_o, 0);
  EXPECT_EQ(h.dut.de_o, 1);
  h.dut.rst_ni = 1;
  h.tick();
  EXPECT_EQ(h.dut.h_o, 1);
}

}  // namespace
