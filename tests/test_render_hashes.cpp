// The model's frames pinned by hash: every shipped scene in both shadings (at the default
// configuration with the capacity and edge order it needs, and at its sized configuration where
// scenes/sized has one) and 600 random frames across configurations (fitted and random fraction
// bits, both depth-tie rules, eq. (2), smoothing, curved edges at edge order 3), each frame's
// image (rgb, coverage, owner) and stage counts (PipelineStats) hashed, against
// tests/render_hashes.txt. Any change to the model that alters one value or count fails here; the
// frames are drawn as the renderer draws them (no observer: the per-frame fast path), and the
// observed path (every fragment reported) and three threads must give the same image and counts.
// WATKINS_WRITE_RENDER_HASHES=1 rewrites the file from the model as built.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "config_file.hpp"
#include "curve_scenes.hpp"
#include "prepare.hpp"
#include "random_scene.hpp"
#include "scene.hpp"
#include "shipped_scenes.hpp"
#include "watkins_top.hpp"

namespace watkins {
namespace {

constexpr const char* kHashFile = WATKINS_SOURCE_DIR "/tests/render_hashes.txt";

// FNV-1a, 64 bits: a fixed function of the bytes (std::hash is not).
struct Fnv {
  std::uint64_t h = 0xcbf29ce484222325ull;
  void bytes(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 0x100000001b3ull;
  }
  void i64v(long long v) { bytes(&v, sizeof v); }
};

std::string hex(std::uint64_t v) {  // a hex literal: never read as a commit's name
  char s[19];
  std::snprintf(s, sizeof s, "0x%016llx", static_cast<unsigned long long>(v));
  return s;
}

std::uint64_t frame_hash(const Image& img, const PipelineStats& s) {
  Fnv f;
  f.i64v(img.width), f.i64v(img.height);
  f.bytes(img.rgb.data(), img.rgb.size());
  f.bytes(img.covered.data(), img.covered.size());
  f.bytes(img.owner.data(), img.owner.size() * sizeof(int));
  for (const long long v : {s.edges, s.segments, s.fragments, s.visible, static_cast<long long>(s.max_active_edges)})
    f.i64v(v);
  return f.h;
}

// One frame: the unobserved render (what `watkins render` draws) hashed, after checking that the
// observed path draws the same. A frame the configuration refuses hashes its message.
std::string frame_result(const std::function<PreparedScene()>& make) {
  PreparedScene p;
  try {
    p = make();
  } catch (const std::exception& e) {
    Fnv f;
    const std::string m = e.what();
    f.bytes(m.data(), m.size());
    return "refused:" + hex(f.h);
  }
  WatkinsTop fast(p.config);
  Image img;
  try {
    fast.render_into(p, img);
  } catch (const std::exception& e) {
    return std::string("throws:") + e.what();
  }
  WatkinsTop banded(p.config);  // three bands of scan lines: the same frame
  banded.set_threads(3);
  Image img_banded;
  banded.render_into(p, img_banded);
  EXPECT_EQ(frame_hash(img_banded, banded.stats()), frame_hash(img, fast.stats()));
  WatkinsTop observed(p.config);
  long long seen = 0;
  const Image img_observed = observed.render(p, [&](int, const Fragment&, bool) { ++seen; });
  EXPECT_EQ(frame_hash(img_observed, observed.stats()), frame_hash(img, fast.stats()));
  EXPECT_EQ(seen, fast.stats().fragments);
  return hex(frame_hash(img, fast.stats()));
}

// The default configuration with the edge order and divider the scene needs and an active-edge
// list as long as it needs.
Config holding_with_order(const BuiltScene& scene) {
  Config c = with_scene_edge_order(scene, Config{});
  c.max_active_edges = 1 << 16;
  c.max_active_edges = std::max(fmt::MaxActiveEdges, prepare(scene, c).needs.max_active_edges);
  return c;
}

// A valid configuration with random fraction bits (and depth_bits), integer bits fitted to the scene.
Config random_fitted(std::mt19937_64& rng, const BuiltScene& scene, Config base) {
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  base.x.frac_bits = pick(Config::MinXFrac, Config::MaxXFrac);
  base.depth_bits = pick(8, 30);
  base.depth.frac_bits = pick(0, 20);
  base.shade.frac_bits = pick(0, 24);
  base.normal.frac_bits = pick(8, 24);
  base.max_active_edges = 1 << 16;
  return fit_int_bits(scene, base);
}

// The i-th random frame: a scene and a configuration.
std::string random_frame(int i) {
  std::mt19937_64 rng(0x5eed0000u + static_cast<std::uint64_t>(i));
  const int kind = i % 8;
  return frame_result([&] {
    BuiltScene s;
    Config cfg;
    switch (kind) {
      case 0:  // the co-simulation's scenes at the default configuration
        s = test::random_scene(static_cast<std::uint64_t>(i));
        cfg = holding_with_order(s);
        break;
      case 1:
        s = test::random_phong_scene(static_cast<std::uint64_t>(i));
        cfg = holding_with_order(s);
        break;
      case 2:  // fitted random fractions, polygon-id ties
        s = test::random_scene(rng);
        s.depth_tie = DepthTie::Submission;
        cfg = random_fitted(rng, s, with_scene_edge_order(s, Config{}));
        break;
      case 3:
        s = test::random_phong_scene(static_cast<std::uint64_t>(i));
        s.depth_tie = i % 16 < 8 ? DepthTie::Submission : DepthTie::Arrival;
        cfg = random_fitted(rng, s, with_scene_edge_order(s, Config{}));
        break;
      case 4: {  // Gouraud's eq. (2)
        s = test::random_scene(rng);
        s.interpolation = Interpolation::Eq2;
        Config base = with_scene_edge_order(s, Config{});
        base.eq2_recip_bits = std::uniform_int_distribution<int>(Config::MinEq2RecipBits, 20)(rng);
        cfg = i % 16 < 8 ? holding_with_order(s) : random_fitted(rng, s, base);
        cfg.eq2 = true;
        cfg.eq2_recip_bits = base.eq2_recip_bits;
        break;
      }
      case 5: {  // meshes: shared edges, equal X on a line; smoothed
        const int w = std::uniform_int_distribution<int>(16, 120)(rng);
        const int h = std::uniform_int_distribution<int>(8, 80)(rng);
        // One draw per statement: the order of a call's arguments is the compiler's.
        const int rows = std::uniform_int_distribution<int>(1, 8)(rng);
        const int cols = std::uniform_int_distribution<int>(1, 8)(rng);
        s = test::mesh_scene(rng, w, h, cols, rows);
        s.smooth = std::uniform_int_distribution<int>(0, 255)(rng) / 128.0;
        cfg = holding_with_order(s);
        break;
      }
      case 6: {  // bow-ties and wide screens, random fractions
        test::RandomSceneSpec spec;
        spec.convex_quads = false;
        spec.max_width = 400;
        spec.max_polygons = 40;
        s = test::random_scene(rng, spec);
        cfg = random_fitted(rng, s, with_scene_edge_order(s, Config{}));
        break;
      }
      default:  // curved edges (edge order 3), both shadings
        s = test::curve_scene(i % 16 < 8 ? ShadingMode::Gouraud : ShadingMode::Phong);
        s.depth_tie = i % 3 == 0 ? DepthTie::Submission : DepthTie::Arrival;
        cfg = i % 5 == 0 ? holding_with_order(s) : random_fitted(rng, s, with_scene_edge_order(s, Config{}));
        break;
    }
    return prepare(s, cfg);
  });
}

std::map<std::string, std::string> computed_hashes() {
  std::map<std::string, std::string> out;
  for (const std::string& name : test::shipped_scene_names()) {
    const std::string path = WATKINS_SOURCE_DIR "/scenes/" + name;
    const std::string stem = name.substr(0, name.size() - 5);
    for (const ShadingMode sh : {ShadingMode::Gouraud, ShadingMode::Phong}) {
      BuildOptions opt;
      opt.shading = sh;
      const std::string tag = sh == ShadingMode::Phong ? "phong" : "gouraud";
      std::string key = "scene " + name + " " + tag;
      std::unique_ptr<BuiltScene> scene;
      try {
        scene = std::make_unique<BuiltScene>(load_scene(path, opt));
      } catch (const std::exception& e) {
        out[key] = "unbuilt";
        continue;
      }
      out[key] = frame_result([&] { return prepare(*scene, holding_with_order(*scene)); });
      const std::string sized = WATKINS_SOURCE_DIR "/scenes/sized/" + stem + "." + tag + ".json";
      if (std::filesystem::exists(sized))
        out[key + " sized"] = frame_result([&] { return prepare(*scene, load_config(sized)); });
    }
  }
  for (int i = 0; i < 600; ++i) out["random " + std::to_string(i)] = random_frame(i);
  return out;
}

TEST(RenderHashes, EveryShippedSceneAndRandomFrameUnchanged) {
  const std::map<std::string, std::string> got = computed_hashes();
  int refused = 0;
  for (const auto& [k, v] : got) refused += v.rfind("refused", 0) == 0 || v.rfind("throws", 0) == 0;
  EXPECT_LT(refused, 60) << "most frames render";
  if (const char* w = std::getenv("WATKINS_WRITE_RENDER_HASHES"); w && std::string(w) == "1") {
    std::ofstream f(kHashFile);
    f << "# tests/test_render_hashes.cpp: frame hashes of the model (WATKINS_WRITE_RENDER_HASHES=1 rewrites)\n";
    for (const auto& [k, v] : got) f << k << "\t" << v << "\n";
    GTEST_SKIP() << "wrote " << kHashFile;
  }
  std::ifstream f(kHashFile);
  ASSERT_TRUE(f) << kHashFile;
  std::map<std::string, std::string> want;
  for (std::string line; std::getline(f, line);) {
    if (line.empty() || line[0] == '#') continue;
    const auto tab = line.find('\t');
    ASSERT_NE(tab, std::string::npos) << line;
    want[line.substr(0, tab)] = line.substr(tab + 1);
  }
  EXPECT_EQ(want.size(), got.size());
  int differ = 0;
  for (const auto& [k, v] : want) {
    const auto it = got.find(k);
    if (it == got.end()) {
      ADD_FAILURE() << k << ": not rendered";
      continue;
    }
    if (it->second != v) {
      ++differ;
      ADD_FAILURE() << k << ": hash " << it->second << ", pinned " << v;
    }
  }
  EXPECT_EQ(differ, 0);
}

}  // namespace
}  // namespace watkins
