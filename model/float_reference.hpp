// Double-precision reference of the same algorithm (GLM): the same edges, the same pixel-centre
// coverage rule, even-odd pairing into segments, Gouraud's α interpolation evaluated directly
// (S = (1 − α)S_E + αS_F, no stepping, no quantization), the same depth test and tie rule.
// Phong shading (BuiltScene::shading): the vertex normal is interpolated the same way, normalized
// in double and shaded with phong_levels (eq. 3). The fixed-point model's difference from it is
// the cost of quantization alone.
#pragma once

#include <array>

#include "image.hpp"
#include "scene.hpp"

namespace watkins {

struct FloatReferenceStats {
  long long fragments = 0;
};

// Phong's eq. (3), S = Cp [cos(i)(1 - d) + d] + W cos(s)^n, in double, with the rules of
// model/phong_shader.hpp: cos(i) = N.L; cos(s) = 2 (N.L)(N.E) - L.E clamped to [0, 1];
// cos(i) <= 0 (N = 0 included) gives Cp d and no specular; cos(s) <= 0 no specular (also for
// n = 0); d clamped to 1; specular white. Returns 255 S per channel clamped to [0, 255], unrounded.
std::array<double, 3> phong_levels(const PhongMaterial& m, const std::array<double, 3>& n,
                                   const double (&light)[3], const double (&eye)[3]);

Image render_float_reference(const BuiltScene& scene, FloatReferenceStats* stats = nullptr);

}  // namespace watkins
