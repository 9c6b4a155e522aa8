// Shared by the co-simulation tests (test_cosim.cpp, test_cosim_phong.cpp): random scenes, the
// stall patterns, the shipped scene list and the failure report.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "watkins_top.hpp"
#include "prepare.hpp"
#include "rtl_bench.hpp"
#include "scene.hpp"

namespace watkins::tb::test {

// Everything a failing run needs to be reproduced and diagnosed, in one message.
inline std::string report(const std::string& what, const RtlOptions& o, const RtlResult& r) {
  return what + " (seed " + std::to_string(o.seed) + ", gap " + std::to_string(o.gap) + ", stall " +
         std::to_string(o.stall) + ", stall burst " + std::to_string(o.stall_burst) + "):\n" + r.summary();
}

inline void expect_clean(const std::string& what, const RtlOptions& o, const RtlResult& r) {
  EXPECT_TRUE(r.ok()) << report(what, o, r);
  EXPECT_EQ(r.mismatches, 0) << report(what, o, r);
  EXPECT_FALSE(r.hang) << report(what, o, r);
  EXPECT_FALSE(r.overflow) << what;
  EXPECT_TRUE(r.model_error.empty()) << r.model_error;
}

// ---------------------------------------------------------------- random scenes
inline ScreenVertex random_vertex(std::mt19937_64& rng, double cx, double cy, double radius, double w, double h) {
  std::uniform_real_distribution<double> u(0, 1);
  ScreenVertex v;
  const double a = u(rng) * 2 * M_PI, d = radius * (0.3 + 0.7 * u(rng));
  v.x = std::clamp(cx + d * std::cos(a), -0.5 * w, 1.5 * w);
  v.y = std::clamp(cy + d * std::sin(a), -0.5 * h, 1.5 * h);
  v.depth = u(rng) * 0.999;
  for (double& c : v.rgb) c = u(rng) * 255;
  return v;
}

// Triangles and convex quads of random size, partly off screen, overlapping and (random per-vertex
// depths) interpenetrating; now and then vertices on pixel centres and horizontal edges.
inline BuiltScene random_scene(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  BuiltScene s;
  s.name = "random scene " + std::to_string(seed);
  s.width = 8 + static_cast<int>(rng() % 89);   // 8..96
  s.height = 8 + static_cast<int>(rng() % 57);  // 8..64
  for (double& c : s.background) c = static_cast<double>(rng() % 256);
  const int polys = 1 + static_cast<int>(rng() % 12);
  for (int p = 0; p < polys; ++p) {
    const double cx = (u(rng) * 1.4 - 0.2) * s.width, cy = (u(rng) * 1.4 - 0.2) * s.height;
    const double radius = (0.05 + u(rng) * 0.7) * std::max(s.width, s.height);
    ScreenPolygon poly;
    poly.object = p;
    const bool quad = rng() % 2;
    if (quad) {  // convex: four points on an ellipse in angle order
      std::vector<double> ang(4);
      for (double& a : ang) a = u(rng) * 2 * M_PI;
      std::sort(ang.begin(), ang.end());
      const double rx = radius * (0.3 + 0.7 * u(rng)), ry = radius * (0.3 + 0.7 * u(rng));
      for (double a : ang) {
        ScreenVertex v = random_vertex(rng, cx, cy, radius, s.width, s.height);
        v.x = cx + rx * std::cos(a);
        v.y = cy + ry * std::sin(a);
        poly.v.push_back(v);
      }
    } else {
      for (int k = 0; k < 3; ++k) poly.v.push_back(random_vertex(rng, cx, cy, radius, s.width, s.height));
    }
    if (rng() % 5 == 0) {  // snap to pixel centres: edges through centres, horizontal edges
      for (ScreenVertex& v : poly.v) {
        v.x = std::floor(v.x) + 0.5;
        v.y = std::floor(v.y) + 0.5;
      }
      if (poly.v.size() >= 2) poly.v[1].y = poly.v[0].y;
    }
    double a2 = 0;
    for (std::size_t k = 0; k < poly.v.size(); ++k) {
      const ScreenVertex &a = poly.v[k], &b = poly.v[(k + 1) % poly.v.size()];
      a2 += a.x * b.y - b.x * a.y;
    }
    if (std::fabs(a2) < 1e-6) continue;
    s.polygons.push_back(poly);
  }
  return s;
}

// Stall patterns cycle through: none, light random, heavy random, all-stall bursts.
inline RtlOptions random_options(std::uint64_t seed) {
  RtlOptions o;
  o.seed = seed;
  switch (seed % 4) {
    case 0: o.gap = 0; o.stall = 0; break;
    case 1: o.gap = 0.1; o.stall = 0.1; break;
    case 2: o.gap = 0.5; o.stall = 0.6; break;
    case 3: o.gap = 0.3; o.stall = 0.05; o.stall_burst = 200; break;
  }
  return o;
}

// The scenes/*.json file names, sorted ("<none>" when there are none yet).
inline std::vector<std::string> shipped_scenes() {
  std::vector<std::string> v;
  const std::filesystem::path dir = WATKINS_SOURCE_DIR "/scenes";
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec))
    if (e.path().extension() == ".json") v.push_back(e.path().filename().string());
  std::sort(v.begin(), v.end());
  if (v.empty()) v.push_back("<none>");
  return v;
}

// A shipped scene on the RTL at full speed, under gaps and stalls and all-stall bursts, then in
// sparse output mode; every frame bit for bit the model's.
inline void check_shipped_scene(const std::string& name, const BuildOptions& opt) {
  if (name == "<none>") GTEST_SKIP() << "no scenes/*.json yet";
  const std::string path = WATKINS_SOURCE_DIR "/scenes/" + name;
  BuiltScene scene;
  try {
    scene = load_scene(path, opt);
  } catch (const SceneError& e) {
    GTEST_SKIP() << "the scene does not load in this mode: " << e.what();
  }
  PreparedScene prepared;
  try {
    prepared = prepare(scene);
  } catch (const SceneError& e) {
    GTEST_SKIP() << "the scene does not fit the hardware: " << e.what();
  }
  if (prepared.width > rtl_max_width()) GTEST_SKIP() << "wider than the RTL line buffer";
  const Image model = WatkinsTop().render(prepared);
  // Full speed first, then gaps and stalls, then all-stall bursts.
  // Then sparse output mode at full speed and under gaps and stalls.
  RtlOptions patterns[] = {{1, 0.0, 0.0}, {2, 0.25, 0.3}, {3, 0.1, 0.02, 300}, {4, 0.0, 0.0}, {5, 0.2, 0.3, 20}};
  patterns[3].sparse = patterns[4].sparse = true;
  for (const RtlOptions& o : patterns) {
    const RtlResult r = run_rtl(prepared, o, &model);
    expect_clean(name + (o.sparse ? " sparse" : ""), o, r);
    if (!r.ok()) return;
    EXPECT_EQ(r.frames.at(0).image.rgb, model.rgb) << name << (o.sparse ? " sparse" : "");
    EXPECT_EQ(r.frames.at(0).image.covered, model.covered) << name << (o.sparse ? " sparse" : "");
  }
}

// GoogleTest parameter name of a scene file: "sphere.json" -> "sphere_json".
inline std::string scene_test_name(const ::testing::TestParamInfo<std::string>& i) {
  std::string n = i.param;
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

}  // namespace watkins::tb::test
