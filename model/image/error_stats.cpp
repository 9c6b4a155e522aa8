// RMSE, PSNR and the Mach-band measure (error_stats.hpp).
#include "error_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace watkins {

namespace {

bool same_owner(const Image& a, const Image& b, std::size_t i) {
  return a.covered[i] && b.covered[i] && a.owner[i] == b.owner[i];
}

double intensity(const Image& img, std::size_t i) {
  const std::uint8_t* p = &img.rgb[i * 3];
  return (p[0] + p[1] + p[2]) / 3.0;
}

}  // namespace

ErrorStats error_stats(const Image& a, const Image& b) {
  ErrorStats e;
  const std::size_t n = std::size_t(a.width) * a.height;
  if (a.width != b.width || a.height != b.height) return e;
  double sum_abs = 0, sum_sq = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!same_owner(a, b, i)) continue;
    ++e.compared;
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int(a.rgb[i * 3 + c]) - int(b.rgb[i * 3 + c]));
      worst = std::max(worst, d);
      sum_abs += d;
      sum_sq += double(d) * d;
    }
    e.max_abs = std::max(e.max_abs, worst);
    e.over_one += worst > 1;
  }
  if (e.compared) {
    e.mean_abs = sum_abs / (3.0 * e.compared);
    e.rmse = std::sqrt(sum_sq / (3.0 * e.compared));
  }
  e.psnr = e.rmse > 0 ? 20.0 * std::log10(255.0 / e.rmse) : std::numeric_limits<double>::infinity();
  return e;
}

namespace {

// Calls jump(|d12 - d01|, |d23 - d12|) at every polygon edge mach_band measures (see the header).
template <typename F>
void for_each_edge_jump(const Image& img, const std::vector<int>& polygon, const Image* ref, F jump) {
  const int W = img.width, H = img.height;
  if (ref && (ref->width != W || ref->height != H)) return;
  auto usable = [&](std::size_t i) { return ref ? same_owner(img, *ref, i) : img.covered[i] != 0; };
  auto value = [&](std::size_t i) { return intensity(img, i) - (ref ? intensity(*ref, i) : 0.0); };
  // Along rows (step 1) and along columns (step W): p1 at (x, y), p2 the next pixel.
  for (int dir = 0; dir < 2; ++dir) {
    const int len = dir == 0 ? W : H, lines = dir == 0 ? H : W;
    for (int l = 0; l < lines; ++l)
      for (int k = 1; k + 2 < len; ++k) {
        auto at = [&](int j) { return dir == 0 ? std::size_t(l) * W + j : std::size_t(j) * W + l; };
        const std::size_t p0 = at(k - 1), p1 = at(k), p2 = at(k + 1), p3 = at(k + 2);
        if (polygon[p1] < 0 || polygon[p2] < 0 || polygon[p1] == polygon[p2]) continue;
        if (!(usable(p0) && usable(p1) && usable(p2) && usable(p3))) continue;
        if (polygon[p0] != polygon[p1] || polygon[p3] != polygon[p2]) continue;  // a sliver: no slope on one side
        const double d01 = value(p1) - value(p0), d12 = value(p2) - value(p1), d23 = value(p3) - value(p2);
        jump(std::fabs(d12 - d01), std::fabs(d23 - d12));
      }
  }
}

}  // namespace

double mach_band(const Image& img, const std::vector<int>& polygon, const Image* ref) {
  double worst = 0;
  for_each_edge_jump(img, polygon, ref, [&](double a, double b) { worst = std::max({worst, a, b}); });
  return worst;
}

double mach_band_mean(const Image& img, const std::vector<int>& polygon, const Image* ref) {
  double sum = 0;
  long long n = 0;
  for_each_edge_jump(img, polygon, ref, [&](double a, double b) { sum += a + b, n += 2; });
  return n ? sum / double(n) : 0;
}

namespace {

// The image's intensity filtered by the normalized Gaussian `g` along rows, then columns, the
// border clamped (a window reaching past the frame sees its edge pixels).
std::vector<double> gaussian_filter(const std::vector<double>& v, int w, int h, const std::vector<double>& g) {
  const int r = static_cast<int>(g.size() / 2);
  std::vector<double> rows(v.size()), out(v.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double sum = 0;
      for (int k = -r; k <= r; ++k) sum += g[std::size_t(k + r)] * v[std::size_t(y) * w + std::clamp(x + k, 0, w - 1)];
      rows[std::size_t(y) * w + x] = sum;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double sum = 0;
      for (int k = -r; k <= r; ++k) sum += g[std::size_t(k + r)] * rows[std::size_t(std::clamp(y + k, 0, h - 1)) * w + x];
      out[std::size_t(y) * w + x] = sum;
    }
  return out;
}

}  // namespace

double ssim(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.width == 0 || a.height == 0) return 0;
  const int w = a.width, h = a.height;
  const std::size_t n = std::size_t(w) * h;
  std::vector<double> g(11);
  double total = 0;
  for (int k = -5; k <= 5; ++k) total += g[std::size_t(k + 5)] = std::exp(-k * k / (2 * 1.5 * 1.5));
  for (double& x : g) x /= total;
  std::vector<double> ia(n), ib(n), aa(n), bb(n), ab(n);
  for (std::size_t i = 0; i < n; ++i) {
    ia[i] = intensity(a, i);
    ib[i] = intensity(b, i);
    aa[i] = ia[i] * ia[i];
    bb[i] = ib[i] * ib[i];
    ab[i] = ia[i] * ib[i];
  }
  const std::vector<double> ma = gaussian_filter(ia, w, h, g), mb = gaussian_filter(ib, w, h, g),
                            saa = gaussian_filter(aa, w, h, g), sbb = gaussian_filter(bb, w, h, g),
                            sab = gaussian_filter(ab, w, h, g);
  const double c1 = (0.01 * 255) * (0.01 * 255), c2 = (0.03 * 255) * (0.03 * 255);
  double sum = 0;
  long long count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!same_owner(a, b, i)) continue;
    const double va = saa[i] - ma[i] * ma[i], vb = sbb[i] - mb[i] * mb[i], cov = sab[i] - ma[i] * mb[i];
    sum += (2 * ma[i] * mb[i] + c1) * (2 * cov + c2) / ((ma[i] * ma[i] + mb[i] * mb[i] + c1) * (va + vb + c2));
    ++count;
  }
  return count ? sum / count : 0;
}

}  // namespace watkins
