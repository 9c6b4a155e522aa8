// Error statistics of a sweep point beyond ImageError: RMSE and PSNR over the pixels two renders
// share, and a Mach-band measure — how sharply the shading bends where one polygon meets the
// next, the artifact Gouraud's paper is about (1971, "The Mach band effect", Fig. 1).
#pragma once

#include <vector>

#include "image.hpp"

namespace watkins {

// Over pixels where a and b both show the same owner (as compare_images counts them), all of
// R, G, B, in 8-bit levels. psnr = 20 log10(255 / rmse): +infinity when the images agree.
struct ErrorStats {
  long long compared = 0;  // pixels
  long long over_one = 0;  // compared pixels with some channel off by more than 1 level (a visible step)
  int max_abs = 0;
  double mean_abs = 0, rmse = 0, psnr = 0;
};
ErrorStats error_stats(const Image& a, const Image& b);

// Mach-band measure: the largest jump of the intensity's first difference across a polygon edge,
// in 8-bit levels. Intensity I is the mean of R, G, B. At each edge between neighbours p1, p2 of
// a row or column (polygon[p1] != polygon[p2]), with p0 before p1 and p3 after p2 on the same
// line, the first differences are d01, d12, d23 and the jumps are |d12 - d01| and |d23 - d12|
// (the second differences at p1 and p2): a step in value (flat shading, Fig. 1a) and a kink in
// slope (Gouraud's linear interpolation, Fig. 1b) both show. `polygon` holds each pixel's polygon
// (-1: none). With `ref`, the measure is taken on I(img) - I(ref), so a surface's own curvature
// (a highlight) does not count; p0..p3 must then show the same owner in img and ref. Without it,
// p0..p3 need only be covered. Returns 0 when there is no such edge.
double mach_band(const Image& img, const std::vector<int>& polygon, const Image* ref = nullptr);
// The same jumps averaged instead of their maximum: how strong the bands are over the whole image
// (a surface of thousands of voxel faces has one worst edge whatever the shading).
double mach_band_mean(const Image& img, const std::vector<int>& polygon, const Image* ref = nullptr);

// Structural similarity (Wang, Bovik, Sheikh and Simoncelli 2004) of the intensities (the mean of
// R, G, B), with their constants: an 11 x 11 Gaussian window of sigma 1.5, C1 = (0.01 * 255)^2,
// C2 = (0.03 * 255)^2. The SSIM map is averaged over the pixels where a and b show the same owner
// (as error_stats compares them); 1 when the images agree there, 0 when no pixel compares.
double ssim(const Image& a, const Image& b);

}  // namespace watkins
