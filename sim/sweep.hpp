// watkins sweep: error against cost over a grid of scenes × shading × tessellation × fraction
// bits per channel group, in process
// (the model libraries, no subprocess per point). One CSV row per point, a markdown table, a
// progress bar on a terminal; --jobs N threads and --shard i/N for batch systems. See sweep.cpp.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace watkins::sweep {

struct SweepArgs {
  std::vector<std::string> scenes;  // scene files; default: the sphere and the cone
  // whitted: the patch objects drawn by Whitted's curved edges (Phong pipeline, edge_order 3).
  std::vector<std::string> shadings{"flat", "gouraud-eq1", "gouraud-eq2", "phong"};
  std::vector<double> tess{0.5, 1, 2, 4};  // factors on the first object's u and v
  // Instead of factors: u = v = n on the first object (axis "uv"), the same cells in every scene.
  std::vector<int> uv;
  // Fraction bits per channel group (axes attr_frac, x_frac, depth_frac). attr_frac is the
  // shading's attribute group: shade (R G B) for flat and Gouraud, normal (Nx Ny Nz) for Phong.
  // Integer bits are not an axis: each point gets exactly the ones its scene needs at its
  // fractions (SceneNeeds::int_bits_needed), so the configuration is the smallest that holds it.
  std::vector<int> attr_frac{16}, x_frac{16}, depth_frac{16};  // default: formats.hpp's FracBits
  std::string rule = "phong";  // vertex rule of flat and Gouraud (the truth needs eq. 3)
  std::string csv = "sweep.csv", md;
  int jobs = 1;
  std::string shard = "0/1";  // i/N: this process runs the points k with k mod N == i
  int max_active_edges = 1024;  // the model's active-edge list (the RTL's is fmt::MaxActiveEdges)
  bool rtl = false;             // cycles from the Verilated RTL (sparse output unless full_frame)
  bool full_frame = false;
  bool compact = false;         // with --rtl: the compact top (Gouraud points, full frames)
  bool quiet = false;           // no progress bar
  std::string images;           // a folder: each point's fixed-point image and each scene's truth (PNG)
};

// Registers `watkins sweep` and its options on `app`; returns the subcommand.
CLI::App* add_sweep_command(CLI::App& app, SweepArgs& args);
// The checks of the command line that need no file: UsageError (exit code 2) naming the option.
void check_sweep(const SweepArgs& args);
// Runs the sweep; returns the exit code (3 when the RTL differs from the model at some point).
// A scene that cannot be read is std::runtime_error (exit code 1) before anything is written.
int run_sweep(const SweepArgs& args);

}  // namespace watkins::sweep
