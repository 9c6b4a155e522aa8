// rtl/edge_incrementer.sv against EdgeIncrementer::step, with random valid gaps and back-pressure.
#include <gtest/gtest.h>

#include <deque>

#include "Vedge_incrementer.h"
#include "edge_incrementer.hpp"
#include "rtl_harness.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

constexpr int CB = fmt::ChannelBits;
constexpr int NC = fmt::NumChannels;

i64 random_channel(std::mt19937_64& rng) {
  switch (rng() % 4) {
    case 0: return wrap_signed(static_cast<i128>(rng()), CB);                  // any word
    case 1: return (i64{1} << (CB - 1)) - 1 - static_cast<i64>(rng() % 4);    // near +max: wraps
    case 2: return -(i64{1} << (CB - 1)) + static_cast<i64>(rng() % 4);       // near -max
    default: return static_cast<i64>(rng() % (1u << 30)) - (1 << 29);         // typical
  }
}

struct Expect {
  ActiveEdge e;
  bool retire;
  std::uint32_t tag;
};

void run(int gap_pct, int bp_pct, int count, std::uint64_t seed) {
  Harness<Vedge_incrementer> h;
  std::mt19937_64 rng(seed);
  Stalls gaps{rng, gap_pct}, bp{rng, bp_pct};
  h.reset();
  std::deque<Expect> expect;
  int sent = 0, got = 0;
  h.dut.valid_i = 0;
  ActiveEdge cur;
  while (got < count) {
    if (!h.dut.valid_i && sent < count && !gaps.stall()) {
      for (int c = 0; c < NC; ++c) {
        cur.rec.value[c] = random_channel(rng);
        cur.rec.slope[c] = random_channel(rng);
        set_bits(h.dut.value_i, c * CB, CB, to_bits(cur.rec.value[c], CB));
        set_bits(h.dut.slope_i, c * CB, CB, to_bits(cur.rec.slope[c], CB));
      }
      cur.remaining = rng() % 3 == 0 ? static_cast<int>(rng() % 3) : static_cast<int>(rng() % 8192);
      h.dut.remaining_i = cur.remaining;
      h.dut.payload_i = static_cast<std::uint32_t>(sent);
      h.dut.valid_i = 1;
    }
    h.dut.ready_i = !bp.stall();
    h.dut.eval();
    const bool in_fire = h.dut.valid_i && h.dut.ready_o;
    if (h.dut.valid_o && h.dut.ready_i) {
      ASSERT_FALSE(expect.empty());
      const Expect& x = expect.front();
      for (int c = 0; c < NC; ++c) {
        EXPECT_EQ(get_signed(h.dut.value_o, c * CB, CB), x.e.rec.value[c]) << "edge " << got << " ch " << c;
        EXPECT_EQ(get_signed(h.dut.slope_o, c * CB, CB), x.e.rec.slope[c]);
      }
      EXPECT_EQ(h.dut.remaining_o, static_cast<std::uint32_t>(x.e.remaining) & 0x1FFF);
      EXPECT_EQ(h.dut.retire_o, x.retire) << "remaining " << x.e.remaining;
      EXPECT_EQ(h.dut.payload_o, x.tag);
      expect.pop_front();
      ++got;
    }
    if (in_fire) {
      ActiveEdge stepped = cur;
      EdgeIncrementer::step(stepped);
      expect.push_back({stepped, stepped.remaining <= 0, static_cast<std::uint32_t>(sent)});
      ++sent;
    }
    h.tick();
    if (in_fire) h.dut.valid_i = 0;
    ASSERT_LT(h.cycles, 100u * count + 1000) << "hang";
  }
}

}  // namespace

TEST(RtlEdgeIncrementer, FullRate) { run(0, 0, 20000, 1); }
TEST(RtlEdgeIncrementer, GapsAndBackPressure) { run(40, 40, 20000, 2); }
TEST(RtlEdgeIncrementer, HeavyBackPressure) { run(5, 85, 5000, 3); }
