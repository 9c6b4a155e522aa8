// Cycle model of watkins_top built with Compact = 1 (docs/reference/compact.md): the four compact
// blocks' cycle twins (compact_*_timing.hpp) composed with the top's glue clock by clock: the
// edge source offering records at its pace (CycleOptions: back to back, or the iCEBreaker's
// SPRAM frame player's), compact_active_edge_list, compact_segment_former
// straight into compact_segment_interpolator (no segment skid: the interpolator's seg_ready_o is
// a flop), [Phong: compact_normalizer, the interpolator's stall its ready_o, then
// compact_phong_shader (compact_normalizer_timing.hpp, compact_phong_shader_timing.hpp; at the
// narrow formats, cfg.phong, their _narrow forms)], the
// fragment queue (stream_fifo, FragQueueDepth; an entry is a beat of cfg.lanes
// fragments at most), compact_scanline_buffer and the
// pixel skid (stream_skid), pixel_ready_i from the consumer. Each twin is the one its unit bench
// holds equal to its RTL on every clock. Every cycle is clocked, so each pixel's take is exact
// under any ready pattern. The twins take from the data what decides their clocks: the records
// (the list's keys, stepped by the EdgeIncrementer twin), each active edge's polygon (whether it
// closes a segment), each item's pixel range (walk_scan_lines, SegmentInterpolator::pixels).
#pragma once

#include <vector>

#include "compact_segment_interpolator_timing.hpp"
#include "config.hpp"
#include "cycle_model.hpp"
#include "frame.hpp"

namespace watkins {

namespace rtl_timing {
constexpr int CompactQuotientBitsPerClock = 2;  // compact_segment_interpolator's QuotientBitsPerClock
}  // namespace rtl_timing

// predict_cycles for cfg.compact: a Gouraud or Phong frame (frame.shading; Phong at one lane) in
// full-frame output, neither smoothed nor divided (the compact top has no sparse output, no
// smoother and no divider); anything else is std::invalid_argument naming what the compact top
// lacks. opt.after_reset says whether the blocks' reset clears still run when the frame's first
// beat is offered and, for Phong, the phase of the normalizer's and the shader's 5-clock
// schedules then (after_reset modulo 5; a negative one counts as phase 0).
CyclePrediction predict_compact_cycles(const Frame& frame, const Config& cfg, const CycleOptions& opt);

// The segment former's output stream as the compact interpolator takes it: each line's segments in
// closing order (their pixel ranges), then the line's marker. Throws CapacityError as
// walk_scan_lines does.
std::vector<CompactSegmentInterpolatorTiming::Item> compact_segment_items(const Frame& frame, int capacity,
                                                                          const Config& cfg);

}  // namespace watkins
