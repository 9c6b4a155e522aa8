// What the scene front end hands to scene preparation: polygons already in screen space,
// each vertex with its position in pixels, its depth and its shade. Everything is double
// here; quantization to fixed point happens in prepare.cpp and nowhere else.
#pragma once

#include <string>
#include <vector>

namespace watkins {

struct ScreenVertex {
  double x = 0;        // pixels, +x right; pixel (i, j) has its centre at (i + 0.5, j + 0.5)
  double y = 0;        // pixels, +y down (scan lines are numbered top to bottom)
  double depth = 0;    // [0, 1): smaller is nearer. Eq. (1) mode: 1 - near/Z; eq. (2): (Z-near)/(far-near); interpolation eq2: Z/far
  double eye_z = 0;    // camera-space Z of the vertex (0 for polygons given in screen space)
  double rgb[3] = {0, 0, 0};  // shade in 8-bit levels, [0, 255] (Gouraud)
  double normal[3] = {0, 0, -1};  // camera-space unit normal of the side seen (Phong)
};

struct ScreenPolygon {
  std::vector<ScreenVertex> v;  // 3 or 4 vertices in order around the polygon (quads may be non-planar)
  int object = 0;               // index of the scene object it came from
  int material = 0;             // index into BuiltScene::materials (Phong)
};

}  // namespace watkins
