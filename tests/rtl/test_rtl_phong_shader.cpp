// rtl/phong_shader.sv against PhongShader::shade, bit-exact: frames with random unit L and E
// (changed only while the pipe is empty, as the port contract says), random unit normals, normals
// near the highlight, grazing and back-facing normals, the null normal, every n in 0..255,
// d beyond 1.0, W up to 511/256; under random valid gaps and ready back-pressure.
#include <gtest/gtest.h>

#include <cmath>
#include <deque>
#include <sstream>
#include <string>

#include "Vphong_shader.h"
#include "fixed_point.hpp"
#include "normalizer.hpp"
#include "phong_shader.hpp"
#include "rtl_harness.hpp"
#include "stream_bench.hpp"

using namespace watkins;
using namespace watkins::rtl;
using Vec = PhongShader::Vec;

namespace {

// {R, G, B} as watkins_pkg::rgb_t packs it: red in the top byte.
std::uint32_t rgb_word(const std::array<int, 3>& c) {
  return (std::uint32_t(c[0]) << 16) | (std::uint32_t(c[1]) << 8) | std::uint32_t(c[2]);
}

constexpr int UB = fmt::UnitBits;

std::uint64_t pack(const Vec& v) {
  std::uint64_t w = 0;
  for (int c = 0; c < 3; ++c) w |= wrap_unsigned(v[c], UB) << (c * UB);
  return w;
}

Vec unit_of(std::mt19937_64& rng, double bias_x = 0, double bias_y = 0, double bias_z = 0, double spread = 1) {
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  const auto u = Normalizer::normalize(std::llround((bias_x + spread * U(rng)) * 32768),
                                       std::llround((bias_y + spread * U(rng)) * 32768),
                                       std::llround((bias_z + spread * U(rng)) * 32768));
  return {u.n[0], u.n[1], u.n[2]};
}

struct Bench {
  Harness<Vphong_shader> h;
  std::mt19937_64 rng;
  StreamBench<std::size_t> stream;  // the index of each output's pixel
  const StreamPorts ports{h.dut.valid_i, h.dut.ready_o, h.dut.valid_o, h.dut.ready_i};
  explicit Bench(std::uint64_t seed, int gap, int back) : rng(seed), stream(rng, gap, back) {
    stream.report_limit = 5;
    reset_stream(h, ports);
  }
  // One frame: set L and E on an empty pipe, then stream the pixels.
  void frame(const Vec& L, const Vec& E, const std::vector<PhongShader::Pixel>& px) {
    h.dut.light_i = pack(L);
    h.dut.eye_i = pack(E);
    h.dut.valid_i = 0;
    h.tick();  // le_q settles
    std::size_t next = 0;
    std::uint32_t tag = 0, want = 0;
    stream.run(
        h, ports, [&] { return next < px.size(); },
        [&] {
          const auto& p = px[next];
          h.dut.normal_i = pack(p.n);
          h.dut.cp_i = rgb_word(p.cp);  // watkins_pkg::rgb_t: red in the top byte
          h.dut.d_i = static_cast<std::uint16_t>(p.d);
          h.dut.w_i = static_cast<std::uint16_t>(p.w);
          h.dut.shininess_i = static_cast<std::uint8_t>(p.shininess);
          h.dut.payload_i = tag;
          return true;
        },
        [&](std::deque<std::size_t>& inflight) {
          inflight.push_back(next++);
          ++tag;
        },
        [&](std::size_t k) {
          const auto& p = px[k];
          const auto want_rgb = PhongShader::shade(p, L, E);
          const std::uint32_t m = rgb_word(want_rgb);
          const bool same = h.dut.rgb_o == m && h.dut.payload_o == want++;
          if (same) return std::string();
          const auto t = PhongShader::terms(p, L, E);
          std::ostringstream diff;
          diff << "pixel " << k << " n " << p.shininess << " d " << p.d << " W " << p.w << ": rtl rgb 0x" << std::hex
               << h.dut.rgb_o << " model 0x" << m << std::dec << " tag " << h.dut.payload_o << "/" << want - 1
               << " (cos_i " << t.cos_i << " cs " << t.cs << " pow " << t.pow << ")";
          return diff.str();
        });
  }
};

std::vector<PhongShader::Pixel> pixels(std::mt19937_64& rng, const Vec& L, const Vec& E, int count) {
  std::vector<PhongShader::Pixel> px(count);
  const double hx = std::ldexp(double(L[0] + E[0]), -15), hy = std::ldexp(double(L[1] + E[1]), -15),
               hz = std::ldexp(double(L[2] + E[2]), -15);
  for (int k = 0; k < count; ++k) {
    auto& p = px[k];
    switch (k % 6) {
      case 0: p.n = unit_of(rng); break;
      case 1: case 2: p.n = unit_of(rng, hx, hy, hz, 0.1); break;   // near the highlight
      case 3: p.n = unit_of(rng, -hx, -hy, -hz, 0.5); break;         // mostly back-facing
      case 4: {                                                       // grazing: N.L ~ 0
        Vec n = unit_of(rng);
        const double t = std::ldexp(double(PhongShader::dot(n, L)), -28);
        p.n = unit_of(rng, std::ldexp(n[0] - t * L[0], -14), std::ldexp(n[1] - t * L[1], -14),
                      std::ldexp(n[2] - t * L[2], -14), 0.01);
        break;
      }
      default: p.n = (k % 60 == 5) ? Vec{0, 0, 0} : unit_of(rng); break;  // and the null normal
    }
    for (int& c : p.cp) c = static_cast<int>(rng() % 256);
    p.d = static_cast<int>(rng() % 512);  // beyond 1.0 on purpose: clamped
    p.w = static_cast<int>(rng() % 512);
    p.shininess = static_cast<int>(rng() % 256);
  }
  return px;
}

}  // namespace

TEST(RtlPhongShader, RandomFramesUnderStalls) {
  Bench b(21, 25, 25);
  std::uint64_t total = 0;
  for (int f = 0; f < 40; ++f) {
    const Vec L = unit_of(b.rng), E = unit_of(b.rng);
    const auto px = pixels(b.rng, L, E, 25000);
    b.frame(L, E, px);
    total += px.size();
  }
  EXPECT_EQ(b.stream.mismatches, 0u);
  EXPECT_EQ(b.stream.checked, total);
}

TEST(RtlPhongShader, EveryExponentFullThroughput) {
  Bench b(22, 0, 0);
  std::uint64_t total = 0;
  for (int f = 0; f < 4; ++f) {
    const Vec L = unit_of(b.rng), E = f == 0 ? L : unit_of(b.rng);  // eye at the light first
    auto px = pixels(b.rng, L, E, 256 * 200);
    for (std::size_t k = 0; k < px.size(); ++k) px[k].shininess = static_cast<int>(k % 256);
    b.frame(L, E, px);
    total += px.size();
  }
  EXPECT_EQ(b.stream.mismatches, 0u);
  EXPECT_EQ(b.stream.checked, total);
}
