// rtl/normalizer.sv against Normalizer::normalize, bit-exact: every exponent class (component
// magnitudes below 2^e, e = 0..17) with edges (axis vectors, range limits, null and near-null
// vectors), then 10^6 random inputs, under random valid gaps and ready back-pressure.
#include <gtest/gtest.h>

#include <array>
#include <deque>
#include <functional>
#include <sstream>
#include <string>

#include "Vnormalizer.h"
#include "fixed_point.hpp"
#include "normalizer.hpp"
#include "rtl_harness.hpp"
#include "stream_bench.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

constexpr int NB = fmt::NormalInBits, UB = fmt::UnitBits;
using Vec = std::array<i64, 3>;

std::uint64_t pack(const Vec& v) {
  std::uint64_t w = 0;
  for (int c = 0; c < 3; ++c) w |= wrap_unsigned(v[c], NB) << (c * NB);
  return w;
}

// Streams inputs from next() (false when done), checks each output and the payload order.
std::uint64_t run(const std::function<bool(Vec&)>& next, int gap_pct, int bp_pct, std::uint64_t seed) {
  Harness<Vnormalizer> h;
  std::mt19937_64 rng(seed);
  StreamBench<Vec> b(rng, gap_pct, bp_pct);  // the input of each output
  b.report_limit = 5;
  const StreamPorts ports{h.dut.valid_i, h.dut.ready_o, h.dut.valid_o, h.dut.ready_i};
  reset_stream(h, ports);
  std::uint32_t tag = 0, want = 0;
  Vec v{};
  b.run(
      h, ports, [] { return true; },
      [&] {
        if (!next(v)) return false;
        h.dut.normal_i = pack(v);
        h.dut.payload_i = tag;
        return true;
      },
      [&](std::deque<Vec>& inflight) {
        inflight.push_back(v);
        ++tag;
      },
      [&](const Vec& in) {
        const Normalizer::Unit u = Normalizer::normalize(in[0], in[1], in[2]);
        bool same = h.dut.payload_o == want && h.dut.null_o == u.null;
        for (int c = 0; c < 3; ++c) same &= wrap_signed(static_cast<i128>(h.dut.unit_o >> (c * UB)), UB) == u.n[c];
        ++want;
        if (same) return std::string();
        std::ostringstream diff;
        diff << "in (" << in[0] << ", " << in[1] << ", " << in[2] << "): rtl ("
             << wrap_signed(static_cast<i128>(h.dut.unit_o), UB) << ", "
             << wrap_signed(static_cast<i128>(h.dut.unit_o >> UB), UB) << ", "
             << wrap_signed(static_cast<i128>(h.dut.unit_o >> 2 * UB), UB) << ") null " << int(h.dut.null_o)
             << " tag " << h.dut.payload_o << ", model (" << u.n[0] << ", " << u.n[1] << ", " << u.n[2]
             << ") null " << u.null << " tag " << want - 1;
        return diff.str();
      });
  EXPECT_EQ(b.mismatches, 0u);
  return b.checked;
}

constexpr i64 Hi = i64{1} << (NB - 1);
i64 clampin(i64 v) { return std::max(-Hi, std::min(Hi - 1, v)); }

}  // namespace

TEST(RtlNormalizer, EveryExponentClassAndEdges) {
  std::mt19937_64 rng(11);
  std::vector<Vec> in;
  for (i64 x = -3; x <= 3; ++x)
    for (i64 y = -3; y <= 3; ++y)
      for (i64 z = -3; z <= 3; ++z) in.push_back({x, y, z});
  for (int e = 0; e < NB; ++e) {
    const i64 lim = i64{1} << e;
    for (i64 s : {lim - 1, lim, -lim, -(lim - 1)}) {
      const i64 v = clampin(s);
      in.push_back({v, 0, 0}), in.push_back({0, v, 0}), in.push_back({0, 0, v});
      in.push_back({v, v, v}), in.push_back({v, clampin(-v), 1}), in.push_back({-Hi, -Hi, -Hi});
    }
    for (int k = 0; k < 20000; ++k) {
      auto r = [&] { return clampin(static_cast<i64>(rng() % (2 * lim + 1)) - lim); };
      in.push_back({r(), r(), r()});
    }
  }
  std::size_t i = 0;
  const std::uint64_t n = run([&](Vec& v) { if (i == in.size()) return false; v = in[i++]; return true; },
                              30, 30, 5);
  EXPECT_EQ(n, in.size());
}

TEST(RtlNormalizer, MillionRandom) {
  std::mt19937_64 rng(12);
  std::uint64_t k = 0;
  constexpr std::uint64_t N = 1000000;
  const std::uint64_t n = run([&](Vec& v) {
        if (k++ == N) return false;
        const int e = static_cast<int>(rng() % NB) + 1;
        for (auto& c : v) c = wrap_signed(static_cast<i128>(rng()), e);
        return true;
      },
      20, 20, 6);
  EXPECT_EQ(n, N);
}

TEST(RtlNormalizer, FullThroughputNoStalls) {
  std::mt19937_64 rng(13);
  std::uint64_t k = 0;
  constexpr std::uint64_t N = 100000;
  const std::uint64_t n = run([&](Vec& v) {
        if (k++ == N) return false;
        for (auto& c : v) c = wrap_signed(static_cast<i128>(rng()), NB);
        return true;
      },
      0, 0, 7);
  EXPECT_EQ(n, N);
}
