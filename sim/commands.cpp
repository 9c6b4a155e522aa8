#include "commands.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <new>
#include <stdexcept>

#include "board.hpp"
#include "export_stl.hpp"
#include "render.hpp"
#include "size.hpp"
#include "sweep.hpp"
#include "synth.hpp"
#include "usage_error.hpp"
#include "voxel_compare.hpp"

namespace watkins::cli {

struct Commands::Args {
  render::RenderArgs render;
  stl_command::ExportStlArgs export_stl;
  sweep::SweepArgs sweep;
  size::SizeArgs size;
  synth::SynthArgs synth;
  voxel_compare::VoxelCompareArgs voxel_compare;
  board_command::BoardArgs board;
  CLI::App *render_app = nullptr, *export_stl_app = nullptr, *sweep_app = nullptr, *size_app = nullptr,
           *synth_app = nullptr, *voxel_compare_app = nullptr;
};

Commands::Commands(CLI::App& app) : args_(std::make_unique<Args>()) {
  app.require_subcommand(1);
  Args& a = *args_;
  a.render_app = render::add_render_command(app, a.render);
  a.export_stl_app = stl_command::add_export_stl_command(app, a.export_stl);
  a.sweep_app = sweep::add_sweep_command(app, a.sweep);
  a.size_app = size::add_size_command(app, a.size);
  a.synth_app = synth::add_synth_command(app, a.synth);
  a.voxel_compare_app = voxel_compare::add_voxel_compare_command(app, a.voxel_compare);
  board_command::add_board_command(app, a.board);
}

Commands::~Commands() = default;

void Commands::check() const {
  const Args& a = *args_;
  if (*a.render_app) render::check_render(a.render);
  if (*a.sweep_app) sweep::check_sweep(a.sweep);
  if (*a.size_app) size::check_size(a.size);
  if (*a.synth_app) synth::check_synth(a.synth);
  if (*a.voxel_compare_app) voxel_compare::check_voxel_compare(a.voxel_compare);
  if (*a.board.board_app) board_command::check_board(a.board);
}

int Commands::run() const {
  const Args& a = *args_;
  if (*a.render_app) return render::run_render(a.render);
  if (*a.export_stl_app) return stl_command::run_export_stl(a.export_stl);
  if (*a.sweep_app) return sweep::run_sweep(a.sweep);
  if (*a.size_app) return size::run_size(a.size);
  if (*a.synth_app) return synth::run_synth(a.synth);
  if (*a.voxel_compare_app) return voxel_compare::run_voxel_compare(a.voxel_compare);
  if (*a.board.board_app) return board_command::run_board(a.board);
  return 0;
}

int main_entry(int argc, char** argv) {
  CLI::App app{"watkins: fixed-point model of the Watkins / Gouraud scan-line shading pipeline"};
  const Commands commands(app);
  // One line per error, in the form every other usage error takes.
  app.failure_message([](const CLI::App*, const CLI::Error& e) { return std::string("watkins: usage: ") + e.what() + "\n"; });
  // Exit codes (docs/guide/cli.md): 0 ok, 1 bad input (a scene, mesh, volume or configuration
  // file; an output that cannot be written), 2 usage (the command line, an output naming an
  // input), 3 internal error or RTL mismatch, 4 `board check`: a line misses its deadline.
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help, or the message
    return code == 0 ? 0 : 2;
  }
  try {
    commands.check();
    return commands.run();
  } catch (const UsageError& e) {
    std::fprintf(stderr, "watkins: usage: %s\n", e.what());
    return 2;
  } catch (const std::logic_error& e) {  // a broken invariant of the model, not the input
    std::fprintf(stderr, "watkins: internal error: %s\n", e.what());
    return 3;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "watkins: internal error: out of memory\n");
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "watkins: error: %s\n", e.what());
    return 1;
  }
}

}  // namespace watkins::cli
