// watkins synth: every block and both tops of rtl/ at a configuration, through yosys and
// nextpnr (iCE40 UP5K and HX8K, ECP5-85), inside a generated wrapper that registers all IO and
// needs four pins; a table of utilisation, routed Fmax and critical path.
// With --seeds, each netlist is placed and routed once per nextpnr seed, and the table gains the
// spread of Fmax over the seeds and the best seed. See synth.cpp.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace watkins::synth {

struct SynthArgs {
  std::vector<std::string> configs{"default"};  // configuration files; "default" = formats.hpp
  std::vector<std::string> designs;             // default: every block, then both tops
  std::vector<std::string> targets{"ice40-up5k", "ice40-hx8k", "ecp5-85"};
  std::string work = "synth";                   // wrappers, scripts, netlists, logs, reports
  std::string md, csv;                          // tables to write (none when empty)
  int jobs = 1;
  int timeout = 3600;                           // seconds per tool run (yosys, nextpnr)
  std::string rtl_dir;                          // default: the source tree's rtl/
  std::vector<std::string> seeds;               // nextpnr --seed values; none = nextpnr's default
  // --nextpnr-options: replaces every target's placement options (Target::placer) when given.
  std::string nextpnr_options;  // whitespace-separated, checked by run_synth
  bool nextpnr_options_given = false;
};

// Registers `watkins synth` and its options on `app`; returns the subcommand.
CLI::App* add_synth_command(CLI::App& app, SynthArgs& args);
// The checks of the command line that need no file: UsageError (exit code 2) naming the option.
void check_synth(const SynthArgs& args);
// Runs every (configuration, design, target); returns 0 when each one ran to a result (a design
// that does not fit is a result), 1 when a tool failed or timed out. Bad input throws.
int run_synth(const SynthArgs& args);

}  // namespace watkins::synth
