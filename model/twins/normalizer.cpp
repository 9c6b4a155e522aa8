// Twin of rtl/normalizer.sv; see normalizer.hpp for the stage list (the stages are inline there:
// the Phong pipeline runs them per shaded pixel).
#include "normalizer.hpp"

namespace watkins {

static_assert(Normalizer::F + 4 - RsqrtUnit::MaxJ >= 1, "final shift must stay a right shift");
static_assert(fmt::NormalInBits - 1 + Normalizer::F + 1 <= 61, "scale() products are in round_shift62's range");

}  // namespace watkins
