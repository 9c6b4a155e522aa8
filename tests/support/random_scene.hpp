// Random screen-space scenes for the model tests, the RTL unit benches and the co-simulation: one
// parameterized generator of polygon soups, its Phong dressing, and jittered meshes.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "scene.hpp"

namespace watkins::test {

// What random_scene draws. The defaults are the co-simulation's scenes (tests/cosim).
struct RandomSceneSpec {
  int min_width = 8, max_width = 96;
  int min_height = 8, max_height = 64;
  int min_polygons = 1, max_polygons = 12;
  bool convex_quads = true;  // quads on an ellipse in angle order; false: any four points (bow-ties)
  int snap_one_in = 5;       // one polygon in this many on pixel centres with a horizontal edge (0: none)
};

// Triangles and quads of random size around random centres, partly off screen, overlapping and
// (random per-vertex depths) interpenetrating; a random background. Zero-area polygons are
// dropped, so a scene may hold fewer than it drew. Draws from `rng` and nothing else: the same
// seed gives the same scene.
BuiltScene random_scene(std::mt19937_64& rng, const RandomSceneSpec& spec = {});

// The co-simulation's scene of `seed`, named "random scene <seed>".
BuiltScene random_scene(std::uint64_t seed);

// random_scene(seed)'s geometry with vertex normals and materials: normals mostly towards the
// viewer, some polygons with antipodal vertex normals (the interpolated normal passes through
// zero), some with normals in the screen plane; 1..16 materials with n over 0..255; a light from
// anywhere (grazing and from behind included). Named "random Phong scene <seed>".
BuiltScene random_phong_scene(std::uint64_t seed);

// A cols x rows mesh of quads (or two triangles each) over the rectangle at (x0, y0) of
// cols * cell_w by rows * cell_h pixels. Vertices move by up to `jitter` cells at random, X on
// the inner columns and Y on the inner rows, so the outline stays the rectangle and (jitter below
// 1/4) every quad stays convex; neighbours share their vertices (the same doubles). Each vertex
// gets a random shade and `depth`, or a random depth when none is given.
struct GridSpec {
  int cols = 1, rows = 1;
  double x0 = 0, y0 = 0, cell_w = 1, cell_h = 1;
  double jitter = 0;
  bool triangles = false;
  std::optional<double> depth;
};
std::vector<ScreenPolygon> jittered_grid(std::mt19937_64& rng, const GridSpec& spec);

// A w x h scene covered by a cols x rows jittered_grid of quads (jitter 0.3 of a cell, random
// depths), named "mesh": shared edges, so equal X on a line, ties broken by edge id.
BuiltScene mesh_scene(std::mt19937_64& rng, int w, int h, int cols, int rows);

}  // namespace watkins::test
