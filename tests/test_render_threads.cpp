// The model's frame drawn in bands of scan lines (WatkinsTop::set_threads) and by each span path
// (WatkinsTop::set_span_path) is the scalar loop's frame on one thread, bit for bit: every shipped
// scene in both shadings at N = 1..4 threads, and every path the processor has. A band starts from
// its first line's edge state computed directly (EdgeIncrementer::step_lines), which equals k
// single steps for straight and cubic edges on any word.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "curve_scenes.hpp"
#include "edge_incrementer.hpp"
#include "prepare.hpp"
#include "scene.hpp"
#include "shipped_scenes.hpp"
#include "watkins_top.hpp"

namespace watkins {
namespace {

// The default configuration with the edge order the scene needs and an active-edge list as long
// as it needs.
Config holding_with_order(const BuiltScene& scene) {
  Config c = with_scene_edge_order(scene, Config{});
  c.max_active_edges = 1 << 16;
  c.max_active_edges = std::max(fmt::MaxActiveEdges, prepare(scene, c).needs.max_active_edges);
  return c;
}

void expect_same_frame(const Image& a, const PipelineStats& sa, const Image& b, const PipelineStats& sb,
                       const std::string& what) {
  EXPECT_EQ(a.rgb, b.rgb) << what;
  EXPECT_EQ(a.covered, b.covered) << what;
  EXPECT_EQ(a.owner, b.owner) << what;
  EXPECT_EQ(sa.edges, sb.edges) << what;
  EXPECT_EQ(sa.segments, sb.segments) << what;
  EXPECT_EQ(sa.fragments, sb.fragments) << what;
  EXPECT_EQ(sa.visible, sb.visible) << what;
  EXPECT_EQ(sa.max_active_edges, sb.max_active_edges) << what;
}

// The frame on one thread by the scalar loop, then at every thread count and span path.
void check_frame(const PreparedScene& p, const std::string& name) {
  WatkinsTop ref(p.config);
  ref.set_span_path(SpanPath::Scalar);
  Image want;
  ref.render_into(p, want);
  for (const SpanPath path : {SpanPath::Auto, SpanPath::Avx2, SpanPath::Avx512})
    for (int threads = 1; threads <= 4; ++threads) {
      WatkinsTop top(p.config);
      top.set_span_path(path);
      top.set_threads(threads);
      Image got(3, 3);  // a used image: render_into resets it
      top.render_into(p, got);
      expect_same_frame(want, ref.stats(), got, top.stats(),
                        name + " path " + std::to_string(static_cast<int>(path)) + " threads " + std::to_string(threads));
    }
}

class ShippedSceneBands : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedSceneBands, EveryThreadCountAndSpanPathDrawTheSameFrame) {
  for (const ShadingMode sh : {ShadingMode::Gouraud, ShadingMode::Phong}) {
    BuildOptions opt;
    opt.shading = sh;
    BuiltScene scene;
    try {
      scene = load_scene(WATKINS_SOURCE_DIR "/scenes/" + GetParam(), opt);
    } catch (const std::exception&) {
      continue;  // a scene this shading cannot build (checked by the scene tests)
    }
    const PreparedScene p = prepare(scene, holding_with_order(scene));
    check_frame(p, GetParam() + (sh == ShadingMode::Phong ? " phong" : " gouraud"));
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedSceneBands, ::testing::ValuesIn(test::shipped_scene_names()),
                         [](const ::testing::TestParamInfo<std::string>& i) {
                           std::string n = i.param.substr(0, i.param.size() - 5);
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(RenderBands, CurvedEdgesAtEdgeOrderThree) {
  for (const ShadingMode sh : {ShadingMode::Gouraud, ShadingMode::Phong}) {
    const BuiltScene s = test::curve_scene(sh);
    const PreparedScene p = prepare(s, holding_with_order(s));
    ASSERT_EQ(p.config.edge_order, 3);
    check_frame(p, "curve scene");
  }
}

// A Phong frame whose polygons name materials past its table: every path raises the scalar loop's
// std::out_of_range, or draws its frame where no such polygon wins a pixel (the table of a scene
// with several materials cut to k entries).
TEST(RenderBands, PhongMaterialPastTheTableOnEveryPath) {
  for (const std::string& name : test::shipped_scene_names()) {
    BuildOptions opt;
    opt.shading = ShadingMode::Phong;
    BuiltScene scene;
    try {
      scene = load_scene(WATKINS_SOURCE_DIR "/scenes/" + name, opt);
    } catch (const std::exception&) {
      continue;
    }
    const PreparedScene full = prepare(scene, holding_with_order(scene));
    if (full.materials.size() < 2) continue;  // a scene where a cut table leaves some polygons drawn
    for (std::size_t k = 0; k < full.materials.size(); ++k) {
      PreparedScene p = full;
      p.materials.resize(k);
      WatkinsTop ref(p.config);
      ref.set_span_path(SpanPath::Scalar);
      Image want;
      bool threw = false;
      try {
        ref.render_into(p, want);
      } catch (const std::out_of_range&) {
        threw = true;
      }
      for (const SpanPath path : {SpanPath::Auto, SpanPath::Avx2, SpanPath::Avx512}) {
        WatkinsTop top(p.config);
        top.set_span_path(path);
        Image got;
        const std::string what = name + " materials " + std::to_string(k) + " path " + std::to_string(static_cast<int>(path));
        if (threw) {
          EXPECT_THROW(top.render_into(p, got), std::out_of_range) << what;
        } else {
          top.render_into(p, got);
          expect_same_frame(want, ref.stats(), got, top.stats(), what);
        }
      }
    }
    return;  // one such scene
  }
  FAIL() << "no shipped scene builds in Phong with two materials";
}

// k lines at once equal k single steps, for random words (wrapping ones included) of any width.
TEST(RenderBands, StepLinesEqualsSingleSteps) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 2000; ++trial) {
    ChannelFormats f = Config{}.channels(ShadingMode::Gouraud);
    for (int c = 0; c < fmt::NumChannels; ++c) f.bits[c] = std::uniform_int_distribution<int>(2, 62)(rng);
    const EdgeIncrementer::Signs sign = EdgeIncrementer::signs(f);
    ActiveEdge e;
    for (int c = 0; c < fmt::NumChannels; ++c) {
      auto word = [&] { return wrap_to_sign(static_cast<i64>(rng()), sign[c]); };
      e.rec.value[c] = word(), e.rec.slope[c] = word(), e.rec.d2[c] = word(), e.rec.d3[c] = word();
    }
    const int k = std::uniform_int_distribution<int>(0, 4200)(rng);
    e.remaining = k + 1;
    ActiveEdge one = e, three = e, direct1 = e, direct3 = e;
    for (int i = 0; i < k; ++i) EdgeIncrementer::step<1>(one, sign), EdgeIncrementer::step<3>(three, sign);
    EdgeIncrementer::step_lines<1>(direct1, k, sign);
    EdgeIncrementer::step_lines<3>(direct3, k, sign);
    EXPECT_EQ(direct1.rec.value, one.rec.value) << "k " << k;
    EXPECT_EQ(direct3.rec.value, three.rec.value) << "k " << k;
    EXPECT_EQ(direct3.rec.slope, three.rec.slope) << "k " << k;
    EXPECT_EQ(direct3.rec.d2, three.rec.d2) << "k " << k;
    EXPECT_EQ(direct1.remaining, one.remaining);
  }
}

// An active-edge overflow is reported at the first line that overflows, whichever band holds it.
TEST(RenderBands, CapacityErrorNamesTheFirstLine) {
  BuiltScene s = load_scene(WATKINS_SOURCE_DIR "/scenes/mesh.json");
  const PreparedScene p = prepare(s, holding_with_order(s));
  WatkinsTop one(4), four(4);
  four.set_threads(4);
  std::string e1, e4;
  try {
    one.render(p);
  } catch (const std::exception& e) {
    e1 = e.what();
  }
  try {
    Image img;
    four.render_into(p, img);
  } catch (const std::exception& e) {
    e4 = e.what();
  }
  EXPECT_NE(e1, "");
  EXPECT_EQ(e1, e4);
}

}  // namespace
}  // namespace watkins
