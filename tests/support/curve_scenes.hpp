// Screen curves built in code for the curved-edge hardware (edge_order 3): the model tests and the
// co-simulation render the same ones. Each curve carries its exact double crossing of every scan
// line, as Whitted's intersection processor hands them to preparation (ScreenCurve).
#pragma once

#include <functional>

#include "scene.hpp"

namespace watkins::test {

// One channel set on a scan line's crossing: x, depth, shade and normal from the line's centre y.
using CrossingAt = std::function<ScreenVertex(double y)>;

// The curve crossing lines y0 .. y0 + lines - 1 at f(y + 0.5).
ScreenCurve sampled_curve(int region, int material, int y0, int lines, const CrossingAt& f);

// A 160 x 120 scene of three curved regions over one triangle (Phong materials 0..2 for the
// regions, 3 for the triangle; Gouraud shades on every crossing as well):
//   region 0: a disc, the left and right halves of a circle of radius 34 at (52.3, 46.7);
//   region 1: a sine-like band, x = 118 + 14 sin(y/9) +- 9, lines 8 .. 111;
//   region 2: a curve with a steep part, x = 40 + 32 tanh((y - 92.2)/1.5) (about 21 pixels per
//             line at its steepest), closed on the right by x = 100 + 0.1 y.
// Depth, shade and normal vary along every curve, not linearly.
BuiltScene curve_scene(ShadingMode shading);

// The exact crossing of curve `i` of curve_scene on scan line y (centre y + 0.5): the double X
// a per-line check compares the hardware's with.
double curve_scene_x(int i, double y);

}  // namespace watkins::test
