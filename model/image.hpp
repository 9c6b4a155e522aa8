// An RGB8 frame with a coverage mask, PNG output and the error statistics every render reports.
#pragma once

#include <array>
#include <cstdint>
#include <string>
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
  std::uint8_t* at(int x, int y) { return &rgb[(std::size_t(y) * width + x) * 3]; }
  const std::uint8_t* at(int x, int y) const { return &rgb[(std::size_t(y) * width + x) * 3]; }
  bool is_covered(int x, int y) const { return covered[std::size_t(y) * width + x] != 0; }
};

// Writes a PNG; throws std::runtime_error naming the path when it cannot.
void write_png(const Image& img, const std::string& path);

// Difference between two renders of the same scene, in 8-bit levels over R, G, B.
// Shading error is measured where both show the same polygon; pixels where quantization moved a
// silhouette or flipped visibility between polygons are counted apart, since there a difference
// of any size is a change of geometry, not of shade.
struct ImageError {
  int compared = 0;            // pixels where both images show the same polygon
  int coverage_differs = 0;    // pixels covered in one image only (silhouettes moved by quantization)
  int visibility_differs = 0;  // pixels covered in both but by different polygons
  int max_abs = 0;           // max |Δ| over compared pixels and channels
  double mean_abs = 0;       // mean |Δ| over compared pixels and channels
  int over_one = 0;          // compared pixels with some channel off by more than 1 level
  int differing = 0;         // pixels (any) whose RGB differs at all
};
ImageError compare_images(const Image& a, const Image& b);

// |a − b| per pixel, scaled by `gain` so small errors are visible; magenta where coverage or the
// visible polygon differs.
Image diff_image(const Image& a, const Image& b, int gain = 16);

}  // namespace watkins
