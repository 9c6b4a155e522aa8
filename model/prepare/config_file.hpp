// Configuration files (docs/guide/config-format.md): a JSON object with the format of each channel
// group and the capacities, every key optional (a missing key keeps the default, which is
// formats.hpp's). Bad input is a SceneError of one line naming the file and the field,
// like scenes: "narrow.json: shade.frac_bits: expected an integer, got 2.5".
#pragma once

#include <string>

#include "config.hpp"

namespace watkins {

// Parses `text`; `name` prefixes every message. The result passes Config::check().
Config parse_config(const std::string& text, const std::string& name);
// Reads and parses the file at `path`.
Config load_config(const std::string& path);
// The configuration as a file parse_config reads back (every key written but edge_order 1 and
// smoothing true, the defaults, so older files and new ones read the same).
std::string config_json(const Config& config);

}  // namespace watkins
