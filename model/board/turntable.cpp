// The turntable's frames (turntable.hpp).
#include "turntable.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "camera.hpp"

namespace watkins::board {
namespace {

constexpr double DegPerRad = 180.0 / 3.14159265358979323846;

glm::dmat3 object_linear(const Transform& t) {
  return rotation(t.rotate_deg) * glm::dmat3(t.scale.x, 0, 0, 0, t.scale.y, 0, 0, 0, t.scale.z);
}

glm::dvec3 anchor(const SceneObject& o) {
  const bool centred = o.type == ObjectType::Sphere || o.type == ObjectType::Cone || o.type == ObjectType::Pier;
  return o.transform.translate + object_linear(o.transform) * (centred ? o.center : glm::dvec3(0.0));
}

}  // namespace

glm::dvec3 euler_degrees(const glm::dmat3& m) {
  // m = Rz(c) Ry(b) Rx(a); glm is column-major, m[col][row]: row 2 is (-sin b, cos b sin a,
  // cos b cos a), column 0 is (cos c cos b, sin c cos b, -sin b).
  const double sb = std::clamp(-m[0][2], -1.0, 1.0);
  const double b = std::asin(sb);
  double a = 0, c = 0;
  if (std::abs(sb) < 1 - 1e-12) {
    a = std::atan2(m[1][2], m[2][2]);
    c = std::atan2(m[0][1], m[0][0]);
  } else {
    a = std::atan2(-m[2][1], m[1][1]);  // gimbal lock: c = 0, row 1 is (0, cos a, -sin a)
  }
  return glm::dvec3(a, b, c) * DegPerRad;
}

glm::dvec3 turntable_centre(const Scene& scene) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const SceneObject& o : scene.objects) {
    const glm::dvec3 p = anchor(o);
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], p[c]);
      hi[c] = std::max(hi[c], p[c]);
    }
  }
  return scene.objects.empty() ? glm::dvec3(0.0) : (lo + hi) * 0.5;
}

Scene turntable(const Scene& scene, double degrees) {
  const glm::dvec3 centre = turntable_centre(scene);
  const glm::dmat3 turn = rotation(glm::dvec3(0, degrees, 0));
  Scene out = scene;
  for (SceneObject& o : out.objects) {
    if (o.type == ObjectType::Polygons)
      throw std::invalid_argument(scene.name + ": " + o.field + ": screen-space polygons cannot turn on a turntable");
    o.transform.rotate_deg = euler_degrees(turn * rotation(o.transform.rotate_deg));
    o.transform.translate = centre + turn * (o.transform.translate - centre);
  }
  return out;
}

}  // namespace watkins::board
