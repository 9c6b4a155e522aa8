// The SystemC bench (sc_bench.cpp): the default configuration's watkins_top Verilated as --sc
// models (Phong = 0 and 1) with assertions (--assert) and FST tracing, on sc_signals, clocked from
// one SC_THREAD that runs the drive loop. The co-simulation tests' bench and the one that writes
// --trace waveforms; `watkins render --rtl` runs the plain C++ harness unless asked for this one
// (RtlHarness, rtl_bench.hpp). Built unless CMake's WATKINS_RTL_SYSTEMC is OFF.
//
// The same source compiled with WATKINS_SC_SPEED=1 is the bench's speed build (namespace sc_speed
// below; library watkins_tb_sc_speed, built only for watkins_rtl_speed_sc_fast): the two tops
// Verilated --sc without --assert and without tracing, as the plain harness's --cc speed tops.
// The tests and `watkins render --rtl --systemc` keep the assertion tops.
#pragma once

#include <string>
#include <vector>

#include "rtl_bench.hpp"

namespace watkins::tb::detail {

// Runs frames prepared for the default configuration on the top of their shading; sets r.top.
void run_systemc(const std::vector<const PreparedScene*>& scenes, const RtlOptions& opt,
                 const std::vector<const Image*>& expected, RtlResult& r);

// rtl_initial_state() for the two SystemC tops (they are built at the first run_systemc).
void systemc_initial_state(int seed);

std::string systemc_description();

// The speed build's three (only in programs linked with watkins_tb_sc_speed). run_systemc takes
// frames of the default configuration only and throws std::invalid_argument for others.
namespace sc_speed {
void run_systemc(const std::vector<const PreparedScene*>& scenes, const RtlOptions& opt,
                 const std::vector<const Image*>& expected, RtlResult& r);
void systemc_initial_state(int seed);
std::string systemc_description();
}  // namespace sc_speed

}  // namespace watkins::tb::detail
