// TopPins (top_pins.hpp) of a plain Verilated (--cc) watkins_top, clocked by eval(): one cycle
// is clock low + eval (settle), clock high + eval (posedge). Used by every --cc top of the
// registry (cc_models.hpp: the plain C++ harness) and the top's unit test
// (tests/rtl/test_rtl_watkins_top.cpp), whatever the model's parameters. `Trace` is FstTrace (fst_trace.hpp) for a model Verilated with
// --trace-fst, NoTrace otherwise.
#pragma once

#include <optional>

#include "top_pins.hpp"
#include "verilated_stop.hpp"

namespace watkins::tb::detail {

struct NoTrace {
  template <class Model>
  bool open(Model&, const std::string&) { return false; }
  void dump(std::uint64_t) {}
  void close() {}
};

template <class Model, class Trace>
class CcTopPins final : public TopPins {
 public:
  explicit CcTopPins(Model& dut) : dut_(dut) {}
  // The internal stage streams to check (stage_taps(*dut.rootp)); none unless bound.
  void bind_stage_taps(const StageTaps& taps) { taps_ = taps; }

  void reset_pin(bool v) override { dut_.rst_ni = v; }
  void frame_pins(std::uint32_t w, std::uint32_t h, std::uint32_t bg, bool sparse, bool tie_submission,
                  std::uint32_t smooth_w, bool eq2) override {
    dut_.width_i = w;
    dut_.height_i = h;
    dut_.background_i = bg;
    dut_.sparse_i = sparse;
    dut_.tie_submission_i = tie_submission;
    dut_.smooth_w_i = smooth_w;
    dut_.eq2_i = eq2;
  }
  void phong_pins(std::uint64_t light, std::uint64_t eye) override {
    dut_.light_i = light;
    dut_.eye_i = eye;
  }
  void material_pins(const MaterialPins& m) override {
    dut_.material_we_i = m.we;
    dut_.material_addr_i = m.addr;
    dut_.material_cp_i = m.cp;
    dut_.material_d_i = m.d;
    dut_.material_w_i = m.w;
    dut_.material_n_i = m.n;
  }
  void edge_pins(bool valid, bool eof, const EdgeWords& data) override {
    dut_.edge_valid_i = valid;
    dut_.edge_eof_i = eof;
    write_edge(dut_.edge_i, data);
  }
  void ready_pin(bool v) override { dut_.pixel_ready_i = v; }
  void settle(std::uint64_t t) override {
    dut_.clk_i = 0;
    dut_.eval();
    trace_.dump(t);
  }
  PinsOut sample() override {
    PinsOut o;
    o.edge_ready = dut_.edge_ready_o;
    o.pixel_valid = dut_.pixel_valid_o;
    o.pixel_last = dut_.pixel_last_o;
    o.pixel_covered = dut_.pixel_covered_o;
    o.pixel_rgb = dut_.pixel_rgb_o;
    o.pixel_x = dut_.pixel_x_o;
    o.pixel_y = dut_.pixel_y_o;
    o.overflow = dut_.overflow_o;
    return o;
  }
  void posedge(std::uint64_t t) override {
    dut_.clk_i = 1;
    dut_.eval();
    trace_.dump(t);
  }
  bool stopped() override { return take_stop(*dut_.contextp()); }
  bool trace_open(const std::string& path) override { return trace_.open(dut_, path); }
  void trace_close() override { trace_.close(); }
  const StageTaps* stage_taps() override { return taps_ ? &*taps_ : nullptr; }

 private:
  Model& dut_;
  Trace trace_;
  std::optional<StageTaps> taps_;
};

}  // namespace watkins::tb::detail
