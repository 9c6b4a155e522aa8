// The equal-depth rule by submission order (tie_submission_i = 1) on the RTL against the model:
// every shipped scene in which the rule changes the image (coplanar overlaps: depth ties that
// arrival order and submission order settle differently), and scenes/coplanar.json, made for it,
// in both pipelines. Each runs at full speed (cycles = the cycle model's), in sparse mode, and
// under gaps and stalls; 0 mismatching pixels and every stage stream the model's.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "cosim_support.hpp"
#include "cycle_model.hpp"

namespace watkins::tb::test {
namespace {

// Pixels whose rgb differs between two images of one size.
long long differing_pixels(const Image& a, const Image& b) {
  long long n = 0;
  for (std::size_t i = 0; i < a.rgb.size(); i += 3)
    n += a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2];
  return n;
}

void check_submission(const std::string& name, ShadingMode shading, bool must_differ) {
  if (name == "<none>") GTEST_SKIP() << "no scenes/*.json yet";
  BuildOptions opt;
  opt.shading = shading;
  opt.depth_tie = DepthTie::Submission;
  PreparedScene p;
  try {
    p = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/" + name, opt));
  } catch (const SceneError& e) {
    GTEST_SKIP() << "the scene does not load or fit in this mode: " << e.what();
  }
  if (p.width > rtl_max_width()) GTEST_SKIP() << "wider than the RTL line buffer";
  ASSERT_EQ(p.depth_tie, DepthTie::Submission);
  const Image model = WatkinsTop().render(p);
  PreparedScene arrival = p;
  arrival.depth_tie = DepthTie::Arrival;
  const long long differ = differing_pixels(model, WatkinsTop().render(arrival));
  if (must_differ) EXPECT_GT(differ, 0) << name << ": made for the rule, yet both rules give one image";
  else if (differ == 0) GTEST_SKIP() << "no depth tie that the two rules settle differently";
  std::printf("%s: %lld pixels differ between the rules\n", name.c_str(), differ);
  RtlOptions patterns[] = {{1, 0.0, 0.0}, {2, 0.0, 0.0}, {3, 0.25, 0.3}, {4, 0.1, 0.02, 300}};
  patterns[1].sparse = true;
  for (const RtlOptions& o : patterns) {
    const std::string what = name + (o.sparse ? " sparse" : "") + (o.gap > 0 ? " with gaps and stalls" : "");
    const RtlResult r = run_rtl(p, o, &model);
    expect_clean(what, o, r);
    ASSERT_TRUE(r.ok()) << what;
    EXPECT_EQ(r.frames.at(0).image.rgb, model.rgb) << what;
    EXPECT_EQ(r.frames.at(0).image.covered, model.covered) << what;
    if (o.gap == 0 && o.stall == 0)
      EXPECT_EQ(r.cycles, predict_cycles(p, o.sparse ? PixelOutput::Sparse : PixelOutput::FullFrame).cycles) << what;
  }
}

class DepthTieScene : public ::testing::TestWithParam<std::string> {};

TEST_P(DepthTieScene, SubmissionOrderGouraud) {
  check_submission(GetParam(), ShadingMode::Gouraud, GetParam() == "coplanar.json");
}

INSTANTIATE_TEST_SUITE_P(Scenes, DepthTieScene, ::testing::ValuesIn(shipped_scenes()), scene_test_name);

TEST(CosimDepthTie, CoplanarPhong) { check_submission("coplanar.json", ShadingMode::Phong, true); }

// Both rules in one simulation, frame by frame: the rule is sampled with each frame's size.
TEST(CosimDepthTie, RuleChangesBetweenFrames) {
  PreparedScene sub = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/coplanar.json"));
  ASSERT_EQ(sub.depth_tie, DepthTie::Submission);  // the scene's shading.depth_tie
  PreparedScene arr = sub;
  arr.depth_tie = DepthTie::Arrival;
  const Image ms = WatkinsTop().render(sub), ma = WatkinsTop().render(arr);
  ASSERT_NE(ms.rgb, ma.rgb);
  const RtlResult r = run_rtl_frames({&sub, &arr, &sub, &arr}, RtlOptions{5, 0.1, 0.1}, {&ms, &ma, &ms, &ma});
  expect_clean("coplanar.json, rules alternating", RtlOptions{5, 0.1, 0.1}, r);
  ASSERT_EQ(r.frames.size(), 4u);
  for (int f = 0; f < 4; ++f) EXPECT_EQ(r.frames[f].image.rgb, (f % 2 ? ma : ms).rgb) << "frame " << f;
}

}  // namespace
}  // namespace watkins::tb::test
