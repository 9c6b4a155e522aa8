// Cycle twin of rtl/compact_normalizer.sv: its schedule's control (compact_schedule_timing.hpp)
// with the block's constants, no values (the unit vectors are Normalizer::normalize's,
// normalizer.hpp). A normal spends 7 periods inside and is loaded into the output register in
// phase 1 of the last: latency 33.
#pragma once

#include "compact_schedule_timing.hpp"

namespace watkins {

class CompactNormalizerTiming : public CompactScheduleTiming {
 public:
  static constexpr int Periods = 7, LoadPhase = 1;
  static constexpr int Latency = (Periods - 1) * Period + LoadPhase + 2;  // 33
  CompactNormalizerTiming() : CompactScheduleTiming(Periods, LoadPhase) {}
};

}  // namespace watkins
