// `watkins size SCENE`: on shipped scenes the configuration it writes is smaller than the default's
// 466-bit edge records, renders within the bound with no coverage or visibility change beyond
// the default configuration's, and is a local minimum (one bit less in any width breaks the bound
// or the flips, or is no valid configuration); bad input is one line, exit code 1, no file.
// The criterion is re-derived here from the images, not taken from sim/size.cpp.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include "cli_run.hpp"
#include "config_file.hpp"
#include "float_reference.hpp"
#include "image_io.hpp"
#include "prepare.hpp"
#include "scene.hpp"
#include "scene_error.hpp"
#include "watkins_top.hpp"

namespace {

using namespace watkins;

using test::CliRun;
CliRun run(const std::string& args, const std::string& cwd = "") { return test::run_cli(args, cwd); }

bool exists(const std::string& path) {
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

class Size : public ::testing::Test, protected test::ScratchDir {};

Image render_with(const BuiltScene& scene, Config cfg) {
  const PreparedScene prepared = prepare(scene, cfg);
  WatkinsTop top(cfg);
  return top.render(prepared);
}

// The criterion of `watkins size`, from the images: at every pixel where the image and the double
// reference show the same polygon, |Δ| ≤ max(L, the default configuration's |Δ| there); coverage
// and the visible polygon differ from the reference only where the default's differ.
struct Verdict {
  int over_bound = 0, extra_flips = 0;
  bool ok() const { return over_bound == 0 && extra_flips == 0; }
};

class Criterion {
 public:
  // `def`: the default configuration the allowance comes from (the compact top's Phong formats
  // for --compact).
  Criterion(const BuiltScene& scene, int bound, Config def = Config{})
      : scene_(scene), bound_(bound), ref_(render_float_reference(scene)) {
    def.max_active_edges = 1 << 20;
    default_ = render_with(scene, def);
  }
  Verdict judge(const Image& img) const {
    Verdict v;
    for (std::size_t i = 0; i < img.covered.size(); ++i) {
      const bool grid_flip = flips(default_, i);
      if (flips(img, i)) {
        v.extra_flips += !grid_flip;
        continue;
      }
      if (!img.covered[i] || grid_flip) continue;
      if (error(img, i) > std::max(bound_, error(default_, i))) ++v.over_bound;
    }
    return v;
  }

 private:
  bool flips(const Image& img, std::size_t i) const {
    return img.covered[i] != ref_.covered[i] || (img.covered[i] && img.owner[i] != ref_.owner[i]);
  }
  int error(const Image& img, std::size_t i) const {
    int e = 0;
    for (int c = 0; c < 3; ++c) e = std::max(e, std::abs(int(img.rgb[i * 3 + c]) - int(ref_.rgb[i * 3 + c])));
    return e;
  }
  const BuiltScene& scene_;
  int bound_;
  Image ref_, default_;
};

struct Case {
  const char* scene;
  const char* shading;
  int bound;
};

void check_scene(const std::string& dir, const Case& k) {
  SCOPED_TRACE(std::string(k.scene) + " " + k.shading + " bound " + std::to_string(k.bound));
  const std::string scene_path = std::string(WATKINS_SOURCE_DIR) + "/scenes/" + k.scene + ".json";
  const std::string out = dir + "/" + k.scene + "." + k.shading + ".json";
  const CliRun r = run("size " + scene_path + " --shading " + k.shading + " --bound " + std::to_string(k.bound) +
                       " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("one bit below"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("wrote         " + out), std::string::npos) << r.output;
  const Config cfg = load_config(out);

  BuildOptions opt;
  opt.shading = parse_shading_mode(k.shading);
  const BuiltScene scene = load_scene(scene_path, opt);
  EXPECT_LT(cfg.edge_record_bits(scene.shading), 466);
  EXPECT_NE(r.output.find("edge record   " + std::to_string(cfg.edge_record_bits(scene.shading)) + " bits"),
            std::string::npos)
      << r.output;

  // The configuration is what the scene needs: prepare() accepts it, and one integer bit fewer
  // in a used group or one active edge fewer is refused.
  const Criterion criterion(scene, k.bound);
  const Verdict chosen = criterion.judge(render_with(scene, cfg));
  EXPECT_TRUE(chosen.ok()) << chosen.over_bound << " pixels over the bound, " << chosen.extra_flips << " extra flips";
  const bool phong = scene.shading == ShadingMode::Phong;
  for (int g = 0; g < 3; ++g) {
    Config narrow = cfg;
    ChannelFormat& f = g == 0 ? narrow.x : g == 1 ? narrow.depth : phong ? narrow.normal : narrow.shade;
    if (f.int_bits == 1) continue;  // the sign alone
    --f.int_bits;
    EXPECT_THROW(prepare(scene, narrow), SceneError) << "group " << g << " int_bits " << f.int_bits;
  }
  Config fewer_edges = cfg;
  --fewer_edges.max_active_edges;
  EXPECT_THROW(prepare(scene, fewer_edges), SceneError);

  // A local minimum: every width one bit lower breaks the bound or the flips (or is no valid
  // configuration). Integer bits widened so that only the fraction changes the image.
  for (int d = 0; d < 4; ++d) {
    Config lower = cfg;
    ChannelFormat& attr = phong ? lower.normal : lower.shade;
    if (d == 0) --lower.x.frac_bits;
    if (d == 1) --attr.frac_bits;
    if (d == 2) --lower.depth_bits;
    if (d == 3) --lower.depth.frac_bits;
    for (ChannelFormat* f : {&lower.x, &lower.depth, &attr}) f->int_bits = Config::MaxWordBits - f->frac_bits;
    lower.max_active_edges = 1 << 20;
    if (!lower.check().empty()) continue;  // the width is at its smallest valid value
    const Verdict v = criterion.judge(render_with(scene, lower));
    EXPECT_FALSE(v.ok()) << "width " << d << " can drop a bit and still pass";
  }

  // None of these scenes smooths: its top is built without the smoother.
  EXPECT_FALSE(cfg.smoothing);
  EXPECT_NE(r.output.find("smoothing     false"), std::string::npos) << r.output;

  // `watkins render --config F` accepts the file.
  const CliRun render = run("render " + scene_path + " --shading " + k.shading + " --config " + out + " --out " +
                            dir + "/r.png");
  EXPECT_EQ(render.exit_code, 0) << render.output;
}

TEST_F(Size, GouraudSphereConeAndDefault) {
  for (const Case& k : {Case{"sphere", "gouraud", 1}, Case{"cone", "gouraud", 1}, Case{"default", "gouraud", 1}})
    check_scene(dir_, k);
}

TEST_F(Size, PhongHighlightAndTorus) {
  for (const Case& k : {Case{"highlight", "phong", 1}, Case{"torus", "phong", 1}}) check_scene(dir_, k);
}

// --compact: the compact top's configuration, "compact": true and, for a Phong scene, the narrow
// Phong formats, its widths judged at them (the criterion against the narrow default); a Gouraud
// scene keeps the model's formats and writes no "phong".
TEST_F(Size, CompactWritesTheNarrowPhongFormats) {
  const std::string scene_path = std::string(WATKINS_SOURCE_DIR) + "/scenes/torus.json";
  const std::string out = dir_ + "/torus.compact.json";
  const CliRun r = run("size " + scene_path + " --shading phong --compact --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("compact       true (the compact top); phong.formats narrow"), std::string::npos) << r.output;
  const Config cfg = load_config(out);
  EXPECT_TRUE(cfg.compact);
  EXPECT_EQ(cfg.phong, PhongFormat::Narrow);
  EXPECT_LE(cfg.normal.frac_bits, narrow::InFracBits);
  BuildOptions opt;
  opt.shading = ShadingMode::Phong;
  const BuiltScene scene = load_scene(scene_path, opt);
  Config narrow_default;
  narrow_default.compact = true;
  narrow_default.phong = PhongFormat::Narrow;
  const Verdict v = Criterion(scene, 1, narrow_default).judge(render_with(scene, cfg));
  EXPECT_TRUE(v.ok()) << v.over_bound << " pixels over the bound, " << v.extra_flips << " extra flips";
  EXPECT_EQ(run("render " + scene_path + " --shading phong --config " + out + " --out " + dir_ + "/r.png").exit_code, 0);

  const std::string gouraud = dir_ + "/torus.gouraud.json";
  ASSERT_EQ(run("size " + scene_path + " --shading gouraud --compact --out " + gouraud).exit_code, 0);
  const Config g = load_config(gouraud);
  EXPECT_TRUE(g.compact);
  EXPECT_EQ(g.phong, PhongFormat::Model);
  std::ifstream in(gouraud);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text.find("phong"), std::string::npos) << text;
}

TEST_F(Size, LooserBoundIsNoWiderOnTheCone) {
  const std::string scene = std::string(WATKINS_SOURCE_DIR) + "/scenes/cone.json";
  ASSERT_EQ(run("size " + scene + " --out " + dir_ + "/b1.json").exit_code, 0);
  check_scene(dir_, Case{"cone", "gouraud", 4});
  const Config tight = load_config(dir_ + "/b1.json");
  const Config loose = load_config(dir_ + "/cone.gouraud.json");
  EXPECT_LE(loose.edge_record_bits(ShadingMode::Gouraud), tight.edge_record_bits(ShadingMode::Gouraud));
}

// A scene that smooths (shading.smooth) keeps the smoother; the same scene without it drops it.
TEST_F(Size, SmoothingFollowsTheScene) {
  std::ifstream in(WATKINS_SOURCE_DIR "/scenes/cone.json");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string from = R"("shading": {)";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  text.insert(at + from.size(), R"("smooth": 0.8, )");
  const std::string scene = write("smoothed_cone.json", text);
  for (const bool smooth : {true, false}) {
    const std::string out = dir_ + (smooth ? "/on.json" : "/off.json");
    const CliRun r = run("size " + (smooth ? scene : std::string(WATKINS_SOURCE_DIR "/scenes/cone.json")) + " --out " + out);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(load_config(out).smoothing, smooth);
    EXPECT_NE(r.output.find(smooth ? "smoothing     true" : "smoothing     false"), std::string::npos) << r.output;
    // The smoothed scene renders on its configuration, and is refused on the other one.
    const CliRun render = run("render " + scene + " --config " + out + " --out " + dir_ + "/r.png");
    EXPECT_EQ(render.exit_code, smooth ? 0 : 1) << render.output;
  }
}

TEST_F(Size, DefaultOutputNameIsTheSceneStem) {
  const CliRun r = run("size " WATKINS_SOURCE_DIR "/scenes/mesh.json", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(exists(dir_ + "/mesh.config.json"));
  EXPECT_NO_THROW(load_config(dir_ + "/mesh.config.json"));
}

// scenes/sized/ holds the shipped scenes' configurations (scripts/lib/size_table.py); they must stay what
// `watkins size` finds, on the scenes that search fastest.
TEST_F(Size, ShippedConfigurationsAreCurrent) {
  for (const char* scene : {"cone", "mesh", "highlight", "default"})
    for (const char* shading : {"gouraud", "phong"}) {
      const std::string name = std::string(scene) + "." + shading + ".json";
      const CliRun r = run(std::string("size " WATKINS_SOURCE_DIR "/scenes/") + scene + ".json --shading " + shading +
                           " --out " + dir_ + "/" + name);
      ASSERT_EQ(r.exit_code, 0) << r.output;
      EXPECT_EQ(load_config(dir_ + "/" + name), load_config(WATKINS_SOURCE_DIR "/scenes/sized/" + name))
          << name << ": re-run scripts/lib/size_table.py";
    }
}

// scenes/sized/patches.curves.phong.json is one configuration for the shipped patch scenes drawn by
// curves: every key at least what `watkins size --patches curves` finds for each (edge_order 3,
// the curve regions counted as polygon ids), so each prepares at it.
TEST_F(Size, CurvesConfigurationCoversTheShippedPatchScenes) {
  const Config cover = load_config(WATKINS_SOURCE_DIR "/scenes/sized/patches.curves.phong.json");
  ASSERT_EQ(cover.edge_order, 3);
  for (const char* scene : {"patch", "bspline", "teapot"}) {
    SCOPED_TRACE(scene);
    const std::string out = dir_ + "/" + scene + ".curves.phong.json";
    const CliRun r = run(std::string("size " WATKINS_SOURCE_DIR "/scenes/") + scene +
                         ".json --shading phong --patches curves --out " + out);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const Config c = load_config(out);
    EXPECT_EQ(c.edge_order, 3);
    for (const auto& [have, need] : {std::pair{cover.x, c.x}, std::pair{cover.depth, c.depth},
                                     std::pair{cover.normal, c.normal}}) {
      EXPECT_GE(have.int_bits, need.int_bits);
      EXPECT_GE(have.frac_bits, need.frac_bits);
    }
    for (const auto& [have, need] : {std::pair{cover.depth_bits, c.depth_bits},
                                     std::pair{cover.max_active_edges, c.max_active_edges},
                                     std::pair{cover.max_width, c.max_width},
                                     std::pair{cover.max_materials, c.max_materials},
                                     std::pair{cover.max_polygons, c.max_polygons},
                                     std::pair{cover.max_edges, c.max_edges}})
      EXPECT_GE(have, need);
    EXPECT_GE(cover.smoothing, c.smoothing) << "the scene smooths: the configuration needs the smoother";
    BuildOptions opt;
    opt.shading = ShadingMode::Phong;
    opt.patches_as_curves = true;
    const BuiltScene built = load_scene(WATKINS_SOURCE_DIR "/scenes/" + std::string(scene) + ".json", opt);
    EXPECT_EQ(c.max_polygons, static_cast<int>(built.curve_regions));
    EXPECT_NO_THROW(prepare(built, cover));
  }
}

TEST_F(Size, BadInputIsOneLineAndWritesNothing) {
  const std::string out = dir_ + "/bad.json";
  struct Bad {
    std::string args, message;
    int code = 2;  // a wrong option value: "watkins: usage: "; 1: a bad file, "watkins: error: "
  };
  const Bad cases[] = {
      {"size " + dir_ + "/missing.json --out " + out, dir_ + "/missing.json", 1},
      {"size " WATKINS_SOURCE_DIR "/scenes/cone.json --bound x --out " + out,
       "--bound: expected a whole number of levels in 0..255, got \"x\""},
      {"size " WATKINS_SOURCE_DIR "/scenes/cone.json --bound=-1 --out " + out,
       "--bound: expected a whole number of levels in 0..255, got \"-1\""},
      {"size " WATKINS_SOURCE_DIR "/scenes/cone.json --bound 1.5 --out " + out,
       "--bound: expected a whole number of levels in 0..255, got \"1.5\""},
      {"size " WATKINS_SOURCE_DIR "/scenes/cone.json --shading toon --out " + out, "--shading: unknown shading mode"},
  };
  for (const Bad& b : cases) {
    const CliRun r = run(b.args);
    EXPECT_EQ(r.exit_code, b.code) << b.args;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_EQ(r.output.rfind(b.code == 2 ? "watkins: usage: " : "watkins: error: ", 0), 0u) << r.output;
    EXPECT_NE(r.output.find(b.message), std::string::npos) << r.output;
    EXPECT_FALSE(exists(out)) << b.args;
  }
}

}  // namespace
