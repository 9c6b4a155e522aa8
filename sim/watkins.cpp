// watkins: the command line of the Watkins pipeline model.
//   watkins render [SCENE] [--out image.png] [--model fixed|float] [--rule R] [--depth D]
//                  [--diff d.png] [--cull|--no-cull] [--max-active-edges N]
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

#include "float_reference.hpp"
#include "gouraud_pipeline.hpp"
#include "prepare.hpp"
#include "scene.hpp"

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct RenderArgs {
  std::string scene;
  std::string out = "watkins.png";
  std::string model = "fixed";
  std::string rule, depth, diff;
  bool cull = false, no_cull = false;
  int max_active_edges = watkins::fmt::MaxActiveEdges;
};

void print_needs(const watkins::SceneNeeds& n) {
  using namespace watkins;
  std::printf("needs         active edges %d (scan line %d), widest span %d px, longest edge %d lines\n",
              n.max_active_edges, n.max_active_line, n.max_segment_pixels, n.max_edge_lines);
  static const char* names[fmt::NumChannels] = {"X", "Z", "R", "G", "B"};
  for (int c = 0; c < fmt::NumChannels; ++c)
    std::printf("  channel %s  value [%lld, %lld]  slope [%lld, %lld]  -> %d of %d bits\n", names[c],
                static_cast<long long>(n.value_min[c]), static_cast<long long>(n.value_max[c]),
                static_cast<long long>(n.slope_min[c]), static_cast<long long>(n.slope_max[c]),
                n.bits_for_value(c), fmt::ChannelBits);
}

int render(const RenderArgs& a) {
  using namespace watkins;
  BuildOptions opt;
  if (!a.rule.empty()) {
    opt.rule = parse_shading_rule(a.rule);
    if (!opt.rule) throw SceneError("--rule: unknown shading rule \"" + a.rule +
                                    "\" (gouraud, lambert, warnock, romney)");
  }
  if (!a.depth.empty()) {
    opt.depth = parse_depth_mode(a.depth);
    if (!opt.depth) throw SceneError("--depth: unknown depth mode \"" + a.depth + "\" (inverse-z, z)");
  }
  if (a.cull) opt.cull_backfaces = true;
  if (a.no_cull) opt.cull_backfaces = false;

  const auto t0 = Clock::now();
  const BuiltScene scene = a.scene.empty()
      ? load_scene_text(default_scene_text(), "<default scene>", ".", opt)
      : load_scene(a.scene, opt);
  PrepareOptions popt;
  popt.max_active_edges = a.max_active_edges;
  const PreparedScene prepared = prepare(scene, popt);
  const double t_prep = seconds_since(t0);

  std::printf("scene         %s  %dx%d  rule %s  depth %s\n", scene.name.c_str(), scene.width,
              scene.height, to_string(scene.rule), to_string(scene.depth));
  std::printf("polygons      %zu (culled %d back faces, %d clipped, %d degenerate)\n",
              scene.polygons.size(), scene.culled_backfaces, scene.near_clipped, scene.degenerate);
  std::printf("edge records  %zu\n", prepared.edges.size());
  print_needs(prepared.needs);

  const auto t1 = Clock::now();
  FloatReferenceStats fstats;
  const Image reference = render_float_reference(scene, &fstats);
  const double t_ref = seconds_since(t1);

  Image result;
  if (a.model == "fixed") {
    GouraudPipeline pipe(a.max_active_edges);
    const auto t2 = Clock::now();
    result = pipe.render(prepared);
    const double t_model = seconds_since(t2);
    const auto& s = pipe.stats();
    std::printf("fixed model   %lld segments, %lld fragments (%lld won the depth test)\n", s.segments,
                s.fragments, s.visible);
    std::printf("wall time     prepare %.3f s, fixed model %.3f s (%.2f M fragments/s), double reference %.3f s\n",
                t_prep, t_model, s.fragments / std::max(t_model, 1e-9) / 1e6, t_ref);
    const ImageError e = compare_images(result, reference);
    std::printf("vs double     max |d| %d levels, mean |d| %.4f levels, %d pixels > 1 level "
                "(over %d pixels showing the same polygon); %d pixels change polygon, %d change coverage\n",
                e.max_abs, e.mean_abs, e.over_one, e.compared, e.visibility_differs, e.coverage_differs);
  } else {
    result = reference;
    std::printf("double model  %lld fragments, %.3f s\n", fstats.fragments, t_ref);
  }
  if (!a.diff.empty()) write_png(diff_image(result, reference), a.diff);
  write_png(result, a.out);
  std::printf("wrote         %s%s%s\n", a.out.c_str(), a.diff.empty() ? "" : ", ", a.diff.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"watkins: fixed-point model of the Watkins / Gouraud scan-line shading pipeline"};
  app.require_subcommand(1);
  RenderArgs ra;
  auto* r = app.add_subcommand("render", "render a scene (the embedded default scene if none is given)");
  r->add_option("scene", ra.scene, "scene file (JSON); see docs/scene-format.md");
  r->add_option("--out,-o", ra.out, "PNG to write")->capture_default_str();
  r->add_option("--model", ra.model, "fixed (bit-exact pipeline model) or float (double reference)")
      ->check(CLI::IsMember({"fixed", "float"}))->capture_default_str();
  r->add_option("--rule", ra.rule, "vertex shading rule: gouraud, lambert, warnock, romney");
  r->add_option("--depth", ra.depth, "depth channel: inverse-z (Gouraud eq. 1) or z (eq. 2)");
  r->add_option("--diff", ra.diff, "PNG of |model - double reference| x16 (magenta: coverage differs)");
  r->add_flag("--cull", ra.cull, "cull back faces");
  r->add_flag("--no-cull", ra.no_cull, "keep back faces");
  r->add_option("--max-active-edges", ra.max_active_edges, "active-edge list capacity")
      ->check(CLI::Range(1, 1 << 16))->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    if (*r) return render(ra);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "watkins: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
