// Run-time configurations (model/twins/config.hpp, docs/guide/config-format.md): the default is
// formats.hpp exactly; configuration files are validated field by field; narrower shade formats
// cost the error derived below and no more; a configuration too narrow for a scene is refused.
#include <gtest/gtest.h>

#include <dirent.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "config_file.hpp"
#include "float_reference.hpp"
#include "holding_config.hpp"
#include "image_io.hpp"
#include "prepare.hpp"
#include "random_scene.hpp"
#include "scene.hpp"
#include "shipped_scenes.hpp"
#include "test_support.hpp"
#include "watkins_top.hpp"

namespace {

using namespace watkins;

using watkins::test::error_of;

std::vector<std::string> shipped_scenes() { return watkins::test::shipped_scene_paths(); }

Image render(const PreparedScene& p, const Config& cfg) { return WatkinsTop(cfg).render(p); }
using watkins::test::default_holding;

TEST(Config, DefaultIsTodaysFormats) {
  const Config c;
  EXPECT_EQ(c.check(), "");
  for (ShadingMode m : {ShadingMode::Gouraud, ShadingMode::Phong}) {
    EXPECT_EQ(c.edge_record_bits(m), fmt::EdgeRecordBits);
    const ChannelFormats f = c.channels(m);
    for (int ch = 0; ch < fmt::NumChannels; ++ch) {
      EXPECT_EQ(f.bits[ch], fmt::ChannelBits);
      EXPECT_EQ(f.frac[ch], fmt::FracBits);
    }
    EXPECT_EQ(f.depth_bits, fmt::DepthBits);
  }
  EXPECT_EQ(id_bits(c.max_polygons), fmt::PolyIdBits);
  EXPECT_EQ(id_bits(c.max_materials), fmt::MaterialIdBits);
  EXPECT_EQ(c.max_active_edges, fmt::MaxActiveEdges);
  // An empty file is the default; a written file reads back.
  EXPECT_TRUE(parse_config("{}", "c.json") == c);
  Config n;
  n.shade = {9, 6};
  n.x = {12, 8};
  n.max_width = 640;
  EXPECT_TRUE(parse_config(config_json(n), "c.json") == n);
}

TEST(Config, FileErrorsNameTheField) {
  auto err = [](const std::string& text) { return error_of([&] { parse_config(text, "c.json"); }); };
  EXPECT_EQ(err(R"({"shade": {"frac_bits": 2.5}})"), "c.json: shade.frac_bits: expected an integer, got 2.5");
  EXPECT_EQ(err(R"({"shade": {"fracbits": 2}})"), "c.json: shade: unknown key \"fracbits\"");
  EXPECT_EQ(err(R"({"colour": {}})"), "c.json: unknown key \"colour\"");
  EXPECT_EQ(err(R"({"x": 3})"), "c.json: x: expected an object, got 3");
  EXPECT_EQ(err(R"({"x": {"frac_bits": 3}})"),
            "c.json: x.frac_bits: 3 is below 4 (X holds the vertices' 1/16 pixel exactly)");
  EXPECT_EQ(err(R"({"x": {"frac_bits": 24}})"),
            "c.json: x.frac_bits: 24 is above 23 (the span step shifts by p + RecipBits - x.frac_bits >= 1)");
  EXPECT_EQ(err(R"({"depth": {"int_bits": 0}})"), "c.json: depth.int_bits: 0 is below 1 (the sign bit)");
  EXPECT_EQ(err(R"({"normal": {"int_bits": 40, "frac_bits": 30}})"),
            "c.json: normal: int_bits + frac_bits = 70 exceeds the model's 62-bit words");
  EXPECT_EQ(err(R"({"max_materials": 17})"), "c.json: max_materials: 17 is outside [1, 16]");
  EXPECT_EQ(err(R"({"max_width": "wide"})"), "c.json: max_width: expected an integer, got \"wide\"");
  EXPECT_EQ(err("{"), err("{").substr(0, 0) + err("{"));  // malformed JSON: one message
  EXPECT_NE(err("{").find("c.json:1:2: malformed JSON"), std::string::npos);
}

// `watkins_gen_pkg --params F --shading S`: watkins_top's parameters for the configuration, one
// Verilator -G option per line; the default configuration gives formats.hpp's widths.
TEST(Config, GeneratorPrintsTheRtlParametersOfAConfiguration) {
  char tmpl[] = "/tmp/watkins_cfgpkg_XXXXXX";
  const int fd = mkstemp(tmpl);
  ASSERT_GE(fd, 0);
  const std::string path = tmpl;
  auto generate = [&](const std::string& text, const char* shading) {
    FILE* f = std::fopen(path.c_str(), "w");
    std::fputs(text.c_str(), f);
    std::fclose(f);
    std::string out;
    FILE* p = popen((std::string(WATKINS_GEN_PKG) + " --params " + path + " --shading " + shading + " 2>&1").c_str(), "r");
    char buf[512];
    while (p && std::fgets(buf, sizeof buf, p)) out += buf;
    if (p) pclose(p);
    return out;
  };
  EXPECT_EQ(generate("{}", "gouraud"),
            "-GPhong=0\n-GMaxActiveEdges=64\n-GMaxWidth=1024\n-GXIntBits=26\n-GXFracBits=16\n"
            "-GDepthIntBits=26\n-GDepthFracBits=16\n-GAttrIntBits=26\n-GAttrFracBits=16\n-GDepthBits=24\n"
            "-GPolyIdBits=16\n-GMaterialIdBits=4\n-GEdgeIdBits=18\n");
  const std::string narrow = R"({"shade": {"int_bits": 9, "frac_bits": 8}, "normal": {"int_bits": 2, "frac_bits": 15},
                                 "max_materials": 4, "max_polygons": 6})";
  const std::string g = generate(narrow, "gouraud"), p = generate(narrow, "phong");
  EXPECT_NE(g.find("-GAttrIntBits=9\n-GAttrFracBits=8\n"), std::string::npos) << g;
  EXPECT_NE(p.find("-GPhong=1\n"), std::string::npos) << p;
  EXPECT_NE(p.find("-GAttrIntBits=2\n-GAttrFracBits=15\n"), std::string::npos) << p;
  EXPECT_NE(p.find("-GPolyIdBits=3\n-GMaterialIdBits=2\n"), std::string::npos) << p;
  EXPECT_NE(generate(R"({"x": {"frac_bits": 1}})", "gouraud").find("x.frac_bits: 1 is below 4"), std::string::npos);
  EXPECT_NE(generate("{}", "flat").find("--shading: expected gouraud or phong, got flat"), std::string::npos);
  // Without the smoother: the same list and Smoothing = 0 last (the RTL's default is 1).
  EXPECT_EQ(generate(R"({"smoothing": false})", "phong"),
            "-GPhong=1\n-GMaxActiveEdges=64\n-GMaxWidth=1024\n-GXIntBits=26\n-GXFracBits=16\n"
            "-GDepthIntBits=26\n-GDepthFracBits=16\n-GAttrIntBits=26\n-GAttrFracBits=16\n-GDepthBits=24\n"
            "-GPolyIdBits=16\n-GMaterialIdBits=4\n-GEdgeIdBits=18\n-GSmoothing=0\n");
  EXPECT_EQ(generate(R"({"smoothing": true})", "gouraud"), generate("{}", "gouraud"));
  close(fd);
  std::remove(path.c_str());
}

// "smoothing": absent or true keeps the default top (and its parameter list, so a file without the
// key builds the same top as one with it true); false drops the smoother: Smoothing = 0, and a
// scene that smooths is refused in one line naming the field, while one that does not renders
// exactly as on the top with the smoother.
TEST(Config, SmoothingFalseBuildsATopWithoutTheSmoother) {
  auto err = [](const std::string& text) { return error_of([&] { parse_config(text, "c.json"); }); };
  EXPECT_TRUE(parse_config("{}", "c.json").smoothing);
  EXPECT_EQ(err(R"({"smoothing": 0})"), "c.json: smoothing: expected true or false, got 0");
  EXPECT_EQ(err(R"({"smoothing": "no"})"), "c.json: smoothing: expected true or false, got \"no\"");
  Config off;
  off.smoothing = false;
  EXPECT_TRUE(parse_config(R"({"smoothing": false})", "c.json") == off);
  EXPECT_FALSE(off == Config{});
  EXPECT_NE(config_json(off).find("\"smoothing\": false"), std::string::npos);
  EXPECT_EQ(config_json(Config{}).find("smoothing"), std::string::npos);
  EXPECT_TRUE(parse_config(config_json(off), "c.json") == off);
  for (ShadingMode m : {ShadingMode::Gouraud, ShadingMode::Phong}) {
    std::vector<RtlParameter> with = rtl_parameters(Config{}, m), without = rtl_parameters(off, m);
    for (const RtlParameter& p : with) EXPECT_STRNE(p.name, "Smoothing");
    ASSERT_EQ(without.size(), with.size() + 1);
    EXPECT_TRUE((without.back() == RtlParameter{"Smoothing", 0}));
    without.pop_back();
    EXPECT_EQ(without, with);
  }

  BuildOptions opt;
  opt.smooth = 0.8;
  const BuiltScene smoothed = load_scene(WATKINS_SOURCE_DIR "/scenes/cone.json", opt);
  EXPECT_EQ(error_of([&] { prepare(smoothed, off); }),
            smoothed.name + ": smoothing: the scene smooths (W = 102/128, shading.smooth or --smooth); the "
            "configuration has smoothing false (no smoother)");
  EXPECT_EQ(error_of([&] { prepare(smoothed, Config{}); }), "");
  const BuiltScene plain = load_scene(WATKINS_SOURCE_DIR "/scenes/cone.json");
  const PreparedScene a = prepare(plain, Config{}), b = prepare(plain, off);
  EXPECT_EQ(b.edges.size(), a.edges.size());
  EXPECT_EQ(b.smooth_w, 0);
  const Image ia = render(a, Config{}), ib = render(b, off);
  EXPECT_EQ(ib.rgb, ia.rgb);
  EXPECT_EQ(ib.covered, ia.covered);
}

// "phong": {"formats": "narrow"}: a field of the compact configuration only (one line naming it
// otherwise), written only when narrow, listed to the RTL as PhongNarrow = 1 for a Phong top only.
// Its images come from the narrow twins on every path (one thread or several, observed or not)
// and stay within a few levels of the model set's.
TEST(Config, NarrowPhongFormatsAreACompactField) {
  auto err = [](const std::string& text) { return error_of([&] { parse_config(text, "c.json"); }); };
  EXPECT_EQ(err(R"({"phong": {"formats": "narrow"}})"),
            "c.json: phong.formats: narrow needs compact true (the pipelined Phong blocks take the model's formats)");
  EXPECT_EQ(err(R"({"compact": true, "phong": {"formats": "wide"}})"),
            "c.json: phong.formats: expected \"model\" or \"narrow\", got \"wide\"");
  EXPECT_EQ(err(R"({"phong": {"format": "narrow"}})"), "c.json: phong: unknown key \"format\"");
  EXPECT_EQ(err(R"({"phong": "narrow"})"), "c.json: phong: expected an object, got \"narrow\"");
  EXPECT_TRUE(parse_config(R"({"phong": {"formats": "model"}})", "c.json") == Config{});
  EXPECT_TRUE(parse_config(R"({"phong": {}})", "c.json") == Config{});
  Config compact;
  compact.compact = true;
  Config narrow = compact;
  narrow.phong = PhongFormat::Narrow;
  EXPECT_TRUE(parse_config(R"({"compact": true, "phong": {"formats": "narrow"}})", "c.json") == narrow);
  EXPECT_FALSE(narrow == compact);
  EXPECT_TRUE(parse_config(config_json(narrow), "c.json") == narrow);
  EXPECT_NE(config_json(narrow).find("\"phong\": {\"formats\": \"narrow\"}"), std::string::npos);
  EXPECT_EQ(config_json(compact).find("phong"), std::string::npos);
  EXPECT_EQ(narrow.channels(ShadingMode::Phong).phong, PhongFormat::Narrow);
  std::vector<RtlParameter> with = rtl_parameters(narrow, ShadingMode::Phong);
  const std::vector<RtlParameter> without = rtl_parameters(compact, ShadingMode::Phong);
  ASSERT_EQ(with.size(), without.size() + 1);
  EXPECT_TRUE((with.back() == RtlParameter{"PhongNarrow", 1}));
  with.pop_back();
  EXPECT_EQ(with, without);
  EXPECT_EQ(rtl_parameters(narrow, ShadingMode::Gouraud), rtl_parameters(compact, ShadingMode::Gouraud));

  BuildOptions opt;
  opt.shading = ShadingMode::Phong;
  for (const char* name : {"/scenes/sphere.json", "/scenes/highlight.json"}) {
    const BuiltScene scene = load_scene(std::string(WATKINS_SOURCE_DIR) + name, opt);
    const PreparedScene pm = prepare(scene, compact), pn = prepare(scene, narrow);
    const Image model = render(pm, compact);
    WatkinsTop top(narrow);
    const Image img = top.render(pn);
    // Every covered pixel is the narrow twins' shade of its fragment, observed or not, threaded.
    Image observed_img;
    {
      WatkinsTop o(narrow);
      observed_img = o.render(pn, [](int, const Fragment&, bool) {});
    }
    EXPECT_EQ(observed_img.rgb, img.rgb) << name;
    for (SpanPath path : {SpanPath::Scalar, SpanPath::Auto}) {
      WatkinsTop t(narrow);
      t.set_threads(3);
      t.set_span_path(path);
      EXPECT_EQ(t.render(pn).rgb, img.rgb) << name;
    }
    EXPECT_EQ(img.covered, model.covered) << name;
    EXPECT_NE(img.rgb, model.rgb) << name;
    const ImageError e = compare_images(img, model);
    EXPECT_LE(e.max_abs, 12) << name;
    EXPECT_LT(e.mean_abs, 0.5) << name;
  }
}

// Narrower shade fraction bits F on the Gouraud scenes. X and depth keep their formats, so
// coverage, spans, α0 and visibility are identical; only the shade values move. Against the
// exact interpolation v* of the exact vertex shades over the same spans, with q = 2^-(F+1):
//   vertex quantization ≤ q, edge prestep ≤ q, slope drift ≤ (L-1) q over L lines,
//   value at the span start: interpolated edge error + rounding q + α0/reciprocal error,
//   per-pixel step drift ≤ (W-1) q over W pixels, reciprocal error ≤ 255·2^-23 over a span,
// so |v - v*| ≤ (L + W + 1) q + 2^-13 levels, L the longest edge and W the widest span.
// Two configurations differ by at most the sum of their bounds before rounding to levels,
// e = (L + W + 1)(q_F + q_16) + 2^-12, and by at most ceil(e) levels after rounding and clamping.
// So every pixel's error against the double reference grows by at most ceil(e) over the default.
TEST(NarrowConfig, ShadeErrorGrowsWithinTheDerivedBound) {
  int gouraud_scenes = 0;
  for (const std::string& path : shipped_scenes()) {
    SCOPED_TRACE(path);
    const BuiltScene scene = load_scene(path);
    if (scene.shading != ShadingMode::Gouraud) continue;
    ++gouraud_scenes;
    const Config wide = default_holding(scene);
    const PreparedScene pw = prepare(scene, wide);
    const Image iw = render(pw, wide);
    const Image ref = render_float_reference(scene);
    const ImageError ew = compare_images(iw, ref);
    const int L = pw.needs.max_edge_lines, W = pw.needs.max_segment_pixels;
    // A scene whose every polygon has one shade at all its vertices (voxel faces with face
    // normals) interpolates constants: the fraction bits cannot change it, so it cannot grow.
    bool shades_vary = false;
    for (const ScreenPolygon& q : scene.polygons)
      for (const ScreenVertex& v : q.v)
        for (int c = 0; c < 3; ++c) shades_vary = shades_vary || std::fabs(v.rgb[c] - q.v[0].rgb[c]) > 1e-9;
    double previous_mean = ew.mean_abs;
    for (int f : {12, 8, 5, 3, 1}) {
      SCOPED_TRACE("shade.frac_bits " + std::to_string(f));
      Config narrow = wide;
      narrow.shade.frac_bits = f;
      const PreparedScene pn = prepare(scene, narrow);
      const Image in = render(pn, narrow);
      ASSERT_EQ(in.covered, iw.covered);
      ASSERT_EQ(in.owner, iw.owner);
      const double e = (L + W + 1) * (std::ldexp(1.0, -(f + 1)) + std::ldexp(1.0, -(fmt::FracBits + 1))) +
                       std::ldexp(1.0, -12);
      const int bound = static_cast<int>(std::ceil(e));
      int worst = 0, worst_vs_ref_growth = 0;
      for (std::size_t i = 0; i < in.rgb.size(); ++i) {
        worst = std::max(worst, std::abs(int(in.rgb[i]) - int(iw.rgb[i])));
        worst_vs_ref_growth = std::max(
            worst_vs_ref_growth, std::abs(int(in.rgb[i]) - int(ref.rgb[i])) - std::abs(int(iw.rgb[i]) - int(ref.rgb[i])));
      }
      EXPECT_LE(worst, bound) << "L " << L << " W " << W << " e " << e;
      EXPECT_LE(worst_vs_ref_growth, bound);
      const ImageError en = compare_images(in, ref);
      EXPECT_LE(en.max_abs, ew.max_abs + bound);
      // The mean error against the double reference grows as the fraction shrinks (up to noise
      // of a thousandth of a level where the extra error is far below a level).
      EXPECT_GE(en.mean_abs, previous_mean - 1e-3);
      if (f <= 3 && shades_vary) EXPECT_GT(en.mean_abs, ew.mean_abs);
      previous_mean = en.mean_abs;
    }
  }
  EXPECT_GE(gouraud_scenes, 5);
}

// Narrower normal fraction bits on every shipped scene shaded with Phong's pipeline: the normals
// move, coverage and visibility do not, and the error against the double reference grows (the
// specular power amplifies a normal's error, so no small bound holds here: measured, not derived).
TEST(NarrowConfig, NormalErrorGrowsUnderPhong) {
  for (const std::string& path : shipped_scenes()) {
    SCOPED_TRACE(path);
    BuildOptions opt;
    opt.shading = ShadingMode::Phong;
    const BuiltScene scene = load_scene(path, opt);
    const Image ref = render_float_reference(scene);
    const Config base = default_holding(scene);
    const Image iw = render(prepare(scene, base), base);
    double previous = compare_images(iw, ref).mean_abs;
    const double wide = previous;
    // From 16 to 12 bits the extra error is far below the existing one and the mean may move
    // either way by a hundredth of a level (hypar); from 8 bits down it grows, step by step within
    // 5 %: a large smooth sheet's coarsely quantized normals can land closer on average at one
    // step (deep_horizon: 6.41 levels at 6 bits, 6.18 at 4).
    for (int f : {8, 6, 4}) {
      Config c = base;
      c.normal.frac_bits = f;
      const Image in = render(prepare(scene, c), c);
      ASSERT_EQ(in.covered, iw.covered);
      ASSERT_EQ(in.owner, iw.owner);
      const double mean = compare_images(in, ref).mean_abs;
      EXPECT_GE(mean, 0.95 * previous - 1e-3) << "normal.frac_bits " << f;
      previous = mean;
    }
    EXPECT_GT(previous, wide);
  }
}

// A Phong frame does not read the shade group, and a Gouraud frame not the normal group.
TEST(NarrowConfig, UnusedGroupChangesNothing) {
  for (const std::string& path : shipped_scenes()) {
    SCOPED_TRACE(path);
    const BuiltScene scene = load_scene(path);
    const Config base = default_holding(scene);
    Config c = base;
    if (scene.shading == ShadingMode::Phong) c.shade = {1, 0};
    else c.normal = {1, 0};
    const Image a = render(prepare(scene, base), base);
    const Image b = render(prepare(scene, c), c);
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_EQ(a.covered, b.covered);
  }
}

TEST(NarrowConfig, TooNarrowForTheSceneIsRefused) {
  const BuiltScene sphere = load_scene(WATKINS_SOURCE_DIR "/scenes/sphere.json");  // 320x240, X up to ~270 px
  auto err = [&](const Config& c) { return error_of([&] { prepare(sphere, c); }); };
  Config c;
  c.shade.int_bits = 8;  // levels up to 255 need 9 signed integer bits
  EXPECT_NE(err(c).find("edge values of channel R need 25 signed bits; the configuration's shade word is 24 "
                        "(shade.int_bits 8, needs 9)"),
            std::string::npos)
      << err(c);
  c = Config{};
  c.depth.int_bits = 20;
  EXPECT_NE(err(c).find("values of channel Z need"), std::string::npos) << err(c);
  EXPECT_NE(err(c).find("depth.int_bits 20, needs 25"), std::string::npos) << err(c);
  c = Config{};
  c.x.int_bits = 9;  // [-256, 256) pixels
  EXPECT_NE(err(c).find("edge values of channel X need 26 signed bits; the configuration's x word is 25 "
                        "(x.int_bits 9, needs 10)"),
            std::string::npos)
      << err(c);
  c = Config{};
  c.max_width = 256;
  EXPECT_NE(err(c).find("screen 320x240 exceeds the pipeline's limit of 256x4096 (max_width of the configuration)"),
            std::string::npos)
      << err(c);
  c = Config{};
  c.max_polygons = 100;
  EXPECT_NE(err(c).find("polygons; the polygon id is 7 bits (at most 100)"), std::string::npos) << err(c);
  c = Config{};
  c.max_active_edges = 8;
  EXPECT_NE(err(c).find("active edges on scan line"), std::string::npos) << err(c);
  c = Config{};
  c.shade.frac_bits = 70;
  EXPECT_EQ(err(c), "configuration: shade.frac_bits: 70 is above 53 (the model quantizes in 62-bit words)");
  // Exactly wide enough passes: the integer bits the scene reports it needs.
  const PreparedScene p = prepare(sphere, Config{});
  Config tight;
  tight.shade.int_bits = p.needs.int_bits_needed(fmt::ChanR, fmt::FracBits);
  tight.x.int_bits = p.needs.int_bits_needed(fmt::ChanX, fmt::FracBits);
  tight.depth.int_bits = p.needs.int_bits_needed(fmt::ChanZ, fmt::FracBits);
  for (int ch = fmt::ChanR; ch < fmt::NumChannels; ++ch)
    tight.shade.int_bits = std::max(tight.shade.int_bits, p.needs.int_bits_needed(ch, fmt::FracBits));
  EXPECT_EQ(err(tight), "");
  EXPECT_LT(tight.edge_record_bits(ShadingMode::Gouraud), fmt::EdgeRecordBits);
  // And renders the same image as the default (no value wraps at these widths).
  EXPECT_EQ(render(prepare(sphere, tight), tight).rgb, render(p, Config{}).rgb);
}

// Random fractions on random scenes (Gouraud and Phong): at the integer bits SceneNeeds reports
// the scene is accepted and renders exactly as with wide words (nothing wrapped); one bit fewer
// in any group is refused, naming that group. So the range checks are exact, not just safe.
TEST(NarrowConfig, ReportedIntegerBitsAreExactlyEnough) {
  std::mt19937_64 rng(9);
  for (std::uint64_t seed = 1; seed <= 120; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const bool phong = seed % 2 == 0;
    const BuiltScene scene = phong ? test::random_phong_scene(seed) : test::random_scene(seed);
    auto draw = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    Config wide;
    wide.max_active_edges = 1024;
    wide.x.frac_bits = draw(Config::MinXFrac, Config::MaxXFrac);
    wide.depth.frac_bits = draw(0, 20);
    wide.shade.frac_bits = draw(0, 20);
    wide.normal.frac_bits = draw(0, 20);
    for (ChannelFormat* g : {&wide.x, &wide.depth, &wide.shade, &wide.normal}) g->int_bits = Config::MaxWordBits - g->frac_bits;
    const PreparedScene pw = prepare(scene, wide);
    const Image iw = render(pw, wide);
    Config tight = wide;
    const ShadingMode mode = scene.shading;
    ChannelFormat* group_of[fmt::NumChannels] = {&tight.x, &tight.depth, phong ? &tight.normal : &tight.shade,
                                                 phong ? &tight.normal : &tight.shade,
                                                 phong ? &tight.normal : &tight.shade};
    for (ChannelFormat* g : group_of) g->int_bits = 1;
    for (int c = 0; c < fmt::NumChannels; ++c)
      group_of[c]->int_bits = std::max(group_of[c]->int_bits, pw.needs.int_bits_needed(c, group_of[c]->frac_bits));
    const PreparedScene pt = prepare(scene, tight);
    EXPECT_EQ(render(pt, tight).rgb, iw.rgb);
    for (int c : {fmt::ChanX, fmt::ChanZ, fmt::ChanR}) {
      if (group_of[c]->int_bits == 1) continue;
      Config less = tight;
      ChannelFormat* g = c == fmt::ChanX ? &less.x : c == fmt::ChanZ ? &less.depth : phong ? &less.normal : &less.shade;
      --g->int_bits;
      const std::string e = error_of([&] { prepare(scene, less); });
      EXPECT_NE(e.find(std::string("the configuration's ") + channel_group_name(c, mode) + " word"), std::string::npos)
          << e;
    }
  }
}

TEST(NarrowConfig, PhongMaterialsCapacity) {
  std::string objs;
  for (int i = 0; i < 2; ++i) {
    const std::string k = std::to_string(i);
    objs += std::string(i ? "," : "") + R"({"type": "polygons", "material": "m)" + k + R"(", "polygons": [{"vertices": [
      {"x": 1, "y": )" + k + R"(, "depth": 0.5, "normal": [0, 0, -1], "rgb": [1, 1, 1]},
      {"x": 30, "y": )" + k + R"(, "depth": 0.5, "normal": [0, 0, -1], "rgb": [1, 1, 1]},
      {"x": 16, "y": 31, "depth": 0.5, "normal": [0, 0, -1], "rgb": [1, 1, 1]}]}]})";
  }
  const std::string text = R"({"screen": {"width": 32, "height": 32}, "shading": {"mode": "phong"},
    "materials": {"m0": {"color": [0.5, 0.5, 0.5]}, "m1": {"color": [1, 0, 0]}}, "objects": [)" + objs + "]}";
  const BuiltScene s = load_scene_text(text, "s.json", ".");
  ASSERT_EQ(s.materials.size(), 2u);
  Config c;
  c.max_materials = 1;
  EXPECT_EQ(error_of([&] { prepare(s, c); }),
            "s.json: scene needs 2 materials; the material id is 1 bits and holds 1 (max_materials of the configuration)");
  c.max_materials = 2;
  EXPECT_EQ(error_of([&] { prepare(s, c); }), "");
}

}  // namespace
