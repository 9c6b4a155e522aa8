// rtl/edge_incrementer.sv against EdgeIncrementer::step, with random valid gaps and back-pressure;
// built again with EdgeOrder = 3 (test_rtl_edge_incrementer_cubic: the forward differences
// {d3, d2, d1} in slope_i, stepped with the value).
#include <gtest/gtest.h>

#include <deque>
#include <string>

#include "Vedge_incrementer.h"
#include "edge_incrementer.hpp"
#include "rtl_harness.hpp"
#include "stream_bench.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

constexpr int CB = fmt::ChannelBits;
constexpr int NC = fmt::NumChannels;
#ifdef WATKINS_RTL_PARAM_EdgeOrder
constexpr int Order = WATKINS_RTL_PARAM_EdgeOrder;
#else
constexpr int Order = 1;
#endif
constexpr int VB = NC * CB;  // one channel vector

ChannelFormats formats() {
  Config c;
  c.edge_order = Order;
  return c.channels(ShadingMode::Gouraud);
}

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
  StreamBench<Expect> b(rng, gap_pct, bp_pct);
  b.max_cycles = 100u * count + 1000;
  const StreamPorts ports{h.dut.valid_i, h.dut.ready_o, h.dut.valid_o, h.dut.ready_i};
  reset_stream(h, ports);
  int sent = 0;
  ActiveEdge cur;
  b.run(
      h, ports, [&] { return sent < count; },
      [&] {
        for (int c = 0; c < NC; ++c) {
          cur.rec.value[c] = random_channel(rng);
          cur.rec.slope[c] = random_channel(rng);
          set_bits(h.dut.value_i, c * CB, CB, to_bits(cur.rec.value[c], CB));
          set_bits(h.dut.slope_i, c * CB, CB, to_bits(cur.rec.slope[c], CB));
          if (Order == 3) {
            cur.rec.d2[c] = random_channel(rng);
            cur.rec.d3[c] = random_channel(rng);
            set_bits(h.dut.slope_i, VB + c * CB, CB, to_bits(cur.rec.d2[c], CB));
            set_bits(h.dut.slope_i, 2 * VB + c * CB, CB, to_bits(cur.rec.d3[c], CB));
          }
        }
        cur.remaining = rng() % 3 == 0 ? static_cast<int>(rng() % 3) : static_cast<int>(rng() % 8192);
        h.dut.remaining_i = cur.remaining;
        h.dut.payload_i = static_cast<std::uint32_t>(sent);
        return true;
      },
      [&](std::deque<Expect>& expect) {
        ActiveEdge stepped = cur;
        EdgeIncrementer::step(stepped, formats());
        expect.push_back({stepped, stepped.remaining <= 0, static_cast<std::uint32_t>(sent)});
        ++sent;
      },
      [&](const Expect& x) {
        std::string diff;
        for (int c = 0; c < NC; ++c) {
          if (get_signed(h.dut.value_o, c * CB, CB) != x.e.rec.value[c]) diff += " value ch " + std::to_string(c);
          if (get_signed(h.dut.slope_o, c * CB, CB) != x.e.rec.slope[c]) diff += " slope ch " + std::to_string(c);
          if (Order == 3 && get_signed(h.dut.slope_o, VB + c * CB, CB) != x.e.rec.d2[c]) diff += " d2 ch " + std::to_string(c);
          if (Order == 3 && get_signed(h.dut.slope_o, 2 * VB + c * CB, CB) != x.e.rec.d3[c]) diff += " d3 ch " + std::to_string(c);
        }
        if (h.dut.remaining_o != (static_cast<std::uint32_t>(x.e.remaining) & 0x1FFF)) diff += " remaining";
        if (h.dut.retire_o != x.retire) diff += " retire (remaining " + std::to_string(x.e.remaining) + ")";
        if (h.dut.payload_o != x.tag) diff += " payload";
        return diff.empty() ? diff : "edge " + std::to_string(x.tag) + " differs in" + diff;
      });
  EXPECT_EQ(b.checked, static_cast<std::uint64_t>(count));
  EXPECT_EQ(b.mismatches, 0u);
}

}  // namespace

TEST(RtlEdgeIncrementer, FullRate) { run(0, 0, 20000, 1); }
TEST(RtlEdgeIncrementer, GapsAndBackPressure) { run(40, 40, 20000, 2); }
TEST(RtlEdgeIncrementer, HeavyBackPressure) { run(5, 85, 5000, 3); }
