// The equal-depth rule by submission order (tie_submission_i = 1) on the RTL against the model:
// every shipped scene in both pipelines at full speed (cycles = the cycle model's); those the rule
// changes (coplanar overlaps: depth ties that arrival order and submission order settle
// differently; scenes/coplanar.json is made for it) also in sparse mode and under gaps and stalls;
// 0 mismatching pixels and every stage stream the model's. And the rule switched frame by frame.
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

// The scene on the RTL with tie_submission_i = 1: at full speed (cycles = the cycle model's) and,
// when the rule changes its image (`differ` pixels against arrival order), also in sparse mode and
// under gaps and stalls. Returns `differ`, or -1 when the scene does not load or fit here.
long long check_submission(const std::string& name, ShadingMode shading) {
  BuildOptions opt;
  opt.shading = shading;
  opt.depth_tie = DepthTie::Submission;
  PreparedScene p;
  try {
    p = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/" + name, opt));
  } catch (const SceneError&) {
    return -1;  // e.g. a Gouraud-only scene in Phong mode
  }
  if (p.width > rtl_max_width()) return -1;
  EXPECT_EQ(p.depth_tie, DepthTie::Submission);
  const Image model = WatkinsTop().render(p);
  PreparedScene arrival = p;
  arrival.depth_tie = DepthTie::Arrival;
  const long long differ = differing_pixels(model, WatkinsTop().render(arrival));
  RtlOptions patterns[] = {{1, 0.0, 0.0}, {2, 0.0, 0.0}, {3, 0.25, 0.3}, {4, 0.1, 0.02, 300}};
  patterns[1].sparse = true;
  for (const RtlOptions& o : patterns) {
    if (differ == 0 && (o.sparse || o.gap > 0)) break;
    const std::string what = name + (shading == ShadingMode::Phong ? " phong" : " gouraud") +
                             (o.sparse ? " sparse" : "") + (o.gap > 0 ? " with gaps and stalls" : "");
    const RtlResult r = run_rtl(p, o, &model);
    expect_clean(what, o, r);
    if (!r.ok()) return differ;
    EXPECT_EQ(r.frames.at(0).image.rgb, model.rgb) << what;
    EXPECT_EQ(r.frames.at(0).image.covered, model.covered) << what;
    if (o.gap == 0 && o.stall == 0)
      EXPECT_EQ(r.cycles, predict_cycles(p, o.sparse ? PixelOutput::Sparse : PixelOutput::FullFrame).cycles) << what;
  }
  return differ;
}

// Every shipped scene in both pipelines. The rule must change coplanar.json, made for it; the
// others are listed with the pixels it changes (none of them has a tie the rules settle
// differently, as of this writing).
TEST(CosimDepthTie, ShippedScenesSubmissionOrder) {
  int ran = 0;
  for (const std::string& name : shipped_scenes())
    for (ShadingMode shading : {ShadingMode::Gouraud, ShadingMode::Phong}) {
      const long long differ = check_submission(name, shading);
      if (differ < 0) continue;
      ++ran;
      std::printf("%-20s %-8s %lld pixels differ between the rules\n", name.c_str(),
                  shading == ShadingMode::Phong ? "phong" : "gouraud", differ);
      if (name == "coplanar.json") EXPECT_GT(differ, 100) << "made for the rule, yet the rules agree";
    }
  EXPECT_GE(ran, 20);
}

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
