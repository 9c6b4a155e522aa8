// rtl/compact_phong_power.sv against PhongShader::power_narrow in its 5-clock schedule: every
// cos(s) (0..2^16) with every n (0..255) at full rate (an input every period), so every row of
// both tables is read as row i and as row i + 1; random inputs under random enable stalls (every
// register and the phase hold) and periods without an input; one input's latency and value by hand.
#include <gtest/gtest.h>

#include <deque>

#include "Vcompact_phong_power.h"
#include "phong_shader.hpp"
#include "rtl_harness.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

constexpr int Latency = 16;  // the take's clock to the first clock of the power's period

struct Bench {
  Harness<Vcompact_phong_power> h;
  std::mt19937_64 rng{43};
  std::deque<std::uint32_t> expected;
  std::uint64_t checked = 0, bad = 0;
  int ph = 0;  // the parent's phase
  int stall_pct = 0, gap_pct = 0;

  Bench() {
    h.dut.en_i = 1;
    h.dut.take_i = 0;
    h.dut.ph_i = 0;
    h.reset();
  }
  // One clock; in phase 4 takes (cs, n) when `offer`. Returns whether it took.
  bool clock(bool offer, std::uint32_t cs, int n) {
    const bool en = !(stall_pct > 0 && static_cast<int>(rng() % 100) < stall_pct);
    h.dut.en_i = en;
    h.dut.ph_i = ph;
    const bool took = en && offer && ph == 4;
    h.dut.take_i = ph == 4 && offer;
    h.dut.cs_i = offer ? cs : static_cast<std::uint32_t>(rng() & 0x1ffff);
    h.dut.n_i = offer ? n : static_cast<int>(rng() & 255);
    if (took) expected.push_back(static_cast<std::uint32_t>(PhongShader::power_narrow(cs, n)));
    const bool valid_before = h.dut.valid_o;
    const std::uint32_t pow_before = h.dut.pow_o;
    h.tick();
    if (!en) {
      if (h.dut.valid_o != valid_before || h.dut.pow_o != pow_before) ++bad;  // a held block holds
      return false;
    }
    ph = ph == 4 ? 0 : ph + 1;
    if (ph == 0 && h.dut.valid_o) {  // a new period: the power of the input taken 3 periods ago
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
  void push(std::uint32_t cs, int n) {
    for (;;) {
      const bool offer = ph == 4 && !(gap_pct > 0 && static_cast<int>(rng() % 100) < gap_pct);
      if (clock(offer, cs, n)) return;
    }
  }
  void drain() {
    stall_pct = 0;
    for (int k = 0; k < 5 * Latency && !expected.empty(); ++k) clock(false, 0, 0);
  }
};

TEST(RtlCompactPhongPower, EveryCosEveryN) {
  Bench b;
  for (int n = 0; n < 256; ++n)
    for (std::uint32_t cs = 0; cs <= (1u << narrow::CosBits); ++cs) b.push(cs, n);
  b.drain();
  EXPECT_EQ(b.bad, 0u);
  EXPECT_TRUE(b.expected.empty());
  EXPECT_EQ(b.checked, 256ull * ((1u << narrow::CosBits) + 1));
}

TEST(RtlCompactPhongPower, StallsAndGaps) {
  Bench b;
  b.stall_pct = 30;
  b.gap_pct = 40;
  std::uint64_t pushed = 0;
  for (int k = 0; k < 300000; ++k) {
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

TEST(RtlCompactPhongPower, OneInputByHand) {
  Bench b;
  while (b.ph != 4) b.clock(false, 0, 0);
  const std::uint32_t cs = 3u << 14;  // 3/4, n = 3: 27/64 = 27648 at 16 fraction bits
  ASSERT_TRUE(b.clock(true, cs, 3));  // the take's clock
  int clocks = 1;
  while (!b.h.dut.valid_o && clocks < 100) b.clock(false, 0, 0), ++clocks;
  EXPECT_EQ(clocks, Latency);
  EXPECT_EQ(b.h.dut.pow_o, static_cast<std::uint32_t>(PhongShader::power_narrow(cs, 3)));
  EXPECT_NEAR(double(b.h.dut.pow_o), 27648.0, 8.0);
  EXPECT_EQ(b.bad, 0u);
}

}  // namespace
