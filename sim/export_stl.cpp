// watkins export-stl (export_stl.hpp).
#include "export_stl.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <string>

#include "options.hpp"
#include "run_files.hpp"
#include "scene.hpp"
#include "scene_types.hpp"
#include "stl_export.hpp"

namespace watkins::stl_command {

CLI::App* add_export_stl_command(CLI::App& app, ExportStlArgs& a) {
  auto* x = app.add_subcommand("export-stl", "write a scene's analytic surfaces and meshes, tessellated as render "
                                             "tessellates them, as STL in world space (z negated: STL and OBJ are "
                                             "right-handed; facets counter-clockwise seen from the front)");
  cli::add_file(x, "scene", a.scene, "scene file (JSON)")->required();
  cli::add_file(x, "--out,-o", a.out, "STL file to write")->required();
  x->add_flag("--ascii", a.ascii, "ASCII STL (default: binary)");
  return x;
}

int run_export_stl(const ExportStlArgs& a) {
  RunFiles files;
  const Scene parsed = parse_scene_file(a.scene);  // validates the whole scene first
  files.input("the scene file", a.scene);
  files.scene_inputs(parsed);
  files.output("--out", a.out);
  const BuildOptions opt;
  const BuiltScene built = build_scene(parsed, opt);
  const StlExport e = watkins::export_stl(*built.source, opt.max_faces);
  const std::string name = std::filesystem::path(a.scene).stem().string();
  if (a.ascii) files.add(a.out, stl_ascii(e, name));
  else files.add(a.out, stl_binary(e, "watkins export-stl " + name));
  files.commit();
  std::printf("wrote         %s: %zu facets (%s STL, world space, z negated)%s%s\n", a.out.c_str(), e.facets.size(),
              a.ascii ? "ASCII" : "binary", e.degenerate ? ", zero-area triangles left out: " : "",
              e.degenerate ? std::to_string(e.degenerate).c_str() : "");
  if (e.screen_polygons)
    std::printf("skipped       %d screen-space polygons object(s): no world geometry\n", e.screen_polygons);
  return 0;
}

}  // namespace watkins::stl_command
