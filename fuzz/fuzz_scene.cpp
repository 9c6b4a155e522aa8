// libFuzzer target over the scene front end and preparation (scripts/fuzz builds and runs it
// under ASan + UBSan). An input that starts (after white space) with '{' or '/' is a JSON scene:
// parsed, built and prepared, and read as a configuration file too. Anything else is a mesh file: written to a scratch file, loaded as
// the mesh of a small fixed scene, built and prepared: STL (binary by its size, or starting with
// "solid") with crease-angle normals and its faces split, else OBJ (normals from the file when it
// has vn lines, else averaged). A clean SceneError (or the prepare's capacity error) is the expected
// outcome of bad input; any other exception, a crash or a sanitizer report is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "config_file.hpp"
#include "mesh_stl.hpp"
#include "prepare.hpp"
#include "scene.hpp"

namespace {

// Small enough that one input costs milliseconds, not seconds (the CLI's limit is 2^22).
constexpr std::size_t kFuzzMaxFaces = 20000;

const std::string& scratch_obj() {
  static const std::string path = "/tmp/watkins_fuzz_" + std::to_string(::getpid()) + ".mesh";  // told by content
  return path;
}

void run(const std::string& text, const std::string& name) {
  watkins::BuildOptions opt;
  opt.max_faces = kFuzzMaxFaces;
  try {
    // Relative mesh paths resolve into a folder that does not exist.
    const watkins::BuiltScene scene = watkins::load_scene_text(text, name, "/nonexistent-watkins-fuzz", opt);
    (void)watkins::prepare(scene);
  } catch (const watkins::SceneError&) {
  } catch (const std::runtime_error&) {  // CapacityError: the frame needs more active edges
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const size_t first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && (text[first] == '{' || text[first] == '/')) {
    run(text, "fuzz.json");
    try {  // the same text as a configuration file (the same strict JSON reader, other fields)
      (void)watkins::parse_config(text, "fuzz-config.json");
    } catch (const watkins::SceneError&) {
    }
    return 0;
  }
  std::FILE* f = std::fopen(scratch_obj().c_str(), "wb");
  if (!f) return 0;
  std::fwrite(text.data(), 1, text.size(), f);
  std::fclose(f);
  const bool stl = watkins::is_binary_stl(text) || text.compare(0, 5, "solid") == 0;
  const bool vn = text.find("vn") != std::string::npos;
  const std::string normals = stl ? "\"crease_angle_deg\": 60, \"max_edge_length\": 0.5"
                                  : std::string("\"normals\": \"") + (vn ? "file" : "average") + "\"";
  run(std::string("{\"screen\": {\"width\": 64, \"height\": 48},\n"
                  " \"camera\": {\"type\": \"lookat\", \"eye\": [0, 1, -4], \"target\": [0, 0, 0]},\n"
                  " \"shading\": {\"cull_backfaces\": false},\n"
                  " \"objects\": [{\"type\": \"mesh\", \"file\": \"") +
          scratch_obj() + "\", " + normals + "}]}",
      "fuzz-obj.json");
  return 0;
}
