// rtl/smoother.sv against its twin Smoother (model/twins/smoother.hpp): every pixel of a frame
// (shade, coverage, position, the last flag), one frame per run.
// - Every coverage mask of a 3x3 frame (2^9), so each position sees every set of f_i with its
//   borders, at several W, with random levels; and the extreme levels (0 and 255 everywhere) under
//   every mask.
// - Random frames of every shape up to 16 x 9 (width 1: the forwarded line-buffer word; height 1:
//   a frame that is all flush), random coverage (holes), random W, under random valid gaps and
//   back-pressure.
// - W = 0 is the identity; with no gaps or stalls a frame takes N + width + 15 clocks.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "Vsmoother.h"
#include "rtl_harness.hpp"
#include "smoother.hpp"
#include "stream_bench.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

constexpr int MaxWidth = WATKINS_RTL_PARAM_MaxWidth;  // PARAMS in tests/rtl/CMakeLists.txt

struct Px {
  std::uint32_t rgb;
  bool covered, last;
  int x, y;
};

std::uint32_t pack(const std::uint8_t* p) { return (std::uint32_t(p[0]) << 16) | (std::uint32_t(p[1]) << 8) | p[2]; }

class SmootherBench {
 public:
  SmootherBench(int gap_pct, int bp_pct) : rng_(7), b_(rng_, gap_pct, bp_pct) {
    reset_stream(h_, ports());
    b_.stuck_cycles = 1000;
  }

  // Runs one frame through the RTL against the twin; the cycles it took (first offer .. last
  // pixel taken), or -1 when it failed.
  long long frame(const Image& in, int w) {
    h_.dut.width_i = in.width;
    h_.dut.height_i = in.height;
    h_.dut.w_i = w;
    const Image want = Smoother(w).apply(in);
    for (int y = 0; y < in.height; ++y)
      for (int x = 0; x < in.width; ++x)
        b_.expect.push_back(Px{pack(want.at(x, y)), want.is_covered(x, y),
                               x == in.width - 1 && y == in.height - 1, x, y});
    const long long n = static_cast<long long>(in.width) * in.height;
    long long next = 0;
    const std::uint64_t start = h_.cycles;
    const bool ok = b_.run(
        h_, ports(), [&] { return next < n; },
        [&] {
          const int x = static_cast<int>(next % in.width), y = static_cast<int>(next / in.width);
          h_.dut.rgb_i = pack(in.at(x, y));
          h_.dut.covered_i = in.is_covered(x, y);
          h_.dut.last_i = next == n - 1;
          return true;
        },
        [&](auto&) { ++next; },
        [&](const Px& e) {
          const Px got{h_.dut.rgb_o, h_.dut.covered_o != 0, h_.dut.last_o != 0, h_.dut.x_o, h_.dut.y_o};
          if (got.rgb == e.rgb && got.covered == e.covered && got.last == e.last && got.x == e.x && got.y == e.y)
            return std::string();
          char buf[200];
          std::snprintf(buf, sizeof buf, "w %d %dx%d: pixel (%d,%d) rgb %06x cov %d last %d, RTL (%d,%d) %06x cov %d last %d",
                        w, in.width, in.height, e.x, e.y, e.rgb, e.covered, e.last, got.x, got.y, got.rgb,
                        got.covered, got.last);
          return std::string(buf);
        });
    if (h_.dut.valid_o) ADD_FAILURE() << "a pixel after the frame's last";
    return ok && b_.mismatches == 0 ? static_cast<long long>(h_.cycles - start) : -1;
  }
  std::uint64_t checked() const { return b_.checked; }
  std::uint64_t in_stalls() const { return b_.in_stalls; }
  std::mt19937_64& rng() { return rng_; }

 private:
  StreamPorts ports() { return {h_.dut.valid_i, h_.dut.ready_o, h_.dut.valid_o, h_.dut.ready_i}; }
  Harness<Vsmoother> h_;
  std::mt19937_64 rng_;
  StreamBench<Px> b_;
};

Image random_image(std::mt19937_64& rng, int w, int h, int coverage_pct) {
  Image img(w, h, {static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng())});
  for (int i = 0; i < w * h; ++i)
    if (static_cast<int>(rng() % 100) < coverage_pct) {
      for (int k = 0; k < 3; ++k) img.rgb[std::size_t(i) * 3 + k] = static_cast<std::uint8_t>(rng());
      img.covered[std::size_t(i)] = 1;
    }
  return img;
}

TEST(RtlSmoother, EveryCoverageMaskOfA3x3Frame) {
  SmootherBench bench(10, 10);
  for (const int w : {1, 64, 102, 128, 255}) {
    for (int mask = 0; mask < 512; ++mask) {
      Image img = random_image(bench.rng(), 3, 3, 100);
      for (int i = 0; i < 9; ++i) img.covered[std::size_t(i)] = (mask >> i) & 1;
      ASSERT_GE(bench.frame(img, w), 0) << "mask " << mask << " w " << w;
    }
  }
  EXPECT_EQ(bench.checked(), 5u * 512 * 9);
}

TEST(RtlSmoother, ExtremeLevelsUnderEveryMask) {
  SmootherBench bench(0, 0);
  for (const int level : {0, 255})
    for (const int w : {1, 255})
      for (int mask = 0; mask < 512; ++mask) {
        Image img(3, 3, {1, 2, 3});
        for (int i = 0; i < 9; ++i)
          if ((mask >> i) & 1) {
            for (int k = 0; k < 3; ++k) img.rgb[std::size_t(i) * 3 + k] = static_cast<std::uint8_t>(level);
            img.covered[std::size_t(i)] = 1;
          }
        ASSERT_GE(bench.frame(img, w), 0) << "mask " << mask;
      }
}

TEST(RtlSmoother, RandomFramesUnderStalls) {
  SmootherBench bench(30, 30);
  for (int t = 0; t < 600; ++t) {
    auto& rng = bench.rng();
    const int width = 1 + static_cast<int>(rng() % MaxWidth);
    const int height = 1 + static_cast<int>(rng() % 9);
    const int w = t % 7 == 0 ? 0 : static_cast<int>(rng() % 256);
    const Image img = random_image(rng, width, height, static_cast<int>(rng() % 101));
    ASSERT_GE(bench.frame(img, w), 0) << width << "x" << height << " w " << w;
  }
  EXPECT_GT(bench.in_stalls(), 0u);  // back-pressure reached the input
}

TEST(RtlSmoother, WeightZeroIsTheIdentity) {
  SmootherBench bench(20, 20);
  const Image img = random_image(bench.rng(), MaxWidth, 6, 70);
  ASSERT_GE(bench.frame(img, 0), 0);
  EXPECT_EQ(Smoother(0).apply(img).rgb, img.rgb);  // so the RTL passed every shade through
}

// One pixel per clock: a frame takes its N pixels, the width + 1 flush steps and 14 stages.
TEST(RtlSmoother, CyclesPerFrame) {
  SmootherBench bench(0, 0);
  for (const auto& [width, height] : std::vector<std::pair<int, int>>{{1, 1}, {1, 5}, {16, 1}, {16, 9}, {5, 3}}) {
    const Image img = random_image(bench.rng(), width, height, 80);
    EXPECT_EQ(bench.frame(img, 102), width * height + width + 15) << width << "x" << height;
  }
}

}  // namespace
