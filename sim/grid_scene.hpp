// The throughput scene of the benchmarks: a size x size screen tiled by cells x cells
// squares, each split into two triangles, so every pixel is covered exactly once (size^2
// fragments, 2 cells^2 triangles), with shades and depths varying smoothly across the screen.
// watkins_bench and watkins_gl_bench render the same triangles.
#pragma once

#include <string>

#include "scene.hpp"

namespace watkins {

inline BuiltScene grid_scene(int size, int cells) {
  BuiltScene s;
  s.name = "grid " + std::to_string(size) + "x" + std::to_string(size) + ", " + std::to_string(2 * cells * cells) +
           " triangles";
  s.width = s.height = size;
  const double step = double(size) / cells;
  auto vertex = [&](int i, int j) {
    ScreenVertex v;
    v.x = i * step, v.y = j * step;
    v.depth = 0.25 + 0.5 * (i + j) / (2.0 * cells);
    v.rgb[0] = 255.0 * i / cells, v.rgb[1] = 255.0 * j / cells, v.rgb[2] = 255.0 * ((i + j) % 2);
    return v;
  };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      ScreenPolygon a, b;
      a.v = {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)};
      b.v = {vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)};
      s.polygons.push_back(a);
      s.polygons.push_back(b);
    }
  return s;
}

}  // namespace watkins
