// The cycle model (model/twins/cycle_model.hpp) without the RTL: counts worked by hand from the
// RTL's latencies, and bounds every frame must meet. (tests/cosim/test_cycle_model.cpp holds it
// equal to Verilator's cycles.)
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "build_options.hpp"
#include "cycle_model.hpp"
#include "prepare.hpp"
#include "scene.hpp"
#include "scene_builder.hpp"
#include "twin_error.hpp"
#include "watkins_top.hpp"

using namespace watkins;
using namespace watkins::test;

namespace {

PreparedScene with_shading(PreparedScene p, ShadingMode mode) {
  p.shading = mode;
  if (mode == ShadingMode::Phong && p.materials.empty()) p.materials.resize(1);
  return p;
}

// An empty W x H frame, by hand. The active-edge list: cycle 0 starts the frame, cycle 1 decides
// the swap to line 1 (the stream's head is its EOF beat), cycle 2 swaps, and from cycle 3 each
// line is its end-of-line marker (one cycle), the swap's decision (one) and the swap (one): 3
// cycles per line. The first marker reaches the line buffer at cycle 44: segment former 4 (its
// input register), 5 (its pairing register) and 6 (its output), s0 7, span_reciprocal 8..33,
// sa/sm/sp/sh/sb/sc/sv/sd 34..41, FIFO 42, the stepper's output register 43, the fragment queue
// 44. Full-frame: each line's read-out (W cycles) hides the next marker, so the last pixel is read
// at 44 + H*W and taken one cycle later: H*W + 46 cycles counting cycle 0. Sparse: an empty line
// is one read step (two cycles after its marker: the swap hands the search's registers over in
// between), so the list's 3 cycles per line set the pace: the last line's marker arrives at
// 44 + 3(H-1), is read two cycles later and taken the next: 3H + 45. The Phong top's 58 stages
// (normalizer 16, shader 42) delay it all by 58.
TEST(CycleModel, EmptyFrameByHand) {
  for (const auto& [w, h] : {std::pair{13, 5}, std::pair{320, 240}, std::pair{1, 1}, std::pair{40, 60}}) {
    const PreparedScene g = prepare(screen(w, h, {}, "empty"));
    const PreparedScene p = with_shading(g, ShadingMode::Phong);
    EXPECT_EQ(predict_cycles(g, PixelOutput::FullFrame).cycles, w * h + 46) << w << "x" << h;
    EXPECT_EQ(predict_cycles(p, PixelOutput::FullFrame).cycles, w * h + 46 + 58) << w << "x" << h;
    EXPECT_EQ(predict_cycles(g, PixelOutput::Sparse).cycles, 3 * h + 45) << w << "x" << h;
    EXPECT_EQ(predict_cycles(p, PixelOutput::Sparse).cycles, 3 * h + 45 + 58) << w << "x" << h;
    EXPECT_EQ(predict_cycles(g, PixelOutput::FullFrame).pixels, w * h);
    EXPECT_EQ(predict_cycles(g, PixelOutput::Sparse).pixels, 1);  // the terminating beat
  }
}

// Every shipped scene: full-frame output costs at least a pixel per cycle; sparse output at least
// a cycle per covered pixel and never more than full-frame plus a cycle per line (each swap
// starts the sparse reader a clock later than the full-frame one); as many sparse beats as the model's
// sparse stream; the full-frame Phong top exactly 58 cycles more (its pipeline only delays the
// read-out, which sets the pace).
TEST(CycleModel, ShippedScenesMeetTheBounds) {
  int checked = 0;
  for (const auto& e : std::filesystem::directory_iterator(WATKINS_SOURCE_DIR "/scenes")) {
    if (e.path().extension() != ".json") continue;
    const std::string name = e.path().filename().string();
    PreparedScene g;
    try {
      g = prepare(load_scene(e.path().string(), shading_options(ShadingMode::Gouraud)));
    } catch (const SceneError&) {
      continue;
    }
    const Image img = WatkinsTop().render(g);
    // A smoothed frame (Herman & Liu's smoother on) is emitted in full even in sparse mode.
    const long long beats = g.smooth_w > 0 ? static_cast<long long>(g.width) * g.height
                                           : static_cast<long long>(sparse_stream(img).size());
    const CyclePrediction full = predict_cycles(g, PixelOutput::FullFrame);
    const CyclePrediction sparse = predict_cycles(g, PixelOutput::Sparse);
    EXPECT_GE(full.cycles, static_cast<long long>(g.width) * g.height) << name;
    EXPECT_EQ(full.pixels, static_cast<long long>(g.width) * g.height) << name;
    EXPECT_EQ(sparse.pixels, beats) << name;
    EXPECT_GE(sparse.cycles, beats) << name;
    EXPECT_LE(sparse.cycles, full.cycles + g.height) << name;
    const PreparedScene p = with_shading(g, ShadingMode::Phong);
    EXPECT_EQ(predict_cycles(p, PixelOutput::FullFrame).cycles, full.cycles + 58) << name;
    ++checked;
  }
  EXPECT_GT(checked, 5);
}

TEST(CycleModel, OverflowIsACapacityError) {
  std::vector<ScreenPolygon> many;
  for (int i = 0; i < 6; ++i) many.push_back(poly({vtx(1 + i, 1), vtx(30 - i, 2), vtx(15, 20)}));
  const PreparedScene p = prepare(screen(32, 24, many, "stack"), PrepareOptions{64});
  EXPECT_THROW(predict_cycles(p, PixelOutput::FullFrame, 4), CapacityError);
  EXPECT_NO_THROW(predict_cycles(p, PixelOutput::FullFrame, 64));
}

}  // namespace

namespace {

class AlwaysHigh : public PixelReady {
 public:
  bool ready(long long, long long) override { return true; }
};

// The clocked pixel path with pixel_ready_i held high takes every pixel in the cycle the closed
// count says: same cycles, first pixel and beats, on every shipped scene in both shadings and
// output modes, smoothed (W = 0.8) and not; the takes are strictly increasing, one per beat.
TEST(CycleModel, ClockedPixelPathEqualsTheFastCount) {
  int checked = 0;
  for (const auto& e : std::filesystem::directory_iterator(WATKINS_SOURCE_DIR "/scenes")) {
    if (e.path().extension() != ".json") continue;
    for (const ShadingMode mode : {ShadingMode::Gouraud, ShadingMode::Phong})
      for (const double w : {0.0, 0.8}) {
        BuildOptions bo = shading_options(mode);
        bo.smooth = w;
        PreparedScene p;
        try {
          p = prepare(load_scene(e.path().string(), bo));
        } catch (const SceneError&) {
          continue;
        }
        for (const PixelOutput out : {PixelOutput::FullFrame, PixelOutput::Sparse}) {
          const std::string what = e.path().filename().string() + (mode == ShadingMode::Phong ? " phong" : " gouraud") +
                                   (w > 0 ? " smoothed" : "") + (out == PixelOutput::Sparse ? " sparse" : " full");
          const CyclePrediction fast = predict_cycles(p, out);
          AlwaysHigh high;
          std::vector<long long> takes;
          CycleOptions o;
          o.output = out;
          o.pixel_ready = &high;
          o.take_cycles = &takes;
          const CyclePrediction clocked = predict_cycles(p, Config{}, o);
          EXPECT_EQ(clocked.cycles, fast.cycles) << what;
          EXPECT_EQ(clocked.first_pixel, fast.first_pixel) << what;
          EXPECT_EQ(clocked.pixels, fast.pixels) << what;
          ASSERT_EQ(static_cast<long long>(takes.size()), fast.pixels) << what;
          EXPECT_EQ(takes.front(), fast.first_pixel) << what;
          EXPECT_EQ(takes.back(), fast.cycles - 1) << what;
          for (std::size_t i = 1; i < takes.size(); ++i) ASSERT_LT(takes[i - 1], takes[i]) << what << " pixel " << i;
          ++checked;
        }
      }
  }
  EXPECT_GT(checked, 40);
}

// A consumer that takes one pixel in three: the frame's last pixel leaves no earlier than three
// cycles a pixel after the first, and the clocked model never takes a pixel the consumer refused.
class OneInThree : public PixelReady {
 public:
  bool ready(long long cycle, long long) override {
    asked.push_back(cycle);
    return cycle % 3 == 0;
  }
  std::vector<long long> asked;
};

TEST(CycleModel, ClockedPixelPathHonoursTheConsumer) {
  const PreparedScene p = prepare(load_scene(WATKINS_SOURCE_DIR "/scenes/sphere.json", shading_options(ShadingMode::Gouraud)));
  OneInThree third;
  std::vector<long long> takes;
  CycleOptions o;
  o.pixel_ready = &third;
  o.take_cycles = &takes;
  const CyclePrediction c = predict_cycles(p, Config{}, o);
  ASSERT_EQ(static_cast<long long>(takes.size()), static_cast<long long>(p.width) * p.height);
  for (const long long t : takes) ASSERT_EQ(t % 3, 0);
  EXPECT_EQ(c.cycles, takes.back() + 1);
  EXPECT_GE(takes.back() - takes.front(), 3 * (static_cast<long long>(takes.size()) - 1));
  for (std::size_t i = 1; i < third.asked.size(); ++i) ASSERT_LT(third.asked[i - 1], third.asked[i]);
}

}  // namespace
