// rtl/span_reciprocal.sv against SpanReciprocal::of: every normalized mantissa (all 2^23 values
// of m, dx = m), every exponent class with random widths, under gaps and back-pressure.
#include <gtest/gtest.h>

#include <deque>
#include <string>

#include "Vspan_reciprocal.h"
#include "rtl_harness.hpp"
#include "span_reciprocal.hpp"
#include "stream_bench.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

constexpr int DxBits = fmt::ChannelBits + 1;

// Streams dx values from `next` (returns false when done) and checks every result.
template <class Next>
void run(Next next, int gap_pct, int bp_pct, std::uint64_t seed, std::uint64_t* checked) {
  Harness<Vspan_reciprocal> h;
  std::mt19937_64 rng(seed);
  StreamBench<i64> b(rng, gap_pct, bp_pct);  // the dx of each result
  b.report_limit = 5;
  const StreamPorts ports{h.dut.valid_i, h.dut.ready_o, h.dut.valid_o, h.dut.ready_i};
  reset_stream(h, ports);
  std::uint32_t tag = 0, want_tag = 0;
  i64 dx = 0;
  b.run(
      h, ports, [] { return true; },
      [&] {
        if (!next(dx)) return false;
        h.dut.dx_i = static_cast<std::uint64_t>(dx);
        h.dut.payload_i = tag;
        return true;
      },
      [&](std::deque<i64>& inflight) {
        inflight.push_back(dx);
        ++tag;
      },
      [&](i64 in) {
        const SpanReciprocal r = SpanReciprocal::of(in);
        const bool same = h.dut.recip_o == static_cast<std::uint32_t>(r.recip) &&
                          h.dut.p_o == static_cast<std::uint32_t>(r.p) && h.dut.payload_o == want_tag++;
        if (same) return std::string();
        return "dx " + std::to_string(in) + ": rtl recip " + std::to_string(h.dut.recip_o) + " p " +
               std::to_string(int(h.dut.p_o)) + ", model recip " + std::to_string(r.recip) + " p " + std::to_string(r.p);
      });
  *checked = b.checked;
  EXPECT_EQ(b.mismatches, 0u);
}

}  // namespace

TEST(RtlSpanReciprocal, EveryMantissa) {
  constexpr i64 lo = i64{1} << (fmt::RecipBits - 1), hi = i64{1} << fmt::RecipBits;
  i64 m = lo;
  std::uint64_t checked = 0;
  run([&](i64& dx) { if (m >= hi) return false; dx = m++; return true; }, 0, 0, 1, &checked);
  EXPECT_EQ(checked, static_cast<std::uint64_t>(hi - lo));
}

TEST(RtlSpanReciprocal, EveryExponentRandomAndEdges) {
  std::mt19937_64 rng(7);
  int p = 0, k = 0;
  constexpr int PerClass = 20000;
  std::uint64_t checked = 0;
  run([&](i64& dx) {
        if (p >= DxBits - 1) return false;
        const i64 base = i64{1} << p;
        switch (k) {  // exact powers of two, all-ones, then random in [2^p, 2^(p+1))
          case 0: dx = base; break;
          case 1: dx = 2 * base - 1; break;
          case 2: dx = base + 1; break;
          default: dx = base + static_cast<i64>(rng() & static_cast<std::uint64_t>(base - 1)); break;
        }
        if (++k == PerClass) { k = 0; ++p; }
        return true;
      },
      30, 30, 2, &checked);
  EXPECT_EQ(checked, static_cast<std::uint64_t>(PerClass) * (DxBits - 1));
}
