// The Phong block benches clock their units with the RTL unit benches' harness.
#pragma once

#include "rtl_harness.hpp"

namespace watkins::phong {
using rtl::Harness;
using rtl::Stalls;
}  // namespace watkins::phong
