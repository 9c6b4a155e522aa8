// The equal-depth rule (model/twins/depth_tie.hpp) on coplanar overlaps: screen-parallel quads
// share one depth exactly, so every overlapped pixel is a tie. Arrival keeps the fragment of the
// segment that closes first (smaller right-edge X); Submission keeps the polygon submitted first,
// whatever the arrival order. Every pixel is checked against the rule worked out from the
// rectangles, and a few by hand.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "prepare.hpp"
#include "scene_builder.hpp"
#include "watkins_top.hpp"

namespace watkins {
namespace {

using Rgb = std::array<int, 3>;

// An axis-aligned quad of one shade at one depth; it covers the pixels whose centres lie in
// [x0, x1) x [y0, y1).
struct Rect {
  int x0, y0, x1, y1;
  Rgb rgb;
  bool covers(int x, int y) const { return x + 0.5 > x0 && x + 0.5 < x1 && y + 0.5 > y0 && y + 0.5 < y1; }
};

ScreenPolygon quad(const Rect& r, double depth) {
  auto v = [&](double x, double y) { return test::vtx(x, y, depth, r.rgb[0], r.rgb[1], r.rgb[2]); };
  return test::poly({v(r.x0, r.y0), v(r.x1, r.y0), v(r.x1, r.y1), v(r.x0, r.y1)});
}

constexpr Rgb kBackground{0, 0, 0};

// Renders the rectangles, submitted in the given order, all at depth 0.5 (coplanar), under `tie`.
Image render(const std::vector<Rect>& rects, DepthTie tie) {
  std::vector<ScreenPolygon> polys;
  for (const Rect& r : rects) polys.push_back(quad(r, 0.5));
  BuiltScene s = test::screen(48, 32, polys, "coplanar");
  s.depth_tie = tie;
  const PreparedScene p = prepare(s);
  EXPECT_EQ(p.depth_tie, tie);
  return WatkinsTop().render(p);
}

Rgb pixel(const Image& img, int x, int y) {
  const std::uint8_t* p = img.at(x, y);
  return {p[0], p[1], p[2]};
}

// The rule worked out from the rectangles: the index of the rectangle that keeps (x, y), or -1.
// Submission: the first one submitted. Arrival: the one whose segment closes first on the line,
// i.e. the smallest right edge (no two rectangles here share a right edge).
int owner(const std::vector<Rect>& rects, int x, int y, DepthTie tie) {
  int best = -1;
  for (int i = 0; i < static_cast<int>(rects.size()); ++i) {
    if (!rects[i].covers(x, y)) continue;
    if (best < 0) best = i;
    else if (tie == DepthTie::Arrival && rects[i].x1 < rects[best].x1) best = i;
  }
  return best;
}

// Every pixel against owner(); returns how many pixels are covered by two or more rectangles.
int check_every_pixel(const std::vector<Rect>& rects, DepthTie tie, const Image& img, const std::string& what) {
  int overlapped = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      int covering = 0;
      for (const Rect& r : rects) covering += r.covers(x, y);
      overlapped += covering > 1;
      const int o = owner(rects, x, y, tie);
      const Rgb want = o < 0 ? kBackground : rects[o].rgb;
      EXPECT_EQ(pixel(img, x, y), want) << what << " pixel (" << x << ", " << y << ")";
      EXPECT_EQ(img.owner[std::size_t(y) * img.width + x], o) << what << " pixel (" << x << ", " << y << ")";
      if (::testing::Test::HasFailure()) return overlapped;
    }
  return overlapped;
}

const Rect kBase{4, 4, 40, 28, {200, 200, 200}};   // a big grey quad
const Rect kDecal{12, 10, 24, 18, {255, 0, 0}};    // a small red quad on it (closes first)

TEST(DepthTie, DecalSubmittedAfterItsBase) {
  const std::vector<Rect> rects{kBase, kDecal};
  // GL (GL_LESS): the decal, submitted second, loses every tie: the base stays whole.
  const Image sub = render(rects, DepthTie::Submission);
  EXPECT_EQ(pixel(sub, 15, 12), (Rgb{200, 200, 200}));
  EXPECT_EQ(pixel(sub, 5, 5), (Rgb{200, 200, 200}));
  EXPECT_EQ(pixel(sub, 2, 2), kBackground);
  EXPECT_EQ(check_every_pixel(rects, DepthTie::Submission, sub, "submission"), 12 * 8);
  // Arrival: the decal's segment closes first on every line it crosses, so it shows.
  const Image arr = render(rects, DepthTie::Arrival);
  EXPECT_EQ(pixel(arr, 15, 12), (Rgb{255, 0, 0}));
  EXPECT_EQ(pixel(arr, 30, 12), (Rgb{200, 200, 200}));
  check_every_pixel(rects, DepthTie::Arrival, arr, "arrival");
}

TEST(DepthTie, DecalSubmittedBeforeItsBase) {
  const std::vector<Rect> rects{kDecal, kBase};
  // Both rules keep the decal here (first submitted and first to arrive).
  for (DepthTie tie : {DepthTie::Submission, DepthTie::Arrival}) {
    const Image img = render(rects, tie);
    EXPECT_EQ(pixel(img, 15, 12), (Rgb{255, 0, 0}));
    EXPECT_EQ(pixel(img, 30, 12), (Rgb{200, 200, 200}));
    check_every_pixel(rects, tie, img, tie == DepthTie::Submission ? "submission" : "arrival");
  }
}

// Two quads overlapping in x on the same lines: in arrival order the left one (right edge 24)
// always wins the overlap [16, 24); by submission the first submitted one does.
TEST(DepthTie, OverlapInBothSubmissionOrders) {
  const Rect left{4, 6, 24, 20, {0, 255, 0}}, right{16, 10, 44, 26, {0, 0, 255}};
  for (bool left_first : {true, false}) {
    const std::vector<Rect> rects = left_first ? std::vector<Rect>{left, right} : std::vector<Rect>{right, left};
    const std::string order = left_first ? "left first" : "right first";
    const Image sub = render(rects, DepthTie::Submission);
    EXPECT_EQ(pixel(sub, 20, 15), left_first ? left.rgb : right.rgb) << order;
    EXPECT_EQ(check_every_pixel(rects, DepthTie::Submission, sub, "submission, " + order), 8 * 10) << order;
    const Image arr = render(rects, DepthTie::Arrival);
    EXPECT_EQ(pixel(arr, 20, 15), left.rgb) << order;
    check_every_pixel(rects, DepthTie::Arrival, arr, "arrival, " + order);
  }
}

// Three coplanar quads, each overlapping the others, in all six submission orders: the first
// submitted of the quads covering a pixel keeps it; arrival order ignores submission.
TEST(DepthTie, ThreeQuadsEverySubmissionOrder) {
  const std::vector<Rect> base{{2, 2, 30, 22, {255, 0, 0}}, {10, 8, 46, 30, {0, 255, 0}}, {6, 12, 20, 26, {0, 0, 255}}};
  std::array<int, 3> order{0, 1, 2};
  const Image arrival_first = render(base, DepthTie::Arrival);
  int orders = 0;
  do {
    std::vector<Rect> rects;
    for (int i : order) rects.push_back(base[i]);
    const std::string what = "order " + std::to_string(order[0]) + std::to_string(order[1]) + std::to_string(order[2]);
    const Image sub = render(rects, DepthTie::Submission);
    EXPECT_GT(check_every_pixel(rects, DepthTie::Submission, sub, "submission, " + what), 0);
    // The pixel inside all three goes to the first one submitted.
    EXPECT_EQ(pixel(sub, 15, 15), base[order[0]].rgb) << what;
    const Image arr = render(rects, DepthTie::Arrival);
    check_every_pixel(rects, DepthTie::Arrival, arr, "arrival, " + what);
    EXPECT_EQ(arr.rgb, arrival_first.rgb) << what;  // arrival does not depend on submission order
    ++orders;
  } while (std::next_permutation(order.begin(), order.end()));
  EXPECT_EQ(orders, 6);
}

// A strictly nearer fragment wins under both rules whatever the ids: the rule only breaks ties.
TEST(DepthTie, NearerStillWins) {
  const Rect far_first{4, 4, 40, 28, {10, 20, 30}}, near_second{12, 10, 44, 18, {40, 50, 60}};
  for (DepthTie tie : {DepthTie::Arrival, DepthTie::Submission}) {
    BuiltScene s = test::screen(48, 32, {quad(far_first, 0.75), quad(near_second, 0.25)});
    s.depth_tie = tie;
    const Image img = WatkinsTop().render(prepare(s));
    EXPECT_EQ(pixel(img, 20, 12), near_second.rgb);
    EXPECT_EQ(pixel(img, 20, 20), far_first.rgb);
  }
}

// Submission order from a scene file: an OBJ file's faces in file order, a zero-area face skipped
// without disturbing the order of the others. A small square on a big one, both in the plane
// Z = 4 (equal depth everywhere); the faces share one material and normal, so the visible polygon
// (Image::owner, the id in submission order) tells them apart.
class ObjSubmissionOrder : public ::testing::Test, protected test::ScratchDir {
 protected:
  Image render(bool big_first, DepthTie tie, BuiltScene* built = nullptr) {
    // `flat`: a triangle in the plane X = 0, through the eye: seen edge-on, zero area on screen.
    const std::string big = "f 1 2 3 4\n", small = "f 5 6 7 8\n", flat = "f 9 10 11\n";
    write("planes.obj", "v -1 -1 -4\nv 1 -1 -4\nv 1 1 -4\nv -1 1 -4\n"
                        "v -0.4 -0.3 -4\nv 0.2 -0.3 -4\nv 0.2 0.3 -4\nv -0.4 0.3 -4\n"
                        "v 0 -1 -4\nv 0 1 -4\nv 0 0 -6\n" +
                        (big_first ? big + flat + small : small + flat + big));
    const std::string scene = write("planes.json", std::string(R"({"screen": {"width": 64, "height": 64},
      "camera": {"type": "gouraud", "focal": 3}, "light": {"type": "eye"},
      "shading": {"cull_backfaces": false, "depth_tie": ")") + (tie == DepthTie::Submission ? "submission" : "arrival") +
      R"("}, "objects": [{"type": "mesh", "file": "planes.obj", "normals": "average"}]})");
    const BuiltScene s = load_scene(scene);
    if (built) *built = s;
    return WatkinsTop().render(prepare(s));
  }
};

TEST_F(ObjSubmissionOrder, FileOrderWithAZeroAreaFaceBetween) {
  BuiltScene s;
  const Image sub = render(true, DepthTie::Submission, &s);
  ASSERT_EQ(s.polygons.size(), 2u);  // the zero-area face is skipped and counted
  EXPECT_EQ(s.degenerate, 1);
  EXPECT_EQ(s.depth_tie, DepthTie::Submission);
  const auto owner = [](const Image& img, int x, int y) { return img.owner[std::size_t(y) * img.width + x]; };
  // Inside the small square (screen x 22.4..36.8, y 24.8..39.2) and on the big one only.
  EXPECT_EQ(owner(sub, 30, 32), 0);  // the big square, submitted first, keeps the tie
  EXPECT_EQ(owner(sub, 50, 32), 0);
  const Image arr = render(true, DepthTie::Arrival);
  EXPECT_EQ(owner(arr, 30, 32), 1);  // the small square closes first on its lines
  EXPECT_EQ(owner(arr, 50, 32), 0);
  // Small square first in the file: id 0, and it wins under both rules.
  for (DepthTie tie : {DepthTie::Submission, DepthTie::Arrival}) {
    const Image img = render(false, tie);
    EXPECT_EQ(owner(img, 30, 32), 0);
    EXPECT_EQ(owner(img, 50, 32), 1);
  }
}

}  // namespace
}  // namespace watkins
