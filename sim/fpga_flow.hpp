// The FPGA tool flow every command that builds hardware runs through (`watkins synth`, `watkins
// board build`): the targets (part, yosys synthesis command, nextpnr and its device options), one
// process runner (argv, a log, a wall-clock limit), yosys to a JSON netlist with its cell counts,
// nextpnr to a routed design with its utilisation and every clock's Fmax, ecppack or icepack to a
// bitstream.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace watkins::flow {

namespace fs = std::filesystem;

enum class Family { Ice40, Ecp5 };

struct Target {
  const char* name;
  Family family;
  const char* synth;                // yosys synthesis command (without -top)
  const char* nextpnr;              // binary; WATKINS_NEXTPNR_ICE40 / _ECP5 override
  std::vector<std::string> device;  // nextpnr's device and package options
  double freq_mhz;                  // clock constraint: the pipeline's target on that part
  std::vector<std::string> placer;  // nextpnr's placement options
};

// Every target, in the order tables list them.
const std::vector<Target>& targets();
// The target named `name`, or nullptr.
const Target* find_target(const std::string& name);
// nextpnr's binary for the target (the environment's override, else Target::nextpnr).
std::string nextpnr_binary(const Target& t);

// ---------------------------------------------------------------------------------------------
// Processes.

struct ProcessResult {
  int status = -1;  // exit code; -1 when it did not exit normally
  bool timed_out = false;
  double seconds = 0;
};

// Runs argv in `cwd`, its output and errors to `log`; killed (with what it started) after timeout_s.
ProcessResult run_process(const std::vector<std::string>& argv, const fs::path& cwd, const fs::path& log,
                          int timeout_s);
std::string read_text(const fs::path& p);
// A work file (wrapper, script): the close is checked too, so a full disk is an error.
void write_text(const fs::path& p, const std::string& text);
bool on_path(const std::string& bin);
// First line of `bin flag` (the tool's version); its output kept in `work`.
std::string tool_version(const std::string& bin, const char* flag, const fs::path& work);
// The first ERROR line of a log, else the first line of the tool's own output.
std::string last_error_line(const std::string& log, const std::string& output = "");

// ---------------------------------------------------------------------------------------------
// yosys.

// yosys's cells after synthesis, by kind (-1: not counted).
struct CellCounts {
  long lut4 = -1, ff = -1, carry = -1, dsp = -1, bram = -1, ram_other = -1;
};

struct SynthesisJob {
  const Target* target = nullptr;
  fs::path dir;                    // the script, logs, netlist.json and stat.txt go here
  std::vector<std::string> reads;  // yosys commands that read the sources
  std::string top;                 // the top module
  int timeout_s = 3600;
};

struct SynthesisResult {
  bool ok = false;
  std::string result;  // why not, when !ok ("yosys timeout", "failed (yosys): <line>")
  double seconds = 0;
  CellCounts cells;
  fs::path netlist;  // dir/netlist.json
};

// `read_verilog -lib` of the target family's primitives, for sources that instantiate them.
std::string read_primitives(const Target& t);
// yosys: job.reads, the target's synthesis to its final check step, netlist.json and stat.txt.
SynthesisResult synthesize(const SynthesisJob& job);

// ---------------------------------------------------------------------------------------------
// nextpnr.

struct ClockFmax {
  std::string clock;
  double achieved = 0, constraint = 0;  // MHz
};

struct PlaceJob {
  const Target* target = nullptr;
  std::vector<std::string> placer;  // placement options (the target's, or the user's)
  fs::path netlist, dir;            // report.json, nextpnr.log and nextpnr.out go to dir
  int seed = 0;                     // 0: no --seed
  double freq_mhz = 0;              // --freq; 0: the constraint file's clocks only
  std::vector<std::string> extra;   // further options (--lpf FILE, --textcfg FILE), paths relative to dir
  int timeout_s = 3600;
  std::string netlist_top;          // the netlist's top module, for register names on the critical path
};

struct PlaceResult {
  bool ok = false;    // a result: routed, or does not fit; not a tool failure
  bool routed = false;
  std::string result; // routed | does not fit (TYPE, ...) | nextpnr timeout | failed (nextpnr): <line>
  std::string logic;  // logic cells used / available (percent)
  std::map<std::string, std::pair<long, long>> utilisation;  // type -> used, available
  std::vector<ClockFmax> clocks;                            // every clock of the design
  double fmax = 0;                                           // the slowest clock's achieved
  std::string path_start, path_end;                          // the critical path of the last clock reported
  double path_ns = 0;
  double seconds = 0;
};

PlaceResult place_and_route(const PlaceJob& job);

// ecppack: nextpnr's textual configuration to a bitstream. Empty when it worked, else why.
std::string pack_ecp5(const fs::path& config, const fs::path& bit, const fs::path& dir, int timeout_s);
// icepack: nextpnr-ice40's ASCII configuration (--asc) to a bitstream (.bin). Empty when it
// worked, else why.
std::string pack_ice40(const fs::path& asc, const fs::path& bin, const fs::path& dir, int timeout_s);

}  // namespace watkins::flow
