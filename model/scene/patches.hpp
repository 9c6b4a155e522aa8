// Bicubic patch objects ("bezier_patch", "patches"): every patch is held in Bezier form
// (SceneObject::patches, scene_types.hpp); this evaluates a patch, its exact normal (with the
// limit at a collapsed boundary, as the lid and bottom of Newell's teapot have), turns a uniform
// B-spline control net into Bezier patches by the basis change, and lists a patch's parameter
// lines (the tessellation's grid with Whitted's interior edges k_u, k_v among them).
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "scene_types.hpp"

namespace watkins {

// The point and its partial derivatives dP/ds, dP/dt at (s, t) of a bicubic Bezier patch (s
// along a row of control points, t from row to row). Shared by the tessellation, the analytic
// truth and the edge description.
void bezier_point(const BicubicPatch& cp, double s, double t, glm::dvec3& p, glm::dvec3& ds, glm::dvec3& dt);

// Patch i of a patch object (o.patches[i]), evaluated in place.
inline void patch_point(const SceneObject& o, std::size_t i, double s, double t, glm::dvec3& p, glm::dvec3& ds,
                        glm::dvec3& dt) {
  bezier_point(o.patches[i], s, t, p, ds, dt);
}

// The front side's normal dP/ds x dP/dt at (s, t), not of unit length. Where it vanishes (a
// boundary collapsed to a point, a pole), its limit from inside the patch: the vanishing partial
// replaced by the twist d2P/dsdt (its first-order term), else the cross product a little way
// inside. (0, 0, 0) only where the patch has no tangent plane near (s, t) at all.
glm::dvec3 patch_normal(const BicubicPatch& cp, double s, double t);

// A uniform bicubic B-spline control net, `rows` x `cols` points (net[row * cols + col], rows
// listed as bezier_patch lists its control points) -> its Bezier patches, row of patches by row
// of patches: (rows - 3) x (cols - 3) patches, or rows (closed_v) / cols (closed_u) patches where
// the net is periodic in that direction. The basis change is done once on the whole net, so
// neighbouring patches hold their common boundary control points as the same doubles (positions
// on a shared boundary are bit-identical; the surface is C2 across it).
std::vector<BicubicPatch> bspline_patches(const std::vector<glm::dvec3>& net, int rows, int cols, bool closed_u,
                                          bool closed_v);

}  // namespace watkins
