// Cycle twin of rtl/compact_normalizer_narrow.sv: its schedule's control
// (compact_schedule_timing.hpp) with the block's constants, no values (the unit vectors are
// Normalizer::normalize_narrow's, normalizer.hpp). A normal spends 3 periods inside and is loaded
// into the output register in phase 3 of the last: latency 15.
#pragma once

#include "compact_schedule_timing.hpp"

namespace watkins {

class CompactNormalizerNarrowTiming : public CompactScheduleTiming {
 public:
  static constexpr int Periods = 3, LoadPhase = 3;
  static constexpr int Latency = (Periods - 1) * Period + LoadPhase + 2;  // 15
  CompactNormalizerNarrowTiming() : CompactScheduleTiming(Periods, LoadPhase) {}
};

}  // namespace watkins
