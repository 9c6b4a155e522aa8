// Cycle twin of rtl/compact_phong_shader.sv: its schedule's control (compact_schedule_timing.hpp)
// with the block's constants, no values (the shades are PhongShader::shade's, phong_shader.hpp).
// A pixel spends 13 periods inside and is loaded into the output register in phase 3 of the
// last: latency 65.
#pragma once

#include "compact_schedule_timing.hpp"

namespace watkins {

class CompactPhongShaderTiming : public CompactScheduleTiming {
 public:
  static constexpr int Periods = 13, LoadPhase = 3;
  static constexpr int Latency = (Periods - 1) * Period + LoadPhase + 2;  // 65
  CompactPhongShaderTiming() : CompactScheduleTiming(Periods, LoadPhase) {}
};

}  // namespace watkins
