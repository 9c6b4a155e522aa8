// watkins board sim (board_sim.hpp).
#include "board_sim.hpp"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "beam_schedule.hpp"
#include "board.hpp"
#include "board_image.hpp"
#include "config_file.hpp"
#include "flash_image.hpp"
#include "image.hpp"
#include "image_io.hpp"
#include "options.hpp"
#include "prepare.hpp"
#include "run_files.hpp"
#include "scene.hpp"
#include "scene_types.hpp"
#include "usage_error.hpp"
#include "watkins_top.hpp"

// The Verilated board tops: owned by the testbench (testbench/board/), linked in where it is built.
#ifdef WATKINS_HAVE_BOARD_SIM
#include "board_bench.hpp"
#include "icebreaker_bench.hpp"
#endif

namespace watkins::board_command {

CLI::App* add_sim_command(CLI::App* board, SimArgs& a) {
  auto* s = board->add_subcommand("sim", "the virtual board: the Verilated board top draws the scene; each video frame "
                                         "as a PNG and a report line (exit 4 when a line misses, 3 when a frame "
                                         "differs from the model)");
  cli::add_file(s, "scene", a.scene, "scene file (JSON), 320x240; default: the embedded default scene");
  s->add_option("--board", a.board, "the board")->check(CLI::IsMember({"ulx3s", "icebreaker"}))->capture_default_str();
  s->add_option("--top", a.top, "icebreaker: the top built compact (default, what the UP5K holds) or pipelined")
      ->check(CLI::IsMember({"compact", "pipelined"}));
  cli::add_shading(s, a.shading, "gouraud or phong: the top built with that pipeline (default: the scene's "
                                 "shading.mode)");
  s->add_option("--frames", a.frames, "rendered frames to show (each after the video frame before it)")
      ->check(cli::integer_in(1, 100000))
      ->capture_default_str();
  cli::add_file(s, "--out,-o", a.out, "the folder of the frames (frame_000.png, ...)")->capture_default_str();
  return s;
}

#ifndef WATKINS_HAVE_BOARD_SIM

int run_sim(const SimArgs&) {
  throw UsageError("board sim: this build has no Verilated board tops; they are built with the RTL and the tests "
                   "(cmake -DWATKINS_RTL=ON -DWATKINS_TESTS=ON, Verilator installed)");
}

#else

namespace {

namespace tb = board_tb;

// The top a run uses and what it was built for.
struct SimTop {
  bool icebreaker = false;
  tb::BoardTop ulx3s = tb::BoardTop::Default;
  tb::IcebreakerTop ice = tb::IcebreakerTop::Compact;
  tb::TopBuild build;
  std::string label;  // "ulx3s_top (pipelined, Gouraud)"
};

// The Verilated top of the board that draws `shading`: on the ULX3S the pipelined Gouraud or
// Phong top; on the iCEBreaker the Gouraud top built compact or pipelined (--top), or the Phong top
// where the build has one, its blocks those its configuration names.
SimTop sim_top(const SimArgs& a, ShadingMode shading) {
  SimTop t;
  t.icebreaker = a.board == "icebreaker";
  const bool phong = shading == ShadingMode::Phong;
  if (!t.icebreaker) {
    if (a.top == "compact")
      throw UsageError("--top compact: the ulx3s board tops are built pipelined (testbench/board/CMakeLists.txt)");
    t.ulx3s = phong ? tb::BoardTop::Phong : tb::BoardTop::Default;
    t.build = tb::top_build(t.ulx3s);
  } else if (phong) {
    if (!tb::top_built(tb::IcebreakerTop::Phong))
      throw std::runtime_error("shading phong: this build has no Verilated icebreaker board top with Phong = 1 "
                               "(cmake -DWATKINS_BOARD_ICEBREAKER_PHONG_CONFIG=FILE builds one); --board ulx3s "
                               "draws Phong");
    t.ice = tb::IcebreakerTop::Phong;
    t.build = tb::top_build(t.ice);
  } else {
    t.ice = a.top == "pipelined" ? tb::IcebreakerTop::Pipelined : tb::IcebreakerTop::Compact;
    t.build = tb::top_build(t.ice);
  }
  const bool compact = load_config(t.build.config).compact;
  if (!a.top.empty() && (a.top == "compact") != compact)
    throw UsageError("--top " + a.top + ": the " + a.board + " board's " + to_string(shading) + " top is built " +
                     (compact ? "compact" : "pipelined") + " (testbench/board/CMakeLists.txt)");
  t.label = std::string(t.icebreaker ? "icebreaker_top" : "ulx3s_top") + " (" + (compact ? "compact" : "pipelined") +
            ", " + (phong ? "Phong" : "Gouraud") + ")";
  return t;
}

std::string relative_to_source(const std::string& path) {
  const std::string root = std::string(WATKINS_SOURCE_DIR) + "/";
  return path.rfind(root, 0) == 0 ? path.substr(root.size()) : path;
}

// The rendered frames shown so far.
struct FrameTally {
  long long missed = 0;
  int equal = 0, frames = 0;
};

}  // namespace

int run_sim(const SimArgs& a) {
  RunFiles files;
  const Scene parsed = parse_scene_file(a.scene);
  if (!a.scene.empty()) files.input("the scene file", a.scene);
  files.scene_inputs(parsed);
  const BuiltScene scene = build_scene(parsed, cli::shading_options(a.shading));
  const SimTop top = sim_top(a, scene.shading);
  files.input("the top's configuration", top.build.config);
  files.output_folder("--out", a.out);

  // The scene against what the top was built for: its screen and its configuration.
  const std::string name = a.scene.empty() ? std::string("the default scene") : a.scene;
  const std::string config_name = relative_to_source(top.build.config);
  const std::string built = "the " + a.board + " board top (built for " + config_name + ")";
  const int doubling = top.build.doubling;
  const int want_w = board::HVisible / doubling, want_h = board::VVisible / doubling;
  if (scene.width != want_w || scene.height != want_h)
    throw std::runtime_error(name + ": screen " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                             ": " + built + " shows " + std::to_string(want_w) + "x" + std::to_string(want_h) +
                             (doubling > 1 ? " doubled" : ""));
  const Config cfg = load_config(top.build.config);
  const Config needs = with_scene_edge_order(scene, cfg);
  if (needs.eq2 != cfg.eq2)
    throw std::runtime_error(name + ": interpolation eq2: " + built + " has no eq. (2) divider");
  if (needs.edge_order != cfg.edge_order)
    throw std::runtime_error(name + ": curved edges (edge order " + std::to_string(needs.edge_order) + "): " + built +
                             " steps edge order " + std::to_string(cfg.edge_order));
  PreparedScene prepared;
  board::BankImage bank;
  try {
    prepared = prepare(scene, cfg);
    bank = board::bank_image(prepared, cfg);
  } catch (const std::exception& e) {
    std::string what = e.what();  // the scene's messages name their file: once is enough
    if (!a.scene.empty() && what.rfind(a.scene + ": ", 0) == 0) what = what.substr(a.scene.size() + 2);
    throw std::runtime_error(name + ": does not fit " + built + ": " + what);
  }
  if (bank.words.size() > static_cast<std::size_t>(top.build.bank_words))
    throw std::runtime_error(name + ": the frame needs " + std::to_string(bank.words.size()) + " bank words (" +
                             std::to_string(bank.edges) + " edge records), more than " + built + "'s BankWords " +
                             std::to_string(top.build.bank_words));

  // The model's image as the board shows it: doubled; on the iCEBreaker's 12-bit Pmod each 8-bit
  // level's top four bits.
  const Image model = WatkinsTop(cfg).render(prepared);
  const Image want = tb::doubled(top.icebreaker ? board::pmod_levels(model) : model, doubling);

  const board::BoardTiming timing = board::board_timing(top.icebreaker ? board::Board::Icebreaker : board::Board::Ulx3s);
  const double pixel_mhz = timing.ticks_per_us / timing.ticks_per_pixel;
  const double pipe_mhz = timing.ticks_per_us / timing.ticks_per_pipe;
  std::printf("scene         %s  %dx%d  shading %s, %zu polygons, %zu edge records\n", scene.name.c_str(), scene.width,
              scene.height, to_string(scene.shading), scene.polygons.size(), prepared.edges.size());
  if (top.icebreaker)
    std::printf("board         icebreaker: Verilated %s at %s, doubling %d, one clock (%.3f MHz)\n", top.label.c_str(),
                config_name.c_str(), doubling, pixel_mhz);
  else
    std::printf("board         ulx3s: Verilated %s at %s, doubling %d, clk_pixel %.2f MHz, clk_pipe %.2f MHz\n",
                top.label.c_str(), config_name.c_str(), doubling, pixel_mhz, pipe_mhz);
  std::printf("bank          %zu words of %d bits in %d (%s)\n", bank.words.size(), bank.word_bits,
              top.build.bank_words, top.icebreaker ? "copied from the SPI flash model" : "bank 0, +watkins_bank");
  std::printf("display       none: the frames are PNG files in %s\n", a.out.c_str());
  std::fflush(stdout);

  FrameTally tally;
  long long last_pixel = 0, last_pipe = 0;
  double last_wall = 0;
  const long long lines_per_frame = prepared.height;
  std::size_t missed_seen = 0;
  std::vector<long long> missed_of(static_cast<std::size_t>(a.frames) + 1, 0);
  auto on_frame = [&](tb::BoardRun& r) {
    const int video = static_cast<int>(r.frames.size()) - 1;  // video frame v shows rendered frame v - 1
    for (; missed_seen < r.missed.size(); ++missed_seen) {
      const long long f = r.missed[missed_seen].line / lines_per_frame;
      if (f >= 0 && f < static_cast<long long>(missed_of.size())) ++missed_of[static_cast<std::size_t>(f)];
    }
    const long long pixel = r.pixel_clocks - last_pixel, pipe = r.pipe_clocks - last_pipe;
    const double wall = r.wall_seconds - last_wall;
    last_pixel = r.pixel_clocks, last_pipe = r.pipe_clocks, last_wall = r.wall_seconds;
    Image& shown = r.frames.back();
    if (video == 0) {
      std::printf("reset         to the end of the first video frame (no rendered frame shown yet): %lld %s, %.2f s\n",
                  r.pixel_clocks, top.icebreaker ? "clocks" : "pixel clocks", wall);
    } else {
      const int f = video - 1;
      const bool equal = shown.rgb == want.rgb;
      const long long missed = missed_of[static_cast<std::size_t>(f)];
      tally.missed += missed;
      tally.equal += equal;
      ++tally.frames;
      char file[32];
      std::snprintf(file, sizeof file, "frame_%03d.png", f);
      files.add_in(a.out, file, encode_png(shown));
      files.commit();
      char clocks[96];
      if (top.icebreaker)
        std::snprintf(clocks, sizeof clocks, "%lld clocks", pixel);
      else
        std::snprintf(clocks, sizeof clocks, "%lld pixel clocks (%lld pipeline clocks)", pixel, pipe);
      char rate[96];
      if (top.icebreaker)
        std::snprintf(rate, sizeof rate, "%.0f clocks/s", wall > 0 ? pixel / wall : 0.0);
      else
        std::snprintf(rate, sizeof rate, "%.0f pipeline clocks/s", wall > 0 ? pipe / wall : 0.0);
      std::printf("frame %-7d %lld missed lines, %s the model's image; %s in %.2f s: %.2f frames/s, %s; %s\n", f,
                  missed, equal ? "equals" : "differs from", clocks, wall, wall > 0 ? 1.0 / wall : 0.0, rate,
                  (std::filesystem::path(a.out) / file).string().c_str());
    }
    std::fflush(stdout);
    // Written and counted: a long run keeps no frame's pixels and no records.
    shown = Image();
    r.missed.clear();
    missed_seen = 0;
    r.lines.clear();
    r.start_clocks.clear();
    r.begin_clocks.clear();
    r.request_pixel_clocks.clear();
    r.begin_banks.clear();
  };

  tb::BoardRun run;
  if (top.icebreaker) {
    tb::IcebreakerBench bench(top.ice);
    tb::IcebreakerOptions opt;
    opt.flash = board::flash_image(board::bank_image(prepared, cfg, top.build.bank_words), top.build.bank_words);
    opt.video_frames = a.frames + 1;
    opt.record_video = false;
    opt.on_frame = on_frame;
    run = bench.run(opt).run;
  } else {
    // Bank 0 from the scene's bank image, through +watkins_bank (a temporary file, removed after).
    namespace fs = std::filesystem;
    const fs::path bank_file = fs::temp_directory_path() / ("watkins-board-sim-" + std::to_string(::getpid()) + ".hex");
    struct Remove {
      fs::path p;
      ~Remove() {
        std::error_code ec;
        fs::remove(p, ec);
      }
    } remove{bank_file};
    board::write_readmemh_file(bank_file.string(), board::bank_image(prepared, cfg, top.build.bank_words));
    tb::BoardBench bench(top.ulx3s);
    tb::BoardOptions opt;
    opt.bank_file = bank_file.string();
    opt.video_frames = a.frames + 1;
    opt.tmds_clock = false;  // the serializers: what the encoders take is the frame
    opt.record_video = false;
    opt.on_frame = on_frame;
    run = bench.run(opt);
  }
  const double fps = run.wall_seconds > 0 ? (a.frames + 1) / run.wall_seconds : 0.0;
  std::printf("total         %d frames: %lld missed lines, %d equal the model's image; %lld evals in %.2f s "
              "(%.2f video frames/s, %.0f evals/s)\n",
              tally.frames, tally.missed, tally.equal, run.evals, run.wall_seconds, fps,
              run.wall_seconds > 0 ? run.evals / run.wall_seconds : 0.0);
  if (tally.missed > 0) return MissedExit;
  return tally.equal == tally.frames ? 0 : SimMismatchExit;
}

#endif

}  // namespace watkins::board_command
