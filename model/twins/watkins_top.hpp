// Twin of rtl/watkins_top.sv: the whole Watkins scan-line pipeline, stage by stage, on the
// y-sorted edge-record stream: active-edge list + edge_incrementer → segment_former →
// segment_interpolator → [Phong: normalizer → phong_shader] → scanline_buffer → pixels in
// raster order (every pixel of the screen). Gouraud shading (frame.shading) writes the
// interpolated shade; Phong shading normalizes the interpolated normal and shades it with the
// fragment's material, per pixel, before the depth test. At equal depth the frame's rule decides
// (frame.depth_tie, the top's tie_submission_i): first arrival, or the smaller polygon id.
// frame.smooth_w != 0: Herman & Liu's 3x3 smoother (smoother.hpp) after the scanline buffer; it
// needs the full raster, so a smoothed frame is always emitted in full (sparse_i is ignored).
// frame.eq2 (Gouraud, the top's eq2_i): Gouraud's eq. (2), each fragment's shade the quotient of
// its shade slots (S·Z) by its depth (shade_divider.hpp) instead of the slots' rounding. A
// configuration with eq2 (the top's HasEq2) changes only the cycles (cycle_model.hpp), not a value.
//
// From the configuration (config.hpp), as rtl/watkins_top.sv takes it (rtl_parameters()): one
// format per group -- XIntBits/XFracBits, DepthIntBits/DepthFracBits, and the attribute slots'
// AttrIntBits/AttrFracBits (the shade group when Phong = 0, the normal group when 1), DepthBits =
// depth_bits, MaxActiveEdges, MaxWidth, and the id widths PolyIdBits, MaterialIdBits, EdgeIdBits; the
// normalizer and phong_shader keep their package formats (the interpolator converts the normal
// to FracBits fraction bits, NormalInBits wide, at its fragment output).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "active_edge_list.hpp"
#include "config.hpp"
#include "frame.hpp"
#include "image.hpp"
#include "scanline_buffer.hpp"

namespace watkins {

struct PipelineStats {
  long long edges = 0;      // edge records read
  long long segments = 0;   // segments formed (including empty spans)
  long long fragments = 0;  // fragments produced by the segment interpolator
  long long visible = 0;    // fragments that won their pixel when they arrived
  int max_active_edges = 0;
};

// Called for every fragment in pipeline order: scan line, fragment, whether it won the depth test.
using FragmentObserver = std::function<void(int y, const Fragment& f, bool won)>;

// Every internal stage stream of the pipeline, item by item, in each stage's own output order
// (the streams of rtl/watkins_top.sv between its stages; the co-simulation bench compares
// them to the RTL's). Every callback is optional; per stage, the items of scan line y come first,
// then its end-of-line marker, for y = 0 .. height-1.
struct PipelineObserver {
  // active_edge_list output: the active edges of line y in (X, edge id) order, channels on line y.
  std::function<void(int y, const ActiveEdge& e)> active_edge;
  std::function<void(int y)> active_edges_end;
  // segment_former output: the segments of line y in closing order (empty spans included).
  std::function<void(int y, const Segment& s)> segment;
  std::function<void(int y)> segments_end;
  // Fragments of line y in order as the scanline_buffer receives them, and whether each won its
  // pixel: the interpolator's output (x, depth, normal, material), with rgb the interpolated
  // shade (Gouraud) or the phong_shader's output (Phong).
  std::function<void(int y, const Fragment& f, bool won)> fragment;
  std::function<void(int y)> fragments_end;
};

// One beat of the sparse pixel stream (watkins_top with sparse_i = 1): the covered pixels
// of the frame in raster order; `last` on the frame's last beat. When the last line has no
// covered pixel (e.g. a frame that covers nothing) a terminating beat follows, not covered, with
// the background colour at (width-1, height-1), and carries `last` instead.
struct SparseBeat {
  int x = 0, y = 0;
  std::array<std::uint8_t, 3> rgb{};
  bool covered = true;
  bool last = false;
};
// The sparse stream of a rendered frame (its covered pixels, plus the terminator when needed).
std::vector<SparseBeat> sparse_stream(const Image& img);

// Which span loop draws the spans of an unobserved Gouraud frame whose values stay in range: the
// scalar loop (the reference, and the baseline x86-64 build's), or a span kernel several pixels
// at a time, built for AVX2 and AVX-512 and chosen at run time (Auto: the widest the processor
// has; a path it lacks falls back to the next narrower, down to the scalar loop). Every path
// draws the same frame, bit for bit.
enum class SpanPath { Auto, Scalar, Avx2, Avx512 };

class WatkinsTop {
 public:
  // The default configuration with an active-edge list of `max_active_edges` entries.
  explicit WatkinsTop(int max_active_edges = fmt::MaxActiveEdges)
      : max_active_edges_(max_active_edges) {}
  // The pipeline built for `config`: its channel formats (per the frame's shading mode) and its
  // active-edge list. Capacities other than the list (width, materials, polygons) are checked
  // by scene preparation, which must be given the same configuration.
  explicit WatkinsTop(const Config& config)
      : max_active_edges_(config.max_active_edges), config_(config) {}
  // Renders the frame. Throws CapacityError if the active-edge list would overflow.
  Image render(const Frame& frame, const FragmentObserver& observe = nullptr);
  // The same, reporting every stage stream to `observe`.
  Image render(const Frame& frame, const PipelineObserver& observe);
  // The same into `out`, whose storage is reused (Image::reset): for a loop drawing frame after
  // frame. The image is the one render() returns.
  void render_into(const Frame& frame, Image& out, const PipelineObserver& observe = {});
  const PipelineStats& stats() const { return stats_; }
  // Threads drawing an unobserved frame: n bands of scan lines, each started from its first
  // line's exact edge state, so the frame and its counts are one thread's. Default 1.
  void set_threads(int n) { threads_ = n < 1 ? 1 : n; }
  void set_span_path(SpanPath p) { span_path_ = p; }

 private:
  int max_active_edges_;
  Config config_;
  PipelineStats stats_;
  int threads_ = 1;
  SpanPath span_path_ = SpanPath::Auto;
};

}  // namespace watkins
