// watkins render (render.hpp).
#include "render.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analytic_truth.hpp"
#include "config_file.hpp"
#include "cycle_model.hpp"
#include "float_reference.hpp"
#include "image_io.hpp"
#include "options.hpp"
#include "prepare.hpp"
#include "run_files.hpp"
#include "scene.hpp"
#include "scene_types.hpp"
#include "usage_error.hpp"
#include "watkins_top.hpp"

// ==== RTL co-simulation (--rtl): owned by the testbench; see testbench/rtl_bench.hpp ==========
#ifdef WATKINS_HAVE_RTL
#include "rtl_bench.hpp"
#endif

namespace watkins::render {

namespace {

void add_rtl_options(CLI::App* r, RtlArgs& a) {
  r->add_flag("--rtl", a.enabled, "also run the Verilated RTL, compare it with the fixed model and write "
                                  "the RTL image to --out (exit code 3 and no output on any mismatch)");
  r->add_flag("--systemc", a.systemc, "with --rtl: run the default configuration on the SystemC bench (Verilated "
                                      "with assertions, as the co-simulation tests do) instead of the plain C++ "
                                      "harness built for speed");
  cli::add_file(r, "--trace", a.trace, "with --rtl: write an FST waveform of the RTL run (on the SystemC bench)");
  r->add_option("--seed", a.seed, "with --rtl: random seed of input gaps and output stalls (0 .. 2^64 - 1)")
      ->transform(cli::seed64())->capture_default_str();
  r->add_option("--gap", a.gap, "with --rtl: probability of an idle cycle before each edge beat")
      ->check(cli::finite_in(0.0, 0.99))->capture_default_str();
  r->add_option("--stall", a.stall, "with --rtl: probability that the pixel sink stalls a cycle")
      ->check(cli::finite_in(0.0, 0.99))->capture_default_str();
  r->add_flag("--sparse", a.sparse, "with --rtl: sparse output mode (sparse_i = 1): the RTL emits only the "
                                    "covered pixels with their coordinates");
}

// Fails early, before any rendering, when this build cannot simulate the RTL.
void check_rtl_args(const RtlArgs& a, const std::string& model) {
  if (!a.enabled) {
    if (!a.trace.empty()) throw UsageError("--trace needs --rtl");
    if (a.sparse) throw UsageError("--sparse needs --rtl");
    if (a.systemc) throw UsageError("--systemc needs --rtl");
    return;
  }
#ifndef WATKINS_HAVE_RTL
#ifndef WATKINS_RTL_UNAVAILABLE_REASON
#define WATKINS_RTL_UNAVAILABLE_REASON "configured without the RTL: -DWATKINS_RTL=OFF or no testbench/"
#endif
  throw UsageError(std::string("--rtl: this build has no RTL simulation (") +
                           WATKINS_RTL_UNAVAILABLE_REASON +
                           "); install Verilator and SystemC (libsystemc-dev) and re-run cmake");
#endif
  if (model != "fixed") throw UsageError("--rtl compares with the fixed model; drop --model " + model);
#ifdef WATKINS_HAVE_RTL
  const std::string no_systemc = tb::rtl_systemc_unavailable();
  if (!no_systemc.empty() && (a.systemc || !a.trace.empty()))
    throw UsageError(std::string(a.systemc ? "--systemc" : "--trace") + ": " + no_systemc);
#endif
}

// A Verilated top exists for the default configuration and for each one the build was asked for
// (CMake option WATKINS_RTL_CONFIGS; a configuration with compact true gets the compact top):
// refuse, in one line, a configuration without one rather than compare two different pipelines.
void check_rtl_config(const RtlArgs& a, const PreparedScene& prepared, const std::string& config_file) {
  if (!a.enabled) return;
  // The compact top (a configuration with compact true) emits full frames only.
  if (a.sparse && prepared.config.compact)
    throw UsageError("--sparse: --config " + config_file + " has compact true: the compact top emits full frames only");
#ifdef WATKINS_HAVE_RTL
  const std::string why = tb::rtl_unavailable(prepared.config, prepared.shading,
                                                       config_file.empty() ? "F" : config_file);
  if (!why.empty()) throw UsageError("--rtl" + (config_file.empty() ? "" : " --config " + config_file) + ": " + why);
#else
  (void)prepared, (void)config_file;
#endif
}

// Runs the RTL on the prepared scene, compares with the model image, prints the statistics and
// replaces `image` with the RTL's. Returns the exit code: 3 on mismatch, hang, overflow or protocol error.
int run_rtl_mode(const RtlArgs& a, const PreparedScene& prepared, Image& image,
                 long long fragments, long long predicted, RunFiles& files) {
#ifdef WATKINS_HAVE_RTL
  namespace tb = tb;
  tb::RtlOptions opt;
  opt.harness = a.systemc ? tb::RtlHarness::SystemC : tb::RtlHarness::Fast;
  opt.seed = a.seed;
  opt.gap = a.gap;
  opt.stall = a.stall;
  // The waveform streams out during the run, under a temporary name renamed with the other
  // outputs only when the whole run succeeded.
  if (!a.trace.empty()) opt.trace_path = files.stage(a.trace);
  opt.sparse = a.sparse;
  const tb::RtlResult r = tb::run_rtl(prepared, opt, &image);
  std::printf("rtl           %s\n", r.top.c_str());
  std::printf("rtl cycles    %lld (first edge beat offered to last pixel; %s output; gap %.2f, stall %.2f, seed %llu)\n",
              r.cycles, a.sparse ? "sparse" : "full-frame", a.gap, a.stall, a.seed);
  std::printf("rtl predicted %lld cycles (cycle model, no gaps or stalls)%s\n", predicted,
              a.gap > 0 || a.stall > 0 ? "" : predicted == r.cycles ? ": equal" : ": DIFFERS");
  std::printf("rtl pixels    %lld, fragments %lld (model), %.3f fragments/cycle, %.3f pixels/cycle\n", r.pixels,
              fragments, r.cycles ? double(fragments) / r.cycles : 0.0, r.cycles ? double(r.pixels) / r.cycles : 0.0);
  std::printf("rtl vs model  %lld mismatching pixels%s%s\n", r.mismatches, r.mismatches ? "; first: " : "",
              r.first_pixel_mismatch.c_str());
  std::printf("rtl stages    %lld stage transfers compared, %zu diverging stage(s)%s%s\n", r.stage_items,
              r.stage_mismatches.size(), r.stage_mismatches.empty() ? "" : "; first: ",
              r.stage_mismatches.empty() ? "" : r.stage_mismatches.front().c_str());
  std::printf("rtl speed     %.0f simulated cycles/s (%lld cycles in %.3f s)\n", r.cycles_per_second(),
              r.sim_cycles, r.wall_seconds);
  if (r.overflow) std::printf("rtl overflow  overflow_o set at cycle %lld\n", r.overflow_cycle);
  if (!a.trace.empty()) std::printf("rtl trace     %s\n", a.trace.c_str());
  // The RTL's pixels and coverage; the visible-polygon ids stay the model's (the RTL emits none),
  // so --diff and the truth comparison still tell shading from visibility changes.
  image.rgb = r.frames.at(0).image.rgb;
  image.covered = r.frames.at(0).image.covered;
  if (!r.ok() || r.overflow) {
    const std::string s = r.summary();
    std::fprintf(stderr, "watkins: RTL run failed:\n%s%s\n", s.c_str(),
                 r.overflow ? (s.empty() ? "overflow_o set" : "\noverflow_o set") : "");
    return 3;
  }
  return 0;
#else
  (void)a, (void)prepared, (void)image, (void)fragments, (void)predicted, (void)files;
  return 3;
#endif
}


}  // namespace
// ==== end of RTL co-simulation ===================================================================

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

void print_needs(const SceneNeeds& n, ShadingMode shading, const Config& cfg) {
  using namespace watkins;
  std::printf("needs         active edges %d (scan line %d), widest span %d px, longest edge %d lines\n",
              n.max_active_edges, n.max_active_line, n.max_segment_pixels, n.max_edge_lines);
  if (n.curve_edges > 0)
    std::printf("              curved edges %d records, at most %d active (scan line %d), edge order %d\n",
                n.curve_edges, n.max_curve_edges, n.max_curve_line, cfg.edge_order);
  const ChannelFormats f = cfg.channels(shading);
  for (int c = 0; c < fmt::NumChannels; ++c)
    std::printf("  channel %s  value [%lld, %lld]  slope [%lld, %lld]  -> %d of %d bits\n", channel_name(c, shading),
                static_cast<long long>(n.value_min[c]), static_cast<long long>(n.value_max[c]),
                static_cast<long long>(n.slope_min[c]), static_cast<long long>(n.slope_max[c]),
                n.bits_for_value(c), f.bits[c]);
  // Per group: integer bits (sign included) every value the pipeline holds needs, at the
  // configuration's fraction bits (slopes may wrap: they step the same values).
  for (int c = fmt::ChanX; c <= fmt::ChanR; ++c) {
    int need = 0;
    for (int k = c; k < (c == fmt::ChanR ? fmt::NumChannels : c + 1); ++k) need = std::max(need, n.value_bits[k]);
    std::printf("  group %-6s values need %d bits: int %d of %d, frac %d\n", channel_group_name(c, shading), need,
                need - f.frac[c], f.bits[c] - f.frac[c], f.frac[c]);
  }
}

// The error of the algorithm: the double reference (and the fixed-point model) against the exact
// surfaces ray-cast with the same illumination, over pixels showing the same scene object.
AnalyticTruth print_truth(const BuiltScene& scene, const Image& reference,
                                   const Image* fixed, const char* fixed_name) {
  using namespace watkins;
  const auto t0 = Clock::now();
  AnalyticTruth truth = render_analytic_truth(scene);
  if (!truth.unavailable.empty()) {
    std::printf("vs truth      none: %s\n", truth.unavailable.c_str());
    return truth;
  }
  const double t = seconds_since(t0);
  auto line = [&](const char* what, const Image& img) {
    const ImageError e = compare_with_truth(scene, img, truth);
    std::printf("vs truth      %s: max |d| %d levels, mean |d| %.4f levels, %d pixels > 1 level (over %d pixels "
                "showing the same object; %d change coverage)\n",
                what, e.max_abs, e.mean_abs, e.over_one, e.compared, e.coverage_differs);
  };
  line("double reference", reference);
  if (fixed) line(fixed_name, *fixed);
  std::printf("truth         %d exact surface(s) ray-cast in %.3f s%s\n", truth.surfaces, t,
              truth.without_truth ? "; objects without a closed form are not compared" : "");
  return truth;
}

// The command line's names parsed into the scene's build options (UsageError naming the option).
BuildOptions build_options(const RenderArgs& a) {
  using namespace watkins;
  BuildOptions opt;
  if (!a.shading.empty()) {
    opt.shading = parse_shading_mode(a.shading);
    if (!opt.shading) throw UsageError("--shading: unknown shading mode \"" + a.shading + "\" (gouraud, phong)");
  }
  if (!a.rule.empty()) {
    opt.rule = parse_shading_rule(a.rule);
    if (!opt.rule) throw UsageError("--rule: unknown shading rule \"" + a.rule +
                                    "\" (gouraud, lambert, warnock, romney, phong)");
  }
  if (!a.depth.empty()) {
    opt.depth = parse_depth_mode(a.depth);
    if (!opt.depth) throw UsageError("--depth: unknown depth mode \"" + a.depth + "\" (inverse-z, z)");
  }
  if (!a.interpolation.empty()) {
    opt.interpolation = parse_interpolation(a.interpolation);
    if (!opt.interpolation)
      throw UsageError("--interpolation: unknown interpolation " + quote_input(a.interpolation) + " (eq1, eq2)");
    if (*opt.interpolation == Interpolation::Eq2 && opt.depth == DepthMode::InverseZ)
      throw UsageError("--depth inverse-z: contradicts --interpolation eq2, which divides by the interpolated Z");
  }
  if (a.depth_tie_given) {
    opt.depth_tie = parse_depth_tie(a.depth_tie);
    if (!opt.depth_tie)
      throw UsageError("--depth-tie: unknown rule " + quote_input(a.depth_tie) + " (arrival, submission)");
  }
  if (a.smooth >= 0) opt.smooth = a.smooth;
  if (a.cull) opt.cull_backfaces = true;
  if (a.no_cull) opt.cull_backfaces = false;
  if (!a.patches.empty()) opt.patches_as_curves = a.patches == "curves";
  opt.strict = a.strict;
  return opt;
}

}  // namespace

CLI::App* add_render_command(CLI::App& app, RenderArgs& ra) {
  auto* r = app.add_subcommand("render", "render a scene (the embedded default scene if none is given)");
  r->add_option_function<std::string>(
       "scene",
       [&ra](const std::string& v) {
         ra.scene = v;
         ra.scene_given = true;
       },
       "scene file (JSON); see docs/guide/scene-format.md")
      ->type_name("TEXT");
  r->add_flag("--strict", ra.strict, "a zero-area polygon of a command list is an error (default: skipped and "
                                     "counted, as GL does)");
  cli::add_file(r, "--out,-o", ra.out, "PNG to write")->capture_default_str();
  cli::add_file(r, "--truth", ra.truth, "PNG of the analytic truth (exact surfaces ray-cast, eq. 3 per pixel)");
  cli::add_file(r, "--truth-diff", ra.truth_diff, "PNG of |image - analytic truth| x16 (magenta: coverage or object differs)");
  r->add_option("--model", ra.model, "fixed (bit-exact pipeline model) or float (double reference)")
      ->check(CLI::IsMember({"fixed", "float"}))->capture_default_str();
  r->add_option("--shading", ra.shading, "pipeline: gouraud (interpolate vertex shades) or phong (interpolate "
                                          "vertex normals, Phong's eq. 3 per pixel); overrides the scene's shading.mode");
  r->add_option("--rule", ra.rule, "vertex shading rule of the gouraud pipeline: gouraud, lambert, warnock, romney, "
                                   "phong (eq. 3 at the vertices)");
  r->add_option("--depth", ra.depth, "depth channel: inverse-z (Gouraud eq. 1) or z (eq. 2)");
  r->add_option("--interpolation", ra.interpolation,
                "gouraud pipeline: eq1 (interpolate the shade, Gouraud's eq. 1) or eq2 (interpolate S*Z and Z, one "
                "division per pixel: his eq. 2, the top's shade divider; depth Z/far); overrides shading.interpolation");
  r->add_option_function<std::string>(
       "--depth-tie",
       [&ra](const std::string& v) {
         ra.depth_tie = v;
         ra.depth_tie_given = true;
       },
       "equal depth at a pixel: arrival (the segment that closes first, the default) or submission (the polygon "
       "submitted first, as GL's GL_LESS; tie_submission_i = 1); overrides shading.depth_tie")
      ->type_name("TEXT");
  r->add_option("--smooth", ra.smooth, "Herman & Liu's 3x3 image smoothing with weight W (0: off; W in 1/128 "
                                       "steps); overrides shading.smooth")
      ->check(cli::finite_in(0.0, fmt::SmoothWMax));
  cli::add_file(r, "--diff", ra.diff, "PNG of |model - double reference| x16 (magenta: coverage differs)");
  r->add_option("--patches", ra.patches, "patch objects drawn as curves (Whitted's edges, Newton per scan line) or "
                                       "polygons (tessellated); overrides each object's \"draw\"")
      ->check(CLI::IsMember({"curves", "polygons"}));
  CLI::Option* cull = r->add_flag("--cull", ra.cull, "cull back faces");
  CLI::Option* no_cull = r->add_flag("--no-cull", ra.no_cull, "keep back faces");
  cli::exclusive({cull, no_cull});
  r->add_option_function<int>(
       "--max-active-edges",
       [&ra](int v) {
         ra.max_active_edges = v;
         ra.max_active_edges_given = true;
       },
       "active-edge list capacity (overrides the configuration's)")
      ->check(cli::integer_in(1, 1 << 16))
      ->type_name("INT")
      ->default_str(std::to_string(fmt::MaxActiveEdges));
  cli::add_file(r, "--config", ra.config, "hardware configuration (JSON, docs/guide/config-format.md): the format of each "
                                          "channel group and the capacities; default: model/twins/formats.hpp");
  r->add_option("--threads", ra.threads, "threads drawing the fixed model's frame, each a band of scan lines (the same "
                                         "image and counts as one)")
      ->check(cli::integer_in(1, 64))
      ->type_name("INT")
      ->capture_default_str();
  add_rtl_options(r, ra.rtl);  // --rtl, --trace, --seed, --gap, --stall
  return r;
}

void check_render(const RenderArgs& a) {
  (void)build_options(a);
  if (a.scene_given && a.scene.empty()) throw UsageError("the scene file name is empty (omit it for the built-in scene)");
  check_rtl_args(a.rtl, a.model);
}

int run_render(const RenderArgs& a) {
  check_render(a);
  const BuildOptions opt = build_options(a);
  // Every file the run reads is known before it writes or renders anything (run_files.hpp): the
  // scene, the files it names, the configuration; no output may be one of them.
  RunFiles files;
  const auto t0 = Clock::now();
  const Scene parsed = parse_scene_file(a.scene);
  if (!a.scene.empty()) files.input("the scene file", a.scene);
  files.scene_inputs(parsed);
  files.input("the --config file", a.config);
  for (const auto& [option, path] : {std::pair<const char*, const std::string&>{"--out", a.out}, {"--diff", a.diff},
                                     {"--truth", a.truth}, {"--truth-diff", a.truth_diff}, {"--trace", a.rtl.trace}})
    if (!path.empty() || std::string(option) == "--out") files.output(option, path);
  Config cfg = a.config.empty() ? Config{} : load_config(a.config);
  if (a.max_active_edges_given || a.config.empty()) cfg.max_active_edges = a.max_active_edges;
  const BuiltScene scene = build_scene(parsed, opt);
  // Without --config, the default configuration with the edge order the scene needs; a --config
  // is taken as given (prepare refuses curves at edge_order 1, naming the field).
  if (a.config.empty()) cfg = with_scene_edge_order(scene, cfg);
  const PreparedScene prepared = prepare(scene, cfg);
  check_rtl_config(a.rtl, prepared, a.config);  // --rtl
  const double t_prep = seconds_since(t0);

  std::printf("scene         %s  %dx%d  shading %s  rule %s  depth %s  depth-tie %s\n", scene.name.c_str(),
              scene.width, scene.height, to_string(scene.shading), to_string(scene.rule), to_string(scene.depth),
              to_string(scene.depth_tie));
  if (scene.interpolation == Interpolation::Eq2) std::printf("interpolation eq2 (Gouraud's eq. 2: S*Z / Z per pixel)\n");
  if (scene.shading == ShadingMode::Phong)
    std::printf("phong         %zu material(s), light (%.4f, %.4f, %.4f), eye (%.4f, %.4f, %.4f); the rule is unused\n",
                scene.materials.size(), scene.light[0], scene.light[1], scene.light[2], scene.eye[0], scene.eye[1],
                scene.eye[2]);
  std::printf("polygons      %zu (culled %d back faces, %d clipped, %d degenerate: zero area, skipped)\n",
              scene.polygons.size(), scene.culled_backfaces, scene.near_clipped, scene.degenerate);
  if (scene.curve_regions) {
    const EdgeStats& c = scene.curve_stats;
    std::printf("curves        %zu y-monotonic pieces in %d regions (%d subpatches, %d culled), most %d crossings on "
                "one scan line (line %d); %d silhouettes, defaults: %d one crossing, %d more than two, %d twice on a "
                "side, %d inside\n",
                scene.curves.size(), scene.curve_regions, c.cells, c.culled_regions, scene.max_curve_crossings,
                scene.max_curve_line, c.silhouettes, c.default_one, c.default_many, c.default_side_twice,
                c.default_inside);
    std::printf("newton        %lld crossings: %.3f iterations each (%lld in one, %lld in none, max %d), %lld by "
                "brute force (%lld left the piece, %lld did not converge); |E_y - y| at most %.2g px after the estimate, "
                "%.2g px after one iteration (%lld of %lld stepped crossings within 1/1024 px)\n",
                c.newton.crossings, c.newton.mean_iterations(), c.newton.one_iteration, c.newton.zero_iterations,
                c.newton.max_iterations, c.newton.brute_force(), c.newton.left_piece, c.newton.no_convergence, c.newton.max_estimate_residual,
                c.newton.max_one_iteration_residual, c.newton.one_iteration_close, c.newton.stepped);
  }
  std::printf("edge records  %zu (%d bits each)\n", prepared.edges.size(), cfg.edge_record_bits(prepared.shading));
  if (!a.config.empty())
    std::printf("config        %s: x %d.%d, depth %d.%d (depth_bits %d), shade %d.%d, normal %d.%d\n",
                a.config.c_str(), cfg.x.int_bits, cfg.x.frac_bits, cfg.depth.int_bits, cfg.depth.frac_bits,
                cfg.depth_bits, cfg.shade.int_bits, cfg.shade.frac_bits, cfg.normal.int_bits, cfg.normal.frac_bits);
  print_needs(prepared.needs, prepared.shading, cfg);

  const auto t1 = Clock::now();
  FloatReferenceStats fstats;
  const Image reference = render_float_reference(scene, &fstats);
  const double t_ref = seconds_since(t1);

  Image result;          // the fixed model's image, or the RTL's with --rtl
  int rtl_status = 0;    // --rtl: 3 when the RTL differs from the model, hangs or overflows
  if (a.model == "fixed") {
    WatkinsTop pipe(cfg);
    pipe.set_threads(a.threads);
    const auto t2 = Clock::now();
    result = pipe.render(prepared);
    const double t_model = seconds_since(t2);
    const auto& s = pipe.stats();
    std::printf("fixed model   %lld segments, %lld fragments (%lld won the depth test)\n", s.segments,
                s.fragments, s.visible);
    std::printf("wall time     prepare %.3f s, fixed model %.3f s (%.2f M fragments/s), double reference %.3f s\n",
                t_prep, t_model, s.fragments / std::max(t_model, 1e-9) / 1e6, t_ref);
    // Smoothing spreads a moved silhouette into its neighbours: those are counted apart.
    const ImageError e = compare_images(result, reference, prepared.smoothed() ? 1 : 0);
    std::printf("vs double     max |d| %d levels, mean |d| %.4f levels, %d pixels > 1 level "
                "(over %d pixels showing the same polygon); %d pixels change polygon, %d change coverage\n",
                e.max_abs, e.mean_abs, e.over_one, e.compared, e.visibility_differs, e.coverage_differs);
    if (e.guarded)
      std::printf("              %d smoothed pixels next to a changed polygon or coverage left out\n", e.guarded);
    const auto t3 = Clock::now();
    const CyclePrediction full = predict_cycles(prepared, PixelOutput::FullFrame, cfg.max_active_edges, cfg);
    long long rtl_predicted = full.cycles;
    if (cfg.compact) {
      // Full frames only; the bench offers the first beat a clock after reset, while the compact
      // blocks' reset clears still run.
      CycleOptions from_reset;
      from_reset.max_active_edges = cfg.max_active_edges;
      from_reset.after_reset = 1;
      rtl_predicted = predict_cycles(prepared, cfg, from_reset).cycles;
      std::printf("predicted     %lld cycles (full-frame), %lld from reset as the RTL bench starts it: the compact "
                  "top with no gaps or stalls (cycle model, %.3f s)\n", full.cycles, rtl_predicted, seconds_since(t3));
    } else {
      const CyclePrediction sparse = predict_cycles(prepared, PixelOutput::Sparse, cfg.max_active_edges, cfg);
      std::printf("predicted     %lld cycles (full-frame), %lld cycles (sparse): the RTL with no gaps or stalls "
                  "(cycle model, %.3f s)\n", full.cycles, sparse.cycles, seconds_since(t3));
      if (a.rtl.sparse) rtl_predicted = sparse.cycles;
    }
    if (a.rtl.enabled)  // --rtl
      rtl_status = run_rtl_mode(a.rtl, prepared, result, s.fragments, rtl_predicted, files);
  } else {
    result = reference;
    std::printf("double model  %lld fragments, %.3f s\n", fstats.fragments, t_ref);
  }
  const AnalyticTruth truth = print_truth(scene, reference, a.model == "fixed" ? &result : nullptr,
                                          a.rtl.enabled ? "RTL" : "fixed model");
  // Outputs are kept in memory and written only once everything succeeded (RunFiles): a run
  // that fails leaves no file behind, not even one it could have written first.
  if (rtl_status != 0) {
    std::fprintf(stderr, "watkins: nothing written: the RTL run failed\n");
    return rtl_status;
  }
  if ((!a.truth.empty() || !a.truth_diff.empty()) && !truth.unavailable.empty())
    throw SceneError(std::string(!a.truth.empty() ? "--truth " + a.truth : "--truth-diff " + a.truth_diff) +
                     ": no analytic truth for " + scene.name + ": " + truth.unavailable + " (nothing written)");
  if (!a.diff.empty()) files.add(a.diff, encode_png(diff_image(result, reference)));
  if (!a.truth.empty()) files.add(a.truth, encode_png(truth.image));
  if (!a.truth_diff.empty()) files.add(a.truth_diff, encode_png(truth_diff_image(scene, result, truth)));
  files.add(a.out, encode_png(result));
  files.commit();
  std::printf("wrote         %s%s%s%s%s%s%s\n", a.out.c_str(), a.diff.empty() ? "" : ", ", a.diff.c_str(),
              a.truth.empty() ? "" : ", ", a.truth.c_str(), a.truth_diff.empty() ? "" : ", ", a.truth_diff.c_str());
  return 0;
}


}  // namespace watkins::render
