// Image I/O and comparison: PNG output, and the error statistics every render reports between two
// frames (model, RTL, double reference, analytic truth).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "image.hpp"

namespace watkins {

// The PNG file's bytes.
std::vector<unsigned char> encode_png(const Image& img);

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
  int guarded = 0;           // same-polygon pixels left out: within `guard` of a geometry difference
};
// guard > 0 leaves out the pixels within `guard` pixels (a (2·guard+1)² window) of one whose
// coverage or polygon differs: a smoothed frame spreads such a pixel into its neighbours.
ImageError compare_images(const Image& a, const Image& b, int guard = 0);

// Pixel i (row-major) as compare_images judges it: geometry differs when it is covered in one
// image only or by different polygons; otherwise its error is the largest |Δ| over R, G, B.
bool geometry_differs(const Image& a, const Image& b, std::size_t i);
int pixel_max_abs(const Image& a, const Image& b, std::size_t i);

// |a − b| per pixel, scaled by `gain` so small errors are visible; magenta where coverage or the
// visible polygon differs.
Image diff_image(const Image& a, const Image& b, int gain = 16);

}  // namespace watkins
