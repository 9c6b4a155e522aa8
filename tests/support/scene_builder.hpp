// Screen-space scenes built in code: a vertex, a polygon and the BuiltScene around them. Shared by
// the model tests, the RTL unit benches and the co-simulation (one builder, not a BuiltScene filled
// field by field in every test).
#pragma once

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "scene.hpp"

namespace watkins::test {

// A vertex at pixel position (x, y) with its depth and Gouraud shade (8-bit levels).
inline ScreenVertex vtx(double x, double y, double depth = 0.5, double r = 0, double g = 0, double b = 0) {
  ScreenVertex v;
  v.x = x, v.y = y, v.depth = depth;
  v.rgb[0] = r, v.rgb[1] = g, v.rgb[2] = b;
  return v;
}

inline ScreenPolygon poly(std::initializer_list<ScreenVertex> vs) {
  ScreenPolygon p;
  p.v = vs;
  return p;
}

// Background levels of a screen-space scene.
struct Background {
  double r = 0, g = 0, b = 0;
};

// A w x h screen-space scene (Gouraud, default depth mode); `name` is what reports and
// prepare()'s messages call it.
inline BuiltScene screen(int w, int h, std::vector<ScreenPolygon> polys = {}, std::string name = "test",
                         Background bg = {}) {
  BuiltScene s;
  s.name = std::move(name);
  s.width = w, s.height = h;
  s.background[0] = bg.r, s.background[1] = bg.g, s.background[2] = bg.b;
  s.polygons = std::move(polys);
  return s;
}

}  // namespace watkins::test
