// TopPins::stopped() of every harness: an RTL assertion, $stop or $finish seen by a Verilated
// context running with fatalOnError(false) (Verilator has printed its message). True once, then
// cleared, so that the next run (after the driver's reset) starts clean.
#pragma once

#include <verilated.h>

namespace watkins::tb::detail {

inline bool take_stop(VerilatedContext& ctx) {
  if (!ctx.gotFinish() && !ctx.gotError()) return false;
  ctx.gotFinish(false);
  ctx.gotError(false);
  return true;
}

}  // namespace watkins::tb::detail
