// watkins voxel-compare: Herman and Liu's comparison (1978) on the voxel phantoms, in this
// pipeline's terms. Each scene is rendered flat (one shade per voxel face, their Fig. 2), Gouraud
// with averaged vertex normals (their Fig. 3), Phong on the same normals, and flat followed by the
// image-space smoother at a sweep of W (their Fig. 4, W = 0.8), all with eq. (3) illumination so
// the analytic truth (the exact phantom) measures each: error mean and max, Mach-band measures, and
// the cost: front-end (software preparation) time and cycles per frame from the cycle model.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace watkins::voxel_compare {

struct VoxelCompareArgs {
  std::vector<std::string> scenes;  // default: scenes/voxel_{ellipsoid,beaded,two_lobed}.json
  std::vector<double> weights{0.2, 0.4, 0.6, 0.8, 1.0};  // W of the smoother sweep
  std::string md;      // markdown table (default: stdout only)
  std::string images;  // folder for <scene>_{flat,gouraud,phong,smooth,truth}.png
  int repeat = 5;      // front-end timings: the best of this many builds
};

CLI::App* add_voxel_compare_command(CLI::App& app, VoxelCompareArgs& a);
// Nothing to check beyond the option layer's rules (options.hpp): every option is one value.
inline void check_voxel_compare(const VoxelCompareArgs&) {}
int run_voxel_compare(const VoxelCompareArgs& a);

}  // namespace watkins::voxel_compare
