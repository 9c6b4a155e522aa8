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
  // A frame of one shade, nothing covered: one row built and appended h times (each byte
  // written once).
  Image(int w, int h, const std::array<std::uint8_t, 3>& background)
      : width(w), height(h), covered(std::size_t(w) * h, 0), owner(std::size_t(w) * h, -1) {
    std::vector<std::uint8_t> row(std::size_t(w) * 3);
    for (std::size_t i = 0; i < row.size(); i += 3) {
      row[i] = background[0];
      row[i + 1] = background[1];
      row[i + 2] = background[2];
    }
    rgb.reserve(row.size() * static_cast<std::size_t>(h));
    for (int y = 0; y < h; ++y) rgb.insert(rgb.end(), row.begin(), row.end());
  }
  std::uint8_t* at(int x, int y) { return &rgb[(std::size_t(y) * width + x) * 3]; }
  const std::uint8_t* at(int x, int y) const { return &rgb[(std::size_t(y) * width + x) * 3]; }
  bool is_covered(int x, int y) const { return covered[std::size_t(y) * width + x] != 0; }
};

}  // namespace watkins
