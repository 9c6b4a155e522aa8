// Cycle twin of rtl/compact_phong_shader_narrow.sv: its schedule's control
// (compact_schedule_timing.hpp) with the block's constants, no values (the shades are
// PhongShader::shade_narrow's, phong_shader.hpp). A pixel spends 9 periods inside and is loaded
// into the output register in phase 0 of the last: latency 42.
#pragma once

#include "compact_schedule_timing.hpp"

namespace watkins {

class CompactPhongShaderNarrowTiming : public CompactScheduleTiming {
 public:
  static constexpr int Periods = 9, LoadPhase = 0;
  static constexpr int Latency = (Periods - 1) * Period + LoadPhase + 2;  // 42
  CompactPhongShaderNarrowTiming() : CompactScheduleTiming(Periods, LoadPhase) {}
};

}  // namespace watkins
