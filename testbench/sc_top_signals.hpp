// The sc_signals on watkins_top's ports (all but the clock) and their binding to a Verilated
// --sc top, shared by the SystemC bench (rtl_bench.cpp) and the per-signal measurement
// (rtl_speed_signals.cpp). Declared as a member of the bench module, so the signals are its own.
#pragma once

#include <cstdint>

#include <systemc.h>

#include "edge_packing.hpp"

namespace watkins::tb {

struct TopSignals {
  sc_signal<bool> rst_n{"rst_n"}, sparse{"sparse"}, tie_submission{"tie_submission"}, eq2{"eq2"};
  sc_signal<uint32_t> width{"width"}, height{"height"}, background{"background"}, smooth_w{"smooth_w"};
  sc_signal<sc_bv<fmt::EdgeRecordBits>> edge{"edge"};  // the default configuration's edge_t
  sc_signal<bool> edge_eof{"edge_eof"}, edge_valid{"edge_valid"}, edge_ready{"edge_ready"};
  sc_signal<uint32_t> pixel_rgb{"pixel_rgb"}, pixel_x{"pixel_x"}, pixel_y{"pixel_y"};
  sc_signal<bool> pixel_covered{"pixel_covered"}, pixel_last{"pixel_last"}, pixel_valid{"pixel_valid"};
  sc_signal<bool> pixel_ready{"pixel_ready"}, overflow{"overflow"};
  sc_signal<uint64_t> light{"light"}, eye{"eye"};  // Phong inputs: unused by the Gouraud top
  sc_signal<bool> material_we{"material_we"};
  sc_signal<uint32_t> material_addr{"material_addr"}, material_cp{"material_cp"}, material_d{"material_d"};
  sc_signal<uint32_t> material_w{"material_w"}, material_n{"material_n"};

  // Binds every port of `dut`, clk_i to `clk` (an sc_signal<bool> or an sc_clock).
  template <class Dut, class Clock>
  void bind(Dut& dut, Clock& clk) {
    dut.clk_i(clk);
    dut.rst_ni(rst_n);
    dut.width_i(width);
    dut.height_i(height);
    dut.background_i(background);
    dut.sparse_i(sparse);
    dut.tie_submission_i(tie_submission);
    dut.smooth_w_i(smooth_w);
    dut.eq2_i(eq2);
    dut.edge_i(edge);
    dut.edge_eof_i(edge_eof);
    dut.edge_valid_i(edge_valid);
    dut.edge_ready_o(edge_ready);
    dut.pixel_rgb_o(pixel_rgb);
    dut.pixel_covered_o(pixel_covered);
    dut.pixel_x_o(pixel_x);
    dut.pixel_y_o(pixel_y);
    dut.pixel_last_o(pixel_last);
    dut.pixel_valid_o(pixel_valid);
    dut.pixel_ready_i(pixel_ready);
    dut.overflow_o(overflow);
    dut.light_i(light);
    dut.eye_i(eye);
    dut.material_we_i(material_we);
    dut.material_addr_i(material_addr);
    dut.material_cp_i(material_cp);
    dut.material_d_i(material_d);
    dut.material_w_i(material_w);
    dut.material_n_i(material_n);
  }
};

}  // namespace watkins::tb
