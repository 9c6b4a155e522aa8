// Small helpers shared by the model tests: screen-space scenes (scene_builder.hpp) and a run of the
// fixed-point model over one.
#pragma once

#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "float_reference.hpp"
#include "watkins_top.hpp"
#include "prepare.hpp"
#include "scene.hpp"
#include "scene_builder.hpp"

namespace watkins::test {

// The message f throws, "" when it throws nothing.
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
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
