// The one error a hardware twin raises: the frame asks for more than the hardware holds (an
// active-edge list overflow). Scene problems are the front end's SceneError; a twin never sees them.
#pragma once

#include <stdexcept>

namespace watkins {

class CapacityError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace watkins
