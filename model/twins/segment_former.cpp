#include "segment_former.hpp"

#include <unordered_map>

namespace watkins {

void SegmentFormer::form(const std::vector<ActiveEdge>& x_ordered, std::vector<Segment>& out) {
  std::unordered_map<int, const ActiveEdge*> open;  // polygon id -> its unpaired edge
  for (const auto& edge : x_ordered) {
    auto it = open.find(edge.rec.poly);
    if (it == open.end()) {
      open.emplace(edge.rec.poly, &edge);
    } else {
      out.push_back(Segment{edge.rec.poly, edge.rec.material, it->second->rec.value, edge.rec.value});
      open.erase(it);
    }
  }
  // An edge left open has no partner on this line (cannot happen for closed polygons whose
  // edges share the half-open scan-line rule); it draws nothing, as in the RTL.
}

}  // namespace watkins
