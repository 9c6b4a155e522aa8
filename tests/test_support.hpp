// Small helpers shared by the model tests: build screen-space scenes by hand and run them.
#pragma once

#include <initializer_list>
#include <vector>

#include "float_reference.hpp"
#include "watkins_top.hpp"
#include "prepare.hpp"
#include "scene.hpp"

namespace watkins::test {

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

inline BuiltScene screen(int w, int h, std::vector<ScreenPolygon> polys) {
  BuiltScene s;
  s.name = "test";
  s.width = w, s.height = h;
  s.polygons = std::move(polys);
  return s;
}

// Renders with the fixed-point model; counts fragments per pixel when `hits` is given.
// The active-edge capacity is raised above the default so meshes are not limited by it here.
inline Image render_fixed(const BuiltScene& s, std::vector<int>* hits = nullptr,
                          PipelineStats* stats = nullptr, int max_active_edges = 1024) {
  const PreparedScene p = prepare(s, PrepareOptions{max_active_edges});
  WatkinsTop pipe(max_active_edges);
  if (hits) hits->assign(std::size_t(s.width) * s.height, 0);
  Image img = pipe.render(p, [&](int y, const Fragment& f, bool) {
    if (hits) ++(*hits)[std::size_t(y) * s.width + f.x];
  });
  if (stats) *stats = pipe.stats();
  return img;
}

}  // namespace watkins::test
