// Signed bits that hold a value (two's complement, sign included): 0 and -1 need 1, 255 needs 9.
// Private to scene preparation (the edge and span range checks and SceneNeeds).
#pragma once

#include "fixed_point.hpp"

namespace watkins {

inline int signed_bits(i128 v) {
  const i128 m = v < 0 ? ~v : v;  // >= 0; needs msb(m) + 2 bits (one more for the sign)
  if (m == 0) return 1;
  const std::uint64_t hi = static_cast<std::uint64_t>(m >> 64), lo = static_cast<std::uint64_t>(m);
  // 63 - clz is the index of the top set bit (msb_index, without its loop: this runs per span).
  return hi ? 64 + (63 - __builtin_clzll(hi)) + 2 : (63 - __builtin_clzll(lo)) + 2;
}

}  // namespace watkins
