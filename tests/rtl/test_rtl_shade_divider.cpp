// rtl/shade_divider.sv against ShadeDivider (model/twins/shade_divider.hpp): random and corner
// numerators and depths (every depth of a narrow depth word, every power of two and its
// neighbours of a wide one, zero, negative and saturating numerators), under input gaps and
// output back-pressure; the payload checks order. Built for the default formats and for a narrow
// configuration whose shift is often not positive (PARAMS in tests/rtl/CMakeLists.txt).
#include <gtest/gtest.h>

#include <array>
#include <deque>
#include <string>

#include "Vshade_divider.h"
#include "rtl_harness.hpp"
#include "shade_divider.hpp"
#include "stream_bench.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

#ifdef WATKINS_RTL_PARAM_DepthBits
constexpr int DepthBits = WATKINS_RTL_PARAM_DepthBits;
constexpr int AttrBits = WATKINS_RTL_PARAM_AttrBits;
constexpr int AttrFracBits = WATKINS_RTL_PARAM_AttrFracBits;
constexpr int RecipBits = WATKINS_RTL_PARAM_RecipBits;
#else
constexpr int DepthBits = fmt::DepthBits;
constexpr int AttrBits = fmt::ChannelBits;
constexpr int AttrFracBits = fmt::FracBits;
constexpr int RecipBits = fmt::Eq2RecipBits;
#endif

ChannelFormats formats() {
  Config c;
  c.eq2 = true;
  c.depth_bits = DepthBits;
  c.shade.frac_bits = AttrFracBits;
  c.shade.int_bits = AttrBits - AttrFracBits;
  c.eq2_recip_bits = RecipBits;
  return c.channels(ShadingMode::Gouraud);
}

struct Beat {
  std::uint32_t depth = 0;
  std::array<i64, 3> num{};
};

// num_i: {B, G, R}, AttrBits each, R at bit 0, in the Verilated port's 32-bit words.
template <class Port>
void write_numerators(Port& port, const std::array<i64, 3>& v) {
  constexpr int Words = (3 * AttrBits + 31) / 32;
  std::array<std::uint32_t, Words> w{};
  for (int c = 0; c < 3; ++c)
    for (int b = 0; b < AttrBits; ++b)
      if ((static_cast<std::uint64_t>(v[c]) >> b) & 1) w[(c * AttrBits + b) / 32] |= 1u << ((c * AttrBits + b) % 32);
  if constexpr (Words == 1) {
    port = w[0];
  } else if constexpr (Words == 2) {
    port = (std::uint64_t{w[1]} << 32) | w[0];
  } else {
    for (int i = 0; i < Words; ++i) port[i] = w[i];
  }
}

// A numerator the divider may meet: mostly a shade times a depth ([0, 256) levels), some
// negative (interpolation's overshoot), some of any value the word holds.
i64 numerator(std::mt19937_64& rng) {
  const i64 word_lo = -(i64{1} << (AttrBits - 1)), word_hi = (i64{1} << (AttrBits - 1)) - 1;
  const i64 levels = i64{256} << AttrFracBits;
  switch (rng() % 8) {
    case 0: return std::max(word_lo, -static_cast<i64>(rng() % 1000));
    case 1: return word_lo + static_cast<i64>(rng() % 4);
    case 2: return word_hi - static_cast<i64>(rng() % 4);
    case 3: return static_cast<i64>(rng() % 3);
    default: return std::clamp<i64>(static_cast<i64>(rng() % static_cast<std::uint64_t>(levels)), word_lo, word_hi);
  }
}

template <class Next>
void run(Next next, int gap_pct, int bp_pct, std::uint64_t seed, std::uint64_t* checked) {
  Harness<Vshade_divider> h;
  const ShadeDivider twin(formats());
  std::mt19937_64 rng(seed);
  StreamBench<Beat> b(rng, gap_pct, bp_pct);
  b.report_limit = 5;
  const StreamPorts ports{h.dut.valid_i, h.dut.ready_o, h.dut.valid_o, h.dut.ready_i};
  reset_stream(h, ports);
  h.dut.ready_next_i = 1;  // LookAhead = 0 in the unit: not read
  std::uint32_t tag = 0, want_tag = 0;
  Beat beat;
  b.run(
      h, ports, [] { return true; },
      [&] {
        if (!next(beat)) return false;
        h.dut.depth_i = beat.depth;
        write_numerators(h.dut.num_i, beat.num);
        h.dut.payload_i = tag;
        return true;
      },
      [&](std::deque<Beat>& inflight) {
        inflight.push_back(beat);
        ++tag;
      },
      [&](const Beat& in) {
        const std::array<std::uint8_t, 3> want = twin.shade(in.depth, in.num);
        const std::uint32_t got = h.dut.rgb_o;  // {R, G, B}, red on top
        const std::array<std::uint8_t, 3> rgb{static_cast<std::uint8_t>(got >> 16), static_cast<std::uint8_t>(got >> 8),
                                              static_cast<std::uint8_t>(got)};
        const bool in_order = h.dut.payload_o == want_tag++;
        if (rgb == want && in_order) return std::string();
        return "depth " + std::to_string(in.depth) + " n (" + std::to_string(in.num[0]) + ", " +
               std::to_string(in.num[1]) + ", " + std::to_string(in.num[2]) + "): rtl (" + std::to_string(rgb[0]) +
               ", " + std::to_string(rgb[1]) + ", " + std::to_string(rgb[2]) + "), model (" + std::to_string(want[0]) +
               ", " + std::to_string(want[1]) + ", " + std::to_string(want[2]) + ")";
      });
  *checked = b.checked;
  EXPECT_EQ(b.mismatches, 0u);
}

}  // namespace

// Every power of two of the depth word and its neighbours (every depth for a narrow word), each
// with random numerators, at full speed.
TEST(RtlShadeDivider, EveryDepthClass) {
  std::mt19937_64 rng(3);
  std::vector<std::uint32_t> depths{0};
  const std::uint32_t top = DepthBits >= 32 ? ~0u : (1u << DepthBits) - 1;
  if (DepthBits <= 12) {
    for (std::uint32_t d = 1; d <= top; ++d) depths.push_back(d);
  } else {
    for (int p = 0; p < DepthBits; ++p)
      for (std::uint32_t d : {(1u << p) - 1, 1u << p, (1u << p) + 1, (1u << p) + (1u << p) / 3})
        if (d <= top) depths.push_back(d);
    depths.push_back(top);
  }
  constexpr int PerDepth = 40;
  std::size_t i = 0;
  int k = 0;
  std::uint64_t checked = 0;
  run([&](Beat& b) {
        if (i >= depths.size()) return false;
        b.depth = depths[i];
        for (i64& n : b.num) n = numerator(rng);
        if (++k == PerDepth) k = 0, ++i;
        return true;
      },
      0, 0, 1, &checked);
  EXPECT_EQ(checked, depths.size() * PerDepth);
}

// Random depths and numerators under random input gaps and output stalls.
TEST(RtlShadeDivider, RandomUnderStalls) {
  std::mt19937_64 rng(11);
  constexpr int N = 200000;
  int k = 0;
  std::uint64_t checked = 0;
  run([&](Beat& b) {
        if (k++ == N) return false;
        b.depth = static_cast<std::uint32_t>(rng() & ((std::uint64_t{1} << DepthBits) - 1));
        if (rng() % 16 == 0) b.depth >>= rng() % DepthBits;  // small depths too
        for (i64& n : b.num) n = numerator(rng);
        return true;
      },
      30, 30, 2, &checked);
  EXPECT_EQ(checked, static_cast<std::uint64_t>(N));
}
