// watkins voxel-compare (voxel_compare.hpp). Per scene, in process:
//   flat     Gouraud pipeline, one shade per face (BuiltScene::flat), voxel face normals (no
//            averaging: the front end does what Herman and Liu's display did before smoothing);
//   gouraud  Gouraud pipeline on averaged vertex normals (eq. 3 at the vertices);
//   phong    Phong pipeline on the same normals;
//   smooth W the flat frame through the smoother twin (model/twins/smoother.hpp) at weight W.
// BuildOptions::voxel_normals sets each row's voxel normals, whatever the scene's "normals" says.
// Error against the analytic truth over the pixels both show the same object (compare_with_truth);
// Mach-band measures on image - truth at face boundaries (error_stats.hpp): the largest jump and
// the mean jump. Cost: the front end's wall time (parse, voxel faces, normals, projection and
// vertex shading; best of --repeat builds) and cycles per frame from the cycle model (equal to the
// RTL's without stalls), full-frame output (the smoother needs the whole raster) and sparse.
#include "voxel_compare.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "analytic_truth.hpp"
#include "cycle_model.hpp"
#include "error_stats.hpp"
#include "image_io.hpp"
#include "options.hpp"
#include "prepare.hpp"
#include "run_files.hpp"
#include "scene.hpp"
#include "scene_types.hpp"
#include "smoother.hpp"
#include "watkins_top.hpp"

namespace watkins::voxel_compare {
namespace {

struct Row {
  std::string scene, shading;
  long long polygons = 0;
  int active_edges = 0;
  double front_ms = 0;
  long long cycles_full = 0, cycles_sparse = 0;  // sparse: -1 where the frame is always full
  ImageError truth;
  double mach_max = 0, mach_mean = 0;
};

struct Rendered {
  BuiltScene scene;
  PreparedScene frame;
  Image image;
  double front_ms = 0;
  // The default hardware, its active-edge list grown to what the scene needs (a scene over the
  // default's 64 is still measured, and reported in a note).
  Config config;
};

Rendered render(const std::string& text, const std::string& path, const BuildOptions& opt, int repeat) {
  using Clock = std::chrono::steady_clock;
  Rendered r;
  const std::string dir = std::filesystem::path(path).parent_path().string();
  r.front_ms = INFINITY;
  for (int k = 0; k < std::max(1, repeat); ++k) {
    const auto t0 = Clock::now();
    r.scene = load_scene_text(text, path, dir, opt);
    r.front_ms = std::min(r.front_ms, std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  }
  PrepareOptions popt;
  popt.max_active_edges = 1 << 16;  // measured, then checked against the default hardware below
  r.frame = prepare(r.scene, popt);
  r.config.max_active_edges = std::max(r.config.max_active_edges, r.frame.needs.max_active_edges);
  WatkinsTop top(r.config);
  r.image = top.render(r.frame);
  return r;
}

Row measure(const std::string& stem, const std::string& shading, const Rendered& r, const Image& img,
            const AnalyticTruth& truth) {
  Row row;
  row.scene = stem;
  row.shading = shading;
  row.polygons = static_cast<long long>(r.scene.polygons.size());
  row.active_edges = r.frame.needs.max_active_edges;
  row.front_ms = r.front_ms;
  row.cycles_full = predict_cycles(r.frame, PixelOutput::FullFrame, r.config.max_active_edges, r.config).cycles;
  row.cycles_sparse = predict_cycles(r.frame, PixelOutput::Sparse, r.config.max_active_edges, r.config).cycles;
  const Image mine = by_object(r.scene, img);
  row.truth = compare_with_truth(r.scene, img, truth);
  row.mach_max = mach_band(mine, img.owner, &truth.image);
  row.mach_mean = mach_band_mean(mine, img.owner, &truth.image);
  return row;
}

std::string number(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string table(const std::vector<Row>& rows) {
  std::ostringstream s;
  s << "| scene | shading | polygons | active edges | front end ms | cycles full-frame | cycles sparse | vs truth mean "
       "| vs truth max | Mach max | Mach mean | pixels compared |\n";
  s << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Row& r : rows)
    s << "| " << r.scene << " | " << r.shading << " | " << r.polygons << " | " << r.active_edges << " | "
      << number(r.front_ms, 2) << " | " << r.cycles_full << " | "
      << (r.cycles_sparse < 0 ? std::string("—") : std::to_string(r.cycles_sparse)) << " | "
      << number(r.truth.mean_abs, 2) << " | " << r.truth.max_abs << " | " << number(r.mach_max, 1) << " | "
      << number(r.mach_mean, 2) << " | " << r.truth.compared << " |\n";
  return s.str();
}

}  // namespace

CLI::App* add_voxel_compare_command(CLI::App& app, VoxelCompareArgs& a) {
  auto* c = app.add_subcommand("voxel-compare", "Herman & Liu's comparison on voxel phantoms: flat, Gouraud "
                                                "(averaged normals), Phong, flat + smoothing; error against the "
                                                "analytic truth and cost");
  c->add_option("scenes", a.scenes, "scene files (default: scenes/voxel_{ellipsoid,beaded,two_lobed}.json)")
      ->check(cli::non_empty_name());
  cli::add_real_list(c, "--weights", a.weights, "W of the smoother sweep", 0.0, fmt::SmoothWMax);
  cli::add_file(c, "--md", a.md, "write the table (markdown) here");
  cli::add_file(c, "--images", a.images, "folder for <scene>_{flat,gouraud,phong,smooth,truth}.png");
  c->add_option("--repeat", a.repeat, "front-end timing: best of N builds")->check(cli::integer_in(1, 1000));
  return c;
}

int run_voxel_compare(const VoxelCompareArgs& a) {
  std::vector<std::string> scenes = a.scenes;
  if (scenes.empty())
    for (const char* s : {"voxel_ellipsoid", "voxel_beaded", "voxel_two_lobed"})
      scenes.push_back(std::string(WATKINS_SOURCE_DIR) + "/scenes/" + s + ".json");
  // Every scene and the files it names are inputs, read before any output is declared or written.
  RunFiles files;
  for (const std::string& path : scenes) {
    files.input("the scene file " + path, path);
    files.scene_inputs(parse_scene_file(path));
  }
  // The folder first: a table inside a folder the run makes is then declared as one of its files.
  if (!a.images.empty()) files.output_folder("--images", a.images);
  if (!a.md.empty()) files.output("--md", a.md);
  std::vector<Row> rows;
  for (const std::string& path : scenes) {
    const std::string stem = std::filesystem::path(path).stem().string(), text = read_scene_text(path);
    BuildOptions gouraud, phong, flat;
    gouraud.shading = flat.shading = ShadingMode::Gouraud;
    gouraud.rule = flat.rule = phong.rule = ShadingRule::Phong;
    phong.shading = ShadingMode::Phong;
    flat.flat = true;
    flat.voxel_normals = VoxelNormals::Face;
    gouraud.voxel_normals = phong.voxel_normals = VoxelNormals::Average;
    const Rendered f = render(text, path, flat, a.repeat);
    const Rendered g = render(text, path, gouraud, a.repeat);
    const Rendered p = render(text, path, phong, a.repeat);
    const AnalyticTruth truth = render_analytic_truth(g.scene);
    if (!truth.unavailable.empty()) throw std::runtime_error(path + ": no analytic truth: " + truth.unavailable);
    rows.push_back(measure(stem, "flat (Fig. 2)", f, f.image, truth));
    rows.push_back(measure(stem, "Gouraud, averaged normals (Fig. 3)", g, g.image, truth));
    rows.push_back(measure(stem, "Phong, averaged normals", p, p.image, truth));
    Image smoothed08;
    for (double W : a.weights) {
      const int w = quantize_smooth_weight(W);
      const Image s = Smoother(w).apply(f.image);
      Row row = measure(stem, "flat + smoothing W = " + number(W, 2) + (std::fabs(W - 0.8) < 1e-9 ? " (Fig. 4)" : ""),
                        f, s, truth);
      PreparedScene frame = f.frame;
      frame.smooth_w = w;
      row.cycles_full = predict_cycles(frame, PixelOutput::FullFrame, f.config.max_active_edges, f.config).cycles;
      row.cycles_sparse = -1;  // a smoothed frame is always emitted in full
      rows.push_back(row);
      if (std::fabs(W - 0.8) < 1e-9) smoothed08 = s;
    }
    const int needed = std::max({f.frame.needs.max_active_edges, g.frame.needs.max_active_edges,
                                 p.frame.needs.max_active_edges});
    if (needed > fmt::MaxActiveEdges)
      std::fprintf(stderr, "note: %s needs %d active edges, over the default hardware's %d (measured on a model "
                           "with a longer list)\n", stem.c_str(), needed, fmt::MaxActiveEdges);
    if (!a.images.empty()) {
      files.add_in(a.images, stem + "_flat.png", encode_png(f.image));
      files.add_in(a.images, stem + "_gouraud.png", encode_png(g.image));
      files.add_in(a.images, stem + "_phong.png", encode_png(p.image));
      if (smoothed08.width) files.add_in(a.images, stem + "_smooth.png", encode_png(smoothed08));
      files.add_in(a.images, stem + "_truth.png", encode_png(truth.image));
    }
  }
  const std::string t = table(rows);
  std::fputs(t.c_str(), stdout);
  if (!a.md.empty()) files.add(a.md, t);
  files.commit();
  return 0;
}

}  // namespace watkins::voxel_compare
