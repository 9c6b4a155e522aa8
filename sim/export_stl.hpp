// watkins export-stl: a scene's analytic surfaces and meshes, tessellated as render tessellates
// them, as an STL file in world space (model/scene/stl_export.hpp). See export_stl.cpp.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace watkins::stl_command {

struct ExportStlArgs {
  std::string scene, out;
  bool ascii = false;
};

CLI::App* add_export_stl_command(CLI::App& app, ExportStlArgs& args);
int run_export_stl(const ExportStlArgs& args);

}  // namespace watkins::stl_command
