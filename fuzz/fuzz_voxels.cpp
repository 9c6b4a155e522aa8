// libFuzzer target: a voxel scene with a raw volume. The input up to its first NUL byte is the
// scene's JSON; the bytes after it are written to `volume.raw` in the process's private scratch
// folder, which is the scene's base folder, so `"file": "volume.raw"` names them (an input without
// a NUL has no volume file at all). The scene is parsed, built and prepared. A SceneError (or the
// preparation's CapacityError) is the expected answer to bad input; any other exception, a crash
// or a sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <system_error>

#include "fuzz_util.hpp"
#include "prepare.hpp"
#include "scene.hpp"
#include "twin_error.hpp"

namespace {

// Small enough that one input costs milliseconds (the command line allows 2^22).
constexpr std::size_t kFuzzMaxFaces = 20000;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const watkins::fuzz::ScratchDir& dir = watkins::fuzz::ScratchDir::instance();
  const std::string input = watkins::fuzz::bytes_of(data, size);
  const std::size_t nul = input.find('\0');
  if (nul == std::string::npos) {
    std::error_code ec;
    std::filesystem::remove(dir.path() + "/volume.raw", ec);
  } else {
    dir.write("volume.raw", input.substr(nul + 1));
  }
  watkins::BuildOptions opt;
  opt.max_faces = kFuzzMaxFaces;
  try {
    const watkins::BuiltScene scene = watkins::load_scene_text(input.substr(0, nul), "fuzz.json", dir.path(), opt);
    (void)watkins::prepare(scene);
  } catch (const watkins::SceneError&) {
  } catch (const watkins::CapacityError&) {  // the frame needs more active edges than the hardware holds
  }
  return 0;
}
