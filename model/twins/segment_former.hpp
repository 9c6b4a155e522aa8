// Twin of rtl/segment_former.sv: pairs the active edges of each polygon into segments
// ("edges belonging to the same polygon are paired to form segments", Gouraud 1971).
// One pass over the X-ordered active edges: the first edge of a polygon opens a segment, the
// next edge of the same polygon closes it (even-odd pairing, so concave and bow-tie quads with
// four edges on a line give two segments). Segments leave in the order they close.
//
// Widths from the configuration (config.hpp), as the RTL takes them: seg_e_o/seg_f_o carry the
// five channel slots at their own widths, VectorBits = sum of ChannelFormats::bits[c];
// the polygon id register is clog2(max_polygons) bits, the material id clog2(max_materials).
#pragma once

#include <vector>

#include "edge_incrementer.hpp"

namespace watkins {

struct Segment {
  int poly = 0;
  int material = 0;   // of the polygon (taken from the closing edge, like the RTL)
  ChannelVector e{};  // left end E: channel values of the opening edge on this scan line
  ChannelVector f{};  // right end F: channel values of the closing edge
};

class SegmentFormer {
 public:
  // Appends one line's segments to `out`. The open table is kept between lines (indexed by
  // polygon id, left empty after each line), so a frame allocates it once.
  void pair(const std::vector<ActiveEdge>& x_ordered, std::vector<Segment>& out);
  // The same, except that `line` becomes the line's segments (not appended to): its elements
  // are overwritten in place, so a walk reusing one vector line after line initializes only the
  // room a line needs beyond the line before it.
  void pair_line(const std::vector<ActiveEdge>& x_ordered, std::vector<Segment>& line);
  // One line with a fresh table.
  static void form(const std::vector<ActiveEdge>& x_ordered, std::vector<Segment>& out) {
    SegmentFormer former;
    former.pair(x_ordered, out);
  }

 private:
  template <class Poly, class Close>
  void pair_edges(std::size_t n, Poly&& poly_of, Close&& close);

  std::vector<int> open_;  // polygon id -> index of its unpaired edge in x_ordered, or -1
};

}  // namespace watkins
