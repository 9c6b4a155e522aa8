// rtl/phong_power.sv against PhongShader::power_narrow: every cos(s) (0..2^16) with every n
// (0..255) at the block's full rate (one input every other clock), so every row of both tables is
// read as row i and as row i + 1 and the SV table functions and the C++ ones cannot drift; random
// inputs under random enable stalls (every register holds) and input gaps; one input's latency
// and value by hand.
#include <gtest/gtest.h>

#include <deque>

#include "Vphong_power.h"
#include "phong_shader.hpp"
#include "rtl_harness.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

constexpr int Latency = 15;  // the take's clock to the first clock valid_o is high

struct Bench {
  Harness<Vphong_power> h;
  std::mt19937_64 rng{41};
  std::deque<std::uint32_t> expected;
  std::uint64_t checked = 0, bad = 0;
  int stall_pct = 0, gap_pct = 0;

  Bench() {
    h.dut.en_i = 1;
    h.dut.valid_i = 0;
    h.reset();
  }
  // One clock: takes (cs, n) when `offer` and the block is ready and enabled; returns whether it did.
  bool clock(bool offer, std::uint32_t cs, int n) {
    const bool en = !(stall_pct > 0 && static_cast<int>(rng() % 100) < stall_pct);
    h.dut.en_i = en;
    h.dut.valid_i = offer;
    h.dut.cs_i = offer ? cs : static_cast<std::uint32_t>(rng() & 0x1ffff);
    h.dut.n_i = offer ? n : static_cast<int>(rng() & 255);
    const bool took = en && offer && h.dut.ready_o;
    if (took) expected.push_back(static_cast<std::uint32_t>(PhongShader::power_narrow(cs, n)));
    const bool valid_before = h.dut.valid_o;
    const std::uint32_t pow_before = h.dut.pow_o;
    h.tick();
    if (!en) {
      if (h.dut.valid_o != valid_before || h.dut.pow_o != pow_before) ++bad;  // a held block holds
    } else if (h.dut.valid_o) {
      if (expected.empty()) {
        ++bad;
      } else {
        ++checked;
        if (h.dut.pow_o != expected.front() && bad++ < 5)
          ADD_FAILURE() << "rtl " << h.dut.pow_o << ", model " << expected.front();
        expected.pop_front();
      }
    }
    return took;
  }
  // Offers (cs, n) until the block takes it (random gaps before).
  void push(std::uint32_t cs, int n) {
    while (!clock(!(gap_pct > 0 && static_cast<int>(rng() % 100) < gap_pct), cs, n)) {
    }
  }
  void drain() {
    for (int k = 0; k < 4 * Latency && !expected.empty(); ++k) clock(false, 0, 0);
    stall_pct = 0;
    for (int k = 0; k < 2 * Latency && !expected.empty(); ++k) clock(false, 0, 0);
  }
};

TEST(RtlPhongPower, EveryCosEveryN) {
  Bench b;
  for (int n = 0; n < 256; ++n)
    for (std::uint32_t cs = 0; cs <= (1u << narrow::CosBits); ++cs) b.push(cs, n);
  b.drain();
  EXPECT_EQ(b.bad, 0u);
  EXPECT_TRUE(b.expected.empty());
  EXPECT_EQ(b.checked, 256ull * ((1u << narrow::CosBits) + 1));
}

TEST(RtlPhongPower, StallsAndGaps) {
  Bench b;
  b.stall_pct = 30;
  b.gap_pct = 40;
  std::uint64_t pushed = 0;
  for (int k = 0; k < 400000; ++k) {
    // Half near 1 (the highlights, where lc < 1), half anywhere, cs = 0 now and then.
    const std::uint32_t cs = k % 97 == 0 ? 0
                             : (k & 1) ? static_cast<std::uint32_t>(b.rng() % ((1u << narrow::CosBits) + 1))
                                       : (1u << narrow::CosBits) - static_cast<std::uint32_t>(b.rng() % 4096);
    b.push(cs, static_cast<int>(b.rng() & 255));
    ++pushed;
  }
  b.drain();
  EXPECT_EQ(b.bad, 0u);
  EXPECT_TRUE(b.expected.empty());
  EXPECT_EQ(b.checked, pushed);
}

TEST(RtlPhongPower, OneInputByHand) {
  Bench b;
  // cos(s) = 3/4, n = 3: 27/64 = 0.421875, 27648 at 16 fraction bits; the tables give it within
  // a few units of 2^-16.
  const std::uint32_t cs = 3u << 14;
  ASSERT_TRUE(b.h.dut.ready_o);
  b.h.dut.en_i = 1;
  b.h.dut.valid_i = 1;
  b.h.dut.cs_i = cs;
  b.h.dut.n_i = 3;
  b.h.tick();  // the take's clock
  b.h.dut.valid_i = 0;
  int clocks = 1;
  while (!b.h.dut.valid_o && clocks < 100) b.h.tick(), ++clocks;
  EXPECT_EQ(clocks, Latency);
  EXPECT_EQ(b.h.dut.pow_o, static_cast<std::uint32_t>(PhongShader::power_narrow(cs, 3)));
  EXPECT_NEAR(double(b.h.dut.pow_o), 27648.0, 8.0);
}

}  // namespace
