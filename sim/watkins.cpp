// watkins: the command line of the Watkins pipeline model. Subcommands (docs/guide/cli.md):
//   render       one scene through the model, the double reference and the truth; --rtl the RTL (render.cpp)
//   sweep        error against cost over a grid of scenes and formats (sweep.cpp)
//   size         the smallest configuration a scene needs (size.cpp)
//   synth        synthesis, placement and routing of every block and top (synth.cpp)
//   voxel-compare  Herman & Liu's comparison on voxel phantoms (voxel_compare.cpp)
//   export-stl   a scene's surfaces as STL (export_stl.cpp)
// Every subcommand declares its options through options.hpp and its files through run_files.hpp.
#include "commands.hpp"

int main(int argc, char** argv) { return watkins::cli::main_entry(argc, argv); }
