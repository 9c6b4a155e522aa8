// rtl/compact_normalizer.sv against Normalizer::normalize (values) and CompactNormalizerTiming
// (cycles), and with WATKINS_PHONG_NARROW (the bench test_rtl_compact_normalizer_narrow)
// rtl/compact_normalizer_narrow.sv against Normalizer::normalize_narrow and
// CompactNormalizerNarrowTiming, where the input's clamp to 16 bits acts at the range limits and
// every rsqrt table row is read: every unit vector, null flag and payload equal to the twin's, and on every clock
// ready_o and valid_o equal to the cycle twin's, under random valid gaps and ready back-pressure.
// Inputs: every exponent class (component magnitudes below 2^e, e = 0..17) with the edges (axis
// vectors, the range limits -2^17 and 2^17 - 1, null and near-null vectors), random normals of
// every length; a run at full rate (one normal per 5 clocks, the latency by hand); back-pressure
// from light to heavy.
#include <gtest/gtest.h>

#include <array>
#include <deque>
#include <sstream>
#include <string>
#include <vector>

#ifdef WATKINS_PHONG_NARROW
#include "Vcompact_normalizer_narrow.h"
#include "compact_normalizer_narrow_timing.hpp"
#else
#include "Vcompact_normalizer.h"
#include "compact_normalizer_timing.hpp"
#endif
#include "fixed_point.hpp"
#include "normalizer.hpp"
#include "rtl_harness.hpp"
#include "stream_bench.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

// The block under test and its twins: the model's formats, or the narrow ones.
#ifdef WATKINS_PHONG_NARROW
#define SUITE RtlCompactNormalizerNarrow
using Dut = Vcompact_normalizer_narrow;
using Timing = CompactNormalizerNarrowTiming;
Normalizer::Unit twin(i64 x, i64 y, i64 z) { return Normalizer::normalize_narrow(x, y, z); }
#else
#define SUITE RtlCompactNormalizer
using Dut = Vcompact_normalizer;
using Timing = CompactNormalizerTiming;
Normalizer::Unit twin(i64 x, i64 y, i64 z) { return Normalizer::normalize(x, y, z); }
#endif

constexpr int NB = fmt::NormalInBits, UB = fmt::UnitBits;
constexpr int PayloadBits = WATKINS_RTL_PARAM_PayloadBits;  // PARAMS in tests/rtl/CMakeLists.txt
using Vec = std::array<i64, 3>;
constexpr i64 Hi = i64{1} << (NB - 1);

std::uint64_t pack(const Vec& v) {
  std::uint64_t w = 0;
  for (int c = 0; c < 3; ++c) w |= wrap_unsigned(v[c], NB) << (c * NB);
  return w;
}

struct Result {
  std::uint64_t checked = 0, mismatches = 0, cycle_mismatches = 0, cycles = 0;
};

// Streams the inputs under the given gaps and back-pressure: each output against the twin, each
// clock against the cycle twin.
Result run(const std::vector<Vec>& in, int gap_pct, int bp_pct, std::uint64_t seed) {
  Harness<Dut> h;
  std::mt19937_64 rng(seed);
  StreamBench<std::size_t> b(rng, gap_pct, bp_pct);  // the index of each output's input
  b.report_limit = 5;
  const StreamPorts ports{h.dut.valid_i, h.dut.ready_o, h.dut.valid_o, h.dut.ready_i};
  reset_stream(h, ports);
  Timing timing;
  Result r;
  b.on_clock = [&] {
    if (bool(h.dut.ready_o) != timing.ready() || bool(h.dut.valid_o) != timing.valid()) {
      if (r.cycle_mismatches++ < 5)
        ADD_FAILURE() << "cycle " << h.cycles << ": rtl ready " << int(h.dut.ready_o) << " valid "
                      << int(h.dut.valid_o) << "; twin " << timing.ready() << " " << timing.valid();
    }
    timing.clock(h.dut.valid_i, h.dut.ready_i);
  };
  const std::uint64_t mask = (std::uint64_t{1} << PayloadBits) - 1;
  std::size_t next = 0;
  const std::uint64_t start = h.cycles;
  b.run(
      h, ports, [&] { return next < in.size(); },
      [&] {
        h.dut.normal_i = pack(in[next]);
        h.dut.payload_i = static_cast<std::uint32_t>((next * 0x9E3779B97F4A7C15ull >> 20) & mask);
        return true;
      },
      [&](std::deque<std::size_t>& inflight) { inflight.push_back(next++); },
      [&](std::size_t k) {
        const Vec& v = in[k];
        const Normalizer::Unit u = twin(v[0], v[1], v[2]);
        const std::uint64_t tag = (k * 0x9E3779B97F4A7C15ull >> 20) & mask;
        bool same = h.dut.payload_o == tag && bool(h.dut.null_o) == u.null;
        for (int c = 0; c < 3; ++c) same &= wrap_signed(static_cast<i128>(h.dut.unit_o >> (c * UB)), UB) == u.n[c];
        if (same) return std::string();
        std::ostringstream d;
        d << "in (" << v[0] << ", " << v[1] << ", " << v[2] << "): rtl (";
        for (int c = 0; c < 3; ++c) d << wrap_signed(static_cast<i128>(h.dut.unit_o >> (c * UB)), UB) << (c < 2 ? ", " : "");
        d << ") null " << int(h.dut.null_o) << " payload " << h.dut.payload_o << "; model (" << u.n[0] << ", " << u.n[1]
          << ", " << u.n[2] << ") null " << u.null << " payload " << tag;
        return d.str();
      });
  r.checked = b.checked;
  r.mismatches = b.mismatches;
  r.cycles = h.cycles - start;
  EXPECT_EQ(r.mismatches, 0u);
  EXPECT_EQ(r.cycle_mismatches, 0u);
  EXPECT_EQ(r.checked, in.size());
  return r;
}

i64 clampin(i64 v) { return std::max(-Hi, std::min(Hi - 1, v)); }

std::vector<Vec> classes_and_edges(std::mt19937_64& rng, int per_class) {
  std::vector<Vec> in;
  for (i64 x = -2; x <= 2; ++x)
    for (i64 y = -2; y <= 2; ++y)
      for (i64 z = -2; z <= 2; ++z) in.push_back({x, y, z});  // the null vector and near-null ones
  for (int e = 0; e < NB; ++e) {
    const i64 lim = i64{1} << e;
    for (i64 s : {lim - 1, lim, -lim, -(lim - 1)}) {
      const i64 v = clampin(s);
      in.push_back({v, 0, 0}), in.push_back({0, v, 0}), in.push_back({0, 0, v});
      in.push_back({v, v, v}), in.push_back({v, clampin(-v), 1}), in.push_back({-Hi, -Hi, -Hi});
      in.push_back({Hi - 1, -Hi, Hi - 1});
    }
    for (int k = 0; k < per_class; ++k) {
      auto r = [&] { return clampin(static_cast<i64>(rng() % (2 * lim + 1)) - lim); };
      in.push_back({r(), r(), r()});
    }
  }
  return in;
}

std::vector<Vec> random_normals(std::mt19937_64& rng, int n) {
  std::vector<Vec> in(static_cast<std::size_t>(n));
  for (auto& v : in) {
    const int e = static_cast<int>(rng() % NB) + 1;
    for (auto& c : v) c = wrap_signed(static_cast<i128>(rng()), e);
  }
  return in;
}

}  // namespace

TEST(SUITE, EveryExponentClassAndEdgesUnderStalls) {
  std::mt19937_64 rng(31);
  run(classes_and_edges(rng, 2000), 30, 30, 5);
}

TEST(SUITE, RandomNormalsUnderStalls) {
  std::mt19937_64 rng(32);
  run(random_normals(rng, 1000000), 20, 40, 6);
}

#ifdef WATKINS_PHONG_NARROW
// Every row of the rsqrt table at its start and its last d: (a, 0, 0) with a^2 just above and
// below a row's boundary, a over 2^15..2^17 (n_c = a / 2, m = n_c^2 over [2^28, 2^32)), and
// sums of two squares that reach M = 2^32 - 1 (row 255, T[256] forced to 0).
TEST(SUITE, EveryTableRow) {
  std::vector<Vec> in;
  for (i64 a = 1; a < Hi; a += 1 + a / 512) in.push_back({a, 0, 0}), in.push_back({-a, a / 3, 0});
  for (i64 x = 46330; x < 46350; ++x)
    for (i64 y = 46330; y < 46350; ++y) in.push_back({x, y, 0}), in.push_back({x, -y, 1});
  run(in, 25, 25, 9);
}
#endif

// Every normal offered at once and taken at once: one per Period clocks, the first offered
// Latency clocks after its take.
TEST(SUITE, FullRateOnePerPeriod) {
  std::mt19937_64 rng(33);
  constexpr int N = 20000;
  const Result r = run(random_normals(rng, N), 0, 0, 7);
  // From the first offer to the last output taken: the wait for the first take (up to a period),
  // N periods, the latency.
  EXPECT_LE(r.cycles, std::uint64_t{Timing::Period} * (N + 1) + Timing::Latency + 1);
  EXPECT_GE(r.cycles, std::uint64_t{Timing::Period} * (N - 1) + Timing::Latency);
}

// Back-pressure from light to nearly always: the output load finds the register full in every
// relation to the schedule; the twin agrees clock for clock.
TEST(SUITE, BackPressureFromLightToHeavy) {
  std::mt19937_64 rng(34);
  const auto in = random_normals(rng, 6000);
  for (int bp : {10, 50, 80, 95}) run(in, 0, bp, 8 + static_cast<std::uint64_t>(bp));
}

// One normal alone: taken in the first period's last clock, offered Latency clocks after that.
TEST(SUITE, LatencyByHand) {
  Harness<Dut> h;
  const StreamPorts ports{h.dut.valid_i, h.dut.ready_o, h.dut.valid_o, h.dut.ready_i};
  reset_stream(h, ports);
  h.dut.normal_i = pack({3 << 14, -(4 << 14), 0});
  const auto [taken, offered] = take_and_offer(h, ports, 60);
  EXPECT_EQ(taken, Timing::Period - 1);
  EXPECT_EQ(offered - taken, Timing::Latency);
  // (3, -4, 0)/5 in Q2.14, as the twin rounds it
  const Normalizer::Unit u = twin(3 << 14, -(4 << 14), 0);
  EXPECT_EQ(wrap_signed(static_cast<i128>(h.dut.unit_o), UB), u.n[0]);
  EXPECT_EQ(wrap_signed(static_cast<i128>(h.dut.unit_o >> UB), UB), u.n[1]);
  EXPECT_NEAR(static_cast<double>(u.n[0]), 9830.4, 1.0);
}
