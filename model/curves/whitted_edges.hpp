// Whitted's edge description of a bicubic patch (Whitted 1978, "Edge Description of Patches" and
// "Intersection Processor"): the four boundary curves E0..E3 and the interior curves at k_u, k_v
// (which cut the patch into subpatches), and per subpatch the silhouette where the surface turns
// from front- to back-facing, built as his cubic Hermite segment with his alpha, beta rule. Every
// edge is split where it is not monotonic in screen y, and each y-monotonic piece is crossed with
// every scan line by Newton's iteration (newton_scan.hpp). Everything in double; the patch is seen
// only through a camera-space point function, so any bicubic basis (Bezier, B-spline in Bezier
// form) and any object transform work.
//
// Choices (docs/reference/whitted.md): edges are exact surface curves projected exactly (perspective
// division per point), not the cubic through transformed control points; the silhouette's Hermite
// is built in (u, v) parameter space and mapped through the patch, so it lies on the surface; the
// normal along an edge is the exact one (dP/du x dP/dv, its limit at a degenerate point).
#pragma once

#include <functional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "newton_scan.hpp"

namespace watkins {

// A patch in camera space (the eye at the origin, +Z forward): the point and its partials at (u, v).
using PatchPoint = std::function<void(double u, double v, glm::dvec3& p, glm::dvec3& pu, glm::dvec3& pv)>;

// The scene builder's perspective: x_s = W/2 + f (W/2) X/Z, y_s = H/2 - f (W/2) Y/Z (y down).
struct Projection {
  double half_w = 160, half_h = 120, focal = 1;
  double x(const glm::dvec3& p) const { return half_w + focal * half_w * p.x / p.z; }
  double y(const glm::dvec3& p) const { return half_h - focal * half_w * p.y / p.z; }
};

enum class EdgeKind { Boundary, Interior, Silhouette };

// A curve on the patch in parameter space, t in [0, 1]: a straight segment from a to b (an
// iso-parameter line, a boundary or interior edge) or a cubic Hermite with end tangents ta, tb.
// Both forms give a and b exactly at t = 0 and 1, so edges meeting at a point meet bit-exactly.
struct ParamCurve {
  EdgeKind kind = EdgeKind::Boundary;
  glm::dvec2 a{0.0}, b{0.0};
  bool hermite = false;
  glm::dvec2 ta{0.0}, tb{0.0};
  glm::dvec2 at(double t) const;
  glm::dvec2 derivative(double t) const;
};

// Whitted's silhouette segment between the boundary points a = (u_a, v_a) and b = (u_b, v_b):
// |alpha'_u| = 1 / (1 + |v_b - v_a| / |u_b - u_a|), |alpha'_v| = 1 - |alpha'_u|, both scaled by the
// chord length, signs of u_b - u_a and v_b - v_a, beta = alpha. The tangent alpha_u f_u + alpha_v f_v
// is the parameter-space vector (alpha_u, alpha_v) mapped by the patch's Jacobian.
ParamCurve whitted_silhouette(const glm::dvec2& a, const glm::dvec2& b);

// A patch's camera-space normal at (u, v) as its owner defines it (any length; zero where it has
// none): the scene's patches give theirs with their own limit at a pole (patches.hpp).
using PatchNormal = std::function<glm::dvec3(double u, double v)>;

// The exact unit normal: `n` when given and not zero, else dP/du x dP/dv, at a degenerate point
// (a collapsed boundary, a zero partial) its limit from a step inside the patch.
glm::dvec3 unit_normal(const PatchPoint& f, double u, double v, const PatchNormal& n = {});

// N.(P - eye) with both unit (eye at the origin): the cosine between the normal and the line of
// sight; zero on the silhouette, negative where the patch faces the eye (N = dP/du x dP/dv).
double silhouette_cosine(const PatchPoint& f, double u, double v, const PatchNormal& n = {});

// An edge curve as the screen sees it.
class ScreenEdge {
 public:
  ScreenEdge(const PatchPoint& f, const Projection& proj, const ParamCurve& c) : f_(f), proj_(proj), c_(c) {}
  // E_y(t) and dE_y/dt: y_s = H/2 - k Y/Z gives dy_s/dt = -k (Y' Z - Y Z') / Z^2, exact.
  void y(double t, double& y, double& dy) const;
  // The t in (0, 1) where dE_y/dt changes sign: zeros of Y' Z - Y Z'. For an iso-parameter line
  // (cubic Y, Z) that is a quartic, solved exactly (roots isolated between those of its
  // derivatives); for a silhouette (degree 18) bracketed on a grid of `samples` and bisected. Sorted.
  std::vector<double> y_extrema(int samples = 128) const;
  const ParamCurve& curve() const { return c_; }

 private:
  const PatchPoint& f_;
  const Projection& proj_;
  ParamCurve c_;
};

// One crossing of an edge piece with a scan line.
struct EdgeCrossing {
  double t = 0;                 // on the edge's ParamCurve
  double x = 0, y = 0;          // screen; y = the scan line's centre up to the Newton tolerance
  glm::dvec3 p{0.0};            // camera space
  glm::dvec3 normal{0, 0, -1};  // exact unit normal (unit_normal; not turned to the eye)
};

struct EdgePiece {
  int region = 0;  // index into PatchEdges::regions
  EdgeKind kind = EdgeKind::Boundary;
  int y0 = 0;      // scan line of lines[0]
  std::vector<EdgeCrossing> lines;
  ParamCurve curve;               // the edge it is a piece of
  double t_top = 0, t_end = 0;    // its range on curve, top (smaller y) first
};

struct PatchRegion {
  bool front = true;  // faces the eye (N.P < 0 inside it)
  int cell = 0;       // subpatch: k_v index * (k_u count + 1) + k_u index
};

struct PatchEdges {
  std::vector<EdgePiece> pieces;
  std::vector<PatchRegion> regions;
  std::vector<ParamCurve> silhouettes;  // Whitted's Hermite segments built (one per split subpatch)
};

struct EdgeStats {
  NewtonStats newton;
  int cells = 0;            // subpatches
  int regions = 0;          // kept (after culling)
  int culled_regions = 0;   // back-facing regions dropped
  int silhouettes = 0;      // Hermite silhouette segments built
  // Whitted's generator "defaults" (the subpatch is drawn as one region, facing as its centre):
  int default_one = 0;      // the silhouette crosses the subpatch boundary an odd number of times
  int default_many = 0;     // more than twice
  int default_side_twice = 0;  // twice, both on one boundary side
  int default_inside = 0;   // no boundary crossing, but the facing changes inside (a closed silhouette)
  int pieces = 0;           // y-monotonic pieces crossing at least one scan line
  int y_splits = 0;         // extrema of E_y that split an edge
  void add(const EdgeStats& o);
};

struct WhittedOptions {
  std::vector<double> k_u, k_v;  // interior edges u = k_u[i], v = k_v[j], each in (0, 1)
  bool cull = false;             // drop back-facing regions
  int line_lo = 0, line_hi = 0;  // scan lines to cross: line_lo <= n < line_hi
  int silhouette_samples = 16;   // per side, where N.P changes sign
  PatchNormal normal;            // the patch's own normal (empty: the cross product)
  NewtonOptions newton;
};

// The edge description of one patch and the crossings of all its y-monotonic pieces.
PatchEdges describe_patch(const PatchPoint& f, const Projection& proj, const WhittedOptions& opt, EdgeStats& stats);

// The y-monotonic pieces of curve c on t in [a, b] (split at its E_y extrema) and their crossings.
std::vector<EdgePiece> scan_edge(const PatchPoint& f, const Projection& proj, const ParamCurve& c, double a, double b,
                                 const WhittedOptions& opt, EdgeStats& stats);

}  // namespace watkins
