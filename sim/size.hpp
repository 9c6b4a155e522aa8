// watkins size: the smallest hardware configuration a scene needs. A search, not a formula:
// fraction bits per channel group and depth_bits lowered one bit at a time while the fixed-point
// image stays within L levels of the double reference, integer bits and capacities exactly what the
// scene needs. See size.cpp.
#pragma once

#include <string>

#include "config.hpp"
#include "scene.hpp"

namespace CLI {
class App;
}

namespace watkins::size {

struct SizeArgs {
  std::string scene;          // scene file; the embedded default scene when empty
  std::string bound = "1";    // levels; parsed by run_size so bad input is one line
  std::string out;            // configuration file; default <scene stem>.config.json
  std::string shading;        // gouraud | phong; default the scene's
  std::string interpolation;  // eq1 or eq2 (Gouraud's equations); else the scene's
  std::string patches;        // curves | polygons; default each patch object's "draw"
  bool compact = false;       // the compact top: compact true, a Phong scene's narrow formats
};

// Registers `watkins size` and its options on `app`; returns the subcommand.
CLI::App* add_size_command(CLI::App& app, SizeArgs& args);
// The checks of the command line that need no file: UsageError (exit code 2) naming the option.
void check_size(const SizeArgs& args);
// Runs the search, prints the report and writes the configuration; returns the exit code.
// Bad input throws (one line, no file written).
int run_size(const SizeArgs& args);
// The configuration run_size chooses for a built scene at `bound` levels (its search, without the
// report and the file): what `watkins board` sizes a scene with. `compact`: as --compact.
Config sized_config(const BuiltScene& scene, int bound = 1, bool compact = false);

}  // namespace watkins::size
