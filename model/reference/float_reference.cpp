#include "float_reference.hpp"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "illumination.hpp"

namespace watkins {
namespace {

using Attr = glm::dvec4;  // depth, then R, G, B (Gouraud) or Nx, Ny, Nz (Phong)

struct Crossing {
  double x;
  Attr a;
  int edge;  // index within the polygon: breaks X ties
};

struct FloatSegment {
  int poly;
  double xe, xf;
  Attr ae, af;
};

// Gouraud's eq. (2) (BuiltScene::interpolation Eq2): the shade slots carry S·Z, divided by the
// interpolated Z per pixel.
bool eq2(const BuiltScene& scene) {
  return scene.shading == ShadingMode::Gouraud && scene.interpolation == Interpolation::Eq2;
}

// The vertex attributes the mode interpolates, in the slots the edge record uses.
Attr attributes(const ScreenVertex& v, const BuiltScene& scene) {
  const double* c = scene.shading == ShadingMode::Phong ? v.normal : v.rgb;
  const double k = eq2(scene) ? v.depth : 1.0;  // eq. (2)'s numerator S·Z
  return Attr(v.depth, c[0] * k, c[1] * k, c[2] * k);
}

// Depth between two ends, exact when they are equal (a plane of constant depth stays exactly that
// depth, so coplanar polygons tie as they do in the fixed-point pipeline).
double exact_lerp(double a, double b, double t) { return a + t * (b - a); }

// The shade of a visible pixel from its interpolated attributes: the Gouraud shade itself, eq.
// (2)'s quotient S = N/Z (the largest level where Z is 0 and N is not), or Phong's eq. (3) on the
// normalized normal (a null normal stays null, as in the normalizer).
std::array<double, 3> pixel_levels(const BuiltScene& scene, int material, const Attr& a) {
  if (eq2(scene)) {
    std::array<double, 3> s{};
    for (int c = 0; c < 3; ++c) s[c] = a[0] > 0 ? a[c + 1] / a[0] : a[c + 1] > 0 ? 255.0 : 0.0;
    return s;
  }
  if (scene.shading == ShadingMode::Gouraud) return {a[1], a[2], a[3]};
  const glm::dvec3 n(a[1], a[2], a[3]);
  const double len = glm::length(n);
  const glm::dvec3 u = len > 0 ? n / len : n;
  const PhongMaterial& m = scene.materials.at(std::size_t(material));
  return phong_levels(m, {u.x, u.y, u.z}, scene.light, scene.eye);
}

// One polygon's or curve region's crossings of a scan line, sorted by X and paired into segments
// (the first opens, the next closes), as the segment former pairs them.
void pair_crossings(int id, std::vector<Crossing>& xs, std::vector<FloatSegment>& segs) {
  std::sort(xs.begin(), xs.end(), [](const Crossing& l, const Crossing& r) {
    return l.x != r.x ? l.x < r.x : l.edge < r.edge;
  });
  for (std::size_t i = 0; i + 1 < xs.size(); i += 2) segs.push_back({id, xs[i].x, xs[i + 1].x, xs[i].a, xs[i + 1].a});
}

// Herman & Liu's 3x3 weighted mean in double on the unrounded levels, with W as given (not
// rounded to the smoother's 1/128 steps): the twin's difference from it is what the smoother's
// integer arithmetic and W's format cost on top of the pipeline's quantization. f_i as in the
// twin: a neighbour counts when it is on the screen and covered; uncovered pixels are not smoothed.
void smooth_levels(Image& img, const std::vector<double>& levels, double w) {
  const int width = img.width, height = img.height;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (!img.is_covered(x, y)) continue;
      double num[3] = {0, 0, 0}, den = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= width || ny >= height || !img.is_covered(nx, ny)) continue;
          const double f = (dx == 0 && dy == 0) ? 1.0 : (dx == 0 || dy == 0) ? w : w * w;
          den += f;
          for (int c = 0; c < 3; ++c) num[c] += f * levels[(std::size_t(ny) * width + nx) * 3 + c];
        }
      std::uint8_t* px = img.at(x, y);
      for (int c = 0; c < 3; ++c) px[c] = static_cast<std::uint8_t>(std::clamp(std::lround(num[c] / den), 0L, 255L));
    }
}

}  // namespace

Image render_float_reference(const BuiltScene& scene, FloatReferenceStats* stats) {
  const int W = scene.width, H = scene.height;
  const bool submission = scene.depth_tie == DepthTie::Submission;  // equal depth: smaller id wins
  Image img(W, H);
  const bool smoothing = scene.smooth > 0;  // BuiltScene::smooth: Herman & Liu's W
  std::vector<double> levels(smoothing ? std::size_t(W) * H * 3 : 0);
  // Bucket polygons by the scan lines they may cross.
  std::vector<std::vector<int>> bucket(H);
  for (std::size_t p = 0; p < scene.polygons.size(); ++p) {
    double lo = 1e300, hi = -1e300;
    for (const auto& v : scene.polygons[p].v) lo = std::min(lo, v.y), hi = std::max(hi, v.y);
    const int y0 = std::max(0, int(std::ceil(lo - 0.5)));
    const int y1 = std::min(H, int(std::ceil(hi - 0.5)));
    for (int y = y0; y < y1; ++y) bucket[y].push_back(int(p));
  }
  // Curves (Whitted's edges): region r is id polygons.size() + r, as preparation numbers it.
  const int n_poly = int(scene.polygons.size());
  std::vector<int> material(std::size_t(n_poly + scene.curve_regions), 0);
  for (int p = 0; p < n_poly; ++p) material[std::size_t(p)] = scene.polygons[std::size_t(p)].material;
  std::vector<std::vector<int>> curve_bucket(H);
  for (std::size_t c = 0; c < scene.curves.size(); ++c) {
    const ScreenCurve& sc = scene.curves[c];
    material[std::size_t(n_poly + sc.region)] = sc.material;
    for (std::size_t k = 0; k < sc.lines.size(); ++k)
      if (sc.y0 + int(k) < H) curve_bucket[std::size_t(sc.y0) + k].push_back(int(c));
  }
  std::vector<std::vector<Crossing>> region_xs(std::size_t(scene.curve_regions));
  std::vector<int> regions_on_line;
  std::vector<double> depth(W);
  std::vector<Attr> colour(W);
  std::vector<char> written(W);
  std::vector<int> owner(W);
  std::vector<Crossing> xs;
  std::vector<FloatSegment> segs;
  long long fragments = 0;
  for (int y = 0; y < H; ++y) {
    const double yc = y + 0.5;
    segs.clear();
    for (int p : bucket[y]) {
      const auto& v = scene.polygons[p].v;
      xs.clear();
      for (std::size_t i = 0; i < v.size(); ++i) {
        const ScreenVertex* a = &v[i];
        const ScreenVertex* b = &v[(i + 1) % v.size()];
        if (a->y == b->y) continue;
        if (a->y > b->y) std::swap(a, b);  // top first, as the edge setup does
        if (!(a->y <= yc && yc < b->y)) continue;
        const double t = (yc - a->y) / (b->y - a->y);
        Attr at = glm::mix(attributes(*a, scene), attributes(*b, scene), t);
        at.x = exact_lerp(a->depth, b->depth, t);
        xs.push_back({glm::mix(a->x, b->x, t), at, int(i)});
      }
      pair_crossings(p, xs, segs);
    }
    // Whitted: each curve's crossing of this line (found by Newton), paired per region.
    regions_on_line.clear();
    for (int c : curve_bucket[std::size_t(y)]) {
      const ScreenCurve& sc = scene.curves[std::size_t(c)];
      const ScreenVertex& v = sc.lines[std::size_t(y - sc.y0)];
      auto& rx = region_xs[std::size_t(sc.region)];
      if (rx.empty()) regions_on_line.push_back(sc.region);
      rx.push_back({v.x, attributes(v, scene), c});
    }
    for (int r : regions_on_line) {
      pair_crossings(n_poly + r, region_xs[std::size_t(r)], segs);
      region_xs[std::size_t(r)].clear();
    }
    // Same arrival order as the segment former: by closing X.
    std::stable_sort(segs.begin(), segs.end(),
                     [](const FloatSegment& l, const FloatSegment& r) { return l.xf < r.xf; });
    std::fill(written.begin(), written.end(), 0);
    for (const auto& s : segs) {
      const int x0 = std::max(0, int(std::ceil(s.xe - 0.5)));
      const int x1 = std::min(W, int(std::ceil(s.xf - 0.5)));
      for (int x = x0; x < x1; ++x) {
        const double alpha = (x + 0.5 - s.xe) / (s.xf - s.xe);
        Attr a = (1.0 - alpha) * s.ae + alpha * s.af;  // S (or N) = (1 − α)S_E + αS_F
        a.x = exact_lerp(s.ae.x, s.af.x, alpha);
        ++fragments;
        const bool tie_won = submission && a.x == depth[x] && s.poly < owner[x];
        if (written[x] && !(a.x < depth[x]) && !tie_won) continue;
        written[x] = 1;
        depth[x] = a.x;
        colour[x] = a;
        owner[x] = s.poly;
      }
    }
    for (int x = 0; x < W; ++x) {
      std::uint8_t* px = img.at(x, y);
      img.covered[std::size_t(y) * W + x] = written[x];
      img.owner[std::size_t(y) * W + x] = written[x] ? owner[x] : -1;
      const std::array<double, 3> level =
          written[x] ? pixel_levels(scene, material[std::size_t(owner[x])], colour[x])
                     : std::array<double, 3>{scene.background[0], scene.background[1], scene.background[2]};
      for (int c = 0; c < 3; ++c) {
        const double v = level[c];
        px[c] = static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L));
        if (smoothing) levels[(std::size_t(y) * W + x) * 3 + c] = v;
      }
    }
  }
  if (smoothing) smooth_levels(img, levels, scene.smooth);
  if (stats) stats->fragments = fragments;
  return img;
}

}  // namespace watkins
