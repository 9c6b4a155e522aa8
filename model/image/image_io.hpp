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

// Output files written all or nothing: add() keeps each file's bytes; commit() writes each to a
// temporary name beside it and renames them over their names only once all were written, so a
// run that fails anywhere leaves no output (and no temporary) behind. A name that exists and is
// not a regular file (/dev/null, a FIFO) is written in place. Throws std::runtime_error.
class OutputFiles {
 public:
  void add(const std::string& path, std::vector<unsigned char> bytes);
  void add(const std::string& path, const std::string& text) { add(path, std::vector<unsigned char>(text.begin(), text.end())); }
  // A file another writer streams out (e.g. the simulator's waveform): returns the name to write
  // it under, a temporary beside `path` that commit() renames over it and a failed run removes
  // (or `path` itself when it names a device). Every write and close is checked (a full disk is
  // an error, not a truncated file).
  std::string stage(const std::string& path);
  void commit();
  ~OutputFiles();

 private:
  struct File {
    std::string path, temp;
    std::vector<unsigned char> bytes;
    bool staged = false;  // written by someone else under temp (or in place): only renamed here
  };
  static std::string temporary_for(const std::string& path);
  std::vector<File> files_;
};

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
