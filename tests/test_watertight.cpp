// Watertight edges come from sharing: a closed mesh must write every covered pixel exactly once.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "random_scene.hpp"
#include "test_support.hpp"

using namespace watkins;
using namespace watkins::test;

namespace {

// A 32x32 grid of quads (or 2x triangles) over [8, 248)^2 with inner vertices jittered by up to
// ±1.8 pixels at sub-pixel precision (so no quad folds over); shared vertices are the same doubles.
std::vector<ScreenPolygon> grid_mesh(bool triangles, unsigned seed) {
  std::mt19937_64 rng(seed);
  GridSpec g;
  g.cols = g.rows = 32;
  g.x0 = g.y0 = 8;
  g.cell_w = g.cell_h = 7.5;
  g.jitter = 1.8 / 7.5;  // keeps every quad convex
  g.triangles = triangles;
  g.depth = 0.5;
  return jittered_grid(rng, g);
}

void expect_each_pixel_once(const BuiltScene& s, int x0, int x1, int y0, int y1) {
  std::vector<int> hits;
  PipelineStats st;
  render_fixed(s, &hits, &st);
  long long covered = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const int h = hits[y * s.width + x];
      const bool inside = x >= x0 && x < x1 && y >= y0 && y < y1;
      ASSERT_EQ(h, inside ? 1 : 0) << "pixel " << x << "," << y;
      covered += h;
    }
  EXPECT_EQ(st.fragments, covered);  // no fragment landed twice anywhere
}

TEST(Watertight, GridOfQuadsWritesEveryPixelOnce) {
  // Outer boundary [8, 248): pixel centres x + 0.5 in it are x = 8..247 (half-open, top-left rule).
  for (unsigned seed : {1u, 2u, 3u})
    expect_each_pixel_once(screen(256, 256, grid_mesh(false, seed)), 8, 248, 8, 248);
}

TEST(Watertight, GridOfTrianglesWritesEveryPixelOnce) {
  for (unsigned seed : {4u, 5u}) expect_each_pixel_once(screen(256, 256, grid_mesh(true, seed)), 8, 248, 8, 248);
}

TEST(Watertight, FanAroundOneVertex) {
  // 64 thin triangles around a centre at a sub-pixel position: the most edges meeting at a point.
  std::vector<ScreenPolygon> fan;
  const ScreenVertex c = vtx(50.3125, 49.8125, 0.5, 100, 100, 100);
  constexpr int K = 64;
  std::vector<ScreenVertex> rim;
  for (int k = 0; k < K; ++k) {
    const double a = 2 * M_PI * k / K;
    rim.push_back(vtx(50.3125 + 40 * std::cos(a), 49.8125 + 40 * std::sin(a), 0.5, 200, 20, 20));
  }
  for (int k = 0; k < K; ++k) fan.push_back(poly({c, rim[k], rim[(k + 1) % K]}));
  std::vector<int> hits;
  PipelineStats st;
  render_fixed(screen(100, 100, fan), &hits, &st);
  for (int h : hits) ASSERT_LE(h, 1);
  // No hole: every pixel whose centre is well inside the rim polygon is covered.
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 100; ++x)
      if (std::hypot(x + 0.5 - 50.3125, y + 0.5 - 49.8125) < 39.0) EXPECT_EQ(hits[y * 100 + x], 1) << x << "," << y;
}

}  // namespace
