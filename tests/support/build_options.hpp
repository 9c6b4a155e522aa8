// BuildOptions that pick the pipeline a scene file is built for, shared by the model tests and the
// co-simulation.
#pragma once

#include "scene.hpp"

namespace watkins::test {

// The scene file's shading mode overridden by `mode` (its vertex rule kept).
inline BuildOptions shading_options(ShadingMode mode) {
  BuildOptions o;
  o.shading = mode;
  return o;
}

// Phong against Gouraud on one scene: Gouraud evaluates the same illumination (the phong vertex
// rule, eq. (3)) at the vertices only, so the two differ only in what they interpolate.
struct PhongVsGouraud {
  BuildOptions phong, gouraud;
};

inline PhongVsGouraud phong_vs_gouraud() {
  PhongVsGouraud o{shading_options(ShadingMode::Phong), shading_options(ShadingMode::Gouraud)};
  o.gouraud.rule = ShadingRule::Phong;
  return o;
}

}  // namespace watkins::test
