// The strict JSON reader of scenes and configuration files (strict_json.hpp).
#include "strict_json.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene_error.hpp"

namespace watkins {
namespace {

using nlohmann::json;

// Deepest nesting of arrays and objects a file may use (the shipped scenes need 6). Checked on
// the text before parsing, so nothing downstream (the DOM, its destructor, messages) ever
// recurses deeper than this on input.
constexpr int kMaxNesting = 64;

// A short rendering of an offending value for messages: at most 40 characters, built without
// serializing the whole value (an array of 10^6 numbers renders its first few) and with control
// characters escaped as JSON does.
void show_into(const json& j, std::string& out, int depth) {
  if (out.size() > 40) return;
  if (j.is_array() || j.is_object()) {
    if (depth >= 3) {
      out += j.is_array() ? "[...]" : "{...}";
      return;
    }
    out += j.is_array() ? '[' : '{';
    bool first = true;
    for (auto it = j.begin(); it != j.end() && out.size() <= 40; ++it) {
      if (!first) out += ',';
      first = false;
      if (j.is_object()) out += json(it.key()).dump(-1, ' ', false, json::error_handler_t::replace) + ':';
      show_into(it.value(), out, depth + 1);
    }
    out += j.is_array() ? ']' : '}';
    return;
  }
  out += j.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string show(const json& j) {
  std::string s;
  show_into(j, s, 0);
  if (s.size() > 40) s = s.substr(0, 37) + "...";
  return s;
}

// nlohmann reports a byte offset; turn it into the line:column editors show.
std::string located(const std::string& name, const std::string& text, size_t idx, const std::string& detail) {
  idx = std::min(idx, text.size());
  int line = 1, col = 1;
  for (size_t i = 0; i < idx; ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return name + ":" + std::to_string(line) + ":" + std::to_string(col) + ": malformed JSON: " + detail;
}

std::string parse_error_message(const std::string& name, const std::string& text, const json::parse_error& e) {
  std::string detail = e.what();
  auto pos = detail.find(": ");  // drop "[json.exception.parse_error.101] parse error at line 1, column 2"
  if (pos != std::string::npos) detail = detail.substr(pos + 2);
  // e.byte is 1-based: the offending character is text[e.byte - 1].
  return located(name, text, e.byte > 0 ? e.byte - 1 : 0, detail);
}

// Number overflow (e.g. 1e999) carries no position; find the quoted token in the text.
std::string overflow_message(const std::string& name, const std::string& text, const json::out_of_range& e) {
  std::string detail = e.what();
  auto pos = detail.find("] ");
  if (pos != std::string::npos) detail = detail.substr(pos + 2);
  auto q0 = detail.find('\''), q1 = detail.rfind('\'');
  if (q0 != std::string::npos && q1 > q0) {
    auto at = text.find(detail.substr(q0 + 1, q1 - q0 - 1));
    if (at != std::string::npos) return located(name, text, at, detail);
  }
  return name + ": malformed JSON: " + detail;
}

// The byte offset where arrays and objects nest deeper than kMaxNesting, or npos. A scan of
// the text (strings and comments skipped), so a hostile file is refused before any parse.
size_t too_deep_at(const std::string& t) {
  int depth = 0;
  for (size_t i = 0; i < t.size(); ++i) {
    const char c = t[i];
    if (c == '"') {
      for (++i; i < t.size() && t[i] != '"'; ++i)
        if (t[i] == '\\') ++i;
    } else if (c == '/' && i + 1 < t.size() && t[i + 1] == '/') {
      while (i < t.size() && t[i] != '\n') ++i;
    } else if (c == '/' && i + 1 < t.size() && t[i + 1] == '*') {
      const size_t end = t.find("*/", i + 2);
      if (end == std::string::npos) return std::string::npos;  // the parser reports it
      i = end + 1;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxNesting) return i;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return std::string::npos;
}

// nlohmann's DOM builder, plus what it lets pass: a key given twice in one object (the last one
// would silently win) is an error naming the object and the key, and nesting is bounded again
// (the text scan above is the check that reports a position; this one guards the parser).
class StrictDomParser : public nlohmann::detail::json_sax_dom_parser<json> {
  using Base = nlohmann::detail::json_sax_dom_parser<json>;

 public:
  explicit StrictDomParser(json& root) : Base(root, true) {}
  std::string duplicate;  // "field: key" of the first duplicate key, if any
  bool too_deep = false;

  bool null() { return element(), Base::null(); }
  bool boolean(bool v) { return element(), Base::boolean(v); }
  bool number_integer(json::number_integer_t v) { return element(), Base::number_integer(v); }
  bool number_unsigned(json::number_unsigned_t v) { return element(), Base::number_unsigned(v); }
  bool number_float(json::number_float_t v, const std::string& s) { return element(), Base::number_float(v, s); }
  bool string(std::string& v) { return element(), Base::string(v); }
  bool binary(json::binary_t& v) { return element(), Base::binary(v); }
  bool start_object(std::size_t n) {
    element();
    if (frames_.size() >= static_cast<size_t>(kMaxNesting)) return too_deep = true, false;
    frames_.push_back({true, {}, {}, -1});
    return Base::start_object(n);
  }
  bool key(std::string& k) {
    Frame& f = frames_.back();
    if (!f.keys.insert(k).second) {
      duplicate = path();
      duplicate += (duplicate.empty() ? "" : ": ") + std::string("duplicate key ") + quote_input(k);
      return false;
    }
    f.key = k;
    return Base::key(k);
  }
  bool end_object() { return frames_.pop_back(), Base::end_object(); }
  bool start_array(std::size_t n) {
    element();
    if (frames_.size() >= static_cast<size_t>(kMaxNesting)) return too_deep = true, false;
    frames_.push_back({false, {}, {}, -1});
    return Base::start_array(n);
  }
  bool end_array() { return frames_.pop_back(), Base::end_array(); }

 private:
  struct Frame {
    bool object;
    std::set<std::string> keys;
    std::string key;  // object: the key of the value being read
    long long index;  // array: the index of the value being read
  };
  void element() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
  }
  // The field path of the object whose key is being read, as messages spell fields.
  std::string path() const {
    std::string p;
    for (size_t i = 0; i + 1 < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      if (f.object) p += (p.empty() ? "" : ".") + field_key(f.key);
      else p += "[" + std::to_string(f.index) + "]";
    }
    return p;
  }
  std::vector<Frame> frames_;
};

}  // namespace

// Parses `text` (named `name` in messages); throws SceneError on malformed JSON, nesting deeper
// than 64 or a duplicate key. `comments` allows // and /* */ comments.
nlohmann::json parse_strict_json(const std::string& text, const std::string& name, bool comments) {
  if (const size_t at = too_deep_at(text); at != std::string::npos)
    throw SceneError(located(name, text, at, "arrays and objects nested deeper than " +
                                                 std::to_string(kMaxNesting) + " levels"));
  json root;
  try {
    StrictDomParser sax(root);
    if (!json::sax_parse(text, &sax, json::input_format_t::json, /*strict=*/true, comments)) {
      if (!sax.duplicate.empty()) throw SceneError(name + ": " + sax.duplicate);
      throw SceneError(name + ": malformed JSON: arrays and objects nested deeper than " +
                       std::to_string(kMaxNesting) + " levels");
    }
  } catch (const json::parse_error& e) {
    throw SceneError(parse_error_message(name, text, e));
  } catch (const json::out_of_range& e) {
    throw SceneError(overflow_message(name, text, e));
  } catch (const json::exception& e) {
    throw SceneError(name + ": malformed JSON: " + e.what());
  }
  return root;
}

// A value as messages show it: at most 40 characters, control characters escaped.
std::string show_json(const nlohmann::json& j) { return show(j); }

}  // namespace watkins
