// watkins_bench: speed of the bit-exact model and of the double reference on one scene.
// Repeats each render for at least --seconds and prints the best rate (a benchmark, not a test).
#include <CLI/CLI.hpp>

#include <chrono>
#include <algorithm>
#include <cstdio>
#include <string>

#include "config_file.hpp"
#include "grid_scene.hpp"
#include "cycle_model.hpp"
#include "float_reference.hpp"
#include "watkins_top.hpp"
#include "prepare.hpp"
#include "scene.hpp"

namespace {

template <class F>
double best_seconds(F&& body, double budget) {
  using Clock = std::chrono::steady_clock;
  double best = 1e300, spent = 0;
  int runs = 0;
  while (spent < budget || runs < 3) {
    const auto t0 = Clock::now();
    body();
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    best = std::min(best, s);
    spent += s;
    ++runs;
  }
  return best;
}

// The frames callgrind counts (scripts/bench collects this function alone): the model drawing
// into an image it has drawn before, as the timed loop does.
__attribute__((noinline)) void profiled_frames(watkins::WatkinsTop& pipe, const watkins::PreparedScene& prepared,
                                               watkins::Image& frame_buffer, int frames) {
  for (int i = 0; i < frames; ++i) pipe.render_into(prepared, frame_buffer);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"watkins_bench: fragments per second of the model and the double reference"};
  std::string scene_path;
  double budget = 1.0;
  CLI::Option* scene_opt = app.add_option("scene", scene_path, "scene file (default: the embedded default scene)");
  std::string config_path;
  int grid = 0;
  app.add_option("--grid", grid, "instead of a scene: a 512x512 screen of 2*N*N triangles covering each pixel once")
      ->check(CLI::Range(1, 256))
      ->excludes(scene_opt);
  std::string shading;
  app.add_option("--shading", shading, "gouraud or phong: the pipeline (default: the scene's)")
      ->check(CLI::IsMember({"gouraud", "phong"}));
  int profile_frames = 0;
  app.add_option("--profile-frames", profile_frames,
                 "only render the model this many times (in profiled_frames, after a first frame) and print "
                 "its fragments (for callgrind: instructions per fragment)");
  app.add_option("--seconds", budget, "time budget per measurement")->capture_default_str();
  int threads = 1;
  app.add_option("--threads", threads, "threads drawing the model's frames (bands of scan lines)")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  bool only_model = false;
  app.add_flag("--only-model", only_model, "time the model's frame alone (no reference, fitted or cycle figures)");
  app.add_option("--config", config_path, "hardware configuration (docs/guide/config-format.md); default: formats.hpp");
  CLI11_PARSE(app, argc, argv);
  try {
    using namespace watkins;
    BuildOptions opt;
    if (!shading.empty()) opt.shading = shading == "phong" ? ShadingMode::Phong : ShadingMode::Gouraud;
    const BuiltScene scene = grid > 0 ? watkins::grid_scene(512, grid) : load_scene_or_default(scene_path, opt);
    Config cfg = config_path.empty() ? Config{} : load_config(config_path);
    cfg.max_active_edges = 1 << 20;  // measure speed, not capacity
    const PreparedScene prepared = prepare(scene, cfg);
    WatkinsTop pipe(cfg);
    pipe.set_threads(threads);
    pipe.render(prepared);
    const long long fragments = pipe.stats().fragments;
    if (profile_frames > 0) {
      Image frame_buffer;  // as the timed loop draws: one image, sized by a first frame
      pipe.render_into(prepared, frame_buffer);
      profiled_frames(pipe, prepared, frame_buffer, profile_frames);
      std::printf("profiled            %d model frames of %lld fragments\n", profile_frames, fragments);
      return 0;
    }
    const double pixels = double(scene.width) * scene.height;
    if (only_model) {
      Image frame_buffer;
      const double t = best_seconds([&] { pipe.render_into(prepared, frame_buffer); }, budget);
      std::printf("scene               %s (%dx%d, %zu polygons, %zu edge records, %lld fragments)\n",
                  scene.name.c_str(), scene.width, scene.height, scene.polygons.size(), prepared.edges.size(),
                  fragments);
      std::printf("fixed-point model   %.3f ms/frame  %.2f M fragments/s  %.2f M pixels/s  (%d thread%s)\n", t * 1e3,
                  fragments / t / 1e6, pixels / t / 1e6, threads, threads == 1 ? "" : "s");
      return 0;
    }
    const double t_prep = best_seconds([&] { prepare(scene, cfg); }, budget);
    // The model draws into one image frame after frame (render_into), as a video-rate loop does;
    // render() returning a new image per frame is timed too (its pages are faulted in afresh).
    Image frame_buffer;
    const double t_fixed = best_seconds([&] { pipe.render_into(prepared, frame_buffer); }, budget);
    const double t_fixed_new = best_seconds([&] { pipe.render(prepared); }, budget);
    const double t_float = best_seconds([&] { render_float_reference(scene); }, budget);
    // The same fractions with integer bits cut to what the scene needs (fit_int_bits, as
    // `watkins size` does): the same arithmetic on narrower words, so the same image, and the
    // model's setup stays in 64-bit words.
    Config fitted = fit_int_bits(scene, cfg);
    fitted.max_active_edges = cfg.max_active_edges;
    const PreparedScene prepared_fitted = prepare(scene, fitted);
    WatkinsTop pipe_fitted(fitted);
    const bool same_image = pipe_fitted.render(prepared_fitted).rgb == pipe.render(prepared).rgb;
    const double t_fitted = best_seconds([&] { pipe_fitted.render_into(prepared_fitted, frame_buffer); }, budget);
    int widest = 0;
    for (const int b : fitted.channels(scene.shading).bits) widest = std::max(widest, b);
    std::printf("scene               %s (%dx%d, %zu polygons, %zu edge records, %lld fragments)\n",
                scene.name.c_str(), scene.width, scene.height, scene.polygons.size(),
                prepared.edges.size(), fragments);
    std::printf("scene preparation   %.3f ms\n", t_prep * 1e3);
    std::printf("fixed-point model   %.3f ms/frame  %.2f M fragments/s  %.2f M pixels/s\n", t_fixed * 1e3,
                fragments / t_fixed / 1e6, pixels / t_fixed / 1e6);
    std::printf("model, new image    %.3f ms/frame  %.2f M fragments/s  (render(): a new image per frame)\n",
                t_fixed_new * 1e3, fragments / t_fixed_new / 1e6);
    std::printf("fixed-point fitted  %.3f ms/frame  %.2f M fragments/s  (integer bits fitted, words <= %d bits, %s)\n",
                t_fitted * 1e3, fragments / t_fitted / 1e6, widest, same_image ? "same image" : "IMAGE DIFFERS");
    std::printf("double reference    %.3f ms/frame  %.2f M fragments/s\n", t_float * 1e3,
                fragments / t_float / 1e6);
    for (const PixelOutput out : {PixelOutput::FullFrame, PixelOutput::Sparse}) {
      const long long cycles = predict_cycles(prepared, out, 1 << 20).cycles;
      const double t = best_seconds([&] { predict_cycles(prepared, out, 1 << 20); }, budget);
      std::printf("cycle model         %.3f ms/frame  %lld RTL cycles (%s)  %.1f M predicted cycles/s\n", t * 1e3,
                  cycles, out == PixelOutput::Sparse ? "sparse" : "full-frame", cycles / t / 1e6);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "watkins_bench: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
