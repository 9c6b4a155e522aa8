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
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int(a.rgb[i * 3 + c]) - int(b.rgb[i * 3 + c]));
      e.max_abs = std::max(e.max_abs, d);
      sum_abs += d;
      sum_sq += double(d) * d;
    }
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

}  // namespace watkins
