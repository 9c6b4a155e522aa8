// Bad input of any kind, from the scene front end and scene preparation. what() is the full
// user-facing message, e.g. "scenes/x.json: objects[2].radius: expected a positive number, got -1".
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace watkins {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A number as messages show it: the shortest form the stream gives (1, 0.5, 1e+999 -> inf).
inline std::string number_text(double x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

}  // namespace watkins
