#include "image_io.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

// In libstb but declared only in stb_image_write.h's implementation part.
extern "C" unsigned char* stbi_write_png_to_mem(const unsigned char* pixels, int stride_bytes, int x, int y, int n,
                                                int* out_len);

namespace watkins {

std::vector<unsigned char> encode_png(const Image& img) {
  int len = 0;
  unsigned char* png = stbi_write_png_to_mem(img.rgb.data(), img.width * 3, img.width, img.height, 3, &len);
  if (!png) throw std::runtime_error("cannot encode PNG");
  std::vector<unsigned char> out(png, png + len);
  std::free(png);  // stb allocates with malloc (STBIW_FREE)
  return out;
}

namespace {
bool near_geometry_difference(const Image& a, const Image& b, int x, int y, int guard) {
  for (int ny = std::max(0, y - guard); ny <= std::min(a.height - 1, y + guard); ++ny)
    for (int nx = std::max(0, x - guard); nx <= std::min(a.width - 1, x + guard); ++nx)
      if (geometry_differs(a, b, std::size_t(ny) * a.width + nx)) return true;
  return false;
}
}  // namespace

ImageError compare_images(const Image& a, const Image& b, int guard) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("compare_images: images differ in size");
  ImageError e;
  long long sum = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const std::uint8_t *pa = a.at(x, y), *pb = b.at(x, y);
      if (!std::equal(pa, pa + 3, pb)) ++e.differing;
      if (a.is_covered(x, y) != b.is_covered(x, y)) {
        ++e.coverage_differs;
        continue;
      }
      if (!a.is_covered(x, y)) continue;
      const std::size_t i = std::size_t(y) * a.width + x;
      if (a.owner[i] != b.owner[i]) {
        ++e.visibility_differs;
        continue;
      }
      if (guard > 0 && near_geometry_difference(a, b, x, y, guard)) {
        ++e.guarded;
        continue;
      }
      ++e.compared;
      int worst = 0;
      for (int c = 0; c < 3; ++c) {
        const int d = std::abs(int(pa[c]) - int(pb[c]));
        sum += d;
        worst = std::max(worst, d);
      }
      e.max_abs = std::max(e.max_abs, worst);
      if (worst > 1) ++e.over_one;
    }
  e.mean_abs = e.compared ? double(sum) / (3.0 * e.compared) : 0.0;
  return e;
}

bool geometry_differs(const Image& a, const Image& b, std::size_t i) {
  return a.covered[i] != b.covered[i] || (a.covered[i] && a.owner[i] != b.owner[i]);
}

int pixel_max_abs(const Image& a, const Image& b, std::size_t i) {
  int worst = 0;
  for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a.rgb[i * 3 + c]) - int(b.rgb[i * 3 + c])));
  return worst;
}

Image diff_image(const Image& a, const Image& b, int gain) {
  Image d(a.width, a.height);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      std::uint8_t* pd = d.at(x, y);
      const std::size_t i = std::size_t(y) * a.width + x;
      if (a.is_covered(x, y) != b.is_covered(x, y) || a.owner[i] != b.owner[i]) {
        pd[0] = 255, pd[1] = 0, pd[2] = 255;
        continue;
      }
      for (int c = 0; c < 3; ++c)
        pd[c] = static_cast<std::uint8_t>(
            std::min(255, gain * std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c]))));
    }
  return d;
}

}  // namespace watkins
