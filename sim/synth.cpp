// watkins synth: each design (a block of rtl/ or a top) at a configuration goes through yosys and
// nextpnr for each target inside a generated wrapper; the table gives what yosys mapped (LUT4, FF,
// carry, DSP, block RAM), what nextpnr placed (logic cells against the device), the routed Fmax and
// the critical path's start and end registers.
//
// The wrapper needs four pins (clk, si, so and nothing else) on every target, so the same
// netlist is measured on every part, a 466-bit edge record fits a 48-pin UP5K package, and every
// path through the design starts and ends at a register:
//   inputs   one shift register loaded through si; its bits drive every input port (reset too);
//   outputs  captured every clock into a register that folds them into a serial signature,
//            out_q[i] <= out_d[i] ^ out_q[i-1], read at so: every output bit reaches a pin, so
//            yosys removes nothing, and the fold is one 2-input LUT per bit with no wide fanout
//            (a load/shift select would be a net of ~500 loads, itself a critical path).
// The wrapper adds one flip-flop per input and output bit (column "wrapper FF") and up to one
// LUT per output bit.
//
// Parameters: a top gets exactly rtl_parameters(config, shading) (what `watkins_gen_pkg --params`
// prints), the compact tops (top-compact, Gouraud; top-compact-phong, Phong at one lane) those of
// the configuration with compact true, smoothing and eq2 false (a compact top has neither the
// smoother nor the divider); a block
// gets what that top gives it (read from the elaborated top, so the widths are derived in one
// place, rtl/watkins_top.sv): the Gouraud top's instance, except normalizer and phong_shader,
// which exist in the Phong top only. A parameter the top does not declare is listed
// in the table's notes: that design was synthesized at its default for it.
//
// Seeds (--seeds): nextpnr's placement is seeded, and runs of nearly the same netlist differ by
// several MHz from one seed to another. With --seeds, yosys runs once per (configuration, design,
// target) and nextpnr once per seed (`--seed N`, in the job folder's seed-N/), so a figure comes
// with its spread over seeds and a best run that can be reproduced.
#include "synth.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <deque>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "config.hpp"
#include "config_file.hpp"
#include "options.hpp"
#include "fpga_flow.hpp"
#include "run_files.hpp"
#include "usage_error.hpp"

namespace watkins::synth {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using flow::Family;
using flow::ProcessResult;
using flow::Target;
using flow::nextpnr_binary;
using flow::on_path;
using flow::read_text;
using flow::run_process;
using flow::tool_version;
using flow::write_text;

// ---------------------------------------------------------------------------------------------
// What is synthesized and where.

struct Design {
  const char* name;    // --designs name and table row
  const char* module;  // RTL module
  ShadingMode shading; // which parameter set of the configuration it gets
  bool top;
  // The block of watkins_top whose parameters it takes (nullptr: its own module's). A compact
  // block is measured at the parameters its pipelined counterpart has in the top.
  const char* params_of = nullptr;
  // The top as the compact micro-architecture builds it: the configuration with compact true and
  // smoothing and eq2 false (what the compact top supports).
  bool compact = false;
};
// Blocks first, tops last: the tops take minutes per target, the blocks seconds.
const Design kDesigns[] = {
    {"edge_incrementer", "edge_incrementer", ShadingMode::Gouraud, false},
    {"active_edge_list", "active_edge_list", ShadingMode::Gouraud, false},
    {"segment_former", "segment_former", ShadingMode::Gouraud, false},
    {"span_reciprocal", "span_reciprocal", ShadingMode::Gouraud, false},
    {"segment_interpolator", "segment_interpolator", ShadingMode::Gouraud, false},
    {"normalizer", "normalizer", ShadingMode::Phong, false},
    {"phong_shader", "phong_shader", ShadingMode::Phong, false},
    {"scanline_buffer", "scanline_buffer", ShadingMode::Gouraud, false},
    {"smoother", "smoother", ShadingMode::Gouraud, false},
    // The compact micro-architecture's blocks (docs/reference/compact.md).
    {"compact_active_edge_list", "compact_active_edge_list", ShadingMode::Gouraud, false, "active_edge_list"},
    {"compact_segment_former", "compact_segment_former", ShadingMode::Gouraud, false, "segment_former"},
    {"compact_segment_interpolator", "compact_segment_interpolator", ShadingMode::Gouraud, false,
     "segment_interpolator"},
    {"compact_scanline_buffer", "compact_scanline_buffer", ShadingMode::Gouraud, false, "scanline_buffer"},
    {"compact_normalizer", "compact_normalizer", ShadingMode::Phong, false, "normalizer"},
    {"compact_phong_shader", "compact_phong_shader", ShadingMode::Phong, false, "phong_shader"},
    // The compact Phong blocks at the narrow formats (docs/reference/compact-phong.md).
    {"compact_normalizer_narrow", "compact_normalizer_narrow", ShadingMode::Phong, false, "normalizer"},
    {"compact_phong_shader_narrow", "compact_phong_shader_narrow", ShadingMode::Phong, false, "phong_shader"},
    {"top-gouraud", "watkins_top", ShadingMode::Gouraud, true},
    {"top-phong", "watkins_top", ShadingMode::Phong, true},
    {"top-compact", "watkins_top", ShadingMode::Gouraud, true, nullptr, true},
    {"top-compact-phong", "watkins_top", ShadingMode::Phong, true, nullptr, true},
};

// ---------------------------------------------------------------------------------------------
// The RTL as yosys sees it: a module's declared parameters and its ports at a parameter set.

struct Rtl {
  fs::path dir;
  std::vector<std::string> files;  // package first (every module imports it)
};

Rtl find_rtl(const std::string& dir) {
  Rtl r;
  r.dir = fs::absolute(dir);
  if (!fs::is_directory(r.dir)) throw std::runtime_error("--rtl-dir: no directory " + r.dir.string());
  const fs::path pkg = r.dir / "watkins_pkg.sv";
  if (!fs::exists(pkg)) throw std::runtime_error("--rtl-dir: no watkins_pkg.sv in " + r.dir.string());
  std::vector<std::string> rest;
  for (const auto& e : fs::directory_iterator(r.dir))
    if (e.path().extension() == ".sv" && e.path() != pkg) rest.push_back(e.path().string());
  std::sort(rest.begin(), rest.end());
  r.files.push_back(pkg.string());
  r.files.insert(r.files.end(), rest.begin(), rest.end());
  return r;
}

// -defer keeps each module as a syntax tree until something derives it (elaboration of one module).
// defines: " -DNAME" options (the target's, see synthesize).
std::string read_rtl_command(const Rtl& rtl, bool defer = false, const std::string& defines = "") {
  std::string s = std::string("read_verilog -sv") + (defer ? " -defer" : "") + defines + " -I" + rtl.dir.string();
  for (const std::string& f : rtl.files) s += " " + f;
  return s;
}

struct Port {
  std::string name;
  bool input = true;
  int bits = 1;
};

struct Elaborated {
  std::vector<std::pair<std::string, int>> params;  // set on the module (declared by it)
  std::vector<std::string> ignored;                 // the configuration's, not declared by it
  std::vector<Port> ports;
};

// `chparam` derives only the module asked for (read with -defer, nothing below it is
// elaborated), so this takes a fraction of a second even for the top.
json module_json(const Rtl& rtl, const std::string& module, const std::vector<std::pair<std::string, int>>& params,
                 const fs::path& dir, const std::string& tag, int timeout_s) {
  std::string chparam = "chparam";
  for (const auto& [n, v] : params) chparam += " -set " + n + " " + std::to_string(v);
  const std::string out = tag + ".json";
  const std::string script = read_rtl_command(rtl, true) + "; " + chparam + " " + module + "; cd $abstract\\" +
                             module + "; proc; cd; write_json " + out;
  const fs::path log = dir / (tag + ".log");
  const ProcessResult r = run_process({"yosys", "-q", "-p", script}, dir, log, timeout_s);
  if (r.status != 0) {
    std::string first_error;
    std::stringstream l(read_text(log));
    for (std::string line; std::getline(l, line);)
      if (line.find("ERROR") != std::string::npos) { first_error = line; break; }
    throw std::runtime_error("yosys could not elaborate " + module + ": " + first_error + " (" + log.string() + ")");
  }
  const json j = json::parse(read_text(dir / out));
  const std::string key = std::string("$abstract\\") + module;
  if (!j["modules"].contains(key)) throw std::runtime_error("yosys: no module " + module + " in the RTL");
  return j["modules"][key];
}

using Parameters = std::vector<std::pair<std::string, int>>;

Elaborated elaborate(const Rtl& rtl, const Design& d, const Parameters& wanted, const fs::path& dir, int timeout_s) {
  Elaborated e;
  const json defaults = module_json(rtl, d.module, {}, dir, "params", timeout_s);
  const json declared = defaults.value("parameter_default_values", json::object());
  for (const auto& [name, value] : wanted) {
    if (declared.contains(name)) e.params.emplace_back(name, value);
    else e.ignored.push_back(name);
  }
  const json m = e.params.empty() ? defaults : module_json(rtl, d.module, e.params, dir, "ports", timeout_s);
  for (const auto& [name, port] : m["ports"].items()) {
    Port p;
    p.name = name;
    p.input = port["direction"] == "input";
    p.bits = static_cast<int>(port["bits"].size());
    if (port["direction"] == "inout") throw std::runtime_error(std::string(d.module) + ": inout port " + name);
    e.ports.push_back(p);
  }
  return e;
}

// What watkins_top at `top` gives each block it instantiates: after `hierarchy` every derived
// module carries its parameter values, so a block is measured as it sits in that top (its
// payload widths included) and this file repeats none of the top's width arithmetic. One
// elaboration of the whole top: about 20 s. Module name -> parameters (the first instance's
// when a module is instantiated with several sets).
std::map<std::string, Parameters> block_parameters(const Rtl& rtl, const Parameters& top, const fs::path& dir,
                                                   int timeout_s) {
  std::string script = read_rtl_command(rtl) + "; hierarchy -top watkins_top";
  for (const auto& [n, v] : top) script += " -chparam " + n + " " + std::to_string(v);
  // JSON refuses processes and memories; only the modules' names and parameters are wanted.
  script += "; delete p:* m:*; write_json top.json";
  const fs::path log = dir / "top.log";
  const ProcessResult r = run_process({"yosys", "-q", "-p", script}, dir, log, timeout_s);
  if (r.status != 0) throw std::runtime_error("yosys could not elaborate watkins_top: " + log.string());
  const json j = json::parse(read_text(dir / "top.json"));
  std::map<std::string, Parameters> blocks;
  for (const auto& [name, m] : j["modules"].items()) {
    // Derived names: "$paramod$<hash>\\<module>", or "$paramod\\<module>\\<Param>=<value>..." when short.
    std::string module = name;
    if (module.rfind("$paramod", 0) == 0) {
      module = module.substr(module.find('\\') + 1);
      module = module.substr(0, module.find('\\'));
    }
    if (module == "watkins_top" || blocks.count(module)) continue;
    Parameters& ps = blocks[module];
    const json values = m.value("parameter_default_values", json::object());
    for (const auto& [pn, pv] : values.items()) {
      // yosys writes a parameter as its bits, MSB first.
      const long long v = pv.is_string() ? std::stoll(pv.get<std::string>(), nullptr, 2) : pv.get<long long>();
      ps.emplace_back(pn, static_cast<int>(v));
    }
  }
  return blocks;
}

// ---------------------------------------------------------------------------------------------
// The wrapper (see the file comment).

const char* kWrapper = "watkins_synth_wrapper";

struct WrapperSize {
  int in_bits = 0, out_bits = 0;
};

WrapperSize write_wrapper(const Design& d, const Elaborated& e, const std::string& config_label,
                          const fs::path& file) {
  WrapperSize w;
  bool clock = false;
  for (const Port& p : e.ports) {
    if (p.name == "clk_i") clock = true;
    else (p.input ? w.in_bits : w.out_bits) += p.bits;
  }
  if (!clock) throw std::runtime_error(std::string(d.module) + " has no clk_i port");
  if (w.out_bits == 0) throw std::runtime_error(std::string(d.module) + " has no outputs");
  std::ostringstream v;
  v << "// Generated by `watkins synth` (sim/synth.cpp) for " << d.name << " at configuration " << config_label
    << ":\n// inputs from a shift register loaded through si, outputs folded into a registered serial\n"
       "// signature read at so, so every path is register to register and nothing is unobserved.\n"
    << "module " << kWrapper << " (\n  input wire clk,\n  input wire si,\n  output wire so\n);\n";
  if (w.in_bits > 0) {
    v << "  reg [" << w.in_bits - 1 << ":0] in_q;\n"
      << "  always @(posedge clk) in_q <= " << (w.in_bits == 1 ? "si" : "{in_q[" + std::to_string(w.in_bits - 2) + ":0], si}")
      << ";\n";
  }
  v << "  wire [" << w.out_bits - 1 << ":0] out_d;\n"
    << "  reg [" << w.out_bits - 1 << ":0] out_q;\n"
    << "  always @(posedge clk) out_q <= out_d ^ "
    << (w.out_bits == 1 ? "out_q" : "{out_q[" + std::to_string(w.out_bits - 2) + ":0], si}") << ";\n"
    << "  assign so = out_q[" << w.out_bits - 1 << "];\n";
  v << "  " << d.module;
  if (!e.params.empty()) {
    v << " #(";
    for (size_t i = 0; i < e.params.size(); ++i)
      v << (i ? ", " : "") << "." << e.params[i].first << "(" << e.params[i].second << ")";
    v << ")";
  }
  v << " dut (\n";
  int in = 0, out = 0;
  for (size_t i = 0; i < e.ports.size(); ++i) {
    const Port& p = e.ports[i];
    std::string conn;
    if (p.name == "clk_i") {
      conn = "clk";
    } else {
      int& at = p.input ? in : out;
      conn = std::string(p.input ? "in_q" : "out_d") + "[" + std::to_string(at + p.bits - 1) + ":" + std::to_string(at) + "]";
      at += p.bits;
    }
    v << "    ." << p.name << "(" << conn << ")" << (i + 1 < e.ports.size() ? "," : "") << "\n";
  }
  v << "  );\nendmodule\n";
  write_text(file, v.str());
  return w;
}

// ---------------------------------------------------------------------------------------------
// One run: yosys once per netlist, nextpnr once per seed, and what their reports say.

struct Row {
  std::string config, design, target;
  int seed = 0;        // nextpnr's --seed; 0: none given (nextpnr's default)
  std::string result;  // routed | does not fit | yosys timeout | ... | failed: <line>
  bool ok = false;     // a result (routed or does not fit), not a tool failure
  bool finished = false;
  std::string logic;   // nextpnr: logic cells used / available (percent)
  long lut4 = -1, ff = -1, carry = -1, dsp = -1, bram = -1, ram_other = -1;
  int wrapper_ff = 0;
  double fmax = 0, constraint = 0;
  std::string path_start, path_end;
  double path_ns = 0;
  double yosys_s = 0, nextpnr_s = 0;
  std::string dir;
};

// yosys: dir/wrapper.v and the RTL to dir/netlist.json, its cells counted in `row` (the part of a
// row every seed of this netlist shares). False when yosys failed; row.result says how.
// ECP5: WATKINS_ECP5 selects the multiplier blocks with their own product register (rtl/mul18_reg.sv
// instantiates MULT18X18D, which yosys 0.23 does not infer with registers); the library's
// blackboxes are read first so the wrapper's hierarchy check knows the cell.
bool synthesize(Row& row, const Rtl& rtl, const Target& t, const fs::path& dir, int timeout_s) {
  row.dir = dir.string();
  flow::SynthesisJob job;
  job.target = &t;
  job.dir = dir;
  if (t.family == Family::Ecp5) job.reads.push_back(flow::read_primitives(t));
  job.reads.push_back(read_rtl_command(rtl, false, t.family == Family::Ecp5 ? " -DWATKINS_ECP5" : ""));
  job.reads.push_back("read_verilog wrapper.v");
  job.top = kWrapper;
  job.timeout_s = timeout_s;
  const flow::SynthesisResult s = flow::synthesize(job);
  row.yosys_s = s.seconds;
  if (!s.ok) { row.result = s.result; return false; }
  row.lut4 = s.cells.lut4;
  row.ff = s.cells.ff;
  row.carry = s.cells.carry;
  row.dsp = s.cells.dsp;
  row.bram = s.cells.bram;
  row.ram_other = s.cells.ram_other;
  return true;
}

// nextpnr: places and routes `netlist` (synthesize's) with `seed` (0: no --seed), its report.json,
// nextpnr.log and nextpnr.out in `dir` (the netlist's folder, or a seed's folder beside it).
void place_and_route(Row& row, const Target& t, const std::vector<std::string>& placer, const fs::path& netlist,
                     const fs::path& dir, int seed, int timeout_s) {
  row.dir = dir.string();
  flow::PlaceJob job;
  job.target = &t;
  job.placer = placer;
  job.netlist = netlist;
  job.dir = dir;
  job.seed = seed;
  job.freq_mhz = t.freq_mhz;
  job.timeout_s = timeout_s;
  job.netlist_top = kWrapper;
  const flow::PlaceResult p = flow::place_and_route(job);
  row.nextpnr_s = p.seconds;
  row.constraint = t.freq_mhz;
  row.logic = p.logic;
  row.result = p.result;
  row.ok = p.ok;
  if (!p.routed) return;
  // The wrapper has one clock: its Fmax, against the target's constraint.
  row.fmax = p.fmax;
  row.path_start = p.path_start;
  row.path_end = p.path_end;
  row.path_ns = p.path_ns;
  row.result = row.fmax >= t.freq_mhz ? "routed, met" : "routed";
}

// ---------------------------------------------------------------------------------------------
// Tables.

std::string count(long n) { return n < 0 ? "" : std::to_string(n); }

std::string mhz(double f) {
  if (f <= 0) return "";
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", f);
  return b;
}

std::string path_text(const Row& r) {
  if (r.path_start.empty()) return "";
  char b[32];
  std::snprintf(b, sizeof b, " (%.1f ns)", r.path_ns);
  return "`" + r.path_start + "` → `" + r.path_end + "`" + b;
}

std::string secs(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%.0f", s);
  return s > 0 ? b : "";
}

std::string seed_text(const Row& r) { return r.seed > 0 ? std::to_string(r.seed) : "default"; }

// Fmax over seeds, per (config, design, target) with two or more routed seeds, in run order:
// min / median / max and the seed of the best run (the first of equals); "" when there is none.
// `given`: seeds asked for each, so a seed that failed or did not fit shows as "2 of 3".
std::string seed_summary(const std::vector<Row>& rows, size_t given) {
  struct Group {
    std::string key;
    std::vector<std::pair<double, int>> runs;  // Fmax, seed
  };
  std::vector<Group> groups;
  for (const Row& r : rows) {
    if (!r.finished || r.seed == 0 || r.fmax <= 0) continue;
    const std::string key = "| " + r.config + " | " + r.design + " | " + r.target + " | ";
    auto g = std::find_if(groups.begin(), groups.end(), [&](const Group& x) { return x.key == key; });
    if (g == groups.end()) g = groups.insert(groups.end(), Group{key, {}});
    g->runs.emplace_back(r.fmax, r.seed);
  }
  std::ostringstream md;
  for (const Group& g : groups) {
    if (g.runs.size() < 2) continue;
    if (md.tellp() == 0)
      md << "\nFmax over nextpnr's placement seeds (each row: one netlist from yosys, placed and routed once per "
            "seed; the best seed reproduces its run with `--seeds N`):\n\n"
         << "| config | design | target | seeds | Fmax min / median / max MHz | best seed |\n"
         << "|---|---|---|---|---|---|\n";
    std::vector<double> f;
    for (const auto& [fmax, seed] : g.runs) f.push_back(fmax);
    std::sort(f.begin(), f.end());
    const size_t n = f.size();
    const double median = n % 2 ? f[n / 2] : (f[n / 2 - 1] + f[n / 2]) / 2;
    const auto best = std::max_element(g.runs.begin(), g.runs.end(),
                                       [](const auto& x, const auto& y) { return x.first < y.first; });
    md << g.key << n << (n < given ? " of " + std::to_string(given) : std::string()) << " | " << mhz(f.front())
       << " / " << mhz(median) << " / " << mhz(f.back()) << " | " << best->second << " |\n";
  }
  return md.str();
}

std::string csv_quote(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string machine() {
  std::string cpu = "unknown CPU";
  std::ifstream f("/proc/cpuinfo");
  for (std::string l; std::getline(f, l);)
    if (l.rfind("model name", 0) == 0) { cpu = l.substr(l.find(':') + 2); break; }
  char date[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return std::to_string(std::thread::hardware_concurrency()) + " cores, " + cpu + ", " + date;
}

// A comma-separated option's items (each occurrence may hold several): an empty item ("a,,b",
// "a,") is a usage error, as in `watkins sweep`, not silently dropped.
std::vector<std::string> split_list(const char* option, const std::vector<std::string>& items) {
  std::vector<std::string> out;
  for (const std::string& item : items) {
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = item.find(',', start);
      const std::string x = item.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      if (x.empty()) throw UsageError(std::string(option) + ": empty item in \"" + item + "\"");
      out.push_back(x);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return out;
}

// --nextpnr-options: whitespace-separated words, passed to nextpnr as they are. The options the
// flow sets itself (netlist, report, log, clock, seed, device) are refused: a second one would
// either fail in nextpnr or silently change what a row measures.
std::vector<std::string> parse_nextpnr_options(const std::string& text) {
  static const char* const kOwn[] = {"--json", "--report", "-l", "--log", "--freq", "--seed", "--pcf",
                                     "--package", "--up5k", "--hx8k", "--85k", "--timing-allow-fail"};
  std::vector<std::string> words;
  std::istringstream in(text);
  for (std::string w; in >> w;) {
    const std::string name = w.substr(0, w.find('='));
    for (const char* own : kOwn)
      if (name == own)
        throw UsageError("--nextpnr-options: \"" + w + "\" is set by watkins synth itself" +
                         std::string(name == "--seed" ? " (use --seeds)" : ""));
    words.push_back(w);
  }
  return words;
}

std::string join_words(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
  return out;
}

// --seeds: nextpnr's --seed is an int, and 0 stands here for "none given", so [1, 2^31 - 1];
// a seed named twice would be the same run twice.
std::vector<int> parse_seeds(const std::vector<std::string>& items) {
  std::vector<int> seeds;
  for (const std::string& s : split_list("--seeds", items)) {
    const bool digits = s.size() <= 10 && s.find_first_not_of("0123456789") == std::string::npos;
    const long long v = digits ? std::stoll(s) : 0;
    if (v < 1 || v > 2147483647)
      throw UsageError("--seeds: \"" + s + "\" is not a seed (a decimal integer from 1 to 2147483647)");
    if (std::find(seeds.begin(), seeds.end(), v) != seeds.end())
      throw UsageError("--seeds: seed " + std::to_string(v) + " given twice");
    seeds.push_back(static_cast<int>(v));
  }
  return seeds;
}

std::string config_label(const std::string& c) {
  if (c == "default") return c;
  std::string stem = fs::path(c).filename().string();
  if (stem.size() > 5 && stem.compare(stem.size() - 5, 5, ".json") == 0) stem.resize(stem.size() - 5);
  return stem;
}

}  // namespace

CLI::App* add_synth_command(CLI::App& app, SynthArgs& a) {
  auto* s = app.add_subcommand("synth", "synthesize, place and route every block and both tops (yosys, nextpnr-ice40, "
                                        "nextpnr-ecp5): utilisation, routed Fmax, critical path");
  s->add_option("--config", a.configs, "configuration file(s) from `watkins size` (docs/guide/config-format.md); "
                                       "'default' = the default configuration")->capture_default_str();
  s->add_option("--designs", a.designs, "comma-separated: edge_incrementer, active_edge_list, segment_former, "
                                        "span_reciprocal, segment_interpolator, normalizer, phong_shader, "
                                        "scanline_buffer, smoother, compact_active_edge_list, compact_segment_former, "
                                        "compact_segment_interpolator, compact_scanline_buffer, compact_normalizer, "
                                        "compact_phong_shader, compact_normalizer_narrow, compact_phong_shader_narrow, "
                                        "top-gouraud, top-phong, "
                                        "top-compact, top-compact-phong "
                                        "(default: all)");
  s->add_option("--targets", a.targets, "comma-separated: ice40-up5k, ice40-hx8k, ecp5-85")->capture_default_str();
  cli::add_file(s, "--work", a.work, "directory for wrappers, netlists, logs and reports")->capture_default_str();
  cli::add_file(s, "--md", a.md, "markdown table to write");
  cli::add_file(s, "--csv", a.csv, "CSV table to write");
  s->add_option("--jobs,-j", a.jobs, "runs at once (each tool is single-threaded)")
      ->check(cli::integer_in(1, 256))
      ->capture_default_str();
  s->add_option("--timeout", a.timeout, "seconds allowed each tool run")
      ->check(cli::integer_in(1, 1 << 30))
      ->capture_default_str();
  cli::add_file(s, "--rtl-dir", a.rtl_dir, "RTL to synthesize (default: the source tree's rtl/)");
  s->add_option_function<std::string>(
       "--nextpnr-options",
       [&a](const std::string& v) {
         a.nextpnr_options = v;
         a.nextpnr_options_given = true;
       },
       "nextpnr placement options for every target, replacing the flow's (ECP5: --placer-heap-timingweight 30; "
       "iCE40: none); \"\" runs nextpnr's defaults")
      ->allow_extra_args(false);
  s->add_option("--seeds", a.seeds, "comma-separated nextpnr placement seeds (1 .. 2^31 - 1): yosys once, nextpnr once "
                                    "per seed; the table adds Fmax min / median / max and the best seed "
                                    "(default: one run at nextpnr's default seed)");
  return s;
}

namespace {

// What the command line asks for, every name checked (UsageError naming the option).
struct Choices {
  std::vector<const Design*> designs;
  std::vector<const Target*> targets;
  std::vector<std::string> placer;  // --nextpnr-options
  std::vector<int> seeds;           // {0}: one run at nextpnr's default seed
  std::vector<std::string> configs;
};

Choices choose(const SynthArgs& a) {
  Choices c;
  const std::vector<std::string> design_names = split_list("--designs", a.designs);
  if (design_names.empty()) {
    for (const Design& d : kDesigns) c.designs.push_back(&d);
  } else {
    for (const std::string& n : design_names) {
      auto it = std::find_if(std::begin(kDesigns), std::end(kDesigns), [&](const Design& d) { return n == d.name; });
      if (it == std::end(kDesigns)) {
        std::string known;
        for (const Design& d : kDesigns) known += (known.empty() ? "" : ", ") + std::string(d.name);
        throw UsageError("--designs: unknown design \"" + n + "\" (" + known + ")");
      }
      c.designs.push_back(&*it);
    }
    // Blocks before tops whatever order they were named in (a top's minutes come last).
    std::stable_sort(c.designs.begin(), c.designs.end(), [](const Design* x, const Design* y) { return !x->top && y->top; });
  }
  for (const std::string& n : split_list("--targets", a.targets)) {
    const Target* t = flow::find_target(n);
    if (!t) throw UsageError("--targets: unknown target \"" + n + "\" (ice40-up5k, ice40-hx8k, ecp5-85)");
    c.targets.push_back(t);
  }
  if (c.targets.empty()) throw UsageError("--targets: none given");
  c.placer = parse_nextpnr_options(a.nextpnr_options);
  c.seeds = parse_seeds(a.seeds);
  if (c.seeds.empty()) c.seeds.push_back(0);  // one run, no --seed: nextpnr's default
  c.configs = split_list("--config", a.configs);
  if (c.configs.empty()) throw UsageError("--config: none given");
  return c;
}

}  // namespace

void check_synth(const SynthArgs& a) { (void)choose(a); }

int run_synth(const SynthArgs& a) {
  const Choices choices = choose(a);
  const std::vector<const Design*>& designs = choices.designs;
  const std::vector<const Target*>& targets = choices.targets;
  const std::vector<std::string>& given_placer = choices.placer;
  auto placer_options = [&](const Target& t) { return a.nextpnr_options_given ? given_placer : t.placer; };
  const std::vector<int>& seeds = choices.seeds;
  struct NamedConfig {
    std::string arg, label;
    Config config;
  };
  // The tables are the run's only outputs outside --work: never a configuration or an RTL file.
  RunFiles tables;
  const Rtl rtl = find_rtl(a.rtl_dir.empty() ? std::string(WATKINS_SOURCE_DIR) + "/rtl" : a.rtl_dir);
  for (const std::string& f : rtl.files) tables.input("the RTL file " + f, f);
  for (const std::string& c : choices.configs)
    if (c != "default") tables.input("the --config file " + c, c);
  if (fs::exists(a.work) && fs::equivalent(a.work, rtl.dir))
    throw UsageError("--work " + a.work + " is the RTL folder; refusing to write into it");
  // --work is synth's own folder, made when missing: a table inside it has its folder made first,
  // so that the table is declared (and checked against the inputs) like any other output.
  const fs::path work_lexical = fs::absolute(a.work).lexically_normal();
  for (const std::string* table : {&a.md, &a.csv}) {
    if (table->empty()) continue;
    const fs::path folder = fs::absolute(*table).lexically_normal().parent_path();
    const fs::path inside = folder.lexically_relative(work_lexical);
    if (!inside.empty() && *inside.begin() != "..") fs::create_directories(folder);
  }
  if (!a.md.empty()) tables.output("--md", a.md);
  if (!a.csv.empty()) tables.output("--csv", a.csv);
  std::vector<NamedConfig> configs;
  for (const std::string& c : choices.configs)
    configs.push_back({c, config_label(c), c == "default" ? Config{} : load_config(c)});

  if (!on_path("yosys")) throw std::runtime_error("yosys not found on PATH (scripts/setup installs it)");
  for (const Target* t : targets)
    if (!on_path(nextpnr_binary(*t)))
      throw std::runtime_error(nextpnr_binary(*t) + " not found on PATH (scripts/setup installs it)");
  const fs::path work = fs::absolute(a.work);
  fs::create_directories(work);

  // Versions first: also the first run of the WebAssembly nextpnr, which compiles it once.
  std::map<std::string, std::string> versions;
  versions["yosys"] = tool_version("yosys", "-V", work);
  for (const Target* t : targets)
    if (!versions.count(nextpnr_binary(*t))) versions[nextpnr_binary(*t)] = tool_version(nextpnr_binary(*t), "--version", work);

  // Elaborate (a fraction of a second each) and write the wrappers; then the runs, blocks first.
  // A netlist is one yosys run, shared by its seeds' jobs: the first of them to start runs yosys,
  // the others wait for it (call_once), then each runs nextpnr.
  struct Netlist {
    std::once_flag once;
    Row row;  // yosys's part of each seed's row
    bool ok = false;
  };
  std::deque<Netlist> netlists;  // a deque: once_flag does not move
  struct Job {
    const Design* design;
    const Target* target;
    size_t config;
    WrapperSize size;
    fs::path dir;  // the netlist's folder
    size_t netlist;
    int seed;      // 0: no --seed
  };
  std::vector<Job> jobs;
  std::map<std::string, std::string> notes;  // per config and design: parameters set / ignored
  std::map<std::string, std::map<std::string, Parameters>> in_top;  // config + shading -> block parameters
  for (bool tops : {false, true})
    for (size_t ci = 0; ci < configs.size(); ++ci)
      for (const Design* d : designs) {
        if (d->top != tops) continue;
        const fs::path ddir = work / configs[ci].label / d->name;
        fs::create_directories(ddir);
        Config built = configs[ci].config;
        if (d->compact) {
          built.compact = true;
          built.smoothing = false;
          built.eq2 = false;
          if (d->shading == ShadingMode::Phong) built.lanes = 1;  // the compact Phong top shades one a beat
        }
        Parameters top;
        for (const RtlParameter& p : rtl_parameters(built, d->shading)) top.emplace_back(p.name, p.value);
        Parameters wanted = top;
        if (!d->top) {
          // A configuration without the smoother (smoothing false) has none in its top: the smoother
          // is measured as the same configuration's top with the smoother would instantiate it.
          const bool add_smoother = std::string(d->module) == "smoother" && !configs[ci].config.smoothing;
          const std::string key = configs[ci].label + (d->shading == ShadingMode::Phong ? " phong" : " gouraud") +
                                  (add_smoother ? " smoothing" : "");
          if (!in_top.count(key)) {
            const fs::path tdir = work / configs[ci].label /
                                  ((d->shading == ShadingMode::Phong ? "top-phong" : "top-gouraud") +
                                   std::string(add_smoother ? "-smoothing" : ""));
            fs::create_directories(tdir);
            Config with = configs[ci].config;
            with.smoothing = true;
            Parameters elab;
            for (const RtlParameter& p : rtl_parameters(with, d->shading)) elab.emplace_back(p.name, p.value);
            in_top[key] = block_parameters(rtl, add_smoother ? elab : top, tdir, a.timeout);
          }
          const char* from = d->params_of ? d->params_of : d->module;
          if (!in_top[key].count(from)) throw std::runtime_error(std::string("watkins_top does not instantiate ") + from);
          wanted = in_top[key][from];
        }
        const Elaborated e = elaborate(rtl, *d, wanted, ddir, a.timeout);
        std::string note;
        for (const auto& [n, v] : e.params) note += (note.empty() ? "" : " ") + n + "=" + std::to_string(v);
        if (note.empty()) note = "(module defaults)";
        if (!e.ignored.empty()) {
          note += "; not declared, at the module's default:";
          for (const std::string& n : e.ignored) note += " " + n;
        }
        notes[configs[ci].label + " " + d->name] = note;
        for (const Target* t : targets) {
          const fs::path dir = ddir / t->name;
          fs::create_directories(dir);
          const WrapperSize size = write_wrapper(*d, e, configs[ci].label, dir / "wrapper.v");
          netlists.emplace_back();
          for (int seed : seeds) jobs.push_back({d, t, ci, size, dir, netlists.size() - 1, seed});
        }
      }

  std::vector<Row> rows(jobs.size());
  // The tables: every finished run, in run order (blocks, then tops). Rewritten after each run, so
  // an interrupted run of the tops keeps the rows it finished.
  auto write_tables = [&](bool print_it) {
    std::ostringstream md;
    md << "Measured by `watkins synth` (sim/synth.cpp) on a " << machine() << ".\n"
       << "Tools: " << versions["yosys"];
    for (const auto& [bin, v] : versions)
      if (bin != "yosys") md << "; " << bin << ": " << v;
    md << ".\nEach design inside a generated wrapper that registers every input (a shift register) and output (a "
          "registered serial signature), so the Fmax is register to register; LUT4, FF, carry, DSP, BRAM and "
          "SPRAM / DPR16 (ECP5 distributed RAM) are yosys's cells after synthesis, the wrapper's flip-flops "
          "included (column \"wrapper FF\"); logic cells and Fmax are nextpnr's after placement and routing, the "
          "clock constrained to the column's MHz; the seed is nextpnr's placement seed (`--seeds`; \"default\": "
          "none given). ECP5 carry cells (CCU2C) hold two bits each.\n";
    md << "nextpnr's placement options:";
    for (const Target* t : targets) {
      const std::string o = join_words(placer_options(*t));
      md << (t == targets.front() ? " " : "; ") << t->name << " " << (o.empty() ? "none (nextpnr's defaults)" : "`" + o + "`");
    }
    md << ".\n\n"
       << "| config | design | target | seed | result | logic cells (nextpnr) | LUT4 | FF | wrapper FF | carry | DSP "
          "| BRAM | SPRAM / DPR16 | Fmax MHz (constraint) | critical path (start → end) | yosys s | nextpnr s |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows) {
      if (!r.finished) continue;
      md << "| " << r.config << " | " << r.design << " | " << r.target << " | " << seed_text(r) << " | " << r.result
         << " | " << r.logic << " | "
         << count(r.lut4) << " | " << count(r.ff) << " | " << r.wrapper_ff << " | " << count(r.carry) << " | "
         << count(r.dsp) << " | " << count(r.bram) << " | " << count(r.ram_other) << " | " << mhz(r.fmax)
         << (r.constraint > 0 ? " (" + mhz(r.constraint) + ")" : "") << " | " << path_text(r) << " | "
         << secs(r.yosys_s) << " | " << secs(r.nextpnr_s) << " |\n";
    }
    md << seed_summary(rows, seeds.size());
    md << "\nParameters: a top's are what `watkins_gen_pkg --params CONFIG --shading S` prints; a block's are what "
          "that top gives it (the Gouraud top's instance; the normalizer's and the shader's from the Phong top):\n\n";
    for (const auto& [key, note] : notes) md << "- " << key << ": " << note << "\n";
    // The user's tables, rewritten after every run, each replaced whole (RunFiles): an
    // interrupted or failed write leaves the previous table, never a truncated one.
    if (!a.md.empty()) tables.add(a.md, md.str());
    if (print_it) std::printf("%s", md.str().c_str());
    if (!a.csv.empty()) {
      std::ostringstream c;
      c << "config,design,target,seed,result,logic_cells,lut4,ff,wrapper_ff,carry,dsp,bram,ram_other,fmax_mhz,"
           "constraint_mhz,path_start,path_end,path_ns,yosys_s,nextpnr_s,yosys_version,nextpnr_version,dir,"
           "nextpnr_options\n";
      for (const Row& r : rows) {
        if (!r.finished) continue;
        const Target& t = **std::find_if(targets.begin(), targets.end(), [&](const Target* x) { return r.target == x->name; });
        char nums[160];
        std::snprintf(nums, sizeof nums, "%.2f,%.1f,", r.fmax, r.constraint);
        c << r.config << "," << r.design << "," << r.target << "," << seed_text(r) << "," << csv_quote(r.result) << ","
          << csv_quote(r.logic) << "," << count(r.lut4) << "," << count(r.ff) << "," << r.wrapper_ff << ","
          << count(r.carry) << "," << count(r.dsp) << "," << count(r.bram) << "," << count(r.ram_other) << "," << nums
          << csv_quote(r.path_start) << "," << csv_quote(r.path_end) << "," << r.path_ns << "," << r.yosys_s << ","
          << r.nextpnr_s << "," << csv_quote(versions["yosys"]) << "," << csv_quote(versions[nextpnr_binary(t)]) << ","
          << csv_quote(r.dir) << "," << csv_quote(join_words(placer_options(t))) << "\n";
      }
      tables.add(a.csv, c.str());
    }
    tables.commit();
  };
  std::atomic<size_t> next{0};
  std::atomic<size_t> done{0};
  std::mutex print;
  std::exception_ptr table_error;  // the first failed write of the tables (under `print`)
  auto worker = [&] {
    for (size_t i; (i = next++) < jobs.size();) {
      const Job& j = jobs[i];
      Netlist& n = netlists[j.netlist];
      // An exception is caught inside: call_once would let the next seed run yosys again.
      std::call_once(n.once, [&] {
        try {
          n.ok = synthesize(n.row, rtl, *j.target, j.dir, a.timeout);
        } catch (const std::exception& e) {
          n.row.result = std::string("failed: ") + e.what();
        }
      });
      Row r = n.row;  // the tables read rows[] under the lock: this row is filled apart
      r.config = configs[j.config].label;
      r.design = j.design->name;
      r.target = j.target->name;
      r.seed = j.seed;
      r.wrapper_ff = j.size.in_bits + j.size.out_bits;
      if (n.ok) {
        try {
          const fs::path dir = j.seed > 0 ? j.dir / ("seed-" + std::to_string(j.seed)) : j.dir;
          fs::create_directories(dir);
          place_and_route(r, *j.target, placer_options(*j.target), j.dir / "netlist.json", dir, j.seed, a.timeout);
        } catch (const std::exception& e) {
          r.result = std::string("failed: ") + e.what();
        }
      }
      std::lock_guard<std::mutex> lock(print);
      r.finished = true;
      rows[i] = r;
      // A table that cannot be written ends the run from the main thread (exit code 1, RunFiles
      // removing its temporaries): an exception leaving a worker would terminate the program.
      if (!table_error) {
        try {
          write_tables(false);
        } catch (...) {
          table_error = std::current_exception();
          next = jobs.size();  // no further run starts
        }
      }
      std::fprintf(stderr, "[%zu/%zu] %s %s %s%s: %s%s%s (yosys %.0f s, nextpnr %.0f s)\n", ++done, jobs.size(),
                   r.config.c_str(), r.design.c_str(), r.target.c_str(),
                   r.seed > 0 ? (" seed " + std::to_string(r.seed)).c_str() : "", r.result.c_str(),
                   r.fmax > 0 ? ", " : "", r.fmax > 0 ? (mhz(r.fmax) + " MHz").c_str() : "", r.yosys_s, r.nextpnr_s);
    }
  };
  std::vector<std::thread> pool;
  for (int k = 0; k < std::min<int>(a.jobs, static_cast<int>(jobs.size())); ++k) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  if (table_error) std::rethrow_exception(table_error);

  write_tables(true);
  return std::all_of(rows.begin(), rows.end(), [](const Row& r) { return r.ok; }) ? 0 : 1;
}

}  // namespace watkins::synth
