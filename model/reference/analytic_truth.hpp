// Analytic truth: the scene's exact surfaces ray-cast through every pixel centre and shaded by
// Phong's eq. (3) with the exact surface normal at the visible point, the light and the eye as
// the pipelines use them (at infinity). It answers the third question of the references: the
// double reference against the truth is what the *algorithm* costs (tessellation, interpolating
// shades or normals), apart from quantization (fixed point against the double reference).
//
// Defined when the scene's illumination is eq. (3): Phong shading, or Gouraud shading with the
// "phong" vertex rule. Exact surfaces: sphere, cone (side and base cap), quarter torus,
// hyperbolic paraboloid, bicubic Bezier patch, cross vault (each barrel on its side of the
// groins), pier and portico (vaults and box piers, closed-form roots), voxel phantoms (the union of balls the
// voxels sample, not the voxel faces); meshes, voxel files and screen-space
// polygons have no truth (their pixels are left uncovered and so are not compared). When the scene
// culls back faces, a hit on the back of a surface (a vault's extrados) is not seen: the ray goes on.
#pragma once

#include <string>

#include "image_io.hpp"
#include "scene.hpp"

namespace watkins {

struct AnalyticTruth {
  Image image;              // covered where an exact surface is hit; owner = scene object index
  std::string unavailable;  // non-empty: why there is no truth for this scene (image empty)
  int surfaces = 0;         // objects ray-cast
  int without_truth = 0;    // objects with no closed form here (not compared)
};

AnalyticTruth render_analytic_truth(const BuiltScene& scene);

// Error of `img` (a render of `scene`, owners = polygon ids) against the truth, over pixels where
// both show the same scene object; silhouette pixels covered by one of them only are counted apart.
// The render with each pixel's owner turned from polygon id into scene object index, as the
// truth's owners are (what compare_with_truth compares; the Mach-band measures take it too).
Image by_object(const BuiltScene& scene, const Image& img);
ImageError compare_with_truth(const BuiltScene& scene, const Image& img, const AnalyticTruth& truth);
// |img - truth| x16 per pixel; magenta where coverage or the scene object differs.
Image truth_diff_image(const BuiltScene& scene, const Image& img, const AnalyticTruth& truth);

}  // namespace watkins
