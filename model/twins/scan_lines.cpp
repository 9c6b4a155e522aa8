#include "scan_lines.hpp"

#include <string>

#include "twin_error.hpp"

namespace watkins {

void walk_scan_lines(const std::vector<EdgeRecord>& edges, int height, int capacity,
                     const ChannelFormats& formats, const std::function<void(const ScanLine&)>& visit) {
  ActiveEdgeList active(capacity, formats);
  SegmentFormer former;
  std::vector<Segment> segments;
  std::size_t next = 0;
  for (int y = 0; y < height; ++y) {
    int entered = 0;
    for (; next < edges.size() && edges[next].y0 == y; ++next, ++entered)
      if (!active.insert(edges[next]))
        throw CapacityError("active-edge list overflow on scan line " + std::to_string(y) +
                            " (capacity " + std::to_string(capacity) + ")");
    segments.clear();
    former.pair(active.edges(), segments);
    visit(ScanLine{y, entered, active, segments});
    active.advance();
  }
}

}  // namespace watkins
