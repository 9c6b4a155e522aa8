#include "scan_lines.hpp"

#include <string>

#include "twin_error.hpp"

namespace watkins {

void walk_scan_lines(const std::vector<EdgeRecord>& edges, int height, int capacity,
                     const ChannelFormats& formats, const std::function<void(const ScanLine&)>& visit) {
  walk_scan_lines(edges, 0, height, capacity, formats, visit);
}

void walk_scan_lines(const std::vector<EdgeRecord>& edges, int y_begin, int y_end, int capacity,
                     const ChannelFormats& formats, const std::function<void(const ScanLine&)>& visit) {
  ActiveEdgeList active(capacity, formats);
  SegmentFormer former;
  std::vector<Segment> segments;
  // The records the walk from line 0 has taken before y_begin are in the list already (stepped).
  std::size_t next = 0;
  for (int y = 0; y < y_begin; ++y)
    while (next < edges.size() && edges[next].y0 == y) ++next;
  if (y_begin > 0) active.start_at(edges, next, y_begin);
  for (int y = y_begin; y < y_end; ++y) {
    int entered = 0;
    for (; next < edges.size() && edges[next].y0 == y; ++next, ++entered)
      if (!active.insert(edges[next]))
        throw CapacityError("active-edge list overflow on scan line " + std::to_string(y) +
                            " (capacity " + std::to_string(capacity) + ")");
    former.pair_line(active.edges(), segments);
    visit(ScanLine{y, entered, active, segments});
    active.advance();
  }
}

}  // namespace watkins
