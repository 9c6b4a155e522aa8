// The camera and object transforms of the scene front end, shared by scene_build.cpp (which
// projects the tessellated surfaces) and analytic_truth.cpp (which ray-casts the exact ones).
#pragma once

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "scene_types.hpp"

namespace watkins {

// Column-major glm: m[c][r]. Rotation applies X first, then Y, then Z.
inline glm::dmat3 rotation(const glm::dvec3& deg) {
  const glm::dvec3 a = deg * (3.14159265358979323846 / 180.0);
  const double cx = std::cos(a.x), sx = std::sin(a.x), cy = std::cos(a.y), sy = std::sin(a.y),
               cz = std::cos(a.z), sz = std::sin(a.z);
  glm::dmat3 rx(1, 0, 0, 0, cx, sx, 0, -sx, cx);
  glm::dmat3 ry(cy, 0, -sy, 0, 1, 0, sy, 0, cy);
  glm::dmat3 rz(cz, sz, 0, -sz, cz, 0, 0, 0, 1);
  return rz * ry * rx;
}

// World -> camera: a rotation (rows right, up, forward) and the eye position. The lookat
// basis uses right = up x forward so the map is a proper rotation of the left-handed world.
struct View {
  glm::dvec3 eye{0.0}, right{1, 0, 0}, up{0, 1, 0}, fwd{0, 0, 1};
  glm::dvec3 point(const glm::dvec3& p) const {
    glm::dvec3 d = p - eye;
    return {glm::dot(d, right), glm::dot(d, up), glm::dot(d, fwd)};
  }
  glm::dvec3 dir(const glm::dvec3& d) const { return {glm::dot(d, right), glm::dot(d, up), glm::dot(d, fwd)}; }
};

inline View make_view(const Camera& c) {
  View v;
  if (c.type == Camera::Type::LookAt) {
    v.eye = c.eye;
    v.fwd = glm::normalize(c.target - c.eye);
    v.right = glm::normalize(glm::cross(c.up, v.fwd));
    v.up = glm::cross(v.fwd, v.right);
  }
  return v;
}

// Object space -> camera space, p_cam = linear * p_obj + offset: scale, rotate, translate, view.
struct ObjectToCamera {
  glm::dmat3 linear{1.0};
  glm::dvec3 offset{0.0};
  ObjectToCamera(const View& v, const Transform& t) {
    const glm::dmat3 view_rows = glm::transpose(glm::dmat3(v.right, v.up, v.fwd));  // rows right, up, fwd
    linear = view_rows * rotation(t.rotate_deg) * glm::dmat3(t.scale.x, 0, 0, 0, t.scale.y, 0, 0, 0, t.scale.z);
    offset = v.point(t.translate);
  }
};

// The material as Phong's eq. (3) takes it.
inline PhongMaterial phong_material(const Material& m) {
  PhongMaterial p;
  for (int c = 0; c < 3; ++c) p.cp[c] = m.color[c];
  p.d = m.d, p.W = m.W, p.n = static_cast<int>(m.n);
  return p;
}

}  // namespace watkins
