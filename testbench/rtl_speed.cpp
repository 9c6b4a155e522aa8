// Simulation speed of the RTL on one bench of the default configuration, built three times from
// this one source: watkins_rtl_speed_sc (the SystemC bench: --sc tops with assertions and
// tracing), watkins_rtl_speed_sc_fast (the SystemC bench on --sc tops without assertions or
// tracing: sc_bench.hpp's sc_speed, built only as an explicit target) and watkins_rtl_speed_cc
// (the plain C++ harness on the speed build's --cc tops).
//   watkins_rtl_speed_{sc,sc_fast,cc} [SCENE] [--shading gouraud|phong] [--repeat N] [--gap P] [--stall P]
//                             [--seed N] [--no-stage-check]
#include <CLI/CLI.hpp>

#include <cstdio>
#include <ctime>
#include <stdexcept>
#include <string>

#include "watkins_top.hpp"
#include "prepare.hpp"
#include "rtl_bench.hpp"
#include "scene.hpp"
#ifdef WATKINS_SPEED_SC_FAST
#include "sc_bench.hpp"
#endif

namespace {

// One run on this program's bench.
watkins::tb::RtlResult run(const watkins::PreparedScene& scene, const watkins::tb::RtlOptions& opt,
                           const watkins::Image& expected) {
#ifdef WATKINS_SPEED_SC_FAST
  // run_rtl would take the assertion build's SystemC bench: call the speed build's directly.
  watkins::tb::RtlResult r;
  watkins::tb::detail::sc_speed::run_systemc({&scene}, opt, {&expected}, r);
  return r;
#else
  return watkins::tb::run_rtl(scene, opt, &expected);
#endif
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"watkins_rtl_speed: simulated cycles per second of the Verilated pipeline"};
  std::string scene_path;
  int repeat = 3;
  watkins::tb::RtlOptions opt;
  app.add_option("scene", scene_path, "scene file (JSON); the embedded default scene if none");
  app.add_option("--repeat", repeat, "frames to run (after one warm-up frame)")->capture_default_str();
  app.add_option("--gap", opt.gap, "edge source gap probability")->capture_default_str();
  app.add_option("--stall", opt.stall, "pixel sink stall probability")->capture_default_str();
  app.add_option("--seed", opt.seed, "random seed")->capture_default_str();
  std::string shading;
  app.add_option("--shading", shading, "gouraud or phong (default: the scene's)");
  bool no_stages = false;
  app.add_flag("--no-stage-check", no_stages, "compare the pixels only, not the internal stage streams");
  CLI11_PARSE(app, argc, argv);
  opt.check_stages = !no_stages;
#ifdef WATKINS_SPEED_CC
  opt.harness = watkins::tb::RtlHarness::Fast;
#else
  opt.harness = watkins::tb::RtlHarness::SystemC;
#endif
  try {
    using namespace watkins;
    BuildOptions build;
    if (!shading.empty()) {
      build.shading = parse_shading_mode(shading);
      if (!build.shading) throw std::invalid_argument("--shading: expected gouraud or phong, got \"" + shading + "\"");
    }
    const BuiltScene scene = load_scene_or_default(scene_path, build);
    const PreparedScene prepared = prepare(scene);
    const Image expected = WatkinsTop().render(prepared);
    tb::RtlResult warm = run(prepared, opt, expected);  // also builds the bench
    long long cycles = 0;
    double wall = 0;
    const std::clock_t cpu0 = std::clock();  // CPU time: robust against other jobs on the machine
    bool ok = warm.ok();
    for (int i = 0; i < repeat; ++i) {
      opt.seed += 1;
      const tb::RtlResult r = run(prepared, opt, expected);
      cycles += r.sim_cycles;
      wall += r.wall_seconds;
      ok = ok && r.ok();
      if (!r.ok()) warm = r;
    }
    const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
    std::printf("harness       %s\n", warm.top.c_str());
    std::printf("scene         %s %dx%d, %zu edge records, %s shading\n", scene.name.c_str(), prepared.width,
                prepared.height, prepared.edges.size(), to_string(prepared.shading));
    std::printf("frame cycles  %lld (gap %.2f, stall %.2f)\n", warm.cycles, opt.gap, opt.stall);
    std::printf("stage check   %s (%lld stage transfers compared per frame)\n", opt.check_stages ? "on" : "off",
                warm.stage_items);
    std::printf("speed         %.0f cycles/s over %d frames (%lld cycles in %.3f s wall, %.3f s CPU: %.0f cycles/CPU s)\n",
                wall > 0 ? cycles / wall : 0.0, repeat, cycles, wall, cpu, cpu > 0 ? cycles / cpu : 0.0);
    if (!ok) {
      std::printf("RTL run failed:\n%s\n", warm.summary().c_str());
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "watkins_rtl_speed: error: %s\n", e.what());
    return 1;
  }
}
