// watkins_export: writes a scene's edge-record stream and the model's expected pixels as hex
// files, for HDL simulators that read them with $readmemh (testbench/icarus/tb_watkins.sv).
//   edges.hex   one packed watkins_pkg::edge_t per line (116 hex digits, MSB first)
//   pixels.hex  one {covered, R, G, B} per pixel in raster order (7 hex digits)
//   frame.hex   width, height, background, edge count (one value per line)
#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>

#include "edge_packing.hpp"
#include "watkins_top.hpp"
#include "prepare.hpp"
#include "scene.hpp"

namespace {

// The default configuration's edge_t (the Icarus bench elaborates the top at its defaults).
void write_edge(std::ofstream& out, const watkins::tb::EdgeWords& w) {
  const watkins::tb::EdgeLayout& l = watkins::tb::default_edge_layout();
  // Hex digits from the top: the top word holds bits % 32 bits.
  char buf[16];
  for (int i = l.words - 1; i >= 0; --i) {
    const int bits = i == l.words - 1 ? l.bits - 32 * (l.words - 1) : 32;
    std::snprintf(buf, sizeof buf, "%0*x", (bits + 3) / 4, w[i]);
    out << buf;
  }
  out << '\n';
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"watkins_export: edge records and expected pixels as hex for HDL simulators"};
  std::string scene_path, dir = ".";
  app.add_option("scene", scene_path, "scene file (default: the embedded default scene)");
  app.add_option("--dir", dir, "output folder")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    using namespace watkins;
    const BuiltScene scene = load_scene_or_default(scene_path);
    const PreparedScene p = prepare(scene);
    const Image img = WatkinsTop().render(p);
    std::ofstream edges(dir + "/edges.hex"), pixels(dir + "/pixels.hex"), frame(dir + "/frame.hex");
    if (!edges || !pixels || !frame) throw std::runtime_error(dir + ": cannot write the hex files");
    for (const auto& e : p.edges) {
      write_edge(edges, tb::pack_edge(tb::default_edge_layout(), e));
    }
    char buf[16];
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const std::uint8_t* c = img.at(x, y);
        std::snprintf(buf, sizeof buf, "%01x%02x%02x%02x\n", img.is_covered(x, y) ? 1 : 0, c[0], c[1], c[2]);
        pixels << buf;
      }
    frame << std::hex << p.width << '\n' << p.height << '\n'
          << ((p.background[0] << 16) | (p.background[1] << 8) | p.background[2]) << '\n'
          << p.edges.size() << '\n';
    std::printf("%s: %zu edge records, %dx%d pixels -> %s/{edges,pixels,frame}.hex\n", scene.name.c_str(),
                p.edges.size(), p.width, p.height, dir.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "watkins_export: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
