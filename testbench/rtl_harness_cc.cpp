// Plain C++ harness: the same drive loop (frame_driver.hpp) on a Verilated --cc build of
// watkins_top through CcTopPins (cc_top_pins.hpp). Only for the speed comparison with the
// SystemC bench (watkins_rtl_speed_cc); implements the same API as rtl_bench.cpp, so a program
// links exactly one of watkins_tb and watkins_tb_cc.
#include <memory>
#include <stdexcept>

#include <verilated.h>

#include "Vwatkins_top_cc.h"
#include "Vwatkins_top_cc___024root.h"  // the public internal stage signals
#include "cc_top_pins.hpp"
#include "expectations.hpp"
#include "fst_trace.hpp"
#include "frame_driver.hpp"
#include "formats.hpp"
#include "rtl_bench.hpp"

namespace watkins::tb {
namespace {

// The top at its default MaxWidth (not overridden in testbench/CMakeLists.txt).
constexpr int MaxWidth = fmt::DefaultMaxWidth;

struct Harness {
  VerilatedContext ctx;
  std::unique_ptr<Vwatkins_top_cc> dut;
  std::unique_ptr<detail::CcTopPins<Vwatkins_top_cc, FstTrace>> pins;
  std::unique_ptr<detail::FrameDriver> driver;
  Harness() {
    ctx.traceEverOn(true);
    ctx.fatalOnError(false);  // an assertion ends the run, not the process
    dut = std::make_unique<Vwatkins_top_cc>(&ctx, "watkins_tb");
    pins = std::make_unique<detail::CcTopPins<Vwatkins_top_cc, FstTrace>>(*dut);
    pins->bind_stage_taps(detail::stage_taps(*dut->rootp));
    driver = std::make_unique<detail::FrameDriver>(*pins);
  }
};

Harness& harness() {
  static Harness* h = new Harness;  // never destroyed, like the SystemC bench
  return *h;
}

}  // namespace

std::string rtl_description() { return "plain C++ harness (Verilated --cc watkins_top, eval loop)"; }

// The speed harness keeps the zero power-up state (tests/cosim/test_x_initial.cpp uses the SystemC bench).
void rtl_initial_state(int seed) {
  if (seed != 0) throw std::logic_error("rtl_initial_state: the plain C++ harness starts at zero only");
}

// Only the default configuration's Gouraud top is built here.
std::string rtl_unavailable(const Config& config, ShadingMode shading, const std::string&) {
  if (shading == ShadingMode::Gouraud && rtl_parameters(config, shading) == rtl_parameters(Config{}, shading))
    return "";
  return "plain C++ harness: only the default configuration's Gouraud top is built here";
}

int rtl_max_width(const Config& config, ShadingMode shading) {
  return rtl_unavailable(config, shading).empty() ? MaxWidth : 0;
}

RtlResult run_rtl_frames(const std::vector<const PreparedScene*>& scenes, const RtlOptions& opt,
                         const std::vector<const Image*>& expected) {
  if (detail::phong_frames(scenes))
    throw std::invalid_argument("plain C++ harness: only the Gouraud top (Phong = 0) is built here");
  RtlResult r;
  r.unavailable = rtl_unavailable(detail::frames_config(scenes), ShadingMode::Gouraud);
  if (!r.unavailable.empty()) return r;
  r.top = rtl_description();
  const detail::Expectations want = detail::expect(scenes, opt, expected, r, MaxWidth);
  harness().driver->run(scenes, want.images, want.stages, opt, r);
  return r;
}

}  // namespace watkins::tb
