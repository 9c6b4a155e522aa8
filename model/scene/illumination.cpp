#include "illumination.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace watkins {

std::array<double, 3> phong_levels(const PhongMaterial& m, const std::array<double, 3>& n,
                                   const double (&light)[3], const double (&eye)[3]) {
  const glm::dvec3 N(n[0], n[1], n[2]), L(light[0], light[1], light[2]), E(eye[0], eye[1], eye[2]);
  const double cos_i = std::max(glm::dot(N, L), 0.0);  // i > 90 degrees: no direct light
  const double cos_s = std::clamp(2 * cos_i * glm::dot(N, E) - glm::dot(L, E), 0.0, 1.0);
  const double d = std::min(m.d, 1.0);
  const double spec = cos_i > 0 && cos_s > 0 ? m.W * std::pow(cos_s, m.n) : 0.0;
  std::array<double, 3> out{};
  for (int c = 0; c < 3; ++c)
    out[c] = std::clamp(255.0 * (m.cp[c] * (cos_i * (1 - d) + d) + spec), 0.0, 255.0);
  return out;
}

}  // namespace watkins
