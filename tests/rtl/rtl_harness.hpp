// Shared helpers of the RTL unit benches: clocking a Verilated unit, packing wide ports, and
// random valid gaps / ready back-pressure.
#pragma once

#include <cstdint>
#include <random>

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

// Bits [lo, lo+n) of a Verilator wide signal (n <= 64).
template <class W>
void set_bits(W& w, int lo, int n, std::uint64_t v) {
  for (int i = 0; i < n; ++i) {
    const int b = lo + i;
    const std::uint32_t bit = (v >> i) & 1u;
    w[b / 32] = (w[b / 32] & ~(1u << (b % 32))) | (bit << (b % 32));
  }
}
template <class W>
std::uint64_t get_bits(const W& w, int lo, int n) {
  std::uint64_t v = 0;
  for (int i = 0; i < n; ++i) {
    const int b = lo + i;
    v |= std::uint64_t((w[b / 32] >> (b % 32)) & 1u) << i;
  }
  return v;
}
template <class W>
i64 get_signed(const W& w, int lo, int n) {
  return wrap_signed(static_cast<i128>(get_bits(w, lo, n)), n);
}
inline std::uint64_t to_bits(i64 v, int n) { return wrap_unsigned(v, n); }

// Random stalls: a percentage of cycles with valid low (source) or ready low (sink).
struct Stalls {
  std::mt19937_64& rng;
  int pct;
  bool stall() { return pct > 0 && static_cast<int>(rng() % 100) < pct; }
};

}  // namespace watkins::rtl
