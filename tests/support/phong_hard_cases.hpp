// The Phong hard cases as scenes, shared by the model tests (tests/test_phong_pipeline.cpp: bounds
// against the double reference) and the co-simulation (tests/cosim/test_cosim_phong.cpp: the RTL
// renders each of them bit for bit like the model).
#pragma once

#include <cmath>
#include <vector>

#include "scene_builder.hpp"

namespace watkins::test {

// A screen vertex carrying the camera-space normal (nx, ny, nz) as given: the pipeline and the
// reference both normalize after interpolation, so any length with |component| <= 1 is valid.
inline ScreenVertex rvtx(double x, double y, double nx, double ny, double nz, double depth = 0.5) {
  ScreenVertex v = vtx(x, y, depth);
  v.normal[0] = nx, v.normal[1] = ny, v.normal[2] = nz;
  return v;
}

// The same with the normal normalized.
inline ScreenVertex nvtx(double x, double y, double nx, double ny, double nz, double depth = 0.5) {
  const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
  return rvtx(x, y, nx / len, ny / len, nz / len, depth);
}

inline PhongMaterial material(double c, double d, double W, int n) {
  PhongMaterial m;
  m.cp[0] = m.cp[1] = m.cp[2] = c;
  m.d = d, m.W = W, m.n = n;
  return m;
}

// A Phong screen-space scene with one material (index 0) and a light towards `l` (normalized).
inline BuiltScene phong_scene(int w, int h, std::vector<ScreenPolygon> polys, const PhongMaterial& m,
                              double lx = 0, double ly = 0, double lz = -1) {
  BuiltScene s = screen(w, h, std::move(polys));
  s.shading = ShadingMode::Phong;
  s.materials = {m};
  const double len = std::sqrt(lx * lx + ly * ly + lz * lz);
  s.light[0] = lx / len, s.light[1] = ly / len, s.light[2] = lz / len;
  return s;
}

// A w x h quad at (x0, y0) whose corner normals tilt outwards by `t` around -Z: (∓t, ±t, -1)
// (camera +Y is up, screen +y down), so the normal is (0, 0, -1) only at the centre.
inline ScreenPolygon tilted_quad(double x0, double y0, double w, double h, double t) {
  return poly({nvtx(x0, y0, -t, t, -1), nvtx(x0 + w, y0, t, t, -1), nvtx(x0 + w, y0 + h, t, -t, -1),
               nvtx(x0, y0 + h, -t, -t, -1)});
}

// Antipodal vertex normals: left and right edges carry opposite normals, so the interpolated
// normal is exactly (0, 0, 0) in pixel column 32 on all 32 lines of the quad.
inline BuiltScene antipodal_normals_scene() {
  return phong_scene(70, 40,
                     {poly({rvtx(0.5, 0.5, 0.5, 0.25, -0.75), rvtx(64.5, 0.5, -0.5, -0.25, 0.75),
                            rvtx(64.5, 32.5, -0.5, 0.25, 0.75), rvtx(0.5, 32.5, 0.5, -0.25, -0.75)})},
                     material(0.8, 0.25, 0.5, 8));
}

// Normals almost in the screen plane (|Nz| = 0.001 before normalization), lit from the side.
inline BuiltScene screen_plane_normals_scene() {
  return phong_scene(72, 72,
                     {poly({nvtx(4, 4, -1, 0.2, -0.001), nvtx(68, 4, 0.2, 1, -0.001), nvtx(68, 68, 1, -0.2, -0.001),
                            nvtx(4, 68, -0.2, -1, -0.001)})},
                     material(0.7, 0.2, 0.6, 12), -1, 0.5, -0.05);
}

// Light grazing from behind-right, L = (1, 0, 0.1)/|.|: cos(i) changes sign inside the quad.
inline BuiltScene grazing_light_scene() {
  return phong_scene(
      72, 40,
      {poly({nvtx(4, 4, -0.3, 0, -1), nvtx(68, 4, 0.3, 0, -1), nvtx(68, 36, 0.3, 0, -1), nvtx(4, 36, -0.3, 0, -1)})},
      material(0.8, 0.25, 0.8, 1), 1, 0, 0.1);
}

// An off-centre highlight on a 128 x 128 quad for the specular exponent n (0..255).
inline BuiltScene shininess_scene(int n) {
  return phong_scene(140, 140, {tilted_quad(6, 6, 128, 128, 0.4)}, material(0.6, 0.125, 1.5, n), -0.2, 0.3, -1);
}

}  // namespace watkins::test
