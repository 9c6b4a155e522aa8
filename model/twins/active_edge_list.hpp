// Twin of rtl/active_edge_list.sv: the edges crossing the current scan line, kept in X order.
// Edges enter at their first scan line, are stepped by the edge_incrementer after each line and
// retire after n lines. Order is (X, edge id): ids are unique, so the order is total and the
// RTL's insertion sort reproduces it exactly.
//
// Widths from the configuration (config.hpp), as the RTL takes them: MaxActiveEdges = max_active_edges;
// each entry's value and slope words per slot at ChannelFormats::bits[c]; the X comparison of the
// insertion sort is bits[ChanX] wide; poly clog2(max_polygons), material clog2(max_materials),
// the record number (edge id) clog2(max_edges).
#pragma once

#include <vector>

#include "edge_incrementer.hpp"

namespace watkins {

class ActiveEdgeList {
 public:
  // Widths from the configuration, as the RTL takes them: entries MaxActiveEdges = capacity
  // (Config::max_active_edges); each entry's channel words ChannelFormats::bits[c].
  explicit ActiveEdgeList(int capacity, const ChannelFormats& formats = Config{}.channels(ShadingMode::Gouraud))
      : capacity_(capacity), formats_(formats), signs_(EdgeIncrementer::signs(formats)) {}

  // Adds an edge on its first scan line. Returns false (and drops nothing) when full.
  bool insert(const EdgeRecord& rec);
  // The list as a walk from scan line 0 holds it on line y before line y's records enter: every
  // record of edges[0 .. count) (those with y0 < y) still crossing line y, stepped y - y0 lines
  // (EdgeIncrementer::step_lines), in (X, id) order. The list is emptied first.
  void start_at(const std::vector<EdgeRecord>& edges, std::size_t count, int y);
  // After a scan line: step every edge, retire the finished ones, restore X order.
  void advance();

  const std::vector<ActiveEdge>& edges() const { return edges_; }  // in (X, id) order
  int size() const { return static_cast<int>(edges_.size()); }
  int capacity() const { return capacity_; }

 private:
  template <int Order>
  void advance_at();
  template <int Order>
  void start_at_order(const std::vector<EdgeRecord>& edges, std::size_t count, int y);  // advance() at the configuration's edge order

  int capacity_;
  ChannelFormats formats_;
  EdgeIncrementer::Signs signs_;  // of formats_
  std::vector<ActiveEdge> edges_;
};

}  // namespace watkins
