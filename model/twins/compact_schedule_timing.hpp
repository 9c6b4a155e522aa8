// Cycle twin of rtl/compact_schedule.sv, the control of the compact blocks that work in a fixed
// schedule of 5-clock periods (compact_normalizer, compact_phong_shader): clocked once per cycle
// with the handshake inputs, no values. It says in which cycles the block takes an item (ready_o)
// and offers a result (valid_o), so a bench holds the RTL to it cycle for cycle and a cycle model
// of a compact Phong top composes it.
//
// The clock, as the RTL's header states it: an item is taken in a period's last clock (ready_o is
// high there and only there), moves one period on at each period's end and is loaded into the
// output register in phase load_phase of its last period; a load that finds the output holding a
// result not taken in that clock stalls everything for that clock.
#pragma once

#include <vector>

namespace watkins {

class CompactScheduleTiming {
 public:
  static constexpr int Period = 5;  // clocks per item at full rate

  // periods: the periods an item spends inside; load_phase: the clock of the last one that loads
  // the output. The state right after reset.
  CompactScheduleTiming(int periods, int load_phase)
      : load_phase_(load_phase), v_(static_cast<std::size_t>(periods), false) {}

  // From the take's clock to the first clock the result is offered.
  int latency() const { return (static_cast<int>(v_.size()) - 1) * Period + load_phase_ + 2; }

  // This clock's ready_o and valid_o.
  bool ready() const { return ph_ == Period - 1; }
  bool valid() const { return out_valid_; }

  // One clock edge with the clock's valid_i and ready_i.
  void clock(bool valid_in, bool ready_in) {
    const bool load = ph_ == load_phase_ && v_.back();
    if (load && out_valid_ && !ready_in) return;  // the stall: nothing moves
    if (load) out_valid_ = true;
    else if (ready_in) out_valid_ = false;
    if (ph_ == Period - 1) {
      for (std::size_t k = v_.size() - 1; k > 0; --k) v_[k] = v_[k - 1];
      v_[0] = valid_in;
      ph_ = 0;
    } else {
      ++ph_;
    }
  }

 private:
  int load_phase_;
  int ph_ = 0;             // the clock within the period (0 after reset)
  std::vector<bool> v_;    // [k]: the item in its k-th period is valid
  bool out_valid_ = false;
};

}  // namespace watkins
