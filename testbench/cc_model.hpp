// CcModel (cc_models.hpp) of one Verilated --cc watkins_top: its own VerilatedContext, the model,
// CcTopPins and the stage taps. Included only by the generated registry (cc_models.cpp), which
// instantiates make_cc_model<V...> for each per-configuration prefix.
#pragma once

#include <memory>

#include <verilated.h>

#include "cc_models.hpp"
#include "cc_top_pins.hpp"
#include "stage_taps.hpp"

namespace watkins::tb::detail {

// No FST tracing: the per-configuration tops are Verilated without --trace-fst (a shorter build;
// the SystemC bench traces the default configuration).
template <class Model>
class CcModelOf final : public CcModel {
 public:
  CcModelOf() : dut_(make_dut(ctx_)), pins_(*dut_) { pins_.bind_stage_taps(stage_taps(*dut_->rootp)); }
  TopPins& pins() override { return pins_; }

 private:
  static std::unique_ptr<Model> make_dut(VerilatedContext& ctx) {
    ctx.fatalOnError(false);  // an assertion ends the run, not the process
    return std::make_unique<Model>(&ctx, "watkins_top");
  }
  VerilatedContext ctx_;
  std::unique_ptr<Model> dut_;
  CcTopPins<Model, NoTrace> pins_;
};

template <class Model>
std::unique_ptr<CcModel> make_cc_model() {
  return std::make_unique<CcModelOf<Model>>();
}

}  // namespace watkins::tb::detail
