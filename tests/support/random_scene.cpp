#include "random_scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "scene_builder.hpp"

namespace watkins::test {
namespace {

int between(std::mt19937_64& rng, int lo, int hi) {
  return lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo + 1));
}

// A vertex at a random angle and distance (0.3 to 1 radius) from (cx, cy), kept within half a
// screen of the screen; random depth and shade.
ScreenVertex random_vertex(std::mt19937_64& rng, double cx, double cy, double radius, double w, double h) {
  std::uniform_real_distribution<double> u(0, 1);
  ScreenVertex v;
  const double a = u(rng) * 2 * M_PI, d = radius * (0.3 + 0.7 * u(rng));
  v.x = std::clamp(cx + d * std::cos(a), -0.5 * w, 1.5 * w);
  v.y = std::clamp(cy + d * std::sin(a), -0.5 * h, 1.5 * h);
  v.depth = u(rng) * 0.999;
  for (double& c : v.rgb) c = u(rng) * 255;
  return v;
}

glm::dvec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0, 1);
  for (;;) {
    const glm::dvec3 v(g(rng), g(rng), g(rng));
    if (glm::length(v) > 1e-3) return glm::normalize(v);
  }
}

}  // namespace

BuiltScene random_scene(std::mt19937_64& rng, const RandomSceneSpec& spec) {
  std::uniform_real_distribution<double> u(0, 1);
  BuiltScene s;
  s.name = "random scene";
  s.width = between(rng, spec.min_width, spec.max_width);
  s.height = between(rng, spec.min_height, spec.max_height);
  for (double& c : s.background) c = static_cast<double>(rng() % 256);
  const int polys = between(rng, spec.min_polygons, spec.max_polygons);
  for (int p = 0; p < polys; ++p) {
    const double cx = (u(rng) * 1.4 - 0.2) * s.width, cy = (u(rng) * 1.4 - 0.2) * s.height;
    const double radius = (0.05 + u(rng) * 0.7) * std::max(s.width, s.height);
    ScreenPolygon poly;
    poly.object = p;
    const bool quad = rng() % 2;
    if (quad && spec.convex_quads) {  // four points on an ellipse in angle order
      std::vector<double> ang(4);
      for (double& a : ang) a = u(rng) * 2 * M_PI;
      std::sort(ang.begin(), ang.end());
      const double rx = radius * (0.3 + 0.7 * u(rng)), ry = radius * (0.3 + 0.7 * u(rng));
      for (double a : ang) {
        ScreenVertex v = random_vertex(rng, cx, cy, radius, s.width, s.height);
        v.x = cx + rx * std::cos(a);
        v.y = cy + ry * std::sin(a);
        poly.v.push_back(v);
      }
    } else {
      for (int k = 0; k < (quad ? 4 : 3); ++k)
        poly.v.push_back(random_vertex(rng, cx, cy, radius, s.width, s.height));
    }
    if (spec.snap_one_in > 0 && rng() % static_cast<std::uint64_t>(spec.snap_one_in) == 0) {
      for (ScreenVertex& v : poly.v) {  // edges through pixel centres, a horizontal edge
        v.x = std::floor(v.x) + 0.5;
        v.y = std::floor(v.y) + 0.5;
      }
      if (poly.v.size() >= 2) poly.v[1].y = poly.v[0].y;
    }
    double a2 = 0;
    for (std::size_t k = 0; k < poly.v.size(); ++k) {
      const ScreenVertex &a = poly.v[k], &b = poly.v[(k + 1) % poly.v.size()];
      a2 += a.x * b.y - b.x * a.y;
    }
    if (std::fabs(a2) < 1e-6) continue;
    s.polygons.push_back(poly);
  }
  return s;
}

BuiltScene random_scene(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  BuiltScene s = random_scene(rng);
  s.name = "random scene " + std::to_string(seed);
  return s;
}

BuiltScene random_phong_scene(std::uint64_t seed) {
  BuiltScene s = random_scene(seed);
  s.name = "random Phong scene " + std::to_string(seed);
  std::mt19937_64 rng(seed ^ 0x9E3779B97F4A7C15ull);
  std::uniform_real_distribution<double> u(0, 1);
  s.shading = ShadingMode::Phong;
  const int count = 1 + static_cast<int>(rng() % 16);
  for (int k = 0; k < count; ++k) {
    PhongMaterial m;
    for (double& c : m.cp) c = u(rng);
    m.d = u(rng);
    m.W = u(rng) * 511.0 / 256.0;
    const int pick = static_cast<int>(rng() % 8);
    m.n = pick == 0 ? 0 : pick == 1 ? 128 : pick == 2 ? 255 : static_cast<int>(rng() % 256);
    s.materials.push_back(m);
  }
  const glm::dvec3 l = random_unit(rng);
  for (int c = 0; c < 3; ++c) s.light[c] = l[c];
  for (ScreenPolygon& p : s.polygons) {
    p.material = static_cast<int>(rng() % static_cast<std::uint64_t>(count));
    const int kind = static_cast<int>(rng() % 8);
    for (std::size_t k = 0; k < p.v.size(); ++k) {
      glm::dvec3 n = random_unit(rng);
      if (kind >= 2) n.z = -std::fabs(n.z);                          // towards the viewer
      if (kind == 1) n = glm::normalize(glm::dvec3(n.x, n.y, 0.0));  // in the screen plane
      for (int c = 0; c < 3; ++c) p.v[k].normal[c] = n[c];
    }
    if (kind == 0)  // antipodal: the second vertex faces exactly away from the first
      for (int c = 0; c < 3; ++c) p.v[1].normal[c] = -p.v[0].normal[c];
  }
  return s;
}

std::vector<ScreenPolygon> jittered_grid(std::mt19937_64& rng, const GridSpec& g) {
  std::uniform_real_distribution<double> jitter(-g.jitter, g.jitter), shade(0.0, 255.0), depth(0.0, 0.999);
  std::vector<ScreenVertex> v;
  for (int j = 0; j <= g.rows; ++j)
    for (int i = 0; i <= g.cols; ++i) {
      const double di = i % g.cols ? jitter(rng) : 0.0;
      const double dj = j % g.rows ? jitter(rng) : 0.0;
      const double z = g.depth ? *g.depth : depth(rng);
      const double r = shade(rng), gr = shade(rng), b = shade(rng);
      v.push_back(vtx(g.x0 + (i + di) * g.cell_w, g.y0 + (j + dj) * g.cell_h, z, r, gr, b));
    }
  std::vector<ScreenPolygon> out;
  for (int j = 0; j < g.rows; ++j)
    for (int i = 0; i < g.cols; ++i) {
      const std::size_t a = std::size_t(j) * (g.cols + 1) + i;
      const ScreenVertex &p = v[a], &q = v[a + 1], &r = v[a + g.cols + 2], &s = v[a + g.cols + 1];
      if (g.triangles) {
        out.push_back(poly({p, q, r}));
        out.push_back(poly({p, r, s}));
      } else {
        out.push_back(poly({p, q, r, s}));
      }
    }
  return out;
}

BuiltScene mesh_scene(std::mt19937_64& rng, int w, int h, int cols, int rows) {
  GridSpec g;
  g.cols = cols, g.rows = rows;
  g.cell_w = double(w) / cols, g.cell_h = double(h) / rows;
  g.jitter = 0.3;
  return screen(w, h, jittered_grid(rng, g), "mesh");
}

}  // namespace watkins::test
