// The transaction-level bench of watkins_top, the one drive loop shared by the SystemC bench
// (sc_bench.cpp), the plain C++ harness (the --cc tops, rtl_bench.cpp) and the top's unit test
// (tests/rtl/test_rtl_watkins_top.cpp). Each talks to its Verilated top through TopPins
// (top_pins.hpp). A run clocks the source (edge_source.hpp), the sink and pixel check
// (pixel_sink.hpp) and the stage check (stage_checker.hpp), watches for hangs, and counts cycles.
//
// One clock cycle is: settle -> sample -> posedge. The internal stage streams are checked on the
// same clocks, the pixels after them.
#pragma once

#include <vector>

#include "image.hpp"
#include "prepare.hpp"
#include "rtl_bench.hpp"
#include "top_pins.hpp"

namespace watkins::tb::detail {

class FrameDriver {
 public:
  static constexpr int ResetCycles = 4;

  struct Policy {
    // Reset before the next run after a run that saw overflow_o (it is sticky until reset).
    bool reset_after_overflow = true;
  };

  explicit FrameDriver(TopPins& pins) : FrameDriver(pins, Policy{}) {}
  FrameDriver(TopPins& pins, Policy policy) : pins_(pins), policy_(policy) {}

  // Runs the frames back to back (RtlResult in `r`). expected[f]: frame f's model image, or null
  // (not compared); stages: the model's stage streams of every frame (empty: not checked).
  // Resets the top first when opt.reset (the default), and regardless on the first run and
  // after a failed one. A reset starts from the same pins and the same clocks every time, so a
  // run with reset gives the same result whatever the top ran before.
  void run(const std::vector<const PreparedScene*>& scenes, const std::vector<const Image*>& expected,
           const std::vector<StageStreams>& stages, const RtlOptions& opt, RtlResult& r);

 private:
  // Holds rst_ni low for ResetCycles clocks with every input at rest (as at power-up: zero,
  // edge_i poisoned), so that no pin keeps the previous run's value through the reset.
  void reset(const EdgeWords& poison);

  TopPins& pins_;
  Policy policy_;
  bool need_reset_ = true;
  long long cycle_ = 0;  // cycles since the driver was built
};

}  // namespace watkins::tb::detail
