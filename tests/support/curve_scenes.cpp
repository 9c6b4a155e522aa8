#include "curve_scenes.hpp"

#include <array>
#include <cmath>

namespace watkins::test {
namespace {

constexpr double DiscX = 52.3, DiscY = 46.7, DiscR = 34;

ScreenVertex crossing(double x, double depth, double nx, double ny, double nz, double r, double g, double b) {
  ScreenVertex v;
  v.x = x;
  v.depth = depth;
  const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
  v.normal[0] = nx / len, v.normal[1] = ny / len, v.normal[2] = nz / len;
  v.rgb[0] = r, v.rgb[1] = g, v.rgb[2] = b;
  return v;
}

// The six curves: x as a function of the line centre's y.
double disc_dx(double y) { return std::sqrt(DiscR * DiscR - (y - DiscY) * (y - DiscY)); }
double band_centre(double y) { return 118 + 14 * std::sin(y / 9); }
double steep_left(double y) { return 40 + 32 * std::tanh((y - 92.2) / 1.5); }

}  // namespace

ScreenCurve sampled_curve(int region, int material, int y0, int lines, const CrossingAt& f) {
  ScreenCurve c;
  c.region = region;
  c.material = material;
  c.y0 = y0;
  for (int k = 0; k < lines; ++k) {
    ScreenVertex v = f(y0 + k + 0.5);
    v.y = y0 + k + 0.5;
    c.lines.push_back(v);
  }
  return c;
}

double curve_scene_x(int i, double y) {
  switch (i) {
    case 0: return DiscX - disc_dx(y);
    case 1: return DiscX + disc_dx(y);
    case 2: return band_centre(y) - 9;
    case 3: return band_centre(y) + 9;
    case 4: return steep_left(y);
    default: return 100 + 0.1 * y;
  }
}

BuiltScene curve_scene(ShadingMode shading) {
  BuiltScene s;
  s.name = "curve scene";
  s.width = 160, s.height = 120;
  s.background[0] = 10, s.background[1] = 20, s.background[2] = 30;
  s.shading = shading;
  s.light[0] = -0.3, s.light[1] = -0.4, s.light[2] = -std::sqrt(1 - 0.09 - 0.16);
  s.materials.resize(4);
  const double cp[4][3] = {{0.9, 0.4, 0.3}, {0.3, 0.8, 0.4}, {0.4, 0.5, 0.95}, {0.5, 0.5, 0.5}};
  for (int m = 0; m < 4; ++m)
    for (int c = 0; c < 3; ++c) s.materials[m].cp[c] = cp[m][c];
  s.materials[0].n = 40, s.materials[1].n = 8, s.materials[2].n = 120;

  // A triangle behind everything: straight edges (d2 = d3 = 0) in the same stream.
  ScreenPolygon tri;
  for (const auto& p : {std::array<double, 2>{5, 5}, {155, 20}, {80, 118}}) {
    ScreenVertex v = crossing(p[0], 0.9, 0, 0, -1, 40, 40, 90);
    v.y = p[1];
    tri.v.push_back(v);
  }
  tri.material = 3;
  s.polygons.push_back(tri);

  // Region 0, the disc: lines whose centre lies strictly inside the circle.
  const int disc_y0 = static_cast<int>(std::ceil(DiscY - DiscR - 0.5));
  int disc_lines = 0;
  while (std::fabs(disc_y0 + disc_lines + 0.5 - DiscY) < DiscR) ++disc_lines;
  for (const int side : {-1, 1}) {
    s.curves.push_back(sampled_curve(0, 0, disc_y0, disc_lines, [side](double y) {
      const double dx = disc_dx(y), u = (y - DiscY) / DiscR;
      return crossing(DiscX + side * dx, 0.40 + 0.05 * u * u, 0.8 * side * dx / DiscR, 0.8 * u, -0.6,
                      200 - 60 * u * u, 80 + 60 * u, 120);
    }));
  }
  // Region 1, the band.
  for (const int side : {-1, 1}) {
    s.curves.push_back(sampled_curve(1, 1, 8, 104, [side](double y) {
      return crossing(band_centre(y) + side * 9, 0.3 + 0.1 * std::sin(y / 13), 0.5 * std::cos(y / 9) + 0.3 * side,
                      0.2, -0.8, 90 + 60 * std::sin(y / 9), 160, 40 + side * 30);
    }));
  }
  // Region 2, a steep curve and a nearly straight one.
  s.curves.push_back(sampled_curve(2, 2, 70, 46, [](double y) {
    const double t = std::tanh((y - 92.2) / 1.5);
    return crossing(steep_left(y), 0.6 - 0.1 * t, -0.7 * (1 - t * t), 0.3 * t, -0.7, 100 + 100 * t * t, 50, 200);
  }));
  s.curves.push_back(sampled_curve(2, 2, 70, 46, [](double y) {
    return crossing(100 + 0.1 * y, 0.55, 0.4, 0, -0.9, 60, 60 + y, 180);
  }));
  s.curve_regions = 3;
  return s;
}

}  // namespace watkins::test
