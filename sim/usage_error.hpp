// A wrong command line: an unknown option value, a missing companion option, a value out of range.
// `watkins` reports it as "watkins: usage: ..." with exit code 2, as against bad input (a scene,
// configuration or OBJ file: 1) and internal errors or RTL mismatches (3). Every subcommand throws
// it for its own options.
#pragma once

#include <stdexcept>

namespace watkins {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace watkins
