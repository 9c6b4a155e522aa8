// rtl/rsqrt_unit.sv against RsqrtUnit::normalize_mantissa + rsqrt_mant, exhaustively: every
// mantissa m' at RsqrtMantBits bits for every even shift j that can hold it (the whole reachable
// domain of the unit: for j >= 9 the 36-bit m has fewer bits than the mantissa, so only
// mantissas with zero low bits exist), random bits below the mantissa, m = 0, and random
// ce_i stalls (all stages held). Every seed-ROM row is read, so the SV table function and the C++ one cannot drift.
#include <gtest/gtest.h>

#include <deque>

#include "Vrsqrt_unit.h"
#include "normalizer.hpp"
#include "rtl_harness.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

constexpr int Latency = fmt::RsqrtStages;  // rtl/rsqrt_unit.sv's Stages

struct Bench {
  Harness<Vrsqrt_unit> h;
  std::mt19937_64 rng{3};
  Stalls stalls{rng, 0};
  std::deque<std::uint64_t> pipe;  // m values in flight, one per advancing clock
  std::uint64_t checked = 0, bad = 0;
  std::vector<bool> rows_seen = std::vector<bool>(1 << RsqrtUnit::P, false);

  void push(std::uint64_t m) {
    while (stalls.stall()) {  // a held pipe must not move
      h.dut.ce_i = 0;     // every stage holds
      h.dut.m_i = rng();  // garbage while stalled
      const auto y = h.dut.y_o;
      h.tick();
      if (h.dut.y_o != y) ++bad;
    }
    h.dut.ce_i = 0x3FF;  // every stage loads
    h.dut.m_i = m;
    h.tick();
    pipe.push_back(m);
    if (pipe.size() > Latency) pipe.pop_front();
    if (pipe.size() == Latency) check(pipe.front());
  }
  void check(std::uint64_t m) {
    const RsqrtUnit::Mantissa mm = RsqrtUnit::normalize_mantissa(m);
    const std::uint32_t y = RsqrtUnit::rsqrt_mant(mm.mant);
    rows_seen[mm.mant >> (RsqrtUnit::W - RsqrtUnit::P)] = true;
    ++checked;
    if (h.dut.y_o != y || h.dut.j_o != mm.j || h.dut.null_o != mm.null) {
      if (bad++ < 5)
        ADD_FAILURE() << "m " << m << ": rtl y " << h.dut.y_o << " j " << int(h.dut.j_o) << " null "
                      << int(h.dut.null_o) << ", model y " << y << " j " << mm.j << " null " << mm.null;
    }
  }
  void flush() {
    for (int k = 0; k < Latency; ++k) push(0);
  }
};

}  // namespace

TEST(RtlRsqrtUnit, EveryMantissaEveryShift) {
  Bench r;
  r.stalls.pct = 2;
  std::uint64_t count = 0;
  constexpr int MBits = RsqrtUnit::MBits;
  for (int j = 0; j <= RsqrtUnit::MaxJ; ++j) {
    const int lost = std::max(0, 2 * j - (MBits - RsqrtUnit::W));  // mantissa bits below m's LSB
    for (std::uint64_t mant = RsqrtUnit::MantLo; mant < RsqrtUnit::MantHi; ++mant) {
      if (mant & ((std::uint64_t{1} << lost) - 1)) continue;
      const std::uint64_t low = r.rng() & ((std::uint64_t{1} << (MBits - RsqrtUnit::W)) - 1);
      const std::uint64_t mprime = (mant << (MBits - RsqrtUnit::W)) | low;
      const std::uint64_t m = mprime >> (2 * j);
      ASSERT_EQ(RsqrtUnit::normalize_mantissa(m).mant, mant);
      ASSERT_EQ(RsqrtUnit::normalize_mantissa(m).j, j);
      r.push(m);
      ++count;
    }
  }
  r.push(0);  // null
  ++count;
  r.flush();
  std::printf("rsqrt_unit: %llu (mantissa, shift) inputs + m = 0, %llu checked\n",
              static_cast<unsigned long long>(count - 1), static_cast<unsigned long long>(r.checked));
  EXPECT_EQ(r.bad, 0u);
  EXPECT_GE(r.checked, count);
  for (int row = 1 << (RsqrtUnit::P - 2); row < (1 << RsqrtUnit::P); ++row)
    EXPECT_TRUE(r.rows_seen[row]) << "seed row " << row << " never read";
}
