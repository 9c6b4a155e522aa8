// Twin of rtl/rsqrt_unit.sv; see rsqrt_unit.hpp (the stages are inline there: the normalizer runs
// them per fragment).
#include "rsqrt_unit.hpp"

namespace watkins {

static_assert((RsqrtUnit::W + 2) + 2 * (RsqrtUnit::T + 1) <= 62 && (RsqrtUnit::T + 1) + (RsqrtUnit::G + 3) <= 62,
              "rsqrt_mant products fit 64 bits");
static_assert(RsqrtUnit::seed(RsqrtUnit::MantLo >> (RsqrtUnit::W - RsqrtUnit::P)) < (1u << (RsqrtUnit::T + 1)),
              "seed must fit T+1 bits");
static_assert((RsqrtUnit::W + 1) + 2 * RsqrtUnit::T - RsqrtUnit::G >= 1 && RsqrtUnit::T + RsqrtUnit::G + 1 - RsqrtUnit::F >= 1,
              "rsqrt_mant's roundings are right shifts");

}  // namespace watkins
