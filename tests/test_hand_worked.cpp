// Hand-worked cases: every number below was computed on paper from Gouraud's formulas.
#include <gtest/gtest.h>

#include <cmath>

#include "test_support.hpp"

using namespace watkins;
using namespace watkins::test;

namespace {
constexpr i64 kPx = i64{1} << fmt::FracBits;  // one pixel / one level in channel units
}

// Triangle A(0.5,0.5) B(8.5,8.5) C(0.5,8.5); red: A=0, B=128, C=64; flat depth 0.25.
// Edge AB: X = 0.5 + y (slope 1 px/line), R = 16y; edge AC: X = 0.5, R = 8y; BC is horizontal.
// On scan line y the span is [0.5, 0.5 + y): pixels 0..y-1, and R(x, y) = 8y + 8y·x/y = 8(x + y).
BuiltScene hand_triangle() {
  return screen(12, 10, {poly({vtx(0.5, 0.5, 0.25, 0), vtx(8.5, 8.5, 0.25, 128), vtx(0.5, 8.5, 0.25, 64)})});
}

TEST(HandWorked, TriangleEdgeRecords) {
  const PreparedScene p = prepare(hand_triangle());
  ASSERT_EQ(p.edges.size(), 2u);  // the horizontal edge BC gives no record
  // Stream order: both start on line 0; polygon edge order AB then CA.
  const EdgeRecord& ab = p.edges[0];
  const EdgeRecord& ca = p.edges[1];
  EXPECT_EQ(ab.y0, 0);
  EXPECT_EQ(ab.n, 8);
  EXPECT_EQ(ab.value[fmt::ChanX], kPx / 2);
  EXPECT_EQ(ab.slope[fmt::ChanX], kPx);
  EXPECT_EQ(ab.value[fmt::ChanR], 0);
  EXPECT_EQ(ab.slope[fmt::ChanR], 16 * kPx);  // ΔS = (S2 − S1)/n = 128/8
  EXPECT_EQ(ab.value[fmt::ChanZ], i64{1} << (fmt::DepthBits - 2 + fmt::FracBits));  // 0.25
  EXPECT_EQ(ab.slope[fmt::ChanZ], 0);
  EXPECT_EQ(ca.y0, 0);
  EXPECT_EQ(ca.n, 8);
  EXPECT_EQ(ca.value[fmt::ChanX], kPx / 2);
  EXPECT_EQ(ca.slope[fmt::ChanX], 0);
  EXPECT_EQ(ca.slope[fmt::ChanR], 8 * kPx);
  EXPECT_EQ(p.needs.max_active_edges, 2);
  EXPECT_EQ(p.needs.max_segment_pixels, 7);
}

TEST(HandWorked, TrianglePixels) {
  PipelineStats st;
  std::vector<int> hits;
  const Image img = render_fixed(hand_triangle(), &hits, &st);
  EXPECT_EQ(st.fragments, 28);  // 0 + 1 + ... + 7
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 12; ++x) {
      const bool inside = y < 8 && x < y;
      ASSERT_EQ(img.is_covered(x, y), inside) << x << "," << y;
      EXPECT_EQ(hits[y * 12 + x], inside ? 1 : 0);
      if (inside) EXPECT_EQ(img.at(x, y)[0], 8 * (x + y)) << x << "," << y;
    }
  // The double reference agrees exactly on this one (all values are dyadic).
  const Image ref = render_float_reference(hand_triangle());
  const ImageError e = compare_images(img, ref);
  EXPECT_EQ(e.differing, 0);
}

// Gouraud's grid element: a square whose corner shades are not coplanar (A=B=D=0, C=128) and
// whose depths make it non-planar. Left edge AD: R = 0; right edge BC: R = 16y; X_E = 0.5,
// X_F = 8.5, so pixel x has α = x/8 and R = 16y·x/8 = 2xy — bilinear in the square.
TEST(HandWorked, NonPlanarQuad) {
  const BuiltScene s = screen(10, 10, {poly({vtx(0.5, 0.5, 0.1, 0), vtx(8.5, 0.5, 0.1, 0),
                                             vtx(8.5, 8.5, 0.5, 128), vtx(0.5, 8.5, 0.1, 0)})});
  PipelineStats st;
  const Image img = render_fixed(s, nullptr, &st);
  EXPECT_EQ(st.fragments, 64);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_EQ(img.at(x, y)[0], 2 * x * y) << x << "," << y;
  // Split into two triangles along AC the same corners shade differently (not bilinear):
  // pixel (6,2) lies in triangle ABC, where R depends on y only: R = 16y = 32, not 24.
  const BuiltScene split = screen(10, 10, {poly({vtx(0.5, 0.5, 0.1, 0), vtx(8.5, 0.5, 0.1, 0), vtx(8.5, 8.5, 0.5, 128)}),
                                           poly({vtx(0.5, 0.5, 0.1, 0), vtx(8.5, 8.5, 0.5, 128), vtx(0.5, 8.5, 0.1, 0)})});
  const Image img2 = render_fixed(split);
  EXPECT_EQ(img.at(6, 2)[0], 24);
  EXPECT_EQ(img2.at(6, 2)[0], 32);
}

// Gouraud: "if P ≡ A then S_P ≡ S_A". A vertex at a pixel centre that starts the left edge of
// its span gets exactly the vertex shade (α0 = 0, and the edge prestep is zero).
TEST(HandWorked, VertexPropertyHolds) {
  // A is the left vertex, at the centre of pixel (2, 5); shades chosen with odd fractions.
  const double sa[3] = {37.25, 201.5, 3.75};
  const BuiltScene s = screen(16, 12, {poly({vtx(2.5, 5.5, 0.3, sa[0], sa[1], sa[2]),
                                             vtx(12.5, 0.5, 0.6, 250, 10, 90),
                                             vtx(13.5, 10.5, 0.2, 5, 100, 180)})});
  const Image img = render_fixed(s);
  ASSERT_TRUE(img.is_covered(2, 5));
  for (int c = 0; c < 3; ++c) EXPECT_EQ(img.at(2, 5)[c], std::lround(sa[c])) << c;
  // Also at full channel precision: the first fragment of line 5 has exactly A's values.
  const PreparedScene p = prepare(s);
  WatkinsTop pipe;
  bool seen = false;
  pipe.render(p, [&](int y, const Fragment& f, bool) {
    if (y == 5 && f.x == 2) {
      seen = true;
      EXPECT_EQ(f.depth, static_cast<std::uint32_t>(std::llround(0.3 * (1 << fmt::DepthBits))));
    }
  });
  EXPECT_TRUE(seen);
}

// A rectangle with two horizontal edges: exactly its area in fragments, one per pixel.
TEST(HandWorked, HorizontalEdges) {
  const BuiltScene s = screen(20, 20, {poly({vtx(2.3, 3.0, 0.5, 10), vtx(11.7, 3.0, 0.5, 10),
                                             vtx(11.7, 9.0, 0.5, 10), vtx(2.3, 9.0, 0.5, 10)})});
  const PreparedScene p = prepare(s);
  EXPECT_EQ(p.edges.size(), 2u);  // the two horizontal edges give no records
  PipelineStats st;
  std::vector<int> hits;
  render_fixed(s, &hits, &st);
  // Columns with centres in [2.3, 11.7): x = 2..11 (10); rows with centres in [3, 9): y = 3..8 (6).
  EXPECT_EQ(st.fragments, 60);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) EXPECT_EQ(hits[y * 20 + x], (x >= 2 && x <= 11 && y >= 3 && y <= 8) ? 1 : 0);
}

// One-pixel slivers: a sliver straddling the centre column x = 3.5 gets exactly one fragment per
// scan line; one between two centres gets none; nothing ever hits a pixel twice.
TEST(HandWorked, OnePixelSlivers) {
  PipelineStats st;
  std::vector<int> hits;
  render_fixed(screen(8, 32, {poly({vtx(3.45, 0.5), vtx(3.55, 0.5), vtx(3.55, 20.5), vtx(3.45, 20.5)})}), &hits, &st);
  EXPECT_EQ(st.fragments, 20);
  for (int y = 0; y < 20; ++y) EXPECT_EQ(hits[y * 8 + 3], 1) << y;
  render_fixed(screen(8, 32, {poly({vtx(3.6, 0.5), vtx(4.4, 0.5), vtx(4.4, 20.5), vtx(3.6, 20.5)})}), &hits, &st);
  EXPECT_EQ(st.fragments, 0);
  // A diagonal needle one sub-pixel wide: never more than one fragment per line.
  render_fixed(screen(40, 40, {poly({vtx(1.0, 1.0), vtx(1.0625, 1.0), vtx(35.0625, 37.0)})}), &hits, &st);
  for (int h : hits) EXPECT_LE(h, 1);
  EXPECT_LE(st.fragments, 36);
}
