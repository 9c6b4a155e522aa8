// rtl/board/tmds_serializer.sv with the ODDRX1F stand-in (testbench/board/primitives/ODDRX1F.sv)
// on docs/reference/board.md's time base: one tick = 1/1260 us, clk_pixel toggles every 25 ticks,
// clk_tmds every 5, both rising at tick 0 and evaluated in one eval where their edges coincide.
// symbol_i changes as a pixel-domain register does: just after a pixel clock's rising edge. The
// pad is sampled once per half clk_tmds period (every 5 ticks). Asserted: the symbol registered at
// pixel edge m (tick 50 m) is on the pad bit 0 first, bit j during ticks [50 m + 20 + 5 j,
// 50 m + 25 + 5 j), for every symbol from the first after reset, with the pad low in reset; the
// clock lane's constant gives a pad high for the first five bit times of every symbol.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "Vtmds_serializer.h"
#include "Vtmds_serializer___024root.h"
#include "verilated.h"

namespace {

constexpr int TicksPerStep = 5;              // half a clk_tmds period
constexpr int StepsPerPixel = 10;            // a pixel clock is 50 ticks
constexpr int FirstBitStep = 20 / TicksPerStep;  // the first bit 20 ticks after its pixel edge
constexpr std::uint16_t ClockLane = 0b00'0001'1111;

// Runs the lane: symbols[i] is registered at pixel edge ResetPixels + 1 + i (from the first pixel
// edge that sees rst_ni high). Returns the pad per step (5 ticks) from tick 0.
struct Lane {
  static constexpr int ResetPixels = 3;  // rst_ni sampled low by pixel edges 0..3, high from edge 4
  Vtmds_serializer dut;
  std::vector<std::uint8_t> pad;
  // D0/D1 at each clk_tmds rising edge, read through the public nets (what the board bench uses).
  std::vector<std::uint8_t> pairs;

  void run(const std::vector<std::uint16_t>& symbols) {
    dut.clk_pixel_i = 0;
    dut.clk_tmds_i = 0;
    dut.rst_ni = 0;
    dut.symbol_i = 0;
    dut.eval();
    const int first = ResetPixels + 1;
    const int pixels = first + static_cast<int>(symbols.size()) + 2;
    for (int k = 0; k < pixels * StepsPerPixel; ++k) {
      const bool tmds = k % 2 == 0, pixel = (k / 5) % 2 == 0;
      const bool pixel_rise = pixel && !dut.clk_pixel_i;
      if (tmds && !dut.clk_tmds_i) pairs.push_back(static_cast<std::uint8_t>(dut.rootp->tmds_serializer__DOT__d0 |
                                                                               dut.rootp->tmds_serializer__DOT__d1 << 1));
      dut.clk_tmds_i = tmds;
      dut.clk_pixel_i = pixel;
      dut.eval();
      if (pixel_rise) {  // the pixel-domain registers' new values, after the edge
        const int m = k / StepsPerPixel;
        if (m == ResetPixels) dut.rst_ni = 1;
        const int i = m - first;
        dut.symbol_i = (i >= 0 && i < static_cast<int>(symbols.size())) ? symbols[static_cast<std::size_t>(i)] : 0;
        dut.eval();
      }
      pad.push_back(dut.pad_o);
    }
  }
  // Symbol i's bit j on the pad: the step of pixel edge (first + i), plus the latency, plus j.
  int bit(std::size_t i, int j) const {
    return pad[static_cast<std::size_t>((ResetPixels + 1 + static_cast<int>(i)) * StepsPerPixel + FirstBitStep + j)];
  }
};

TEST(RtlTmdsSerializer, SymbolsBitZeroFirstAtAFixedLatency) {
  std::mt19937_64 rng(0x5e7);
  std::vector<std::uint16_t> symbols;
  for (int i = 0; i < 20000; ++i) symbols.push_back(static_cast<std::uint16_t>(rng() & 0x3ffu));
  // Corner words: all ones, all zeros, alternating, and the clock lane's.
  for (const std::uint16_t w : {0x3ffu, 0x000u, 0x2aau, 0x155u, 0x3ffu, 0x3ffu, 0x000u, unsigned{ClockLane}})
    symbols.push_back(static_cast<std::uint16_t>(w));
  Lane lane;
  lane.run(symbols);
  // From the ODDRX1F's first capture of the cleared shift register (tick 10) until the first
  // symbol's first bit the pad is low.
  const int first_bit_step = (Lane::ResetPixels + 1) * StepsPerPixel + FirstBitStep;
  for (int k = 2; k < first_bit_step; ++k) ASSERT_EQ(lane.pad[static_cast<std::size_t>(k)], 0) << "step " << k;
  std::uint64_t bad = 0;
  for (std::size_t i = 0; i < symbols.size(); ++i) {
    std::uint16_t got = 0;
    for (int j = 0; j < 10; ++j) got = static_cast<std::uint16_t>(got | lane.bit(i, j) << j);
    if (got != symbols[i] && ++bad <= 5) ADD_FAILURE() << "symbol " << i << ": sent " << symbols[i] << ", pad " << got;
  }
  EXPECT_EQ(bad, 0u);
  // The public D0/D1 pair at clk_tmds edge n is the pad's bits for [10 n, 10 n + 10) ticks.
  for (std::size_t n = 0; n + 1 < lane.pairs.size() && 2 * n + 1 < lane.pad.size(); ++n) {
    const int pad_pair = lane.pad[2 * n] | lane.pad[2 * n + 1] << 1;
    ASSERT_EQ(lane.pairs[n], pad_pair) << "clk_tmds edge " << n;
  }
}

// The clock lane: the constant 10'b0000011111 gives a pad high for bits 0..4 and low for 5..9 of
// every symbol time, so its rising edge (tick 50 m + 20) is the first bit of the data lanes'
// symbol registered at pixel edge m, and its period is one pixel clock.
TEST(RtlTmdsSerializer, ClockLane) {
  Lane lane;
  lane.run(std::vector<std::uint16_t>(1000, ClockLane));
  for (std::size_t i = 0; i < 1000; ++i)
    for (int j = 0; j < 10; ++j) ASSERT_EQ(lane.bit(i, j), j < 5 ? 1 : 0) << "symbol " << i << " bit " << j;
  // Rising edges of the pad: one per pixel clock, 20 ticks after each pixel edge.
  int rises = 0;
  for (std::size_t k = 1; k < lane.pad.size(); ++k) {
    if (lane.pad[k] && !lane.pad[k - 1]) {
      EXPECT_EQ(static_cast<int>(k) % StepsPerPixel, FirstBitStep) << "step " << k;
      ++rises;
    }
  }
  EXPECT_EQ(rises, 1000);
}

}  // namespace
