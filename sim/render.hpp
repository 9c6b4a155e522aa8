// watkins render: one scene through the fixed-point pipeline model (or the double reference), its
// error against the double reference and the analytic truth, the cycle model's prediction, and with
// --rtl the Verilated RTL compared pixel by pixel and stage by stage. See render.cpp.
#pragma once

#include <string>

#include "formats.hpp"

namespace CLI {
class App;
}

namespace watkins::render {

struct RtlArgs {
  bool enabled = false;
  std::string trace;             // FST waveform
  unsigned long long seed = 1;   // seeds the input gaps and the output stalls
  double gap = 0.0;              // probability of an idle cycle before each edge beat
  double stall = 0.0;            // probability that the pixel sink holds pixel_ready_i low
  bool sparse = false;           // sparse output mode: only covered pixels, with (x, y)
  bool systemc = false;          // the SystemC bench (assertions on) instead of the plain C++ harness
};

struct RenderArgs {
  std::string scene;
  bool scene_given = false;  // an empty SCENE argument is an error, not the built-in scene
  bool strict = false;       // --strict: a zero-area polygon is an error, not skipped
  std::string out = "watkins.png";
  std::string model = "fixed";
  std::string shading, rule, depth, diff, truth, truth_diff;
  std::string depth_tie;  // equal-depth rule: arrival or submission
  std::string interpolation;  // eq1 or eq2 (Gouraud's equations); else the scene's
  bool depth_tie_given = false;  // else the scene's shading.depth_tie
  double smooth = -1;            // --smooth W (else the scene's shading.smooth)
  bool cull = false, no_cull = false;
  std::string patches;  // --patches curves|polygons
  int max_active_edges = fmt::MaxActiveEdges;
  bool max_active_edges_given = false;  // --max-active-edges overrides the configuration's
  std::string config;                   // --config F (docs/guide/config-format.md)
  int threads = 1;                      // --threads N: the model's bands of scan lines
  RtlArgs rtl;  // --rtl and its options
};

// Registers `watkins render` and its options on `app`; returns the subcommand.
CLI::App* add_render_command(CLI::App& app, RenderArgs& args);
// The checks of the command line that need no file: UsageError (exit code 2) naming the option.
void check_render(const RenderArgs& args);
// Runs it; returns the exit code (3 when the RTL differs from the model).
int run_render(const RenderArgs& args);

}  // namespace watkins::render
