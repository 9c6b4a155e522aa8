#include "scene_needs.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

#include "scan_lines.hpp"
#include "segment_interpolator.hpp"
#include "signed_bits.hpp"

namespace watkins {

int SceneNeeds::bits_for_value(int channel) const {
  return std::max({signed_bits(value_min[channel]), signed_bits(value_max[channel]),
                   signed_bits(slope_min[channel]), signed_bits(slope_max[channel])});
}

SceneNeeds measure_needs(const Frame& frame, int polygons, const ChannelFormats& formats) {
  SceneNeeds needs;
  needs.value_bits.fill(1);
  needs.polygons = polygons;
  needs.edges = static_cast<int>(frame.edges.size());
  for (int c = 0; c < fmt::NumChannels; ++c) {
    needs.value_min[c] = needs.slope_min[c] = INT64_MAX;
    needs.value_max[c] = needs.slope_max[c] = INT64_MIN;
  }
  for (const auto& e : frame.edges) {
    needs.max_edge_lines = std::max(needs.max_edge_lines, e.n);
    needs.curve_edges += e.poly >= polygons;
    const bool cubic = formats.edge_order == 3 && (e.d2 != ChannelVector{} || e.d3 != ChannelVector{});
    if (cubic) {
      // A cubic edge: its extremes may lie inside the run; every line's value as the
      // incrementer steps it (prepare() checks the exact values with the fit's own figures).
      ActiveEdge a{e, e.n};
      for (int k = 0; k < e.n; ++k) {
        for (int c = 0; c < fmt::NumChannels; ++c)
          needs.value_bits[c] = std::max(needs.value_bits[c], signed_bits(a.rec.value[c]));
        EdgeIncrementer::step(a, formats);
      }
    }
    for (int c = 0; c < fmt::NumChannels; ++c) {
      // Edge values step linearly: the first and last scan line are the extremes. The slope may
      // be wrapped to its word; stepping modulo the word gives the true last value whenever it
      // fits (prepare() checks that with the exact figures of the edge setup).
      const i64 last = wrap_signed(static_cast<i128>(e.value[c]) + static_cast<i128>(e.n - 1) * e.slope[c],
                                   formats.bits[c]);
      if (!cubic) needs.value_bits[c] = std::max({needs.value_bits[c], signed_bits(e.value[c]), signed_bits(last)});
      needs.value_min[c] = std::min(needs.value_min[c], e.value[c]);
      needs.value_max[c] = std::max(needs.value_max[c], e.value[c]);
      needs.slope_min[c] = std::min(needs.slope_min[c], e.slope[c]);
      needs.slope_max[c] = std::max(needs.slope_max[c], e.slope[c]);
    }
  }
  if (frame.edges.empty())
    for (int c = 0; c < fmt::NumChannels; ++c)
      needs.value_min[c] = needs.value_max[c] = needs.slope_min[c] = needs.slope_max[c] = 0;

  // The active-edge list and the widest span, from the pipeline's own front half (an unbounded
  // list, so the need is measured rather than refused here).
  walk_scan_lines(frame.edges, frame.height, std::numeric_limits<int>::max(), formats, [&](const ScanLine& line) {
    if (line.active.size() > needs.max_active_edges) {
      needs.max_active_edges = line.active.size();
      needs.max_active_line = line.y;
    }
    int curved = 0;
    for (const ActiveEdge& e : line.active.edges()) curved += e.rec.poly >= polygons;
    if (curved > needs.max_curve_edges) {
      needs.max_curve_edges = curved;
      needs.max_curve_line = line.y;
    }
    for (const Segment& s : line.segments) {
      const SpanSetup span = SegmentInterpolator::setup(s, frame.width, formats);
      const int pixels = span.x_end - span.x_start;
      needs.max_segment_pixels = std::max(needs.max_segment_pixels, pixels);
      if (pixels <= 0) continue;
      // Span values step linearly from the first pixel: the ends are the extremes.
      for (int c = fmt::ChanZ; c < fmt::NumChannels; ++c) {
        const i128 first = span.value[c], last = first + static_cast<i128>(pixels - 1) * span.step[c];
        needs.value_bits[c] = std::max({needs.value_bits[c], signed_bits(first), signed_bits(last)});
      }
    }
  });
  return needs;
}

}  // namespace watkins
