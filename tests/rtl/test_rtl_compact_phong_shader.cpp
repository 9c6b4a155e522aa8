// rtl/compact_phong_shader.sv against PhongShader::shade (values) and CompactPhongShaderTiming
// (cycles), and with WATKINS_PHONG_NARROW (the bench test_rtl_compact_phong_shader_narrow)
// rtl/compact_phong_shader_narrow.sv against PhongShader::shade_narrow and
// CompactPhongShaderNarrowTiming: every shade and payload equal to the twin's, and on every clock
// ready_o and valid_o equal to the cycle twin's, under random valid gaps and ready back-pressure.
// Frames: random unit L and E (set with the block idle, as its port contract says), the eye at the
// light and opposite it; pixels: random unit normals, normals near the highlight (about the half
// vector of L and E), facing away from the light, grazing it (N.L near 0), the null normal; Cp,
// d up to 511/256 (clamped), W up to 511/256 and n over 0..255; every n at full rate; the latency
// of one pixel by hand.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <deque>
#include <sstream>
#include <string>
#include <vector>

#ifdef WATKINS_PHONG_NARROW
#include "Vcompact_phong_shader_narrow.h"
#include "compact_phong_shader_narrow_timing.hpp"
#else
#include "Vcompact_phong_shader.h"
#include "compact_phong_shader_timing.hpp"
#endif
#include "fixed_point.hpp"
#include "normalizer.hpp"
#include "phong_shader.hpp"
#include "rtl_harness.hpp"
#include "stream_bench.hpp"

using namespace watkins;
using namespace watkins::rtl;
using Vec = PhongShader::Vec;

namespace {

// The block under test and its twins: the model's formats, or the narrow ones.
#ifdef WATKINS_PHONG_NARROW
#define SUITE RtlCompactPhongShaderNarrow
using Dut = Vcompact_phong_shader_narrow;
using Timing = CompactPhongShaderNarrowTiming;
std::array<int, 3> twin_shade(const PhongShader::Pixel& p, const Vec& l, const Vec& e) {
  return PhongShader::shade_narrow(p, l, e, PhongShader::narrow_le(l, e));
}
PhongShader::Terms twin_terms(const PhongShader::Pixel& p, const Vec& l, const Vec& e) {
  return PhongShader::terms_narrow(p, l, e, PhongShader::narrow_le(l, e));
}
// N = L = E: the narrow power of 1 is 1 - 2^-16, so 255 W pow / 256 is just below 127.5.
constexpr std::array<int, 3> HandShade{255, 227, 177};
#else
#define SUITE RtlCompactPhongShader
using Dut = Vcompact_phong_shader;
using Timing = CompactPhongShaderTiming;
std::array<int, 3> twin_shade(const PhongShader::Pixel& p, const Vec& l, const Vec& e) {
  return PhongShader::shade(p, l, e);
}
PhongShader::Terms twin_terms(const PhongShader::Pixel& p, const Vec& l, const Vec& e) {
  return PhongShader::terms(p, l, e);
}
// N = L = E: cos(i) = cos(s) = 1, so each level is Cp + 255 W / 256 = Cp + 127.5, saturated.
constexpr std::array<int, 3> HandShade{255, 228, 178};
#endif

constexpr int UB = fmt::UnitBits;
constexpr int PayloadBits = WATKINS_RTL_PARAM_PayloadBits;  // PARAMS in tests/rtl/CMakeLists.txt

std::uint64_t pack(const Vec& v) {
  std::uint64_t w = 0;
  for (int c = 0; c < 3; ++c) w |= wrap_unsigned(v[c], UB) << (c * UB);
  return w;
}
// {R, G, B} as watkins_pkg::rgb_t holds it: red in the top byte.
std::uint32_t rgb(const std::array<int, 3>& c) {
  return (std::uint32_t(c[0]) << 16) | (std::uint32_t(c[1]) << 8) | std::uint32_t(c[2]);
}

// The unit normal (the normalizer's output) of direction d plus a random offset of size spread.
Vec unit_near(std::mt19937_64& rng, const std::array<double, 3>& d, double spread) {
  std::normal_distribution<double> g(0.0, 1.0);
  std::array<i64, 3> n{};
  for (int c = 0; c < 3; ++c) n[c] = std::llround((d[c] + spread * g(rng)) * 16384.0);
  const Normalizer::Unit u = Normalizer::normalize(n[0], n[1], n[2]);
  return {u.n[0], u.n[1], u.n[2]};
}
std::array<double, 3> dir(const Vec& v, double s = 1.0) {
  return {s * std::ldexp(double(v[0]), -14), s * std::ldexp(double(v[1]), -14), s * std::ldexp(double(v[2]), -14)};
}

struct Frame {
  Vec light{}, eye{};
  std::vector<PhongShader::Pixel> px;
};

Frame random_frame(std::mt19937_64& rng, int count, int light_eye) {
  Frame f;
  f.light = unit_near(rng, {0, 0, 0}, 1.0);
  f.eye = light_eye == 1 ? f.light : unit_near(rng, {0, 0, 0}, 1.0);
  if (light_eye == 2) f.eye = {-f.light[0], -f.light[1], -f.light[2]};
  const auto l = dir(f.light), e = dir(f.eye);
  const std::array<double, 3> half{l[0] + e[0], l[1] + e[1], l[2] + e[2]};
  f.px.resize(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    PhongShader::Pixel& p = f.px[static_cast<std::size_t>(k)];
    switch (k % 7) {
      case 0: p.n = unit_near(rng, {0, 0, 0}, 1.0); break;
      case 1: case 2: p.n = unit_near(rng, half, 0.05); break;           // the highlight
      case 3: p.n = unit_near(rng, dir(f.light, -1.0), 0.6); break;      // facing away
      case 4: {                                                           // grazing: N.L near 0
        const Vec r = unit_near(rng, {0, 0, 0}, 1.0);
        const double t = std::ldexp(double(PhongShader::dot(r, f.light)), -28);
        p.n = unit_near(rng, {dir(r)[0] - t * l[0], dir(r)[1] - t * l[1], dir(r)[2] - t * l[2]}, 0.002);
        break;
      }
      case 5: p.n = k % 70 == 5 ? Vec{0, 0, 0} : unit_near(rng, dir(f.light), 0.3); break;  // and null
      default: p.n = unit_near(rng, half, 0.3); break;
    }
    for (int& c : p.cp) c = static_cast<int>(rng() % 256);
    p.d = static_cast<int>(rng() % 512);
    p.w = static_cast<int>(rng() % 512);
    p.shininess = static_cast<int>(rng() % 256);
  }
  return f;
}

struct Bench {
  Harness<Dut> h;
  std::mt19937_64 rng;
  StreamBench<std::size_t> b;  // the index of each output's pixel
  const StreamPorts ports{h.dut.valid_i, h.dut.ready_o, h.dut.valid_o, h.dut.ready_i};
  Timing timing;
  std::uint64_t cycle_mismatches = 0, total = 0;

  Bench(std::uint64_t seed, int gap, int bp) : rng(seed), b(rng, gap, bp) {
    b.report_limit = 5;
    reset_stream(h, ports);
    b.on_clock = [this] {
      if (bool(h.dut.ready_o) != timing.ready() || bool(h.dut.valid_o) != timing.valid()) {
        if (cycle_mismatches++ < 5)
          ADD_FAILURE() << "cycle " << h.cycles << ": rtl ready " << int(h.dut.ready_o) << " valid "
                        << int(h.dut.valid_o) << "; twin " << timing.ready() << " " << timing.valid();
      }
      timing.clock(h.dut.valid_i, h.dut.ready_i);
    };
  }
  // L and E set with the block idle, 12 clocks before the frame's first pixel is offered.
  void frame(const Frame& f) {
    h.dut.light_i = pack(f.light);
    h.dut.eye_i = pack(f.eye);
    h.dut.valid_i = 0;
    for (int c = 0; c < 12; ++c) {
      h.dut.eval();
      timing.clock(false, h.dut.ready_i);
      h.tick();
    }
    const std::uint64_t mask = (std::uint64_t{1} << PayloadBits) - 1;
    std::size_t next = 0;
    b.run(
        h, ports, [&] { return next < f.px.size(); },
        [&] {
          const auto& p = f.px[next];
          h.dut.normal_i = pack(p.n);
          h.dut.cp_i = rgb(p.cp);
          h.dut.d_i = static_cast<std::uint16_t>(p.d);
          h.dut.w_i = static_cast<std::uint16_t>(p.w);
          h.dut.shininess_i = static_cast<std::uint8_t>(p.shininess);
          h.dut.payload_i = static_cast<std::uint32_t>((next * 0x9E3779B97F4A7C15ull >> 17) & mask);
          return true;
        },
        [&](std::deque<std::size_t>& inflight) { inflight.push_back(next++); },
        [&](std::size_t k) {
          const auto& p = f.px[k];
          const std::uint32_t want = rgb(twin_shade(p, f.light, f.eye));
          const std::uint64_t tag = (k * 0x9E3779B97F4A7C15ull >> 17) & mask;
          if (h.dut.rgb_o == want && h.dut.payload_o == tag) return std::string();
          const auto t = twin_terms(p, f.light, f.eye);
          std::ostringstream d;
          d << "pixel " << k << " n " << p.shininess << " d " << p.d << " W " << p.w << ": rtl rgb 0x" << std::hex
            << h.dut.rgb_o << " model 0x" << want << std::dec << " payload " << h.dut.payload_o << "/" << tag
            << " (cos_i " << t.cos_i << " cs " << t.cs << " f " << t.f << " pow " << t.pow << ")";
          return d.str();
        });
    total += f.px.size();
  }
  void expect_clean() {
    EXPECT_EQ(b.mismatches, 0u);
    EXPECT_EQ(cycle_mismatches, 0u);
    EXPECT_EQ(b.checked, total);
  }
};

}  // namespace

TEST(SUITE, RandomFramesUnderStalls) {
  Bench b(41, 25, 25);
  for (int f = 0; f < 20; ++f) b.frame(random_frame(b.rng, 20000, f % 6 == 1 ? 1 : f % 6 == 2 ? 2 : 0));
  b.expect_clean();
}

TEST(SUITE, HeavyBackPressure) {
  Bench b(42, 0, 90);
  for (int f = 0; f < 2; ++f) b.frame(random_frame(b.rng, 3000, 0));
  b.expect_clean();
}

TEST(SUITE, EveryExponentFullRate) {
  Bench b(43, 0, 0);
  for (int f = 0; f < 2; ++f) {
    Frame fr = random_frame(b.rng, 256 * 40, f);
    for (std::size_t k = 0; k < fr.px.size(); ++k) fr.px[k].shininess = static_cast<int>(k % 256);
    const std::uint64_t start = b.h.cycles;
    b.frame(fr);
    // One pixel per period once the first is in, the first offered Latency clocks after its take.
    EXPECT_LE(b.h.cycles - start, 12 + std::uint64_t{Timing::Period} * (fr.px.size() + 1) +
                                      Timing::Latency);
  }
  b.expect_clean();
}

TEST(SUITE, LatencyByHand) {
  Harness<Dut> h;
  const StreamPorts ports{h.dut.valid_i, h.dut.ready_o, h.dut.valid_o, h.dut.ready_i};
  reset_stream(h, ports);
  const Vec L{0, 0, 16384}, E{0, 0, 16384};
  h.dut.light_i = pack(L);
  h.dut.eye_i = pack(E);
  for (int c = 0; c < 12; ++c) h.tick();
  PhongShader::Pixel p;
  p.n = {0, 0, 16384};
  p.cp = {200, 100, 50};
  p.d = 64;
  p.w = 128;
  p.shininess = 10;
  h.dut.normal_i = pack(p.n);
  h.dut.cp_i = rgb(p.cp);
  h.dut.d_i = static_cast<std::uint16_t>(p.d);
  h.dut.w_i = static_cast<std::uint16_t>(p.w);
  h.dut.shininess_i = static_cast<std::uint8_t>(p.shininess);
  const auto [taken, offered] = take_and_offer(h, ports, 100);
  EXPECT_GE(taken, 0);
  EXPECT_EQ(offered - taken, Timing::Latency);
  EXPECT_EQ(h.dut.rgb_o, rgb(twin_shade(p, L, E)));
  EXPECT_EQ(h.dut.rgb_o, rgb(HandShade));
}
