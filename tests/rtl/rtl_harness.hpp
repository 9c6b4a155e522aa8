// Shared helpers of the RTL unit benches: clocking a Verilated unit, packing wide ports, and
// random valid gaps / ready back-pressure.
#pragma once

#include <cstdint>
#include <random>

#include "bit_field.hpp"
#include "fixed_point.hpp"
#include "verilated.h"

namespace watkins::rtl {

// A Verilated unit with clk_i / rst_ni: tick() is one rising edge after the inputs are set.
template <class V>
struct Harness {
  V dut;
  std::uint64_t cycles = 0;
  void tick() {
    dut.clk_i = 0;
    dut.eval();
    dut.clk_i = 1;
    dut.eval();
    ++cycles;
  }
  void reset() {
    dut.rst_ni = 0;
    tick();
    tick();
    dut.rst_ni = 1;
  }
};

// Fields of Verilator wide signals: the benches' one bit packer (model/twins/bit_field.hpp).
using tb::get_bits;
using tb::get_signed;
using tb::set_bits;
inline std::uint64_t to_bits(i64 v, int n) { return wrap_unsigned(v, n); }

// Random stalls: a percentage of cycles with valid low (source) or ready low (sink).
struct Stalls {
  std::mt19937_64& rng;
  int pct;
  bool stall() { return pct > 0 && static_cast<int>(rng() % 100) < pct; }
};

}  // namespace watkins::rtl
