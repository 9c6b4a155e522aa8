// The board top through the shared FPGA flow to a bitstream (board_build.hpp).
#include "board_build.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "flash_image.hpp"

namespace watkins::board_command {

namespace fs = std::filesystem;

namespace {

// A board's top, its part and its pin file (rtl/board/<top>.lpf or .pcf).
struct BoardFlow {
  const char* top;
  const char* target;
  const char* pins;     // nextpnr's option for the pin file
  const char* pin_ext;  // the pin file's extension
  const char* other;    // the other board's file prefix: its files are not read
};

BoardFlow board_flow(const std::string& board) {
  if (board == "icebreaker") return {"icebreaker_top", "ice40-up5k", "--pcf", ".pcf", "ulx3s_"};
  return {"ulx3s_top", "ecp5-85", "--lpf", ".lpf", "icebreaker_"};
}

// The sources yosys reads: the package first (every module uses it), the pipeline, the board's
// (rtl/board/ but the other board's top files).
std::vector<std::string> board_sources(const fs::path& rtl, const BoardFlow& b) {
  std::vector<std::string> files{(rtl / "watkins_pkg.sv").string()}, rest;
  for (const fs::path& dir : {rtl, rtl / "board"})
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".sv" && e.path().filename() != "watkins_pkg.sv" &&
          e.path().filename().string().rfind(b.other, 0) != 0)
        rest.push_back(e.path().string());
  std::sort(rest.begin(), rest.end());
  files.insert(files.end(), rest.begin(), rest.end());
  return files;
}

std::string mhz(double f) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", f);
  return b;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> board_top_parameters(const BitstreamJob& job) {
  std::vector<std::pair<std::string, std::string>> p;
  for (const RtlParameter& r : rtl_parameters(job.config, job.shading)) p.emplace_back(r.name, std::to_string(r.value));
  p.emplace_back("Doubling", std::to_string(job.doubling));
  p.emplace_back("LineSlots", std::to_string(job.line_slots));
  p.emplace_back("BankWords", std::to_string(job.bank_words));
  if (job.board == "icebreaker")
    p.emplace_back("FlashAddress", std::to_string(board::SpramBank::FlashAddress));
  else
    p.emplace_back("BankFile", "\"" + job.bank_file + "\"");
  return p;
}

BitstreamResult build_bitstream(const BitstreamJob& job) {
  const BoardFlow b = board_flow(job.board);
  const flow::Target* target = flow::find_target(b.target);
  const bool ecp5 = target->family == flow::Family::Ecp5;
  const fs::path work = job.work, rtl = job.rtl_dir;
  fs::create_directories(work);
  BitstreamResult r;

  // yosys: the part's primitives (EHXPLLL, ODDRX1F, MULT18X18D; SB_PLL40_PAD, SB_IO, SB_MAC16) as
  // black boxes, every source (on the ECP5 with WATKINS_ECP5: the multipliers with their own
  // product register), the top's parameters set before the hierarchy is elaborated.
  flow::SynthesisJob y;
  y.target = target;
  y.dir = work;
  y.reads.push_back(flow::read_primitives(*target));
  std::string read = std::string("read_verilog -sv") + (ecp5 ? " -DWATKINS_ECP5" : "") + " -I" + rtl.string();
  for (const std::string& f : board_sources(rtl, b)) read += " " + f;
  y.reads.push_back(read);
  std::string chparam = "chparam";
  for (const auto& [name, value] : board_top_parameters(job)) chparam += " -set " + name + " " + value;
  y.reads.push_back(chparam + " " + b.top);
  // yosys 0.23 elaborates icebreaker_top under a derived name ($paramod...) at the first
  // hierarchy after chparam; the synthesis script finds the top by its own name.
  if (!ecp5) y.reads.push_back(std::string("hierarchy -check -top ") + b.top + "; rename -top " + b.top);
  y.top = b.top;
  y.timeout_s = job.timeout_s;
  r.yosys = flow::synthesize(y);
  if (!r.yosys.ok) {
    r.result = r.yosys.result;
    return r;
  }

  // nextpnr: the board's pins and the oscillator's frequency from the constraint file; every PLL
  // output gets the constraint nextpnr derives from it. The textual configuration for the packer.
  flow::PlaceJob p;
  p.target = target;
  p.placer = target->placer;
  p.netlist = r.yosys.netlist;
  p.dir = work;
  p.seed = job.seed;
  p.freq_mhz = 0;
  const fs::path pins = rtl / "board" / (std::string(b.top) + b.pin_ext);
  const std::string config = ecp5 ? "ulx3s.config" : "icebreaker.asc";
  const std::string bit = ecp5 ? "ulx3s.bit" : "icebreaker_bitstream.bin";
  p.extra = {b.pins, fs::relative(pins, work).string(), ecp5 ? "--textcfg" : "--asc", config};
  p.timeout_s = job.timeout_s;
  p.netlist_top = b.top;
  fs::remove(work / config);
  r.nextpnr = flow::place_and_route(p);
  if (!r.nextpnr.routed) {
    r.result = r.nextpnr.result;
    return r;
  }
  if (!fs::exists(work / config)) {
    r.result = "failed (nextpnr): no textual configuration written";
    return r;
  }

  const auto t0 = std::chrono::steady_clock::now();
  const std::string packed = ecp5 ? flow::pack_ecp5(work / config, work / bit, work, job.timeout_s)
                                  : flow::pack_ice40(work / config, work / bit, work, job.timeout_s);
  r.pack_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!packed.empty()) {
    r.result = packed;
    return r;
  }
  r.bit = (work / bit).string();
  if (!ecp5) {
    // The flash's image: the bitstream, then the scene bank at its address.
    std::ifstream in(work / bit, std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::vector<std::uint8_t> flash = board::flash_with_scene(bytes, job.flash_scene);
    r.bit = (work / "icebreaker.bin").string();
    std::ofstream out(r.bit, std::ios::binary);
    out.write(reinterpret_cast<const char*>(flash.data()), static_cast<std::streamsize>(flash.size()));
    if (!out) {
      r.result = "failed: cannot write " + r.bit;
      return r;
    }
  }
  bool met = true;
  for (const flow::ClockFmax& c : r.nextpnr.clocks) met &= c.achieved >= c.constraint;
  r.ok = met;
  r.result = met ? "bitstream, every clock's constraint met" : "bitstream, a clock misses its constraint";
  return r;
}

std::string bitstream_report(const BitstreamJob& job, const BitstreamResult& r) {
  std::ostringstream md;
  md << "| resource | used | available | % |\n|---|---|---|---|\n";
  for (const auto& [type, ua] : r.nextpnr.utilisation) {
    if (ua.first == 0) continue;
    char pct[16];
    std::snprintf(pct, sizeof pct, "%.0f", 100.0 * ua.first / std::max(1L, ua.second));
    md << "| " << type << " | " << ua.first << " | " << ua.second << " | " << pct << " |\n";
  }
  // nextpnr's router works until each clock meets its constraint, so a met clock's Fmax is how far
  // this placement got, not how fast the design can go (watkins synth constrains a top at 125 MHz).
  if (!r.nextpnr.clocks.empty()) md << "\n| clock | constraint MHz | routed Fmax MHz | margin | met |\n|---|---|---|---|---|\n";
  for (const flow::ClockFmax& c : r.nextpnr.clocks) {
    char margin[32];
    std::snprintf(margin, sizeof margin, "%+.1f %%", c.constraint > 0 ? 100.0 * (c.achieved / c.constraint - 1) : 0.0);
    // nextpnr names a clock after its global net: `$glbnet$clk_pipe` is the RTL's clk_pipe.
    const std::string name = c.clock.rfind("$glbnet$", 0) == 0 ? c.clock.substr(8) : c.clock;
    md << "| `" << name << "` | " << mhz(c.constraint) << " | " << mhz(c.achieved) << " | " << margin << " | "
       << (c.achieved >= c.constraint ? "yes" : "**no**") << " |\n";
  }
  char times[160];
  std::snprintf(times, sizeof times, "\nyosys %.0f s, nextpnr %.0f s, %s %.0f s (seed %s); doubling %d, %d line slots, "
                                     "%d bank words.\n",
                r.yosys.seconds, r.nextpnr.seconds, job.board == "icebreaker" ? "icepack" : "ecppack", r.pack_s, job.seed > 0 ? std::to_string(job.seed).c_str() : "default",
                job.doubling, job.line_slots, job.bank_words);
  md << times;
  return md.str();
}

}  // namespace watkins::board_command
