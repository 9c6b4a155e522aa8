// Illumination in double precision: Phong's eq. (3), shared by the "phong" vertex rule of the
// front end, the double reference and the analytic truth (the fixed-point twin is
// model/twins/phong_shader.hpp).
#pragma once

#include <array>

#include "scene.hpp"

namespace watkins {

// Phong's eq. (3), S = Cp [cos(i)(1 - d) + d] + W cos(s)^n, in double, with the rules of
// model/twins/phong_shader.hpp: cos(i) = N.L; cos(s) = 2 (N.L)(N.E) - L.E clamped to [0, 1];
// cos(i) <= 0 (N = 0 included) gives Cp d and no specular; cos(s) <= 0 no specular (also for
// n = 0); d clamped to 1; specular white. Returns 255 S per channel clamped to [0, 255], unrounded.
std::array<double, 3> phong_levels(const PhongMaterial& m, const std::array<double, 3>& n,
                                   const double (&light)[3], const double (&eye)[3]);

}  // namespace watkins
