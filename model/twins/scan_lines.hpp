// The front half of watkins_top, line by line: edge records enter the active-edge list on their
// first scan line, the segment former pairs the active edges of each line, and the list steps
// to the next line. The top's twin interpolates the segments of each line it is handed; scene
// preparation measures a frame's needs with the same walk, so the two never disagree.
#pragma once

#include <functional>
#include <vector>

#include "active_edge_list.hpp"
#include "segment_former.hpp"

namespace watkins {

// What one scan line holds after the front half: the active edges in (X, id) order and the
// segments in closing order (empty spans included).
struct ScanLine {
  int y = 0;
  int entered = 0;  // edge records that entered the list on this line
  const ActiveEdgeList& active;
  const std::vector<Segment>& segments;
};

// Walks scan lines 0 .. height-1 of the y-sorted `edges` with an active-edge list of `capacity`
// entries, calling `visit` once per line. Throws CapacityError naming the line on overflow.
// Channels wrap at the widths of `formats`.
void walk_scan_lines(const std::vector<EdgeRecord>& edges, int height, int capacity,
                     const ChannelFormats& formats, const std::function<void(const ScanLine&)>& visit);
// The same walk over lines [y_begin, y_end) only: the list starts as the walk from line 0 holds
// it on line y_begin (ActiveEdgeList::start_at), so every line's edges, segments and counts are
// those of the whole walk (a band of a frame drawn apart from the others). A capacity error
// names the first overflowing line of the band.
void walk_scan_lines(const std::vector<EdgeRecord>& edges, int y_begin, int y_end, int capacity,
                     const ChannelFormats& formats, const std::function<void(const ScanLine&)>& visit);

}  // namespace watkins
