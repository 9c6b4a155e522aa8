#include "board.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>

#include "beam_schedule.hpp"
#include "config_file.hpp"
#include "options.hpp"
#include "prepare.hpp"
#include "run_files.hpp"
#include "scene.hpp"
#include "scene_types.hpp"
#include "size.hpp"
#include "usage_error.hpp"

namespace watkins::board_command {
namespace {

// Frequencies of the board's clocks: a tick is 1/1260 us.
double mhz(int ticks) { return 1260.0 / ticks; }

std::string line_name(const board::LineSlack& l) {
  return "frame " + std::to_string(l.frame) + " line " + std::to_string(l.y);
}

int run_check(const CheckArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  RunFiles files;  // no output: the inputs are named for the messages
  const Scene parsed = parse_scene_file(a.scene);
  if (!a.scene.empty()) files.input("the scene file", a.scene);
  files.scene_inputs(parsed);
  files.input("the --config file", a.config);
  const BuiltScene scene = build_scene(parsed);
  const std::string name = a.scene.empty() ? std::string("the default scene") : a.scene;
  // The board shows 640 x 480: the frame is that, or half of it doubled.
  int doubling = a.doubling;
  if (doubling == 0) doubling = scene.width == board::HVisible / 2 ? 2 : 1;
  const int want_w = board::HVisible / doubling, want_h = board::VVisible / doubling;
  const std::string shows = "the board shows 640x480 (--doubling 1) or 320x240 (--doubling 2)";
  if (scene.width != want_w)
    throw std::runtime_error(name + ": screen.width " + std::to_string(scene.width) + ": " + shows +
                             (a.doubling ? "; --doubling " + std::to_string(doubling) + " needs " + std::to_string(want_w)
                                         : std::string()));
  if (scene.height != want_h)
    throw std::runtime_error(name + ": screen.height " + std::to_string(scene.height) + ": " + shows +
                             (a.doubling ? "; --doubling " + std::to_string(doubling) + " needs " + std::to_string(want_h)
                                         : std::string()));
  const Config cfg = a.config.empty() ? size::sized_config(scene) : load_config(a.config);
  const PreparedScene prepared = prepare(scene, cfg);

  board::BoardTiming t;
  t.doubling = doubling;
  t.line_slots = a.slots;
  const board::BeamSchedule s = board::beam_schedule(prepared, cfg, t);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::printf("scene         %s  %dx%d  shading %s, %zu polygons, %zu edge records\n", scene.name.c_str(), scene.width,
              scene.height, to_string(scene.shading), scene.polygons.size(), prepared.edges.size());
  const int g = std::gcd(t.ticks_per_pixel, t.ticks_per_pipe);
  std::printf("board         %s: clk_pixel %.2f MHz, clk_pipe %.2f MHz (%d/%d of clk_pixel), clk_tmds %.0f MHz; "
              "doubling %d, %d line slots\n",
              a.board.c_str(), mhz(t.ticks_per_pixel), mhz(t.ticks_per_pipe), t.ticks_per_pixel / g, t.ticks_per_pipe / g,
              mhz(t.ticks_per_pixel) * 5, doubling, a.slots);
  std::printf("config        %s: edge record %d bits, max_active_edges %d, %s\n",
              a.config.empty() ? "sized (watkins size, bound 1 level)" : a.config.c_str(),
              cfg.edge_record_bits(scene.shading), cfg.max_active_edges,
              cfg.smoothing ? "smoother" : "no smoother");
  std::printf("budget        %.0f pipeline clocks per rendered line (%d video line%s of %d pixel clocks)\n",
              s.budget_per_line(), doubling, doubling > 1 ? "s" : "", board::HTotal);
  const board::FrameRun& f0 = s.frames.front();
  std::printf("first frame   %lld cycles, first edge beat to last pixel (start pulse to first beat %d); %zu frames "
              "simulated, %.2f s\n",
              f0.cycles(), s.timing.start_to_first_beat, s.frames.size(), seconds);
  const board::LineSlack& w = s.lines.at(s.worst);
  std::printf("worst line    %s: slack %lld pipeline clocks (its last pixel at pipeline edge %lld, deadline %lld)\n",
              line_name(w).c_str(), w.slack, w.completion, w.deadline);
  if (s.missed == 0) {
    std::printf("missed        0 lines\n");
    return 0;
  }
  std::string first;
  int named = 0;
  for (const board::LineSlack& l : s.lines) {
    if (!l.missed) continue;
    if (named == 5) {
      first += ", ...";
      break;
    }
    first += (named++ ? ", " : "") + line_name(l) + " (" + std::to_string(l.slack) + ")";
  }
  std::printf("missed        %lld lines: %s\n", s.missed, first.c_str());
  return MissedExit;
}

}  // namespace

CLI::App* add_board_command(CLI::App& app, BoardArgs& a) {
  auto* b = app.add_subcommand("board", "the pipeline on an FPGA board, racing the beam (docs/reference/board.md)");
  b->require_subcommand(1);
  a.board_app = b;
  CheckArgs& c = a.check;
  auto* check = b->add_subcommand("check", "each rendered line's completion against the moment the video shows it "
                                           "(exit 4 when a line misses)");
  cli::add_file(check, "scene", c.scene, "scene file (JSON), 640x480 or 320x240; default: the embedded default scene");
  check->add_option("--board", c.board, "the board")->check(CLI::IsMember({"ulx3s"}))->capture_default_str();
  check->add_option("--doubling", c.doubling, "1: 640x480 native; 2: 320x240 shown doubled (default: from the scene's size)")
      ->check(cli::integer_in(1, 2));
  check->add_option("--slots", c.slots, "line-buffer slots, a power of two")
      ->check(cli::integer_in(1, 1024))
      ->capture_default_str();
  cli::add_file(check, "--config", c.config, "hardware configuration (JSON) instead of sizing the scene");
  a.check_app = check;
  return b;
}

void check_board(const BoardArgs& a) {
  if (a.check_app && *a.check_app) {
    if ((a.check.slots & (a.check.slots - 1)) != 0)
      throw UsageError("--slots: " + std::to_string(a.check.slots) + " is not a power of two");
  }
}

int run_board(const BoardArgs& a) {
  if (a.check_app && *a.check_app) return run_check(a.check);
  return 0;
}

}  // namespace watkins::board_command
