// watkins sweep: the error statistics it adds (PSNR, the Mach-band measure) on hand-made images,
// the flat shading rule of the scene front end, and a tiny sweep through the command line whose
// CSV columns and values are checked; Whitted's curved patches against their tessellation.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "cycle_model.hpp"
#include "error_stats.hpp"
#include "prepare.hpp"
#include "scene.hpp"

namespace watkins {
namespace {

// One row of pixels, all covered, grey levels `v`, polygon ids `poly`.
Image row(const std::vector<int>& v, const std::vector<int>& poly) {
  Image img(static_cast<int>(v.size()), 1);
  for (std::size_t x = 0; x < v.size(); ++x) {
    for (int c = 0; c < 3; ++c) img.rgb[x * 3 + c] = static_cast<std::uint8_t>(v[x]);
    img.covered[x] = 1;
    img.owner[x] = poly[x];
  }
  return img;
}

const std::vector<int> kTwoPolygons{0, 0, 0, 0, 1, 1, 1, 1};

TEST(MachBand, KinkInSlopeAtAnEdge) {  // Gouraud's Fig. 1b: continuous value, slope 10 then 20
  const Image img = row({0, 10, 20, 30, 40, 60, 80, 100}, kTwoPolygons);
  EXPECT_DOUBLE_EQ(mach_band(img, img.owner), 10.0);  // d = 10, 10, 20 around the edge
}

TEST(MachBand, StepInValueAtAnEdge) {  // Fig. 1a: flat shading's step of 30 levels
  const Image img = row({50, 50, 50, 50, 80, 80, 80, 80}, kTwoPolygons);
  EXPECT_DOUBLE_EQ(mach_band(img, img.owner), 30.0);
}

TEST(MachBand, KinkInsideOnePolygonIsNotCounted) {
  const Image img = row({0, 10, 20, 30, 50, 70, 90, 110}, std::vector<int>(8, 0));
  EXPECT_DOUBLE_EQ(mach_band(img, img.owner), 0.0);
}

TEST(MachBand, ColumnsCountToo) {
  Image img(1, 8);
  const int v[8] = {0, 0, 0, 0, 40, 40, 40, 40};
  for (int y = 0; y < 8; ++y) {
    for (int c = 0; c < 3; ++c) img.rgb[y * 3 + c] = static_cast<std::uint8_t>(v[y]);
    img.covered[y] = 1;
    img.owner[y] = y < 4 ? 3 : 7;
  }
  EXPECT_DOUBLE_EQ(mach_band(img, img.owner), 40.0);
}

TEST(MachBand, AgainstAReferenceOnlyTheDifferenceCounts) {
  const Image img = row({0, 10, 20, 30, 40, 60, 80, 100}, kTwoPolygons);
  Image ref = img;  // the same kink in the reference: no error in the derivative
  EXPECT_DOUBLE_EQ(mach_band(img, img.owner, &ref), 0.0);
  ref = row({0, 10, 20, 30, 40, 50, 60, 70}, kTwoPolygons);  // the reference is a straight ramp
  EXPECT_DOUBLE_EQ(mach_band(img, img.owner, &ref), 10.0);
  ref.covered[5] = 0;  // p3 not shown by the reference: the edge is not measured
  EXPECT_DOUBLE_EQ(mach_band(img, img.owner, &ref), 0.0);
}

TEST(MachBand, IntensityIsTheMeanOfRGB) {
  Image img = row({0, 0, 0, 0, 0, 0, 0, 0}, kTwoPolygons);
  for (int x = 4; x < 8; ++x) img.rgb[x * 3 + 0] = 30;  // red steps by 30: intensity by 10
  EXPECT_DOUBLE_EQ(mach_band(img, img.owner), 10.0);
}

TEST(ErrorStats, PsnrAndRmse) {
  const Image a = row({100, 100, 100, 100}, {0, 0, 0, 0});
  Image b = row({110, 110, 110, 110}, {0, 0, 0, 0});
  ErrorStats e = error_stats(a, b);
  EXPECT_EQ(e.compared, 4);
  EXPECT_EQ(e.max_abs, 10);
  EXPECT_EQ(e.over_one, 4);
  EXPECT_DOUBLE_EQ(e.rmse, 10.0);
  EXPECT_NEAR(e.psnr, 20 * std::log10(25.5), 1e-12);  // 28.13 dB
  b = row({100, 100, 102, 102}, {0, 0, 0, 0});
  e = error_stats(a, b);
  EXPECT_DOUBLE_EQ(e.mean_abs, 1.0);
  EXPECT_EQ(e.over_one, 2);  // the two pixels 2 levels off; none at exactly 1
  EXPECT_NEAR(e.rmse, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(e.psnr, 20 * std::log10(255 / std::sqrt(2.0)), 1e-12);  // 45.12 dB
  EXPECT_TRUE(std::isinf(error_stats(a, a).psnr));
  b.owner[0] = 5;  // another polygon: not compared
  EXPECT_EQ(error_stats(a, b).compared, 3);
}

// SSIM's three factors on hand-worked cases: equal images give 1; a uniform offset leaves only the
// luminance factor (2 mu_a mu_b + C1) / (mu_a^2 + mu_b^2 + C1); a ramp against its mean loses the
// structure factor; uncompared pixels (another owner) do not count.
TEST(ErrorStats, StructuralSimilarity) {
  const Image a = row({100, 100, 100, 100, 100, 100, 100, 100}, {0, 0, 0, 0, 0, 0, 0, 0});
  EXPECT_DOUBLE_EQ(ssim(a, a), 1.0);
  const Image b = row({110, 110, 110, 110, 110, 110, 110, 110}, {0, 0, 0, 0, 0, 0, 0, 0});
  const double c1 = 2.55 * 2.55;
  EXPECT_NEAR(ssim(a, b), (2 * 100.0 * 110 + c1) / (100.0 * 100 + 110.0 * 110 + c1), 1e-12);  // 0.99548
  const Image ramp = row({40, 60, 80, 100, 120, 140, 160, 180}, {0, 0, 0, 0, 0, 0, 0, 0});
  const Image mean = row({110, 110, 110, 110, 110, 110, 110, 110}, {0, 0, 0, 0, 0, 0, 0, 0});
  EXPECT_LT(ssim(ramp, mean), 0.2);  // the mean is right, the structure is gone
  EXPECT_GT(ssim(ramp, ramp), 0.999999);
  Image other = b;
  for (int& o : other.owner) o = 7;  // nothing shows the same owner
  EXPECT_EQ(ssim(a, other), 0.0);
}

std::string sphere_text(bool flat) {
  return std::string(R"({"screen": {"width": 64, "height": 48},
    "camera": {"type": "lookat", "eye": [0, 0, -6], "target": [0, 0, 0], "fov_deg": 40},
    "light": {"type": "directional", "direction": [-1, 1, -1]},
    "shading": {"rule": "phong", "flat": )") +
         (flat ? "true" : "false") + R"(},
    "objects": [{"type": "sphere", "radius": 1.5, "u": 12, "v": 6}]})";
}

TEST(FlatShading, OneShadePerPolygonFromTheRuleAtTheCentroid) {
  const BuiltScene flat = load_scene_text(sphere_text(true), "flat", ".");
  const BuiltScene smooth = load_scene_text(sphere_text(false), "smooth", ".");
  ASSERT_TRUE(flat.flat);
  ASSERT_EQ(flat.polygons.size(), smooth.polygons.size());
  std::set<std::array<double, 3>> shades;
  for (std::size_t i = 0; i < flat.polygons.size(); ++i) {
    const ScreenPolygon& p = flat.polygons[i];
    for (const ScreenVertex& v : p.v)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(v.rgb[c], p.v[0].rgb[c]) << "polygon " << i;
    shades.insert({p.v[0].rgb[0], p.v[0].rgb[1], p.v[0].rgb[2]});
    // Between the darkest and the brightest of its smooth vertex shades (the centroid's plane
    // normal is a mean of the vertex normals, roughly), within a few levels.
    double lo = 255, hi = 0;
    for (const ScreenVertex& v : smooth.polygons[i].v) lo = std::min(lo, v.rgb[1]), hi = std::max(hi, v.rgb[1]);
    EXPECT_GE(p.v[0].rgb[1], lo - 8) << "polygon " << i;
    EXPECT_LE(p.v[0].rgb[1], hi + 8) << "polygon " << i;
    for (std::size_t k = 0; k < p.v.size(); ++k) {  // geometry untouched
      EXPECT_EQ(p.v[k].x, smooth.polygons[i].v[k].x);
      EXPECT_EQ(p.v[k].depth, smooth.polygons[i].v[k].depth);
    }
  }
  EXPECT_GT(shades.size(), flat.polygons.size() / 2) << "facets must differ in shade";
}

TEST(FlatShading, OptionOverridesTheFileAndPhongRejectsIt) {
  BuildOptions opt;
  opt.flat = true;
  EXPECT_TRUE(load_scene_text(sphere_text(false), "s", ".", opt).flat);
  opt.shading = ShadingMode::Phong;
  try {
    load_scene_text(sphere_text(false), "s", ".", opt);
    FAIL() << "flat with the phong pipeline must be rejected";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("shading.flat"), std::string::npos) << e.what();
  }
}

// ---- the command line -----------------------------------------------------------------------

std::string run(const std::string& args, int* code) {
  const test::CliRun r = test::run_cli(args);
  *code = r.exit_code;
  return r.output;
}

std::vector<std::map<std::string, std::string>> read_csv(const std::string& path, std::vector<std::string>* header) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::map<std::string, std::string>> rows;
  auto split = [](const std::string& l) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (char c : l) {
      if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) cells.push_back(cell), cell.clear();
      else cell += c;
    }
    cells.push_back(cell);
    return cells;
  };
  if (!std::getline(in, line)) return rows;
  *header = split(line);
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split(line);
    std::map<std::string, std::string> r;
    for (std::size_t i = 0; i < header->size() && i < cells.size(); ++i) r[(*header)[i]] = cells[i];
    rows.push_back(r);
  }
  return rows;
}

// Each test's CSV and markdown go to its own scratch directory, removed after the test.
class SweepCli : public ::testing::Test, protected test::ScratchDir {};

TEST_F(SweepCli, TinySweepWritesTheColumnsAndPhongBeatsGouraudOnTheSphere) {
  const std::string dir = dir_, csv = dir + "/s.csv", md = dir + "/s.md";
  int code = 0;
  const std::string out = run("sweep " + std::string(WATKINS_SOURCE_DIR) +
                                  "/scenes/sphere.json --shadings gouraud-eq1,phong --tess 0.5 --jobs 2 --csv " +
                                  csv + " --md " + md,
                              &code);
  ASSERT_EQ(code, 0) << out;
  std::vector<std::string> header;
  const auto rows = read_csv(csv, &header);
  for (const char* col : {"point", "scene", "shading", "tess", "u", "v", "polygons", "truth_max", "truth_mean",
                          "truth_rmse", "truth_psnr", "truth_mach", "double_truth_max", "double_max", "double_mach",
                          "cycles", "cycles_source", "edge_record_bits", "line_buffer_bits", "active_list_bits"})
    EXPECT_NE(std::find(header.begin(), header.end(), col), header.end()) << "missing column " << col;
  ASSERT_EQ(rows.size(), 2u);
  const auto& g = rows[0];
  const auto& p = rows[1];
  EXPECT_EQ(g.at("shading"), "gouraud-eq1");
  EXPECT_EQ(p.at("shading"), "phong");
  EXPECT_EQ(g.at("u"), "16");  // the sphere's 32x16 halved
  EXPECT_EQ(g.at("v"), "8");
  // The configuration's own edge record: default fractions, the integer bits the sphere needs.
  EXPECT_LT(std::stoi(g.at("edge_record_bits")), 466);
  // the sphere's 320-px line: depth, polygon id, shade
  EXPECT_EQ(g.at("line_buffer_bits"), std::to_string(2 * 320 * (24 + 16 + 24)));
  EXPECT_EQ(g.at("cycles_source"), "predicted-sparse");  // the cycle model, no Verilator
  // The cycles the RTL takes on this frame in sparse mode, as the cycle model predicts them: a
  // golden value that moves with every pipeline stage added or removed. The Phong top takes 58
  // more (normalizer 16 stages, shader 42; tests/test_cycle_model.cpp). Regenerate with
  // `watkins sweep scenes/sphere.json --shadings gouraud-eq1,phong --tess 0.5 --csv s.csv`
  // (column "cycles"); with --rtl the sweep measures the same counts on the Verilated RTL.
  EXPECT_EQ(g.at("cycles"), "37321");
  EXPECT_EQ(p.at("cycles"), "37379");
  EXPECT_EQ(g.at("error"), "");
  EXPECT_LT(std::stoi(p.at("truth_max")), std::stoi(g.at("truth_max")));  // the highlight
  EXPECT_LT(std::stod(p.at("truth_mean")), std::stod(g.at("truth_mean")));
  EXPECT_GT(std::stod(p.at("truth_psnr")), std::stod(g.at("truth_psnr")));
  EXPECT_GT(std::stod(g.at("truth_mach")), std::stod(p.at("truth_mach")));  // Gouraud's kinks at the edges
  EXPECT_LT(std::stod(g.at("double_mean")), 0.1);  // quantization: a small fraction of a level on average
  std::ifstream m(md);
  std::stringstream text;
  text << m.rdbuf();
  EXPECT_NE(text.str().find("| sphere | phong | 16×8 |"), std::string::npos) << text.str();
}

// A vault's u must be even (the key is a vertex): the portico's u = 10 halved is 5, which the
// scene would refuse; the sweep rounds it to 6 and the point renders.
TEST_F(SweepCli, VaultTessellationStaysEven) {
  const std::string csv = dir_ + "/v.csv";
  int code = 0;
  const std::string out = run("sweep " + std::string(WATKINS_SOURCE_DIR) +
                                  "/scenes/portico.json --shadings phong --tess 0.5,0.3 --csv " + csv,
                              &code);
  ASSERT_EQ(code, 0) << out;
  std::vector<std::string> header;
  const auto rows = read_csv(csv, &header);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("u"), "6");  // 5 rounded to even
  EXPECT_EQ(rows[1].at("u"), "4");  // 3 rounded to even
  for (const auto& r : rows) {
    EXPECT_EQ(r.at("error"), "") << r.at("u");
    EXPECT_GT(std::stoll(r.at("polygons")), 0);
  }
}

// The fraction-bits axis: two attribute fractions and one the configuration refuses (shade
// 60 + its 9 natural integer bits exceed the model's 62-bit words). Fewer fraction bits: a
// smaller edge record, an error against the double reference that does not fall; the refused
// point keeps its axes and its message, and the sweep still finishes (exit 0).
TEST_F(SweepCli, FractionBitsAxis) {
  const std::string dir = dir_, csv = dir + "/s.csv";
  int code = 0;
  const std::string out = run("sweep " + std::string(WATKINS_SOURCE_DIR) +
                                  "/scenes/sphere.json --shadings gouraud-eq1 --tess 0.5 --frac-bits 2,16,60 "
                                  "--x-frac-bits 8 -q --jobs 2 --csv " + csv,
                              &code);
  ASSERT_EQ(code, 0) << out;
  EXPECT_NE(out.find("1 failed"), std::string::npos) << out;
  std::vector<std::string> header;
  const auto rows = read_csv(csv, &header);
  for (const char* col : {"attr_frac", "x_frac", "depth_frac", "attr_group", "x_int", "depth_int", "attr_int"})
    EXPECT_NE(std::find(header.begin(), header.end(), col), header.end()) << "missing column " << col;
  ASSERT_EQ(rows.size(), 3u);
  const auto &lo = rows[0], &hi = rows[1], &refused = rows[2];
  EXPECT_EQ(lo.at("attr_frac"), "2");
  EXPECT_EQ(hi.at("attr_frac"), "16");
  for (const auto* r : {&lo, &hi, &refused}) {
    EXPECT_EQ(r->at("x_frac"), "8");
    EXPECT_EQ(r->at("depth_frac"), "16");
    EXPECT_EQ(r->at("attr_group"), "shade");
  }
  EXPECT_EQ(lo.at("error"), "");
  EXPECT_EQ(hi.at("error"), "");
  // The shade's integer bits: 8-bit levels and a sign, give or take a rounding (9 or 10).
  for (const auto* r : {&lo, &hi}) {
    EXPECT_GE(std::stoi(r->at("attr_int")), 9);
    EXPECT_LE(std::stoi(r->at("attr_int")), 10);
  }
  EXPECT_EQ(lo.at("x_int"), hi.at("x_int"));
  EXPECT_EQ(lo.at("depth_int"), hi.at("depth_int"));
  const int lo_bits = std::stoi(lo.at("edge_record_bits")), hi_bits = std::stoi(hi.at("edge_record_bits"));
  EXPECT_LT(lo_bits, hi_bits);
  EXPECT_LT(lo_bits, 466);
  // Only the shade words differ: value and slope of R, G, B.
  EXPECT_EQ(hi_bits - lo_bits,
            2 * 3 * ((16 + std::stoi(hi.at("attr_int"))) - (2 + std::stoi(lo.at("attr_int")))));
  EXPECT_GE(std::stod(lo.at("double_mean")), std::stod(hi.at("double_mean")));
  EXPECT_GT(std::stod(lo.at("double_mean")), 0.0);
  EXPECT_EQ(lo.at("double_truth_mean"), hi.at("double_truth_mean"));  // the algorithm's own error
  EXPECT_NE(refused.at("error").find("shade.frac_bits"), std::string::npos) << refused.at("error");
  EXPECT_EQ(refused.at("truth_mean"), "");
  EXPECT_EQ(refused.at("edge_record_bits"), "");
}

// Whitted's curves against the tessellation with the same cells (patch.json, 4 x 4): the curves'
// silhouette is exact where the polygons' is a chord, so far fewer pixels differ in coverage from
// the truth, and the mean error is lower (docs/reference/whitted.md: 0 against 338 pixels, 2.32 against
// 4.46 levels for the double reference). The whitted point's cycles, edge record and curved
// active edges are those of the scene drawn with k_u = k_v = 4 at edge_order 3, rebuilt here.
TEST_F(SweepCli, WhittedCurvesAgainstPolygonsOnThePatch) {
  const std::string scene = std::string(WATKINS_SOURCE_DIR) + "/scenes/patch.json";
  const std::string csv = dir_ + "/w.csv", md = dir_ + "/w.md", images = dir_ + "/img";
  int code = 0;
  const std::string out = run("sweep " + scene + " --shadings phong,whitted --uv 4 -q --jobs 2 --csv " + csv +
                                  " --md " + md + " --images " + images,
                              &code);
  ASSERT_EQ(code, 0) << out;
  std::vector<std::string> header;
  const auto rows = read_csv(csv, &header);
  for (const char* col : {"uv", "truth_coverage_differs", "double_truth_coverage_differs", "edge_order", "regions",
                          "curve_edge_records", "curve_active_edges"})
    EXPECT_NE(std::find(header.begin(), header.end(), col), header.end()) << "missing column " << col;
  ASSERT_EQ(rows.size(), 2u);
  const auto &poly = rows[0], &curv = rows[1];
  ASSERT_EQ(poly.at("error"), "");
  ASSERT_EQ(curv.at("error"), "");
  EXPECT_EQ(curv.at("shading"), "whitted");
  EXPECT_EQ(poly.at("u"), "4");
  EXPECT_EQ(curv.at("u"), "4");
  EXPECT_EQ(poly.at("edge_order"), "1");
  EXPECT_EQ(curv.at("edge_order"), "3");
  EXPECT_EQ(poly.at("polygons"), "16");  // 4 x 4 quads
  EXPECT_EQ(curv.at("polygons"), "0");
  EXPECT_EQ(poly.at("curve_active_edges"), "0");
  EXPECT_GT(std::stoi(curv.at("curve_active_edges")), 0);
  const int poly_cov = std::stoi(poly.at("truth_coverage_differs"));
  const int curv_cov = std::stoi(curv.at("truth_coverage_differs"));
  EXPECT_GT(poly_cov, 100);
  EXPECT_LT(curv_cov * 10, poly_cov) << "curves " << curv_cov << " px, polygons " << poly_cov << " px";
  EXPECT_LT(std::stoi(curv.at("double_truth_coverage_differs")),
            std::stoi(poly.at("double_truth_coverage_differs")));
  EXPECT_LT(std::stod(curv.at("truth_mean")), std::stod(poly.at("truth_mean")));
  EXPECT_LT(std::stod(curv.at("double_truth_mean")), std::stod(poly.at("double_truth_mean")));

  // The same frame built here: the patch with k_u = k_v = 4 drawn as curves, Phong.
  std::string text = read_scene_text(scene);
  text = std::regex_replace(text, std::regex(R"re("u"\s*:\s*\d+)re"), "\"u\": 4");
  text = std::regex_replace(text, std::regex(R"re("v"\s*:\s*\d+)re"), "\"v\": 4");
  for (const char* key : {"k_u", "k_v"}) {  // the scene's own interior edges, if it has them, replaced
    const std::regex re(std::string("\"") + key + R"re("\s*:\s*(\d+|\[[^\]]*\]))re");
    if (std::regex_search(text, re))
      text = std::regex_replace(text, re, std::string("\"") + key + "\": 4");
    else
      text.insert(text.find("\"u\": 4"), std::string("\"") + key + "\": 4, ");
  }
  BuildOptions opt;
  opt.shading = ShadingMode::Phong;
  opt.depth = DepthMode::InverseZ;
  opt.patches_as_curves = true;
  opt.rule = ShadingRule::Phong;
  const BuiltScene built = load_scene_text(text, scene, ".", opt);
  EXPECT_EQ(curv.at("regions"), std::to_string(built.curve_regions));
  Config cfg;
  cfg.max_active_edges = 1024;  // the sweep's default --max-active-edges
  cfg.max_width = built.width;
  PreparedScene prepared;
  cfg = fit_int_bits(built, cfg, &prepared);
  ASSERT_EQ(cfg.edge_order, 3);
  prepared = prepare(built, cfg);
  EXPECT_EQ(curv.at("edge_record_bits"), std::to_string(cfg.edge_record_bits(ShadingMode::Phong)));
  EXPECT_EQ(curv.at("curve_edge_records"), std::to_string(prepared.needs.curve_edges));
  EXPECT_EQ(curv.at("curve_active_edges"), std::to_string(prepared.needs.max_curve_edges));
  EXPECT_EQ(curv.at("cycles"), std::to_string(predict_cycles(prepared, PixelOutput::Sparse, 1024, cfg).cycles));
  EXPECT_GT(std::stoi(curv.at("edge_record_bits")), std::stoi(poly.at("edge_record_bits")));  // d2, d3 per channel

  for (const char* png : {"/patch_phong_4x4.png", "/patch_whitted_4x4.png", "/patch_truth.png"})
    EXPECT_TRUE(std::ifstream(images + png).good()) << png;
  std::ifstream m(md);
  std::stringstream mdtext;
  mdtext << m.rdbuf();
  EXPECT_NE(mdtext.str().find("| patch | whitted | 4×4 | " + curv.at("regions") + " regions |"), std::string::npos)
      << mdtext.str();
}

TEST_F(SweepCli, ShardsSplitTheGrid) {
  const std::string dir = dir_;
  std::set<std::string> points;
  for (int i = 0; i < 2; ++i) {
    int code = 0;
    const std::string csv = dir + "/s" + std::to_string(i) + ".csv";
    const std::string out = run("sweep " + std::string(WATKINS_SOURCE_DIR) +
                                    "/scenes/cone.json --shadings flat,gouraud-eq2,phong --tess 0.5 -q --shard " +
                                    std::to_string(i) + "/2 --csv " + csv,
                                &code);
    ASSERT_EQ(code, 0) << out;
    std::vector<std::string> header;
    for (const auto& r : read_csv(csv, &header)) EXPECT_TRUE(points.insert(r.at("point")).second);
  }
  EXPECT_EQ(points, (std::set<std::string>{"0", "1", "2"}));
  int code = 0;
  EXPECT_NE(run("sweep --shard 2/2", &code).find("--shard"), std::string::npos);
  EXPECT_EQ(code, 2);  // a wrong option value: usage
}

}  // namespace
}  // namespace watkins
