// The pins of watkins_top as the frame driver (frame_driver.hpp) sees them. Each harness
// implements this once: the SystemC bench on sc_signals (rtl_bench.cpp), and every plain
// Verilated (--cc) model through CcTopPins (cc_top_pins.hpp: the speed harness and
// tests/rtl/test_rtl_watkins_top.cpp).
//
// One clock cycle is: settle -> sample -> posedge. A transfer happens on the rising edge when
// valid and ready were both high after settle. The calls are per interface, not per signal: a
// cycle costs about five virtual calls next to two evaluations of the model.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "edge_packing.hpp"
#include "stage_taps.hpp"

namespace watkins::tb::detail {

// {R, G, B} of 8 bits each, as background_i, material_cp_i and pixel_rgb_o carry a colour.
inline std::uint32_t pack_rgb(const std::array<std::uint8_t, 3>& c) {
  return (std::uint32_t(c[0]) << 16) | (std::uint32_t(c[1]) << 8) | c[2];
}

// The outputs as settle() left them (the values the rising edge samples).
struct PinsOut {
  bool edge_ready = false;
  bool pixel_valid = false, pixel_last = false, pixel_covered = false;
  std::uint32_t pixel_rgb = 0;
  std::uint32_t pixel_x = 0, pixel_y = 0;
  bool overflow = false;
};

// One write of the Phong material table, as the material_*_i pins take it.
struct MaterialPins {
  bool we = false;
  std::uint32_t addr = 0;
  std::uint32_t cp = 0;  // {R, G, B}
  std::uint32_t d = 0, w = 0, n = 0;
};

class TopPins {
 public:
  virtual ~TopPins() = default;
  virtual void reset_pin(bool rst_n) = 0;
  // The frame configuration pins: width_i, height_i, background_i, sparse_i, tie_submission_i,
  // smooth_w_i, eq2_i.
  virtual void frame_pins(std::uint32_t width, std::uint32_t height, std::uint32_t background_rgb, bool sparse,
                          bool tie_submission, std::uint32_t smooth_w, bool eq2) = 0;
  virtual void phong_pins(std::uint64_t light, std::uint64_t eye) = 0;  // {z, y, x} Q2.14 each
  virtual void material_pins(const MaterialPins& m) = 0;
  virtual void edge_pins(bool valid, bool eof, const EdgeWords& data) = 0;
  virtual void ready_pin(bool pixel_ready) = 0;
  virtual void settle(std::uint64_t t) = 0;  // clock low with the new inputs; outputs valid
  virtual PinsOut sample() = 0;
  virtual void posedge(std::uint64_t t) = 0;  // rising clock edge
  // True once an RTL assertion, $stop or $finish fired (Verilator prints its message); clears it.
  virtual bool stopped() = 0;
  virtual bool trace_open(const std::string& path) = 0;  // FST of the whole run; false: cannot
  virtual void trace_close() = 0;
  virtual const StageTaps* stage_taps() = 0;  // null: the stage streams are not checked
};

}  // namespace watkins::tb::detail
