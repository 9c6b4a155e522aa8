// Twin of rtl/watkins_gouraud_top.sv: the whole Watkins/Gouraud pipeline, stage by stage, on the
// y-sorted edge-record stream: active-edge list + edge_incrementer → segment_former →
// segment_interpolator → scanline_buffer → pixels in raster order (every pixel of the screen).
#pragma once

#include <functional>

#include "image.hpp"
#include "prepare.hpp"
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

class GouraudPipeline {
 public:
  explicit GouraudPipeline(int max_active_edges = fmt::MaxActiveEdges)
      : max_active_edges_(max_active_edges) {}
  // Renders the frame. Throws SceneError if the active-edge list would overflow.
  Image render(const PreparedScene& scene, const FragmentObserver& observe = nullptr);
  const PipelineStats& stats() const { return stats_; }

 private:
  int max_active_edges_;
  PipelineStats stats_;
};

}  // namespace watkins
