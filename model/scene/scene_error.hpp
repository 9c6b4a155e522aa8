// Bad input of any kind, from the scene front end and scene preparation. what() is the full
// user-facing message, e.g. "scenes/x.json: objects[2].radius: expected a positive number, got -1".
#pragma once

#include <cctype>
#include <sstream>
#include <stdexcept>
#include <string>

namespace watkins {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A number as messages show it: the shortest form the stream gives (1, 0.5, 1e+999 -> inf);
// any NaN is "NaN" (the stream may print "-nan").
inline std::string number_text(double x) {
  if (x != x) return "NaN";
  std::ostringstream os;
  os << x;
  return os.str();
}

// A name taken from input (a JSON key, a material, a file name) as a message shows it: in double
// quotes, with quotes, backslashes and control characters escaped as JSON escapes them, so a
// message never carries raw terminal control sequences. Cut to about 60 characters.
inline std::string quote_input(const std::string& s) {
  static const char* hex = "0123456789abcdef";
  std::string q = "\"";
  for (unsigned char c : s) {
    if (q.size() > 60) {
      q += "...";
      break;
    }
    if (c == '"' || c == '\\') {
      q += '\\';
      q += char(c);
    } else if (c < 0x20 || c == 0x7f) {
      q += "\\u00";
      q += hex[c >> 4];
      q += hex[c & 15];
    } else {
      q += char(c);
    }
  }
  return q + "\"";
}

// A key as a field path shows it: plain when it is a simple name, quoted otherwise.
inline std::string field_key(const std::string& k) {
  bool plain = !k.empty();
  for (unsigned char c : k) plain = plain && (std::isalnum(c) || c == '_' || c == '-');
  return plain ? k : quote_input(k);
}

}  // namespace watkins
