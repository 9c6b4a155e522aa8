// Whitted's curved edges on the forward-difference incrementer (edge_order 3): the configuration
// key, the incrementer twin's cubic step, the fitter's bound on every line of synthetic curves
// (a disc, a sine-like band, a curve with a steep part), what the whole pipeline does with them,
// and the refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "config_file.hpp"
#include "curve_scenes.hpp"
#include "curved_edges.hpp"
#include "prepare.hpp"
#include "scan_lines.hpp"
#include "test_support.hpp"
#include "watkins_top.hpp"

namespace {

using namespace watkins;
using namespace watkins::test;

using watkins::test::error_of;

Config cubic(Config c = Config{}) {
  c.edge_order = 3;
  return c;
}

Config narrow() { return cubic(load_config(WATKINS_SOURCE_DIR "/tests/configs/narrow.json")); }

TEST(CurvedEdges, EdgeOrderKey) {
  const Config c = parse_config("{\"edge_order\": 3}", "c.json");
  EXPECT_EQ(c.edge_order, 3);
  EXPECT_TRUE(parse_config(config_json(c), "c.json") == c);
  EXPECT_EQ(config_json(Config{}).find("edge_order"), std::string::npos) << "order 1 files read as before";
  EXPECT_NE(error_of([] { parse_config("{\"edge_order\": 2}", "c.json"); }).find("c.json: edge_order: 2"),
            std::string::npos);
  for (const ShadingMode m : {ShadingMode::Gouraud, ShadingMode::Phong}) {
    // Order 1: the parameter list as before the key existed (the RTL's default EdgeOrder = 1).
    const std::vector<RtlParameter> p1 = rtl_parameters(Config{}, m), p3 = rtl_parameters(c, m);
    EXPECT_EQ(p1.size(), 13u);
    for (const RtlParameter& p : p1) EXPECT_STRNE(p.name, "EdgeOrder");
    ASSERT_EQ(p3.size(), 14u);
    EXPECT_TRUE((p3.back() == RtlParameter{"EdgeOrder", 3}));
    // Two more channel vectors (d2, d3) per record.
    const ChannelFormats f = c.channels(m);
    int vector_bits = 0;
    for (int ch = 0; ch < fmt::NumChannels; ++ch) vector_bits += f.bits[ch];
    EXPECT_EQ(c.edge_record_bits(m), fmt::EdgeRecordBits + 2 * vector_bits);
    EXPECT_EQ(f.edge_order, 3);
  }
}

// The twin's step k times equals the closed form v0 + d1 C(k,1) + d2 C(k,2) + d3 C(k,3), wrapped
// to the slot's word: also when the differences and the values wrap (narrow words).
// A scene with curves needs edge_order 3: the default configuration gets it (watkins render without
// --config) and so does the sized one; a polygon scene keeps the base's order.
TEST(CurvedEdges, SceneEdgeOrderIsWhatTheSceneNeeds) {
  const BuiltScene curves = curve_scene(ShadingMode::Phong);
  EXPECT_EQ(with_scene_edge_order(curves, Config{}).edge_order, 3);
  EXPECT_EQ(fit_int_bits(curves, Config{}).edge_order, 3);
  BuiltScene polygons = curves;
  polygons.curves.clear();
  polygons.curve_regions = 0;
  EXPECT_EQ(with_scene_edge_order(polygons, Config{}).edge_order, 1);
  EXPECT_EQ(with_scene_edge_order(polygons, cubic()).edge_order, 3);
}

TEST(CurvedEdges, IncrementerStepsTheCubic) {
  std::mt19937_64 rng(5);
  for (const Config& cfg : {cubic(), narrow()}) {
    const ChannelFormats f = cfg.channels(ShadingMode::Phong);
    for (int trial = 0; trial < 200; ++trial) {
      ActiveEdge a;
      a.remaining = a.rec.n = 300;
      for (int c = 0; c < fmt::NumChannels; ++c) {
        auto any = [&] { return wrap_signed(static_cast<i128>(rng()), f.bits[c]); };
        a.rec.value[c] = any(), a.rec.slope[c] = any(), a.rec.d2[c] = any();
        a.rec.d3[c] = trial % 2 ? any() : static_cast<i64>(rng() % 7) - 3;
      }
      const EdgeRecord first = a.rec;
      for (int k = 0; k < 300; ++k) {
        for (int c = 0; c < fmt::NumChannels; ++c)
          ASSERT_EQ(a.rec.value[c], forward_difference_value(first, c, k, f.bits[c])) << "line " << k << " ch " << c;
        EdgeIncrementer::step(a, f);
      }
    }
    // Order 1 ignores d2 and d3 (an order-1 record has none).
    ActiveEdge a;
    a.rec.value[0] = 10, a.rec.slope[0] = 3, a.rec.d2[0] = 100, a.rec.d3[0] = 1000;
    EdgeIncrementer::step(a, Config{}.channels(ShadingMode::Gouraud));
    EdgeIncrementer::step(a, Config{}.channels(ShadingMode::Gouraud));
    EXPECT_EQ(a.rec.value[0], 16);
    EXPECT_EQ(a.rec.slope[0], 3);
  }
}

// Channel c of a line's crossing in the slot's unit (pixels, depth units, levels, 1.0).
double unit_value(const ScreenVertex& v, int c, ShadingMode shading, const Config& cfg) {
  if (c == fmt::ChanX) return v.x;
  if (c == fmt::ChanZ) return std::ldexp(v.depth, cfg.depth_bits);
  return shading == ShadingMode::Phong ? v.normal[c - fmt::ChanNx] : v.rgb[c - fmt::ChanR];
}

// Every curve of the scene, fitted: the pieces cover its lines one after another, the incrementer
// twin steps every piece to the fitted values, and every line is within the bound of the
// quantized crossing (and so within the bound plus half an LSB of the double crossing).
TEST(CurvedEdges, FitHoldsTheBoundOnEveryLine) {
  const CurveFitBounds bounds;
  for (const Config& cfg : {cubic(), narrow()}) {
    for (const ShadingMode shading : {ShadingMode::Gouraud, ShadingMode::Phong}) {
      const BuiltScene scene = curve_scene(shading);
      const ChannelFormats f = cfg.channels(shading);
      const auto bound = bounds.lsb(f, shading);
      EXPECT_EQ(bound[fmt::ChanX], std::ldexp(1.0, f.frac[fmt::ChanX] - 4)) << "X: 1/16 pixel";
      int pieces = 0, longest = 0;
      for (std::size_t i = 0; i < scene.curves.size(); ++i) {
        const ScreenCurve& curve = scene.curves[i];
        const CurveEdges fit = fit_curve(curve, scene.height, shading, cfg);
        const std::string what = "curve " + std::to_string(i) + (cfg == cubic() ? " default" : " narrow");
        ASSERT_EQ(fit.quantized.size(), curve.lines.size()) << what;
        int line = curve.y0;
        for (const EdgeRecord& r : fit.records) {
          ASSERT_EQ(r.y0, line) << what << ": pieces cover consecutive lines";
          ASSERT_GE(r.n, 1);
          longest = std::max(longest, r.n);
          ActiveEdge a{r, r.n};
          for (int k = 0; k < r.n; ++k, ++line) {
            const ScreenVertex& exact = curve.lines[line - curve.y0];
            for (int c = 0; c < fmt::NumChannels; ++c) {
              const i64 hw = a.rec.value[c];
              ASSERT_EQ(hw, forward_difference_value(r, c, k, f.bits[c])) << what << " line " << line;
              const i64 err = hw - fit.quantized[line - curve.y0][c];
              ASSERT_LE(std::abs(err), bound[c]) << what << " line " << line << " channel " << c;
              ASSERT_LE(std::abs(err), fit.max_error[c]) << what;
              // Against the double crossing: the bound plus the quantization's half LSB.
              const double got = std::ldexp(static_cast<double>(hw), -f.frac[c]);
              const double tol = std::ldexp(static_cast<double>(bound[c]) + 0.5, -f.frac[c]) + 1e-9;
              if (c != fmt::ChanZ || exact.depth * std::ldexp(1.0, cfg.depth_bits) < std::ldexp(1.0, cfg.depth_bits) - 1)
                ASSERT_NEAR(got, unit_value(exact, c, shading, cfg), tol) << what << " line " << line << " ch " << c;
            }
            EdgeIncrementer::step(a, f);
          }
          ++pieces;
        }
        ASSERT_EQ(line, curve.y0 + static_cast<int>(curve.lines.size())) << what;
      }
      EXPECT_GT(longest, 4) << "some run is a fitted cubic, not an interpolation of four lines";
      EXPECT_GT(pieces, static_cast<int>(scene.curves.size()));
    }
  }
}

// The pieces and run lengths at the default formats (and the narrow ones), and the hardware's
// error against the double crossings (X in pixels, Z in 2^-16 of the depth range, N in units of
// 1.0), printed for the report; the steep curve needs shorter runs than the nearly straight one
// beside it, and the errors stay inside the bounds.
TEST(CurvedEdges, PiecesAndRunLengths) {
  for (const Config& cfg : {cubic(), narrow()}) {
    const BuiltScene scene = curve_scene(ShadingMode::Phong);
    const ChannelFormats f = cfg.channels(ShadingMode::Phong);
    std::vector<int> pieces;
    double max_err[3] = {0, 0, 0}, sum_err[3] = {0, 0, 0};
    long samples = 0;
    for (std::size_t i = 0; i < scene.curves.size(); ++i) {
      const CurveEdges fit = fit_curve(scene.curves[i], scene.height, ShadingMode::Phong, cfg);
      int line = 0;
      for (const EdgeRecord& r : fit.records)
        for (int k = 0; k < r.n; ++k, ++line) {
          const ScreenVertex& v = scene.curves[i].lines[line];
          auto at = [&](int c) {
            return std::ldexp(static_cast<double>(forward_difference_value(r, c, k, f.bits[c])), -f.frac[c]);
          };
          double n_err = 0;
          for (int c = fmt::ChanNx; c <= fmt::ChanNz; ++c)
            n_err = std::max(n_err, std::fabs(at(c) - v.normal[c - fmt::ChanNx]));
          const double e[3] = {std::fabs(at(fmt::ChanX) - v.x),
                               std::fabs(std::ldexp(at(fmt::ChanZ), 16 - cfg.depth_bits) - std::ldexp(v.depth, 16)),
                               n_err};
          for (int j = 0; j < 3; ++j) max_err[j] = std::max(max_err[j], e[j]), sum_err[j] += e[j];
          ++samples;
        }
      std::string runs;
      for (const EdgeRecord& r : fit.records) runs += " " + std::to_string(r.n);
      const double x_err = std::ldexp(static_cast<double>(fit.max_error[fmt::ChanX]), -cfg.x.frac_bits);
      std::printf("%s curve %zu: %zu lines, %zu pieces, max X error %.4f px vs quantized; runs%s\n",
                  cfg == cubic() ? "default" : "narrow ", i, scene.curves[i].lines.size(), fit.records.size(), x_err,
                  runs.c_str());
      pieces.push_back(static_cast<int>(fit.records.size()));
    }
    std::printf("%s vs double crossings over %ld lines: X max %.5f mean %.5f px; Z max %.4f mean %.4f (2^-16); "
                "N max %.6f mean %.6f\n",
                cfg == cubic() ? "default" : "narrow ", samples, max_err[0], sum_err[0] / samples, max_err[1],
                sum_err[1] / samples, max_err[2], sum_err[2] / samples);
    EXPECT_GT(pieces[4], pieces[5]) << "the steep curve splits more";
    const CurveFitBounds b;
    EXPECT_LE(max_err[0], b.x + std::ldexp(1.0, -cfg.x.frac_bits - 1));
    EXPECT_LE(max_err[1], 1.0 + std::ldexp(1.0, 16 - cfg.depth_bits - cfg.depth.frac_bits - 1));
    EXPECT_LE(max_err[2], b.normal + std::ldexp(1.0, -cfg.normal.frac_bits - 1));
  }
}

// The whole front half: on every line the active curved edges are the fitted pieces (one per
// curve), with the fitted values; regions pair as polygons after the scene's polygons.
TEST(CurvedEdges, PreparedFrameCarriesThePieces) {
  for (const ShadingMode shading : {ShadingMode::Gouraud, ShadingMode::Phong}) {
    const BuiltScene scene = curve_scene(shading);
    const Config cfg = cubic();
    const PreparedScene p = prepare(scene, cfg);
    const ChannelFormats f = cfg.channels(shading);
    // Expected (polygon id, channels) of every curve on every line.
    std::map<int, std::vector<std::pair<int, ChannelVector>>> want;
    int records = 0;
    for (const ScreenCurve& curve : scene.curves) {
      const CurveEdges fit = fit_curve(curve, scene.height, shading, cfg);
      records += static_cast<int>(fit.records.size());
      for (const EdgeRecord& r : fit.records)
        for (int k = 0; k < r.n; ++k) {
          ChannelVector v;
          for (int c = 0; c < fmt::NumChannels; ++c) v[c] = forward_difference_value(r, c, k, f.bits[c]);
          want[r.y0 + k].push_back({1 + curve.region, v});
        }
    }
    EXPECT_EQ(p.needs.curve_edges, records);
    EXPECT_EQ(p.needs.edges, records + 3);
    EXPECT_EQ(p.needs.max_curve_edges, 6) << "disc, band and steep region overlap on lines 70..80";
    EXPECT_EQ(p.needs.max_curve_line, 70);
    int curved_seen = 0;
    walk_scan_lines(p.edges, p.height, cfg.max_active_edges, f, [&](const ScanLine& line) {
      std::vector<std::pair<int, ChannelVector>> got;
      for (const ActiveEdge& e : line.active.edges()) {
        if (e.rec.poly == 0) {
          EXPECT_EQ(e.rec.d2, ChannelVector{}) << "a straight edge has no second difference";
          continue;
        }
        EXPECT_EQ(e.rec.material, shading == ShadingMode::Phong ? e.rec.poly - 1 : 0);
        got.push_back({e.rec.poly, e.rec.value});
      }
      auto w = want[line.y];
      std::sort(w.begin(), w.end());
      std::sort(got.begin(), got.end());
      EXPECT_EQ(got, w) << "line " << line.y;
      curved_seen += static_cast<int>(got.size());
    });
    int lines = 0;
    for (const ScreenCurve& c : scene.curves) lines += static_cast<int>(c.lines.size());
    EXPECT_EQ(curved_seen, lines);
  }
}

// The disc through the model's WatkinsTop: a pixel is the disc's exactly when its centre lies
// between the double crossings of its line, except within the bound (1/16 pixel) plus half an
// LSB of a crossing.
TEST(CurvedEdges, DiscImageMatchesTheExactCrossings) {
  for (const ShadingMode shading : {ShadingMode::Gouraud, ShadingMode::Phong}) {
    const BuiltScene scene = curve_scene(shading);
    const Config cfg = cubic();
    const PreparedScene p = prepare(scene, cfg);
    const Image img = WatkinsTop(cfg).render(p);
    const double slack = 1.0 / 16 + std::ldexp(1.0, -cfg.x.frac_bits);
    int disc_pixels = 0, near_misses = 0;
    for (int y = 0; y < scene.height; ++y) {
      const double yc = y + 0.5;
      const bool on_disc = y >= scene.curves[0].y0 && y < scene.curves[0].y0 + int(scene.curves[0].lines.size());
      const double xl = on_disc ? curve_scene_x(0, yc) : 0, xr = on_disc ? curve_scene_x(1, yc) : 0;
      for (int x = 0; x < scene.width; ++x) {
        const double xc = x + 0.5;
        const bool want = on_disc && xc >= xl && xc < xr;
        const bool got = img.owner[std::size_t(y) * scene.width + x] == 1;
        disc_pixels += got;
        if (want == got) continue;
        const double d = std::min(std::fabs(xc - xl), std::fabs(xc - xr));
        ASSERT_LE(d, slack) << "pixel (" << x << ", " << y << ") disc " << got << ", exact " << want;
        ++near_misses;
      }
    }
    EXPECT_GT(disc_pixels, 3000);  // pi 34^2 = 3632
    EXPECT_LE(near_misses, 4);
  }
}

// Refusals: curves at edge order 1 (naming the field), an X word too narrow for a curve's values
// on some line, more regions than polygon ids.
TEST(CurvedEdges, Refusals) {
  const BuiltScene scene = curve_scene(ShadingMode::Gouraud);
  const std::string e1 = error_of([&] { prepare(scene, Config{}); });
  EXPECT_NE(e1.find("curve scene: edge_order: the scene has 6 curved edges"), std::string::npos) << e1;
  Config tight = cubic();
  tight.x.int_bits = 8;  // +-128 pixels: the band reaches 141
  const std::string e2 = error_of([&] { prepare(scene, tight); });
  EXPECT_NE(e2.find("edge values of channel X need"), std::string::npos) << e2;
  Config few = cubic();
  few.max_polygons = 3;  // one polygon and three regions need four ids
  EXPECT_NE(error_of([&] { prepare(scene, few); }).find("3 curved regions"), std::string::npos);
  // Without curves an order-3 configuration prepares polygons exactly as order 1 does.
  BuiltScene flat = scene;
  flat.curves.clear();
  flat.curve_regions = 0;
  const PreparedScene a = prepare(flat, Config{}), b = prepare(flat, cubic());
  ASSERT_EQ(a.edges.size(), b.edges.size());
  for (std::size_t i = 0; i < a.edges.size(); ++i) {
    EXPECT_EQ(a.edges[i].value, b.edges[i].value);
    EXPECT_EQ(a.edges[i].slope, b.edges[i].slope);
    EXPECT_EQ(b.edges[i].d2, ChannelVector{});
  }
  EXPECT_EQ(WatkinsTop(Config{}).render(a).rgb, WatkinsTop(cubic()).render(b).rgb);
}

}  // namespace
