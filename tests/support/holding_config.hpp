// The default configuration with an active-edge list as long as a scene needs: tests that run
// every shipped scene vary formats or compare renderers, not capacities, and the voxel phantoms at
// Herman and Liu's resolution need about 200 active edges against the default's 64.
#pragma once

#include <algorithm>

#include "config.hpp"
#include "prepare.hpp"
#include "scene.hpp"

namespace watkins::test {

inline Config default_holding(const BuiltScene& scene) {
  PrepareOptions o;
  o.max_active_edges = 1 << 16;
  Config c;
  c.max_active_edges = std::max(c.max_active_edges, prepare(scene, o).needs.max_active_edges);
  return c;
}

}  // namespace watkins::test
