#include "active_edge_list.hpp"

#include <algorithm>

namespace watkins {

static bool x_order(const ActiveEdge& a, const ActiveEdge& b) {
  const i64 xa = a.rec.value[fmt::ChanX], xb = b.rec.value[fmt::ChanX];
  return xa != xb ? xa < xb : a.rec.id < b.rec.id;
}

// (X, id) is a total order (ids are unique), so any correct placement gives the RTL's order;
// these keep the list sorted without re-sorting it: a new edge goes to its place by binary
// search, and a step leaves the list nearly sorted (edges swap only where they cross), which an
// insertion sort restores in about one comparison per edge.
bool ActiveEdgeList::insert(const EdgeRecord& rec) {
  if (size() >= capacity_) return false;
  const ActiveEdge e{rec, rec.n};
  edges_.insert(std::upper_bound(edges_.begin(), edges_.end(), e, x_order), e);
  return true;
}

void ActiveEdgeList::start_at(const std::vector<EdgeRecord>& edges, std::size_t count, int y) {
  if (formats_.edge_order == 3)
    start_at_order<3>(edges, count, y);
  else
    start_at_order<1>(edges, count, y);
}

template <int Order>
void ActiveEdgeList::start_at_order(const std::vector<EdgeRecord>& edges, std::size_t count, int y) {
  edges_.clear();
  for (std::size_t i = 0; i < count; ++i) {
    const EdgeRecord& rec = edges[i];
    if (rec.y0 + rec.n <= y) continue;  // retired before line y
    ActiveEdge e{rec, rec.n};
    EdgeIncrementer::step_lines<Order>(e, y - rec.y0, signs_);
    edges_.push_back(e);
  }
  std::sort(edges_.begin(), edges_.end(), x_order);  // (X, id) is total: the walk's order
}

void ActiveEdgeList::advance() {
  if (formats_.edge_order == 3)
    advance_at<3>();
  else
    advance_at<1>();
}

template <int Order>
void ActiveEdgeList::advance_at() {
  const EdgeIncrementer::Signs sign = signs_;  // a local copy: the edges' stores cannot alias it
  std::size_t kept = 0;
  for (std::size_t i = 0; i < edges_.size(); ++i) {
    ActiveEdge& e = edges_[i];
    EdgeIncrementer::step<Order>(e, sign);
    if (e.remaining <= 0) continue;
    // Insertion sort as the survivors are compacted: shift the sorted prefix up past e.
    std::size_t j = kept;
    if (j > 0 && x_order(e, edges_[j - 1])) {
      const ActiveEdge moving = e;
      do {
        edges_[j] = edges_[j - 1];
        --j;
      } while (j > 0 && x_order(moving, edges_[j - 1]));
      edges_[j] = moving;
    } else if (j != i) {
      edges_[j] = e;
    }
    ++kept;
  }
  edges_.resize(kept);
}

}  // namespace watkins
