// The frame the pipeline writes (watkins_top's pixel stream gathered into raster order): RGB8
// pixels, which pixels some polygon won, and which polygon that was. Plain data; PNG output and
// the error statistics live in model/image/.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace watkins {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;      // width*height*3, raster order
  std::vector<std::uint8_t> covered;  // width*height: 1 where some polygon won the pixel
  std::vector<int> owner;             // width*height: id of the visible polygon, -1 where none

  Image() = default;
  Image(int w, int h)
      : width(w), height(h), rgb(std::size_t(w) * h * 3, 0), covered(std::size_t(w) * h, 0),
        owner(std::size_t(w) * h, -1) {}
  // A frame of one shade, nothing covered.
  Image(int w, int h, const std::array<std::uint8_t, 3>& background) { reset(w, h, background); }
  // The same in this image's storage: a renderer that draws frame after frame into one image
  // reuses its memory instead of faulting in fresh pages each frame. One row is built and
  // copied h times (each byte written once).
  void reset(int w, int h, const std::array<std::uint8_t, 3>& background) {
    width = w;
    height = h;
    const std::size_t pixels = std::size_t(w) * h;
    covered.assign(pixels, 0);
    owner.assign(pixels, -1);
    rgb.resize(pixels * 3);
    for (std::size_t i = 0; i < std::size_t(w) * 3; i += 3) {
      rgb[i] = background[0];
      rgb[i + 1] = background[1];
      rgb[i + 2] = background[2];
    }
    for (int y = 1; y < h; ++y)
      std::copy(rgb.begin(), rgb.begin() + std::ptrdiff_t(w) * 3, rgb.begin() + std::ptrdiff_t(y) * w * 3);
  }
  std::uint8_t* at(int x, int y) { return &rgb[(std::size_t(y) * width + x) * 3]; }
  const std::uint8_t* at(int x, int y) const { return &rgb[(std::size_t(y) * width + x) * 3]; }
  bool is_covered(int x, int y) const { return covered[std::size_t(y) * width + x] != 0; }
};

}  // namespace watkins
