// Plain C++ harness: the same source/sink/checker (frame_driver.hpp) on a Verilated --cc build of
// watkins_top, clocked by a loop (tick = clock low + eval, clock high + eval). Only for the
// speed comparison with the SystemC bench (watkins_rtl_speed_cc); implements the same API as
// rtl_bench.cpp, so a program links exactly one of watkins_tb and watkins_tb_cc.
#include <memory>
#include <stdexcept>

#include <verilated.h>
#include <verilated_fst_c.h>

#include "Vwatkins_top_cc.h"
#include "Vwatkins_top_cc___024root.h"  // the public internal stage signals
#include "fst_trace.hpp"
#include "frame_driver.hpp"
#include "rtl_bench.hpp"

namespace watkins::tb {
namespace {

constexpr int MaxWidth = 1024;

class CcHarness {
 public:
  CcHarness() {
    ctx_.traceEverOn(true);
    ctx_.fatalOnError(false);
    dut_ = std::make_unique<Vwatkins_top_cc>(&ctx_, "watkins_tb");
  }

  // ---- Pins (see frame_driver.hpp) ----
  void reset_pin(bool v) { dut_->rst_ni = v; }
  void frame_pins(std::uint32_t w, std::uint32_t h, std::uint32_t bg, bool sparse) {
    dut_->width_i = w;
    dut_->height_i = h;
    dut_->background_i = bg;
    dut_->sparse_i = sparse;
  }
  void phong_pins(std::uint64_t light, std::uint64_t eye) {
    dut_->light_i = light;
    dut_->eye_i = eye;
  }
  void material_pin(bool we, int addr, const QuantizedMaterial& m) {
    dut_->material_we_i = we;
    dut_->material_addr_i = static_cast<std::uint32_t>(addr);
    dut_->material_cp_i = detail::pack_rgb({std::uint8_t(m.cp[0]), std::uint8_t(m.cp[1]), std::uint8_t(m.cp[2])});
    dut_->material_d_i = static_cast<std::uint32_t>(m.d);
    dut_->material_w_i = static_cast<std::uint32_t>(m.w);
    dut_->material_n_i = static_cast<std::uint32_t>(m.shininess);
  }
  void edge_pins(bool valid, bool eof, const EdgeWords& data) {
    dut_->edge_valid_i = valid;
    dut_->edge_eof_i = eof;
    for (int i = 0; i < edge_layout::Words; ++i) dut_->edge_i[i] = data[i];
  }
  void ready_pin(bool v) { dut_->pixel_ready_i = v; }
  void settle(std::uint64_t t) {
    dut_->clk_i = 0;
    dut_->eval();
    trace_.dump(t);
  }
  detail::PinsOut sample() {
    detail::PinsOut o;
    o.edge_ready = dut_->edge_ready_o;
    o.pixel_valid = dut_->pixel_valid_o;
    o.pixel_last = dut_->pixel_last_o;
    o.pixel_covered = dut_->pixel_covered_o;
    o.pixel_rgb = dut_->pixel_rgb_o;
    o.pixel_x = dut_->pixel_x_o;
    o.pixel_y = dut_->pixel_y_o;
    o.overflow = dut_->overflow_o;
    return o;
  }
  void posedge(std::uint64_t t) {
    dut_->clk_i = 1;
    dut_->eval();
    trace_.dump(t);
  }
  bool trace_open(const std::string& path) {
    return trace_.open(*dut_, path);
  }
  void trace_close() {
    trace_.close();
  }
  const detail::StageTaps& stage_taps() {
    if (!taps_.ae_valid) taps_ = detail::stage_taps(*dut_->rootp);
    return taps_;
  }
  std::string stopped() {
    if (!ctx_.gotFinish() && !ctx_.gotError()) return "";
    ctx_.gotFinish(false);
    ctx_.gotError(false);
    return "an assertion, $stop or $finish fired (Verilator's message is on stdout)";
  }

 private:
  VerilatedContext ctx_;
  std::unique_ptr<Vwatkins_top_cc> dut_;
  FstTrace trace_;
  detail::StageTaps taps_;
};

struct Harness {
  CcHarness pins;
  detail::FrameDriver<CcHarness> driver{pins};
};

Harness& harness() {
  static Harness* h = new Harness;  // never destroyed, like the SystemC bench
  return *h;
}

}  // namespace

std::string rtl_description() { return "plain C++ harness (Verilated --cc watkins_top, eval loop)"; }

int rtl_max_width() { return MaxWidth; }

RtlResult run_rtl_frames(const std::vector<const PreparedScene*>& scenes, const RtlOptions& opt,
                         const std::vector<const Image*>& expected) {
  if (detail::phong_frames(scenes))
    throw std::invalid_argument("plain C++ harness: only the Gouraud top (Phong = 0) is built here");
  RtlResult r;
  std::vector<Image> rendered;
  std::vector<const Image*> use;
  std::vector<StageStreams> stages;
  detail::expected_images(scenes, opt, expected, rendered, use, stages, r, MaxWidth);
  harness().driver.run(scenes, use, stages, opt, r);
  return r;
}

RtlResult run_rtl(const PreparedScene& scene, const RtlOptions& opt, const Image* expected) {
  return run_rtl_frames({&scene}, opt, {expected});
}

}  // namespace watkins::tb
