// libFuzzer target: configuration files (model/prepare/config_file.hpp). The input is parsed as a
// configuration; a configuration it accepts is written back with config_json and must parse again
// to the same text (what `watkins size` writes, `--config` reads). A SceneError is the expected
// answer to bad input; any other exception, a failed round trip, a crash or a sanitizer report is
// a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "config_file.hpp"
#include "fuzz_util.hpp"
#include "scene_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  watkins::Config config;
  try {
    config = watkins::parse_config(watkins::fuzz::bytes_of(data, size), "fuzz-config.json");
  } catch (const watkins::SceneError&) {
    return 0;
  }
  const std::string written = watkins::config_json(config);
  std::string again;
  try {
    again = watkins::config_json(watkins::parse_config(written, "written.json"));
  } catch (const watkins::SceneError& e) {
    std::fprintf(stderr, "config round trip: the written configuration is refused: %s\n%s\n", e.what(), written.c_str());
    std::abort();
  }
  if (again != written) {
    std::fprintf(stderr, "config round trip: written\n%s\nread back and written\n%s\n", written.c_str(), again.c_str());
    std::abort();
  }
  return 0;
}
