#include "active_edge_list.hpp"

#include <algorithm>

namespace watkins {

static bool x_order(const ActiveEdge& a, const ActiveEdge& b) {
  const i64 xa = a.rec.value[fmt::ChanX], xb = b.rec.value[fmt::ChanX];
  return xa != xb ? xa < xb : a.rec.id < b.rec.id;
}

bool ActiveEdgeList::insert(const EdgeRecord& rec) {
  if (size() >= capacity_) return false;
  edges_.push_back(ActiveEdge{rec, rec.n});
  sort();
  return true;
}

void ActiveEdgeList::advance() {
  for (auto& e : edges_) EdgeIncrementer::step(e, formats_);
  edges_.erase(std::remove_if(edges_.begin(), edges_.end(),
                              [](const ActiveEdge& e) { return e.remaining <= 0; }),
               edges_.end());
  sort();
}

void ActiveEdgeList::sort() { std::sort(edges_.begin(), edges_.end(), x_order); }

}  // namespace watkins
