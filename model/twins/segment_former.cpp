#include "segment_former.hpp"

#include <algorithm>

namespace watkins {

void SegmentFormer::pair(const std::vector<ActiveEdge>& x_ordered, std::vector<Segment>& out) {
  int open_count = 0;
  for (std::size_t i = 0; i < x_ordered.size(); ++i) {
    const ActiveEdge& edge = x_ordered[i];
    const auto poly = static_cast<std::size_t>(edge.rec.poly);
    if (poly >= open_.size()) open_.resize(std::max(poly + 1, 2 * open_.size()), -1);
    int& slot = open_[poly];
    if (slot < 0) {
      slot = static_cast<int>(i);
      ++open_count;
    } else {
      const ActiveEdge& opening = x_ordered[static_cast<std::size_t>(slot)];
      out.push_back(Segment{edge.rec.poly, edge.rec.material, opening.rec.value, edge.rec.value});
      slot = -1;
      --open_count;
    }
  }
  // An edge left open has no partner on this line (cannot happen for closed polygons whose
  // edges share the half-open scan-line rule); it draws nothing, as in the RTL. Its entry is
  // cleared for the next line, like the RTL's end-of-line marker clears the table.
  if (open_count > 0)
    for (const ActiveEdge& edge : x_ordered) open_[static_cast<std::size_t>(edge.rec.poly)] = -1;
}

}  // namespace watkins
