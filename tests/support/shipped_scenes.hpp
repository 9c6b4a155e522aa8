// The shipped scenes (scenes/*.json under WATKINS_SOURCE_DIR, a compile definition of the test
// target), sorted: file names for test parameters, or full paths.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace watkins::test {

inline std::vector<std::string> shipped_scene_names() {
  std::vector<std::string> v;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(WATKINS_SOURCE_DIR "/scenes", ec))
    if (e.path().extension() == ".json") v.push_back(e.path().filename().string());
  std::sort(v.begin(), v.end());
  return v;
}

inline std::vector<std::string> shipped_scene_paths() {
  std::vector<std::string> v = shipped_scene_names();
  for (std::string& s : v) s = WATKINS_SOURCE_DIR "/scenes/" + s;
  return v;
}

}  // namespace watkins::test
