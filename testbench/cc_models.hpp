// The Verilated --cc builds of watkins_top: the default configuration's two speed tops (Phong = 0
// and 1, no assertions, no tracing) and one per other configuration of CMake's
// WATKINS_RTL_CONFIGS (assertions on; testbench/CMakeLists.txt): a registry the build generates
// (cc_models.cpp in the build folder), one entry per distinct parameter list. No Verilator
// header here: rtl_bench.cpp picks an entry by parameters and drives it through TopPins.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "config.hpp"
#include "top_pins.hpp"

namespace watkins::tb::detail {

// One Verilated top with its context, its pins and its stage taps bound (cc_model.hpp).
class CcModel {
 public:
  virtual ~CcModel() = default;
  virtual TopPins& pins() = 0;
};

struct CcModelEntry {
  std::string built_for;               // the WATKINS_RTL_CONFIGS entries it serves ("F@gouraud", ...)
  std::vector<RtlParameter> params;    // rtl_parameters() of those entries, as Verilator got them
  std::unique_ptr<CcModel> (*make)();  // a fresh model at reset
  bool default_config = false;         // one of the default configuration's speed tops (no assertions)
};

// Every per-configuration model of this build (empty when WATKINS_RTL_CONFIGS is).
const std::vector<CcModelEntry>& cc_models();

}  // namespace watkins::tb::detail
