#include "segment_former.hpp"

#include <algorithm>

namespace watkins {

// The pairing over n X-ordered edges: poly(i) is edge i's polygon, close(i, j) emits the segment
// that edge j closes, opened by edge i.
template <class Poly, class Close>
void SegmentFormer::pair_edges(std::size_t n, Poly&& poly_of, Close&& close) {
  int open_count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto poly = static_cast<std::size_t>(poly_of(i));
    if (poly >= open_.size()) open_.resize(std::max(poly + 1, 2 * open_.size()), -1);
    int& slot = open_[poly];
    if (slot < 0) {
      slot = static_cast<int>(i);
      ++open_count;
    } else {
      close(static_cast<std::size_t>(slot), i);
      slot = -1;
      --open_count;
    }
  }
  // An edge left open has no partner on this line (cannot happen for closed polygons whose
  // edges share the half-open scan-line rule); it draws nothing, as in the RTL. Its entry is
  // cleared for the next line, like the RTL's end-of-line marker clears the table.
  if (open_count > 0)
    for (std::size_t i = 0; i < n; ++i) open_[static_cast<std::size_t>(poly_of(i))] = -1;
}

void SegmentFormer::pair(const std::vector<ActiveEdge>& x_ordered, std::vector<Segment>& out) {
  pair_edges(
      x_ordered.size(), [&](std::size_t i) { return x_ordered[i].rec.poly; },
      [&](std::size_t opening, std::size_t closing) {
        const EdgeRecord& f = x_ordered[closing].rec;
        out.push_back(Segment{f.poly, f.material, x_ordered[opening].rec.value, f.value});
      });
}

void SegmentFormer::pair_line(const std::vector<ActiveEdge>& x_ordered, std::vector<Segment>& line) {
  if (line.size() < x_ordered.size() / 2) line.resize(x_ordered.size() / 2);  // at most one per two edges
  Segment* const out = line.data();
  std::size_t count = 0;
  pair_edges(
      x_ordered.size(), [&](std::size_t i) { return x_ordered[i].rec.poly; },
      [&](std::size_t opening, std::size_t closing) {
        // Field by field into place: a segment assembled elsewhere and copied would read back its
        // fields' stores at another width, which stalls store forwarding.
        const EdgeRecord& f = x_ordered[closing].rec;
        Segment& s = out[count++];
        s.poly = f.poly, s.material = f.material;
        s.e = x_ordered[opening].rec.value, s.f = f.value;
      });
  line.resize(count);
}

}  // namespace watkins
