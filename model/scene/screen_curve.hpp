// What Whitted's intersection processor hands to scene preparation for a curved surface: its
// edges (boundary curves, interior k_u/k_v curves and silhouettes of bicubic patches), each a
// y-monotonic piece of a curve in screen space with its crossing of every scan line it spans,
// found in double precision by Newton's iteration (model/curves). The crossings of one region
// (a subpatch, or the part of one on either side of a silhouette) pair into segments as a
// polygon's edges do: sorted by X, the first opens, the next closes. Preparation fits the
// hardware's forward-difference edge records to these crossings; the double reference steps
// between them as it does between polygon edges.
#pragma once

#include <vector>

#include "screen_polygon.hpp"

namespace watkins {

struct ScreenCurve {
  int region = 0;    // 0 .. BuiltScene::curve_regions - 1; preparation numbers regions after polygons
  int object = 0;    // index of the scene object it came from
  int material = 0;  // index into BuiltScene::materials (Phong)
  int y0 = 0;        // first scan line whose pixel centre (y0 + 0.5) it crosses, >= 0
  // lines[k]: the crossing of scan line y0 + k (y = y0 + k + 0.5): x, depth, eye_z, shade and
  // normal exactly as a polygon vertex carries them. Not empty.
  std::vector<ScreenVertex> lines;
};

}  // namespace watkins
