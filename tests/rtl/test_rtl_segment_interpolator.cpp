// rtl/segment_interpolator.sv against SegmentInterpolator::setup/fragment/step: random segments
// (realistic and full-range channel words, spans narrower than a pixel, spans clipped at 0 and
// at the width, empty and reversed spans, negative slopes) with end-of-line markers between
// them, under random valid gaps and back-pressure. Also measures the fragment rate.
// Built once per configuration (tests/rtl/CMakeLists.txt): the default formats, and narrow and
// odd ones (a depth word without fraction bits, shades with none, normals with more fraction
// bits than the normalizer reads, fewer than X's headroom), each compared with the twin set up
// for the same ChannelFormats.
#include <gtest/gtest.h>

#include <deque>
#include <sstream>
#include <string>

#include "Vsegment_interpolator.h"
#include "edge_packing.hpp"
#include "rtl_harness.hpp"
#include "segment_interpolator.hpp"
#include "stream_bench.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

constexpr int NC = fmt::NumChannels;

// The unit's configuration, from the parameters it was Verilated with (defaults: Config{}).
#ifdef WATKINS_RTL_PARAM_XBits
constexpr int SlotBits[NC] = {WATKINS_RTL_PARAM_XBits, WATKINS_RTL_PARAM_ZBits, WATKINS_RTL_PARAM_AttrBits,
                              WATKINS_RTL_PARAM_AttrBits, WATKINS_RTL_PARAM_AttrBits};
constexpr int SlotFrac[NC] = {WATKINS_RTL_PARAM_XFracBits, WATKINS_RTL_PARAM_ZFracBits,
                              WATKINS_RTL_PARAM_AttrFracBits, WATKINS_RTL_PARAM_AttrFracBits,
                              WATKINS_RTL_PARAM_AttrFracBits};
constexpr int DepthBits = WATKINS_RTL_PARAM_DepthBits;
#else
constexpr int SlotBits[NC] = {fmt::ChannelBits, fmt::ChannelBits, fmt::ChannelBits, fmt::ChannelBits, fmt::ChannelBits};
constexpr int SlotFrac[NC] = {fmt::FracBits, fmt::FracBits, fmt::FracBits, fmt::FracBits, fmt::FracBits};
constexpr int DepthBits = fmt::DepthBits;
#endif

ChannelFormats formats() {
  ChannelFormats f;
  for (int c = 0; c < NC; ++c) {
    f.bits[c] = SlotBits[c];
    f.frac[c] = SlotFrac[c];
  }
  f.depth_bits = DepthBits;
  return f;
}


// 1.0 in slot c's unit; a value scaled by it, wrapped to the slot's word (every word is legal).
i64 one(int c) { return i64{1} << SlotFrac[c]; }
i64 word(int c, i128 v) { return wrap_signed(v, SlotBits[c]); }

struct Item {
  bool eol = false;
  Segment seg;
};

struct Frag {
  bool eol;
  int x;
  std::uint32_t depth, rgb;
  std::uint64_t normal;  // {Nz, Ny, Nx}, NormalInBits each
  int material;
  int poly;  // the segment's polygon id (the scanline buffer's equal-depth rule)
};

Segment random_segment(std::mt19937_64& rng, int width) {
  Segment s;
  auto rnd = [&](i64 lo, i64 hi) { return lo + static_cast<i64>(rng() % static_cast<std::uint64_t>(hi - lo + 1)); };
  const i64 One = one(fmt::ChanX);
  const int kind = static_cast<int>(rng() % 10);
  i64 xe, xf;
  switch (kind) {
    case 0:  // narrower than a pixel, anywhere
      xe = rnd(-2 * One, (width + 2) * One);
      xf = xe + rnd(1, One);
      break;
    case 1:  // clipped at both ends
      xe = rnd(-8192 * One, 0);
      xf = rnd(width * One, 8191 * One);
      break;
    case 2:  // reversed or zero width: empty
      xe = rnd(0, width * One);
      xf = xe - rnd(0, 4 * One);
      break;
    case 3:  // full-range words (wrapped accumulations)
      xe = word(fmt::ChanX, static_cast<i128>(rng()));
      xf = word(fmt::ChanX, static_cast<i128>(rng()));
      break;
    case 4:  // tiny widths in X units
      xe = rnd(-One, width * One);
      xf = xe + rnd(1, 64);
      break;
    default:  // ordinary span
      xe = rnd(-4 * One, (width + 4) * One);
      xf = xe + rnd(1, (width / 2 + 2) * One);
      break;
  }
  s.e[fmt::ChanX] = word(fmt::ChanX, xe);
  s.f[fmt::ChanX] = word(fmt::ChanX, xf);
  const bool normals = rng() % 3 == 0;  // attribute channels in the range of unit normals
  for (int c = fmt::ChanZ; c < NC; ++c) {
    const i64 u = one(c);
    if (normals && c != fmt::ChanZ) {
      s.e[c] = word(c, rnd(-5 * u / 4 - 1, 5 * u / 4 + 1));
      s.f[c] = word(c, rnd(-5 * u / 4 - 1, 5 * u / 4 + 1));
    } else if (rng() % 8 == 0) {
      s.e[c] = word(c, static_cast<i128>(rng()));
      s.f[c] = word(c, static_cast<i128>(rng()));
    } else if (c == fmt::ChanZ) {  // depth in [0, 2^DepthBits) units, a little beyond both ends
      const i64 range = (i64{1} << DepthBits) * u;
      s.e[c] = word(c, rnd(-range / 16, range + range / 16));
      s.f[c] = word(c, rnd(-range / 16, range + range / 16));
    } else {
      s.e[c] = word(c, rnd(-40 * u, 300 * u));
      s.f[c] = word(c, rnd(-40 * u, 300 * u));
    }
  }
  s.poly = static_cast<int>(rng() % 65536);
  s.material = static_cast<int>(rng() % (1u << fmt::MaterialIdBits));
  return s;
}

void expected(const Item& it, int width, std::deque<Frag>& out) {
  if (it.eol) {
    out.push_back({true, 0, 0, 0, 0, 0, 0});
    return;
  }
  const SpanSetup span = SegmentInterpolator::setup(it.seg, width, formats());
  ChannelVector v = span.value;
  for (int x = span.x_start; x < span.x_end; ++x) {
    const Fragment f = SegmentInterpolator::fragment(span, x, v);
    std::uint64_t n = 0;
    for (int c = 0; c < 3; ++c) n |= wrap_unsigned(f.normal[c], fmt::NormalInBits) << (c * fmt::NormalInBits);
    out.push_back({false, x, f.depth, (std::uint32_t(f.rgb[0]) << 16) | (std::uint32_t(f.rgb[1]) << 8) | f.rgb[2], n,
                   f.material, f.poly});
    SegmentInterpolator::step(span, v);
  }
}

struct Result {
  std::uint64_t cycles = 0, fragments = 0;
};

Result run(int items, int width, int gap_pct, int bp_pct, std::uint64_t seed, int eol_every = 6) {
  Harness<Vsegment_interpolator> h;
  const tb::ChannelLayout slots = tb::ChannelLayout::of(formats());
  std::mt19937_64 rng(seed);
  StreamBench<Frag> b(rng, gap_pct, bp_pct);
  b.max_cycles = 50000000ull;
  const StreamPorts ports{h.dut.seg_valid_i, h.dut.seg_ready_o, h.dut.frag_valid_o, h.dut.frag_ready_i};
  reset_stream(h, ports);
  h.dut.width_i = width;
  Item cur;
  int sent = 0;
  const std::uint64_t start = h.cycles;
  Result res;
  const bool ran = b.run(
      h, ports, [&] { return sent < items; },
      [&] {
        cur.eol = rng() % eol_every == 0;
        cur.seg = random_segment(rng, width);
        for (int c = 0; c < NC; ++c) {  // the channel vectors as the benches lay them out
          set_bits(h.dut.seg_e_i, slots.lsb[c], slots.bits[c], to_bits(cur.seg.e[c], slots.bits[c]));
          set_bits(h.dut.seg_f_i, slots.lsb[c], slots.bits[c], to_bits(cur.seg.f[c], slots.bits[c]));
        }
        h.dut.seg_material_i = static_cast<std::uint8_t>(cur.seg.material);
        h.dut.seg_poly_i = static_cast<std::uint16_t>(cur.seg.poly);
        h.dut.seg_eol_i = cur.eol;
        return true;
      },
      [&](std::deque<Frag>& want) {
        expected(cur, width, want);
        ++sent;
      },
      [&](const Frag& w) {
        res.fragments += !w.eol;
        const bool ok = h.dut.frag_eol_o == w.eol &&
                        (w.eol || (int(h.dut.frag_x_o) == w.x && h.dut.frag_depth_o == w.depth &&
                                   h.dut.frag_rgb_o == w.rgb && h.dut.frag_normal_o == w.normal &&
                                   int(h.dut.frag_material_o) == w.material && int(h.dut.frag_poly_o) == w.poly));
        if (ok) return std::string();
        std::ostringstream diff;
        diff << "rtl eol " << int(h.dut.frag_eol_o) << " x " << h.dut.frag_x_o << " depth " << h.dut.frag_depth_o
             << " rgb " << std::hex << h.dut.frag_rgb_o << " normal " << h.dut.frag_normal_o << std::dec
             << " material " << int(h.dut.frag_material_o) << " poly " << int(h.dut.frag_poly_o) << "; model eol " << w.eol << " x " << w.x << " depth "
             << w.depth << " rgb " << std::hex << w.rgb << " normal " << w.normal << std::dec << " material "
             << w.material << " poly " << w.poly;
        return diff.str();
      });
  if (!ran) return res;
  EXPECT_EQ(b.mismatches, 0u);
  res.cycles = h.cycles - start;
  return res;
}

}  // namespace

TEST(RtlSegmentInterpolator, RandomSegmentsFullRate) { run(30000, 97, 0, 0, 1); }
TEST(RtlSegmentInterpolator, RandomSegmentsGapsAndBackPressure) { run(30000, 64, 35, 35, 2); }
TEST(RtlSegmentInterpolator, WideScreen) { run(5000, 4096, 20, 20, 3); }
TEST(RtlSegmentInterpolator, OnePixelWide) { run(5000, 1, 20, 20, 4); }

// With no stalls the stepper must sustain one fragment per clock once spans are queued: cycles
// stay within fragments + markers + the setup latency (plus one cycle per empty-span-only run).
TEST(RtlSegmentInterpolator, OneFragmentPerClock) {
  const Result r = run(20000, 256, 0, 0, 5, 1000000);
  ASSERT_GT(r.fragments, 0u);
  const double rate = double(r.fragments) / double(r.cycles);
  std::printf("segment_interpolator: %llu fragments in %llu cycles (%.3f per clock)\n",
              static_cast<unsigned long long>(r.fragments), static_cast<unsigned long long>(r.cycles), rate);
  EXPECT_GT(rate, 0.95);
}
