// Frames of an animation for the host link (`watkins board stream --turntable N`): the scene
// turned about the vertical axis (world y) through its centre, the camera and the light fixed.
// The centre is the middle of the box around the objects' anchors: each object's transform
// applied to its `center` (the sphere's centre, the cone's and the pier's base; the object's
// origin for the others). Each object's rotation becomes the turn after its own (as
// rotate_deg: X, then Y, then Z, camera.hpp's rotation()) and its translation turns about the
// centre.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "scene_types.hpp"

namespace watkins::board {

// The centre the turntable turns about (world space).
glm::dvec3 turntable_centre(const Scene& scene);

// `scene` turned by `degrees` about the vertical axis through turntable_centre(scene). Throws
// std::invalid_argument naming the object when one is screen-space polygons (nothing to turn).
Scene turntable(const Scene& scene, double degrees);

// rotate_deg of a rotation matrix (rotation(euler_degrees(m)) == m, camera.hpp).
glm::dvec3 euler_degrees(const glm::dmat3& m);

}  // namespace watkins::board
