#include "smoother.hpp"

namespace watkins {

std::array<std::uint8_t, 3> Smoother::pixel(const Image& in, int x, int y) const {
  const std::uint8_t* c = in.at(x, y);
  if (!in.is_covered(x, y)) return {c[0], c[1], c[2]};
  const std::int64_t one = std::int64_t{1} << fmt::SmoothWFracBits;
  std::array<std::int64_t, 3> s_edge{}, s_corner{};
  int n_edge = 0, n_corner = 0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= in.width || ny >= in.height) continue;
      if (!in.is_covered(nx, ny)) continue;  // f_i = 0: off the object
      const bool corner = dx != 0 && dy != 0;
      const std::uint8_t* g = in.at(nx, ny);
      auto& s = corner ? s_corner : s_edge;
      for (int k = 0; k < 3; ++k) s[k] += g[k];
      (corner ? n_corner : n_edge) += 1;
    }
  const std::int64_t d = denominator(n_edge, n_corner);
  const std::int64_t w = w_;
  std::array<std::uint8_t, 3> out{};
  for (int k = 0; k < 3; ++k) {
    const std::int64_t n = one * one * c[k] + one * w * s_edge[k] + w * w * s_corner[k];
    // n < 2^28 and d < 2^18 (8-bit shades, W < 2): 64 bits hold the division exactly.
    out[k] = static_cast<std::uint8_t>(round_div64(n, d));
  }
  return out;
}

Image Smoother::apply(const Image& in) const {
  Image out = in;
  if (w_ == 0) return out;
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      const auto p = pixel(in, x, y);
      std::uint8_t* o = out.at(x, y);
      o[0] = p[0], o[1] = p[1], o[2] = p[2];
    }
  return out;
}

}  // namespace watkins
