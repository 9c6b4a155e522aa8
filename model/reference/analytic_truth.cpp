// Ray casting of the exact surfaces: each surface is an implicit F(p) = 0 in object space with a
// domain (the part of it the scene object is), or a bicubic patch P(s, t). A camera ray is mapped
// into object space; for F it is marched over the object's bounding sphere to bracket the first
// sign change of F inside the domain, and the root refined by bisection (normal: grad F); for a
// patch, Newton's method on P(s, t) = o + t e from a grid of starts (normal: dP/ds x dP/dt).
// Normals go back to camera space by the inverse transpose.
#include "analytic_truth.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "camera.hpp"
#include "illumination.hpp"
#include "scene_types.hpp"
#include "surfaces.hpp"

namespace watkins {
namespace {

// One piece of an exact surface in object space.
struct Implicit {
  std::function<double(const glm::dvec3&)> f;          // zero on the surface
  std::function<glm::dvec3(const glm::dvec3&)> grad;   // its gradient, or minus it: the normal of the front side
  std::function<bool(const glm::dvec3&)> inside;       // the part that belongs to the object
  // Closed-form roots of f along the ray o + t e (quadrics, planes): up to 2, in t[]; their count.
  // When set, the roots replace the marching below (thin pieces cannot slip between its steps).
  std::function<int(const glm::dvec3& o, const glm::dvec3& e, double t[2])> roots;
};

// Roots of a t^2 + b t + c = 0 (a may be 0), ascending.
int quadratic_roots(double a, double b, double c, double t[2]) {
  if (a == 0) {
    if (b == 0) return 0;
    t[0] = -c / b;
    return 1;
  }
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return 0;
  // The stable pair: q = -(b + sign(b) sqrt(disc)) / 2, roots q/a and c/q.
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  t[0] = q / a;
  t[1] = q != 0 ? c / q : t[0];
  if (t[0] > t[1]) std::swap(t[0], t[1]);
  return 2;
}

// One barrel of a cross-vault bay (surfaces.cpp, cross_vault_bay): the half-elliptic cylinder
// ((w - cw)/half)^2 + ((y - cy)/h)^2 = 1 with w = z (axis along X, across = 0) or w = x (axis
// along Z), restricted to where it is the ceiling seen from below: above the springing plane,
// inside the bay, and on its own side of the groins (|x|/A >= |z|/B for the barrel along X).
Implicit barrel(const glm::dvec3& c, double A, double B, double h, int across) {
  const int w = across == 0 ? 2 : 0, along = 2 - w;  // the spanned axis and the axis of the barrel
  const double half = across == 0 ? B : A, len = across == 0 ? A : B;
  Implicit b;
  b.f = [=](const glm::dvec3& p) {
    const double dw = (p[w] - c[w]) / half, dy = (p.y - c.y) / h;
    return dw * dw + dy * dy - 1;
  };
  b.grad = [=](const glm::dvec3& p) {  // minus the gradient: the intrados, the front side, faces the axis
    glm::dvec3 g(0.0);
    g[w] = -(p[w] - c[w]) / (half * half);
    g.y = -(p.y - c.y) / (h * h);
    return g;
  };
  b.inside = [=](const glm::dvec3& p) {
    const double da = std::fabs(p[along] - c[along]), dw = std::fabs(p[w] - c[w]);
    return p.y >= c.y && da <= len && da / len >= dw / half;
  };
  b.roots = [=](const glm::dvec3& o, const glm::dvec3& e, double t[2]) {
    const double ow = (o[w] - c[w]) / half, ew = e[w] / half, oy = (o.y - c.y) / h, ey = e.y / h;
    return quadratic_roots(ew * ew + ey * ey, 2 * (ow * ew + oy * ey), ow * ow + oy * oy - 1, t);
  };
  return b;
}

// The face of a box (a pier) on the plane p[axis] = at, bounded by lo..hi on the other two axes.
Implicit box_face(const glm::dvec3& lo, const glm::dvec3& hi, int axis, bool upper) {
  const double at = upper ? hi[axis] : lo[axis];
  Implicit b;
  b.f = [=](const glm::dvec3& p) { return upper ? p[axis] - at : at - p[axis]; };
  b.grad = [=](const glm::dvec3&) {
    glm::dvec3 g(0.0);
    g[axis] = upper ? 1 : -1;
    return g;
  };
  b.inside = [=](const glm::dvec3& p) {
    for (int a = 0; a < 3; ++a)
      if (a != axis && (p[a] < lo[a] || p[a] > hi[a])) return false;
    return true;
  };
  b.roots = [=](const glm::dvec3& o, const glm::dvec3& e, double t[2]) {
    if (e[axis] == 0) return 0;
    t[0] = (at - o[axis]) / e[axis];
    return 1;
  };
  return b;
}

// The blossom f(x1, x2, x3) of a cubic Bezier curve (de Casteljau with one parameter per level):
// f(a, a, a), f(a, a, b), f(a, b, b), f(b, b, b) are the control points of its piece over [a, b].
glm::dvec3 blossom(const glm::dvec3 q[4], double x1, double x2, double x3) {
  glm::dvec3 r[3];
  for (int i = 0; i < 3; ++i) r[i] = (1 - x1) * q[i] + x1 * q[i + 1];
  for (int i = 0; i < 2; ++i) r[i] = (1 - x2) * r[i] + x2 * r[i + 1];
  return (1 - x3) * r[0] + x3 * r[1];
}

// The control points of the piece of a patch over [s0, s1] x [t0, t1]: along every row, then
// along every column of the result.
BicubicPatch sub_patch(const BicubicPatch& cp, double s0, double s1, double t0, double t1) {
  BicubicPatch rows, out;
  for (int r = 0; r < 4; ++r) {
    const glm::dvec3 q[4] = {cp[std::size_t(4 * r)], cp[std::size_t(4 * r + 1)], cp[std::size_t(4 * r + 2)],
                             cp[std::size_t(4 * r + 3)]};
    for (int k = 0; k < 4; ++k) rows[std::size_t(4 * r + k)] = blossom(q, k < 3 ? s0 : s1, k < 2 ? s0 : s1, k < 1 ? s0 : s1);
  }
  for (int c = 0; c < 4; ++c) {
    const glm::dvec3 q[4] = {rows[std::size_t(c)], rows[std::size_t(4 + c)], rows[std::size_t(8 + c)],
                             rows[std::size_t(12 + c)]};
    for (int k = 0; k < 4; ++k) out[std::size_t(4 * k + c)] = blossom(q, k < 3 ? t0 : t1, k < 2 ? t0 : t1, k < 1 ? t0 : t1);
  }
  return out;
}

// Where Newton's method on a patch starts: the middle of one of n x n pieces of the patch, and the
// bounding sphere of that piece's control points (its convex hull holds the piece): a ray that
// misses the sphere does not start there.
// Pieces per patch along s and along t: 3 for a lone bezier_patch (the 3 x 3 starts its truth has
// always had); 6 for the patches of a "patches" object (3 leave rays through the teapot's knob,
// folded near its pole, without a root).
int patch_pieces(std::size_t patches) { return patches == 1 ? 3 : 6; }

struct PatchStart {
  std::size_t patch = 0;
  bool first_of_patch = false;
  double u = 0, v = 0;
  glm::dvec3 centre{0.0};
  double radius = 0;
};

std::vector<PatchStart> patch_starts(const std::vector<BicubicPatch>& patches, int n) {
  std::vector<PatchStart> out;
  for (std::size_t i = 0; i < patches.size(); ++i)
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        PatchStart st;
        st.patch = i;
        st.first_of_patch = a == 0 && b == 0;
        st.u = (1 + 2 * a) / (2.0 * n), st.v = (1 + 2 * b) / (2.0 * n);
        const BicubicPatch piece = sub_patch(patches[i], double(a) / n, double(a + 1) / n, double(b) / n, double(b + 1) / n);
        for (const glm::dvec3& q : piece) st.centre += q / 16.0;
        for (const glm::dvec3& q : piece) st.radius = std::max(st.radius, glm::length(q - st.centre));
        out.push_back(st);
      }
  return out;
}

// A root of P(s, t) = o + t e with s, t in [0, 1] and t in [t0, t1] by Newton's method from (u, v)
// (the start's own piece of the patch or any other), with the object-space normal dP/ds x dP/dt
// (patch_normal). `accept` filters by depth.
std::optional<std::pair<double, glm::dvec3>> patch_hit(const BicubicPatch& cp, double u, double v, const glm::dvec3& o,
                                                       const glm::dvec3& e, double t0, double t1,
                                                       const std::function<bool(double)>& accept) {
  const double scale = glm::length(e) * (t1 - t0);
  glm::dvec3 p, ds, dt;
  bezier_point(cp, u, v, p, ds, dt);
  double t = glm::dot(p - o, e) / glm::dot(e, e);
  bool converged = false;
  for (int it = 0; it < 30 && !converged; ++it) {
    bezier_point(cp, u, v, p, ds, dt);
    const glm::dvec3 f = p - (o + t * e);
    if (glm::length(f) < 1e-12 * scale) {
      converged = true;
      break;
    }
    const glm::dmat3 jac(ds, dt, -e);  // columns: d/ds, d/dt, d/dt(ray)
    if (std::fabs(glm::determinant(jac)) < 1e-300) break;
    const glm::dvec3 step = glm::inverse(jac) * f;
    u -= step.x, v -= step.y, t -= step.z;
    if (!(std::fabs(u) < 4 && std::fabs(v) < 4)) break;  // diverging
  }
  const double tol = 1e-9;
  if (!converged || u < -tol || u > 1 + tol || v < -tol || v > 1 + tol || t < t0 || t > t1 || !accept(t))
    return std::nullopt;
  // dP/ds x dP/dt, or its limit from inside at a collapsed boundary (a pole).
  const glm::dvec3 n = patch_normal(cp, u, v);
  if (glm::length(n) == 0) return std::nullopt;  // no tangent plane near here
  return std::make_pair(t, n);
}

struct Surface {
  int object = 0;
  std::vector<Implicit> pieces;
  std::vector<BicubicPatch> patches;  // bezier_patch, patches
  std::vector<PatchStart> starts;     // of Newton's method on them, patch by patch
  std::vector<std::pair<glm::dvec3, double>> patch_bounds;  // each patch's bounding sphere
  glm::dvec3 centre{0.0};  // bounding sphere, object space
  double radius = 0;
  glm::dmat3 to_object{1.0}, normal_to_camera{1.0};
  glm::dvec3 offset{0.0};  // p_cam = inverse(to_object) * p_obj + offset
  PhongMaterial material;
};

std::vector<Implicit> pieces_of(const SceneObject& o, glm::dvec3& centre, double& radius) {
  std::vector<Implicit> v;
  const glm::dvec3 c = o.center;
  switch (o.type) {
    case ObjectType::Sphere: {
      const double r = o.radius;
      v.push_back({[=](const glm::dvec3& p) { return glm::dot(p - c, p - c) - r * r; },
                   [=](const glm::dvec3& p) { return p - c; }, [](const glm::dvec3&) { return true; }, nullptr});
      centre = c, radius = r;
      break;
    }
    case ObjectType::Cone: {
      const double r = o.radius, h = o.height, k = r / h, apex = c.y + h;
      v.push_back({[=](const glm::dvec3& p) {
                     const double dx = p.x - c.x, dz = p.z - c.z, a = apex - p.y;
                     return dx * dx + dz * dz - k * k * a * a;
                   },
                   [=](const glm::dvec3& p) { return glm::dvec3(p.x - c.x, k * k * (apex - p.y), p.z - c.z); },
                   [=](const glm::dvec3& p) { return p.y >= c.y && p.y <= apex; }, nullptr});
      if (o.cap)
        v.push_back({[=](const glm::dvec3& p) { return p.y - c.y; },
                     [](const glm::dvec3&) { return glm::dvec3(0, -1, 0); },
                     [=](const glm::dvec3& p) {
                       const double dx = p.x - c.x, dz = p.z - c.z;
                       return dx * dx + dz * dz <= r * r;
                     },
                     nullptr});
      centre = c + glm::dvec3(0, h / 2, 0), radius = std::sqrt(r * r + h * h / 4);
      break;
    }
    case ObjectType::QuarterTorus: {
      const double R = o.major_radius, r = o.minor_radius;
      v.push_back({[=](const glm::dvec3& p) {
                     const double q = std::sqrt(p.x * p.x + p.z * p.z) - R;
                     return q * q + p.y * p.y - r * r;
                   },
                   [=](const glm::dvec3& p) {
                     const double rho = std::sqrt(p.x * p.x + p.z * p.z), q = rho - R;
                     return rho > 0 ? glm::dvec3(q * p.x / rho, p.y, q * p.z / rho) : glm::dvec3(0, p.y, 0);
                   },
                   [](const glm::dvec3& p) { return p.x >= 0 && p.z >= 0; }, nullptr});
      centre = glm::dvec3(0.0), radius = R + r;
      break;
    }
    case ObjectType::HyperbolicParaboloid: {
      const double cc = o.c, s = o.size;
      v.push_back({[=](const glm::dvec3& p) { return (p.x * p.x - p.y * p.y) / cc - p.z; },
                   [=](const glm::dvec3& p) { return glm::dvec3(2 * p.x / cc, -2 * p.y / cc, -1); },
                   [=](const glm::dvec3& p) { return std::fabs(p.x) <= s && std::fabs(p.y) <= s; }, nullptr});
      centre = glm::dvec3(0.0), radius = std::sqrt(2 * s * s + std::pow(2 * s * s / std::fabs(cc), 2));
      break;
    }
    case ObjectType::CrossVault:
    case ObjectType::Pier:
    case ObjectType::Portico: {
      const VaultLayout l = vault_layout(o);
      const double A = o.span_x / 2, B = o.span_z / 2;
      glm::dvec3 lo(INFINITY), hi(-INFINITY);
      for (const glm::dvec3& b : l.bays) {
        for (int across = 0; across < 2; ++across) v.push_back(barrel(b, A, B, o.rise, across));
        lo = glm::min(lo, b - glm::dvec3(A, 0, B));
        hi = glm::max(hi, b + glm::dvec3(A, o.rise, B));
      }
      for (const glm::dvec3& p : l.piers) {
        const glm::dvec3 plo = p - glm::dvec3(o.pier_x / 2, 0, o.pier_z / 2),
                         phi = p + glm::dvec3(o.pier_x / 2, o.pier_height, o.pier_z / 2);
        for (int axis = 0; axis < 3; ++axis)
          for (bool upper : {false, true}) v.push_back(box_face(plo, phi, axis, upper));
        lo = glm::min(lo, plo);
        hi = glm::max(hi, phi);
      }
      centre = 0.5 * (lo + hi), radius = 0.5 * glm::length(hi - lo);
      break;
    }
    case ObjectType::Voxels: {
      // The phantom the voxels sample (a file volume has no closed form): each ball of its union,
      // scaled per axis, where no other ball holds the point. q = p / size is the unit frame.
      if (!o.has_phantom) break;
      const Phantom& ph = o.phantom;
      const glm::dvec3 size = ph.size;
      const std::vector<Phantom::Ball> balls = ph.balls;
      for (std::size_t b = 0; b < balls.size(); ++b) {
        const glm::dvec3 bc = balls[b].centre;
        const double r = balls[b].radius;
        v.push_back({[=](const glm::dvec3& p) {
                       const glm::dvec3 q = p / size - bc;
                       return glm::dot(q, q) - r * r;
                     },
                     [=](const glm::dvec3& p) { return (p / size - bc) / size; },
                     [=](const glm::dvec3& p) {
                       for (std::size_t other = 0; other < balls.size(); ++other) {
                         const glm::dvec3 q = p / size - balls[other].centre;
                         if (other != b && glm::dot(q, q) < balls[other].radius * balls[other].radius) return false;
                       }
                       return true;
                     },
                     [=](const glm::dvec3& o, const glm::dvec3& e, double t[2]) {
                       const glm::dvec3 oq = o / size - bc, eq = e / size;
                       return quadratic_roots(glm::dot(eq, eq), 2 * glm::dot(oq, eq), glm::dot(oq, oq) - r * r, t);
                     }});
      }
      centre = glm::dvec3(0.0), radius = ph.extent * std::max({size.x, size.y, size.z});
      break;
    }
    default:
      break;
  }
  return v;
}

// First hit of the camera ray t*d (t > 0) on the surface, in camera-space distance along d.
struct Hit {
  double t = std::numeric_limits<double>::infinity();
  glm::dvec3 normal{0.0};  // camera space, unit
};

// `cull`: a hit on the back of a surface (its normal, as the tessellation orients it, facing away
// from the eye) is not seen and the ray goes on, as back-face culling hides the back of an open
// surface in the render (a closed surface's first hit is a front one anyway).
std::optional<Hit> cast(const Surface& s, const glm::dvec3& d, double near, double far, bool cull) {
  // Object-space ray o + t*e for the camera ray t*d.
  const glm::dvec3 o = s.to_object * (-s.offset), e = s.to_object * d;
  // Bounding sphere, a little larger so roots on it are bracketed from outside.
  const glm::dvec3 oc = o - s.centre;
  const double a = glm::dot(e, e), b = glm::dot(oc, e), r = s.radius * 1.01 + 1e-9;
  const double disc = b * b - a * (glm::dot(oc, oc) - r * r);
  if (disc <= 0) return std::nullopt;
  const double q = std::sqrt(disc);
  double t0 = std::max((-b - q) / a, 0.0), t1 = (-b + q) / a;
  if (t1 <= 0) return std::nullopt;
  std::optional<Hit> best;
  constexpr int Steps = 256;  // brackets: the surfaces here have no feature thinner than radius/100
  for (const Implicit& piece : s.pieces) {
    if (piece.roots) {
      double ts[2];
      const int n = piece.roots(o, e, ts);
      for (int k = 0; k < n; ++k) {
        const double t = ts[k];
        if (!(t > 0) || (best && t >= best->t)) continue;
        const glm::dvec3 p = o + t * e;
        const double z = t * d.z;
        if (piece.inside(p) && z >= near && z < far) {
          Hit h;
          h.t = t;
          h.normal = glm::normalize(s.normal_to_camera * piece.grad(p));
          if (cull && glm::dot(h.normal, d) > 0) continue;  // its back: unseen
          best = h;
          break;  // the roots are ascending
        }
      }
      continue;
    }
    const double dt = (t1 - t0) / Steps;
    double ta = t0, fa = piece.f(o + ta * e);
    for (int k = 1; k <= Steps; ++k) {
      const double tb = t0 + k * dt, fb = piece.f(o + tb * e);
      if ((fa <= 0) != (fb <= 0)) {
        double lo = ta, hi = tb, flo = fa;
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (lo + hi), fm = piece.f(o + mid * e);
          if ((fm <= 0) == (flo <= 0)) lo = mid, flo = fm;
          else hi = mid;
        }
        const double t = 0.5 * (lo + hi);
        const glm::dvec3 p = o + t * e;
        const double z = t * d.z;  // camera-space depth of the hit
        if (piece.inside(p) && z >= near && z < far) {
          const glm::dvec3 n = glm::normalize(s.normal_to_camera * piece.grad(p));
          if (!(cull && glm::dot(n, d) > 0)) {
            if (!best || t < best->t) {
              Hit h;
              h.t = t;
              h.normal = n;
              best = h;
            }
            break;  // the first root of this piece inside its domain
          }
        }
      }
      ta = tb, fa = fb;
    }
  }
  const auto accept = [&](double t) { return t * d.z >= near && t * d.z < far; };
  // The ray against each patch's bounding sphere first, then against its pieces'.
  const auto misses = [&](const glm::dvec3& centre, double radius) {
    const glm::dvec3 pc = o - centre;
    const double pr = radius * 1.01 + 1e-9, pb = glm::dot(pc, e);
    return pb * pb - a * (glm::dot(pc, pc) - pr * pr) <= 0;
  };
  for (std::size_t k = 0; k < s.starts.size(); ++k) {
    const PatchStart& st = s.starts[k];
    if (st.first_of_patch && misses(s.patch_bounds[st.patch].first, s.patch_bounds[st.patch].second)) {
      while (k + 1 < s.starts.size() && s.starts[k + 1].patch == st.patch) ++k;
      continue;
    }
    if (misses(st.centre, st.radius)) continue;
    if (const auto h = patch_hit(s.patches[st.patch], st.u, st.v, o, e, t0, t1, accept); h && (!best || h->first < best->t)) {
      Hit hit;
      hit.t = h->first;
      hit.normal = glm::normalize(s.normal_to_camera * h->second);
      if (!(cull && glm::dot(hit.normal, d) > 0)) best = hit;
    }
  }
  return best;
}

}  // namespace

AnalyticTruth render_analytic_truth(const BuiltScene& scene) {
  AnalyticTruth out;
  if (!scene.source) {
    out.unavailable = "the scene was not built from a scene file";
    return out;
  }
  if (scene.shading != ShadingMode::Phong && scene.rule != ShadingRule::Phong) {
    out.unavailable = "the illumination is not Phong's eq. (3) (use --shading phong or --rule phong)";
    return out;
  }
  const Scene& sc = *scene.source;
  const View view = make_view(sc.camera);
  std::vector<Surface> surfaces;
  for (std::size_t i = 0; i < sc.objects.size(); ++i) {
    const SceneObject& o = sc.objects[i];
    Surface s;
    s.object = static_cast<int>(i);
    s.pieces = pieces_of(o, s.centre, s.radius);
    if (o.type == ObjectType::BezierPatch || o.type == ObjectType::Patches) {
      s.patches = o.patches;
      s.starts = patch_starts(s.patches, patch_pieces(s.patches.size()));
      // The bounding sphere: of the control points of one patch (its convex hull holds it), of
      // their box for several.
      glm::dvec3 lo(INFINITY), hi(-INFINITY);
      for (const BicubicPatch& cp : s.patches) {
        glm::dvec3 c(0.0);
        double r = 0;
        for (const glm::dvec3& q : cp) c += q / 16.0, lo = glm::min(lo, q), hi = glm::max(hi, q);
        for (const glm::dvec3& q : cp) r = std::max(r, glm::length(q - c));
        s.patch_bounds.emplace_back(c, r);
      }
      if (s.patches.size() == 1) std::tie(s.centre, s.radius) = s.patch_bounds[0];
      else s.centre = 0.5 * (lo + hi), s.radius = 0.5 * glm::length(hi - lo);
    }
    if (s.pieces.empty() && s.patches.empty()) {
      ++out.without_truth;
      continue;
    }
    const ObjectToCamera m(view, o.transform);
    s.to_object = glm::inverse(m.linear);
    s.normal_to_camera = glm::transpose(s.to_object);
    s.offset = m.offset;
    s.material = phong_material(o.material);
    surfaces.push_back(std::move(s));
  }
  out.surfaces = static_cast<int>(surfaces.size());
  if (surfaces.empty()) {
    out.unavailable = "no object of the scene has an exact surface here (sphere, cone, torus, hypar, patch, "
                      "cross vault, pier, portico, voxel phantom)";
    return out;
  }
  const int W = scene.width, H = scene.height;
  out.image = Image(W, H);
  for (int c = 0; c < 3; ++c)
    for (std::size_t k = 0; k < out.image.rgb.size(); k += 3)
      out.image.rgb[k + c] = static_cast<std::uint8_t>(std::lround(scene.background[c]));
  const double half_w = 0.5 * W, half_h = 0.5 * H, f = sc.camera.focal;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      // Inverse of x_s = W/2 + f (W/2) X/Z, y_s = H/2 - f (W/2) Y/Z at the pixel centre.
      const glm::dvec3 d((x + 0.5 - half_w) / (f * half_w), (half_h - (y + 0.5)) / (f * half_w), 1.0);
      std::optional<Hit> best;
      const Surface* owner = nullptr;
      for (const Surface& s : surfaces) {
        const std::optional<Hit> h = cast(s, d, sc.camera.near, sc.camera.far, scene.cull_backfaces);
        if (h && (!best || h->t < best->t)) best = h, owner = &s;
      }
      if (!best) continue;
      glm::dvec3 n = best->normal;
      if (glm::dot(n, -d) < 0) n = -n;  // the side that is seen
      const auto lv = phong_levels(owner->material, {n.x, n.y, n.z}, scene.light, scene.eye);
      std::uint8_t* p = out.image.at(x, y);
      for (int c = 0; c < 3; ++c) p[c] = static_cast<std::uint8_t>(std::lround(lv[c]));
      const std::size_t i = std::size_t(y) * W + x;
      out.image.covered[i] = 1;
      out.image.owner[i] = owner->object;
    }
  return out;
}

Image by_object(const BuiltScene& scene, const Image& img) {
  Image out = img;
  // Curve regions (ids after the polygons) name their object through their curves.
  std::vector<int> region_object(std::size_t(scene.curve_regions), -1);
  for (const ScreenCurve& c : scene.curves) region_object.at(std::size_t(c.region)) = c.object;
  const int n_poly = int(scene.polygons.size());
  for (int& o : out.owner)
    if (o >= 0) o = o < n_poly ? scene.polygons[std::size_t(o)].object : region_object.at(std::size_t(o - n_poly));
  return out;
}

ImageError compare_with_truth(const BuiltScene& scene, const Image& img, const AnalyticTruth& truth) {
  return compare_images(by_object(scene, img), truth.image);
}

Image truth_diff_image(const BuiltScene& scene, const Image& img, const AnalyticTruth& truth) {
  return diff_image(by_object(scene, img), truth.image);
}

}  // namespace watkins
