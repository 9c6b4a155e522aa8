// JSON as the scene and configuration readers take it: nesting bounded (checked on the text
// before parsing, so nothing — the parser, the DOM's destructor, a message — recurses deeper on
// input), a key given twice in one object refused naming the key, errors located at line:column,
// offending values shown cut to 40 characters without serializing them whole.
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

namespace watkins {

// Parses `text` (named `name` in messages); throws SceneError on malformed JSON (located at
// line:column), nesting deeper than 64 or a duplicate key. `comments` allows // and /* */.
nlohmann::json parse_strict_json(const std::string& text, const std::string& name, bool comments);

// A value as messages show it: at most 40 characters, control characters escaped, built without
// serializing the whole value.
std::string show_json(const nlohmann::json& j);

}  // namespace watkins
