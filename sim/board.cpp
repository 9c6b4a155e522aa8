#include "board.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "beam_schedule.hpp"
#include "board_build.hpp"
#include "board_image.hpp"
#include "cycle_model.hpp"
#include "flash_image.hpp"
#include "fpga_flow.hpp"
#include "config_file.hpp"
#include "options.hpp"
#include "prepare.hpp"
#include "run_files.hpp"
#include "scene.hpp"
#include "scene_types.hpp"
#include "size.hpp"
#include "usage_error.hpp"
#include "watkins_top.hpp"

namespace watkins::board_command {
namespace {

board::Board board_of(const std::string& name) {
  return name == "icebreaker" ? board::Board::Icebreaker : board::Board::Ulx3s;
}

std::string line_name(const board::LineSlack& l) {
  return "frame " + std::to_string(l.frame) + " line " + std::to_string(l.y);
}

// The board's clocks and line slots for `a` at `doubling`.
board::BoardTiming timing_of(const CheckArgs& a, int doubling) {
  board::BoardTiming t = board::board_timing(board_of(a.board));
  t.doubling = doubling;
  t.line_slots = a.slots;
  return t;
}

// A scene on the board: parsed, its size checked against the video mode, its configuration
// (sized, or the --config file) and its prepared frame. The inputs are declared in `files`.
struct BoardScene {
  BuiltScene scene;
  std::string name;  // for messages
  std::string stem;  // for default output names
  int doubling = 2;
  Config cfg;
  PreparedScene prepared;
};

BoardScene load_board_scene(const CheckArgs& a, RunFiles& files) {
  const Scene parsed = parse_scene_file(a.scene);
  if (!a.scene.empty()) files.input("the scene file", a.scene);
  files.scene_inputs(parsed);
  files.input("the --config file", a.config);
  BoardScene b;
  b.scene = build_scene(parsed, cli::shading_options(a.shading));
  const BuiltScene& scene = b.scene;
  b.name = a.scene.empty() ? std::string("the default scene") : a.scene;
  b.stem = a.scene.empty() ? std::string("default") : std::filesystem::path(a.scene).stem().string();
  // The board shows 640 x 480: the frame is that, or half of it doubled.
  int doubling = a.doubling;
  if (doubling == 0) doubling = scene.width == board::HVisible / 2 ? 2 : 1;
  const int want_w = board::HVisible / doubling, want_h = board::VVisible / doubling;
  const std::string shows = "the board shows 640x480 (--doubling 1) or 320x240 (--doubling 2)";
  if (scene.width != want_w)
    throw std::runtime_error(b.name + ": screen.width " + std::to_string(scene.width) + ": " + shows +
                             (a.doubling ? "; --doubling " + std::to_string(doubling) + " needs " + std::to_string(want_w)
                                         : std::string()));
  if (scene.height != want_h)
    throw std::runtime_error(b.name + ": screen.height " + std::to_string(scene.height) + ": " + shows +
                             (a.doubling ? "; --doubling " + std::to_string(doubling) + " needs " + std::to_string(want_h)
                                         : std::string()));
  b.doubling = doubling;
  // The UP5K holds the compact micro-architecture only (docs/reference/compact.md): the scene is
  // sized for the compact top there (`watkins size --compact`: a Phong frame at the compact
  // blocks' narrow formats), and wherever --top compact asks for it; a --config file says for
  // itself.
  const bool compact = a.top.empty() ? board_of(a.board) == board::Board::Icebreaker : a.top == "compact";
  b.cfg = a.config.empty() ? size::sized_config(scene, 1, compact) : load_config(a.config);
  if (!a.top.empty()) b.cfg.compact = compact;
  if (!b.cfg.compact && b.cfg.phong == PhongFormat::Narrow)
    throw std::runtime_error(b.name + ": the configuration's narrow Phong formats (phong.formats) are the compact "
                             "top's; --top compact draws them");
  if (b.cfg.compact && (b.cfg.smoothing || b.cfg.eq2))
    throw std::runtime_error(b.name + ": the compact top has no " +
                             std::string(b.cfg.smoothing ? "smoother" : "eq. (2) divider") +
                             " (the configuration's " + (b.cfg.smoothing ? "smoothing" : "eq2") +
                             "); --top pipelined draws it");
  if (!b.cfg.compact) b.cfg.lanes = 1;  // the pipelined top takes one fragment a clock
  b.prepared = prepare(scene, b.cfg);
  // The deadline is proven by the top's cycle model; a Phong frame it does not time (a given
  // configuration with two fragment lanes, which the compact Phong blocks do not take) is refused
  // before any bank or bitstream is made.
  if (b.cfg.compact && scene.shading == ShadingMode::Phong) {
    try {
      CycleOptions opt;
      opt.max_active_edges = b.cfg.max_active_edges;
      (void)predict_cycles(b.prepared, b.cfg, opt);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(b.name + ": shading phong on the " + a.board +
                               " board's compact top: no line deadline can be proven (" + e.what() +
                               "); the ulx3s board's pipelined top draws Phong");
    }
  }
  // A sized compact configuration gets the fewest fragment lanes whose lines all meet the
  // deadline: two only where one misses and two miss fewer (the values are the same). The
  // compact Phong blocks shade one fragment a beat, so a Phong frame keeps one lane.
  if (a.config.empty() && b.cfg.compact && b.cfg.lanes == 1 && scene.shading == ShadingMode::Gouraud) {
    const board::BoardTiming t = timing_of(a, doubling);
    const long long one = board::beam_schedule(b.prepared, b.cfg, t).missed;
    if (one > 0) {
      Config two = b.cfg;
      two.lanes = 2;
      if (board::beam_schedule(b.prepared, two, t).missed < one) b.cfg = b.prepared.config = two;
    }
  }
  return b;
}

// Runs the beam schedule of `b` and prints it; the number of missed lines.
long long report_schedule(const CheckArgs& a, const BoardScene& b) {
  const auto t0 = std::chrono::steady_clock::now();
  const BuiltScene& scene = b.scene;
  const Config& cfg = b.cfg;
  const PreparedScene& prepared = b.prepared;
  const int doubling = b.doubling;
  const board::BoardTiming t = timing_of(a, doubling);
  const board::BeamSchedule s = board::beam_schedule(prepared, cfg, t);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::printf("scene         %s  %dx%d  shading %s, %zu polygons, %zu edge records\n", scene.name.c_str(), scene.width,
              scene.height, to_string(scene.shading), scene.polygons.size(), prepared.edges.size());
  const auto mhz = [&t](int ticks) { return t.ticks_per_us / ticks; };
  if (board_of(a.board) == board::Board::Icebreaker) {
    std::printf("board         %s: one clock, %.3f MHz (pixel clock and pipeline clock); doubling %d, %d line slots\n",
                a.board.c_str(), mhz(t.ticks_per_pixel), doubling, a.slots);
  } else {
    const int g = std::gcd(t.ticks_per_pixel, t.ticks_per_pipe);
    std::printf("board         %s: clk_pixel %.2f MHz, clk_pipe %.2f MHz (%d/%d of clk_pixel), clk_tmds %.0f MHz; "
                "doubling %d, %d line slots\n",
                a.board.c_str(), mhz(t.ticks_per_pixel), mhz(t.ticks_per_pipe), t.ticks_per_pixel / g,
                t.ticks_per_pipe / g, mhz(t.ticks_per_pixel) * 5, doubling, a.slots);
  }
  std::printf("config        %s: %s top%s, edge record %d bits, max_active_edges %d, %s%s\n",
              a.config.empty() ? "sized (watkins size, bound 1 level)" : a.config.c_str(),
              cfg.compact ? "compact" : "pipelined", cfg.lanes == 2 ? " (2 fragment lanes)" : "",
              cfg.edge_record_bits(scene.shading), cfg.max_active_edges,
              cfg.smoothing ? "smoother" : "no smoother",
              scene.shading != ShadingMode::Phong   ? ""
              : cfg.phong == PhongFormat::Narrow ? ", narrow Phong formats"
                                                 : ", the model's Phong formats");
  std::printf("budget        %.0f pipeline clocks per rendered line (%d video line%s of %d pixel clocks)\n",
              s.budget_per_line(), doubling, doubling > 1 ? "s" : "", board::HTotal);
  const board::FrameRun& f0 = s.frames.front();
  std::printf("first frame   %lld cycles, first edge beat to last pixel (start pulse to first beat %d); %zu frames "
              "simulated, %.2f s\n",
              f0.cycles(), s.timing.start_to_first_beat, s.frames.size(), seconds);
  // The pipeline alone, every pixel taken as it comes: the frame's own cost, apart from the beam.
  std::vector<long long> takes;
  CycleOptions alone_opt;
  alone_opt.max_active_edges = cfg.max_active_edges;
  alone_opt.take_cycles = &takes;
  const CyclePrediction alone = predict_cycles(prepared, cfg, alone_opt);
  WatkinsTop pipe(cfg);
  pipe.render(prepared);
  const long long fragments = pipe.stats().fragments;
  long long slowest = 0, before = -1;
  int slowest_y = 0;
  const std::size_t width = static_cast<std::size_t>(prepared.width);
  for (int y = 0; y < prepared.height && takes.size() >= (y + 1) * width; ++y) {
    const long long end = takes[(y + 1) * width - 1];  // the line's last pixel taken
    if (end - before > slowest) slowest = end - before, slowest_y = y;
    before = end;
  }
  std::printf("alone         %lld cycles a frame, %lld fragments (%.3f per clock), slowest line %d: %lld clocks "
              "(edge records back to back, every pixel taken as it comes)\n",
              alone.cycles, fragments, alone.cycles ? double(fragments) / double(alone.cycles) : 0.0, slowest_y,
              slowest);
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
  return s.missed;
}

int run_check(const CheckArgs& a) {
  RunFiles files;  // no output: the inputs are named for the messages
  const BoardScene b = load_board_scene(a, files);
  return report_schedule(a, b) == 0 ? 0 : MissedExit;
}

// The smallest power of two that holds `words`: at least 512 on the ULX3S (one block RAM deep);
// at least 16 on the iCEBreaker, whose bank is in the SPRAMs and copied from the flash after
// configuration, 128 clocks a SPRAM word (flash_image.hpp): a small bank starts the video sooner.
int bank_words_for(int words, const std::string& board) {
  int n = board_of(board) == board::Board::Icebreaker ? 16 : 512;
  while (n < words) n *= 2;
  return n;
}

int run_image(const ImageArgs& a) {
  RunFiles files;
  const BoardScene b = load_board_scene(a.target, files);
  const std::string out = a.out.empty() ? b.stem + ".bank.hex" : a.out;
  files.output(a.out.empty() ? "the default output (--out)" : "--out", out);
  const board::BankImage bank = board::bank_image(b.prepared, b.cfg, a.bank_words);
  std::ostringstream hex;
  board::write_readmemh(hex, bank);
  const std::string text = hex.str();
  files.add(out, std::vector<unsigned char>(text.begin(), text.end()));
  files.commit();
  std::printf("%s: %zu words of %d bits (%d edge records, %d materials); BankWords %d\n", out.c_str(), bank.words.size(),
              bank.word_bits, bank.edges, bank.materials,
              a.bank_words ? a.bank_words : bank_words_for(static_cast<int>(bank.words.size()), a.target.board));
  return 0;
}

int run_build(const BuildArgs& a) {
  namespace fs = std::filesystem;
  const auto t0 = std::chrono::steady_clock::now();
  RunFiles files;
  const BoardScene b = load_board_scene(a.target, files);
  const std::string rtl = fs::absolute(a.rtl_dir.empty() ? std::string(WATKINS_SOURCE_DIR) + "/rtl" : a.rtl_dir).string();
  if (!fs::is_directory(fs::path(rtl) / "board"))
    throw std::runtime_error("--rtl-dir " + rtl + ": no board/ folder (the board top's sources)");
  for (const auto& dir : {fs::path(rtl), fs::path(rtl) / "board"})
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file()) files.input("the RTL file " + e.path().string(), e.path().string());
  const bool ice40 = board_of(a.target.board) == board::Board::Icebreaker;
  const std::string out = a.out.empty() ? b.stem + "." + a.target.board + (ice40 ? ".bin" : ".bit") : a.out;
  files.output(a.out.empty() ? "the default output (--out)" : "--out", out);
  if (!a.md.empty()) files.output("--md", a.md);
  if (fs::exists(a.work) && fs::equivalent(a.work, rtl))
    throw UsageError("--work " + a.work + " is the RTL folder; refusing to write into it");
  for (const char* tool : {"yosys", ice40 ? "icepack" : "yowasp-ecppack"})
    if (!flow::on_path(tool)) throw std::runtime_error(std::string(tool) + " not found on PATH (scripts/setup installs it)");
  const flow::Target& part = *flow::find_target(ice40 ? "ice40-up5k" : "ecp5-85");
  if (!flow::on_path(flow::nextpnr_binary(part)))
    throw std::runtime_error(flow::nextpnr_binary(part) + " not found on PATH (scripts/setup installs it)");

  // The deadline first: a scene that misses a line is refused before minutes of place and route.
  if (const long long missed = report_schedule(a.target, b); missed > 0) {
    std::fprintf(stderr, "watkins: error: %s misses %lld line deadline%s on the board (above); no bitstream built\n",
                 b.name.c_str(), missed, missed > 1 ? "s" : "");
    return MissedExit;
  }

  BitstreamJob job;
  job.board = a.target.board;
  job.config = b.cfg;
  job.shading = b.scene.shading;
  job.doubling = b.doubling;
  job.line_slots = a.target.slots;
  job.work = fs::absolute(a.work).string();
  job.rtl_dir = rtl;
  job.seed = a.seed;
  job.timeout_s = a.timeout;
  fs::create_directories(job.work);
  const board::BankImage bank = board::bank_image(b.prepared, b.cfg);
  job.bank_words = bank_words_for(static_cast<int>(bank.words.size()), a.target.board);
  job.bank_file = (fs::path(job.work) / "bank0.hex").string();
  board::write_readmemh_file(job.bank_file, bank);
  if (ice40) job.flash_scene = board::flash_image(bank, job.bank_words);
  std::printf("bank          %zu words of %d bits in %d (%s)\n", bank.words.size(), bank.word_bits, job.bank_words,
              job.bank_file.c_str());
  std::fflush(stdout);

  const BitstreamResult r = build_bitstream(job);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::ostringstream md;
  md << "`watkins board build` of " << b.name << " for the " << a.target.board << ": " << r.result << " ("
     << static_cast<long>(seconds) << " s).\n\n";
  // The resources also when the design does not fit: what is over.
  if (r.nextpnr.routed || !r.nextpnr.utilisation.empty()) md << bitstream_report(job, r);
  std::printf("\n%s", md.str().c_str());
  if (!r.ok) {
    std::fprintf(stderr, "watkins: error: %s: %s (logs in %s)\n", b.name.c_str(), r.result.c_str(), job.work.c_str());
    return 1;
  }
  std::ifstream bit(r.bit, std::ios::binary);
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(bit)), std::istreambuf_iterator<char>());
  if (bytes.empty()) throw std::runtime_error(r.bit + ": the bitstream is empty");
  files.add(out, std::move(bytes));
  if (!a.md.empty()) {
    const std::string text = md.str();
    files.add(a.md, std::vector<unsigned char>(text.begin(), text.end()));
  }
  files.commit();
  std::printf("bitstream     %s\n", out.c_str());
  return 0;
}

}  // namespace

CLI::App* add_board_command(CLI::App& app, BoardArgs& a) {
  auto* b = app.add_subcommand("board", "the pipeline on an FPGA board, racing the beam (docs/reference/board.md)");
  b->require_subcommand(1);
  a.board_app = b;
  // The scene and board options every subcommand shares.
  auto target_options = [](CLI::App* sub, CheckArgs& t) {
    cli::add_file(sub, "scene", t.scene, "scene file (JSON), 640x480 or 320x240; default: the embedded default scene");
    sub->add_option("--board", t.board, "the board")->check(CLI::IsMember({"ulx3s", "icebreaker"}))->capture_default_str();
    sub->add_option("--doubling", t.doubling, "1: 640x480 native; 2: 320x240 shown doubled (default: from the scene's size)")
        ->check(cli::integer_in(1, 2));
    sub->add_option("--slots", t.slots, "line-buffer slots, a power of two")
        ->check(cli::integer_in(1, 1024))
        ->capture_default_str();
    cli::add_file(sub, "--config", t.config, "hardware configuration (JSON) instead of sizing the scene");
    sub->add_option("--top", t.top, "the micro-architecture: compact or pipelined (default: the board's, icebreaker "
                                    "compact and ulx3s pipelined; with --config, its \"compact\")")
        ->check(CLI::IsMember({"compact", "pipelined"}));
    cli::add_shading(sub, t.shading, "gouraud or phong: the pipeline sized, timed and built (default: the scene's "
                                     "shading.mode)");
  };
  CheckArgs& c = a.check;
  auto* check = b->add_subcommand("check", "each rendered line's completion against the moment the video shows it "
                                           "(exit 4 when a line misses)");
  target_options(check, c);
  a.check_app = check;

  auto* image = b->add_subcommand("image", "the scene bank's $readmemh file (bank 0 of the board top)");
  target_options(image, a.image.target);
  cli::add_file(image, "--out,-o", a.image.out, "the file to write (default: <scene>.bank.hex)");
  image->add_option("--bank-words", a.image.bank_words, "refuse a frame of more words than this (0: no limit)")
      ->check(cli::integer_in(0, 1 << 20))
      ->capture_default_str();
  a.image_app = image;

  auto* build = b->add_subcommand("build", "the bitstream: size, check the deadline, the bank image, yosys, nextpnr, "
                                           "ecppack (ulx3s: .bit) or icepack (icebreaker: .bin); prints resources and "
                                           "every clock's Fmax (exit 4 when a line misses)");
  target_options(build, a.build.target);
  cli::add_file(build, "--out,-o", a.build.out, "the bitstream to write (default: <scene>.<board>.bit, or .bin "
                                                  "for the icebreaker)");
  cli::add_file(build, "--work", a.build.work, "folder for yosys's and nextpnr's scripts, netlist, logs and reports")
      ->capture_default_str();
  cli::add_file(build, "--md", a.build.md, "the report as markdown");
  cli::add_file(build, "--rtl-dir", a.build.rtl_dir, "the RTL (default: the source tree's rtl/)");
  build->add_option("--seed", a.build.seed, "nextpnr's placement seed (0: nextpnr's default)")
      ->check(cli::integer_in(0, 1 << 30))
      ->capture_default_str();
  build->add_option("--timeout", a.build.timeout, "seconds per tool run")
      ->check(cli::integer_in(1, 86400))
      ->capture_default_str();
  a.build_app = build;
  a.stream_app = add_stream_command(b, a.stream);
  a.sim_app = add_sim_command(b, a.sim);
  return b;
}

void check_board(const BoardArgs& a) {
  for (const auto& [app, t] : {std::pair<CLI::App*, const CheckArgs*>{a.check_app, &a.check},
                               {a.image_app, &a.image.target}, {a.build_app, &a.build.target}})
    if (app && *app && (t->slots & (t->slots - 1)) != 0)
      throw UsageError("--slots: " + std::to_string(t->slots) + " is not a power of two");
}

int run_board(const BoardArgs& a) {
  if (a.check_app && *a.check_app) return run_check(a.check);
  if (a.image_app && *a.image_app) return run_image(a.image);
  if (a.build_app && *a.build_app) return run_build(a.build);
  if (a.stream_app && *a.stream_app) return run_stream(a.stream);
  if (a.sim_app && *a.sim_app) return run_sim(a.sim);
  return 0;
}

}  // namespace watkins::board_command
