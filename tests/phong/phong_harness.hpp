// Clocking a Verilated Phong block (clk_i / rst_ni) and random valid gaps / ready back-pressure.
#pragma once

#include <cstdint>
#include <random>

namespace watkins::phong {

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
};

// A percentage of cycles with valid low (source) or ready low (sink).
struct Stalls {
  std::mt19937_64& rng;
  int pct;
  bool stall() { return pct > 0 && static_cast<int>(rng() % 100) < pct; }
};

}  // namespace watkins::phong
