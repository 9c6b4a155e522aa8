// The smoother twin (model/twins/smoother.hpp): Herman & Liu's 3x3 weighted mean.
#include <gtest/gtest.h>

#include <random>

#include "cycle_model.hpp"
#include "prepare.hpp"
#include "scene.hpp"
#include "smoother.hpp"
#include "watkins_top.hpp"

namespace watkins {
namespace {

Image random_image(int w, int h, unsigned seed, int coverage_percent) {
  std::mt19937 rng(seed);
  Image img(w, h, {7, 8, 9});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (int(rng() % 100) < coverage_percent) {
        std::uint8_t* p = img.at(x, y);
        for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(rng());
        img.covered[std::size_t(y) * w + x] = 1;
      }
  return img;
}

TEST(Smoother, WeightZeroIsTheIdentity) {
  const Image in = random_image(13, 9, 1, 70);
  const Smoother s(0);
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      const auto p = s.pixel(in, x, y);  // the arithmetic, not the shortcut
      for (int k = 0; k < 3; ++k) EXPECT_EQ(p[k], in.at(x, y)[k]) << x << "," << y;
    }
  EXPECT_EQ(s.apply(in).rgb, in.rgb);
}

TEST(Smoother, FlatRegionStaysFlat) {
  Image in(6, 5, {0, 0, 0});
  for (int i = 0; i < 30; ++i) {
    in.rgb[i * 3] = 200, in.rgb[i * 3 + 1] = 17, in.rgb[i * 3 + 2] = 255;
    in.covered[i] = 1;
  }
  for (int w : {1, 102, 128, 255}) {
    const Image out = Smoother(w).apply(in);
    EXPECT_EQ(out.rgb, in.rgb) << "w " << w;
  }
}

// Centre 100, edges 10 20 30 (the fourth uncovered), corners 200 (two covered): W = 0.5 (64).
//   (100 + 0.5·60 + 0.25·400) / (1 + 0.5·3 + 0.25·2) = 230 / 3 = 76.67 -> 77
TEST(Smoother, HandComputedWindow) {
  Image in(3, 3, {1, 1, 1});
  auto put = [&](int x, int y, int v) {
    for (int k = 0; k < 3; ++k) in.at(x, y)[k] = static_cast<std::uint8_t>(v + k);
    in.covered[std::size_t(y) * 3 + x] = 1;
  };
  put(1, 1, 100);
  put(1, 0, 10), put(0, 1, 20), put(2, 1, 30);  // (1, 2) stays background, f = 0
  put(0, 0, 200), put(2, 2, 200);                // (2, 0) and (0, 2) uncovered
  const auto p = Smoother(64).pixel(in, 1, 1);
  EXPECT_EQ(p[0], 77);  // 230 / 3
  EXPECT_EQ(p[1], 78);  // (101 + 0.5·63 + 0.25·402) / 3 = 233 / 3 = 77.67
  EXPECT_EQ(p[2], 79);  // (102 + 33 + 101) / 3 = 78.67
  // The uncovered pixel keeps its background.
  EXPECT_EQ(Smoother(64).pixel(in, 1, 2)[0], 1);
  // A corner pixel: (200 + 0.5·(10 + 20) + 0.25·100) / (1 + 0.5·2 + 0.25) = 240 / 2.25 = 106.67
  EXPECT_EQ(Smoother(64).pixel(in, 0, 0)[0], 107);
}

TEST(Smoother, RoundsHalfUp) {
  EXPECT_EQ(round_div(5, 2), 3);
  EXPECT_EQ(round_div(4, 3), 1);
  EXPECT_EQ(round_div(5, 3), 2);
}

// Against the real-valued formula: within half a level everywhere (exact rounding).
TEST(Smoother, WithinHalfALevelOfTheRealMean) {
  const Image in = random_image(17, 11, 3, 60);
  for (int w : {1, 51, 102, 200, 255}) {
    const double W = w / 128.0;
    const Image out = Smoother(w).apply(in);
    for (int y = 0; y < in.height; ++y)
      for (int x = 0; x < in.width; ++x) {
        if (!in.is_covered(x, y)) continue;
        for (int k = 0; k < 3; ++k) {
          double num = in.at(x, y)[k], den = 1;
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const int nx = x + dx, ny = y + dy;
              if ((!dx && !dy) || nx < 0 || ny < 0 || nx >= in.width || ny >= in.height ||
                  !in.is_covered(nx, ny))
                continue;
              const double f = (dx && dy) ? W * W : W;
              num += f * in.at(nx, ny)[k];
              den += f;
            }
          EXPECT_LE(std::abs(out.at(x, y)[k] - num / den), 0.5 + 1e-9) << x << "," << y;
        }
      }
  }
}

// shading.smooth / --smooth reach the frame rounded to 1/128, and the top smooths its image.
TEST(Smoother, SceneWeightReachesTheTop) {
  BuildOptions opt;
  opt.smooth = 0.8;
  const PreparedScene p = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/sphere.json", opt));
  EXPECT_EQ(p.smooth_w, 102);  // 0.8 · 128 = 102.4
  PreparedScene plain = p;
  plain.smooth_w = 0;
  const Image flat = WatkinsTop().render(plain);
  const Image smoothed = WatkinsTop().render(p);
  EXPECT_EQ(smoothed.rgb, Smoother(102).apply(flat).rgb);
  EXPECT_NE(smoothed.rgb, flat.rgb);
  EXPECT_EQ(smoothed.covered, flat.covered);
  // A smoothed frame is read out in full: sparse output changes nothing, and the smoother adds
  // the flush of its last line and its 14 stages.
  const CyclePrediction full = predict_cycles(p, PixelOutput::FullFrame);
  EXPECT_EQ(predict_cycles(p, PixelOutput::Sparse).cycles, full.cycles);
  EXPECT_EQ(full.cycles, predict_cycles(plain, PixelOutput::FullFrame).cycles + p.width + 15);
  EXPECT_EQ(full.pixels, static_cast<long long>(p.width) * p.height);
}

}  // namespace
}  // namespace watkins
