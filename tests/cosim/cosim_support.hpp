// Shared by the co-simulation tests (test_cosim.cpp, test_cosim_phong.cpp): the stall patterns, the
// shipped scene list and the failure report (the random scenes are tests/support/random_scene.hpp).
#pragma once

#include <cctype>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "shipped_scenes.hpp"
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
  std::vector<std::string> v = watkins::test::shipped_scene_names();
  if (v.empty()) v.push_back("<none>");
  return v;
}

// A shipped scene on the RTL at full speed, under gaps and stalls and all-stall bursts, then in
// sparse output mode; every frame bit for bit the model's.
inline void check_shipped_scene(const std::string& name, const BuildOptions& opt) {
  if (name == "<none>") GTEST_SKIP() << "no scenes/*.json";
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
