#include "compact_cycle_model.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <stdexcept>
#include <string>
#include <vector>

#include "compact_active_edge_list_timing.hpp"
#include "compact_normalizer_narrow_timing.hpp"
#include "compact_normalizer_timing.hpp"
#include "compact_phong_shader_narrow_timing.hpp"
#include "compact_phong_shader_timing.hpp"
#include "compact_scanline_buffer_timing.hpp"
#include "compact_segment_former_timing.hpp"
#include "scan_lines.hpp"
#include "segment_interpolator.hpp"

namespace watkins {
namespace {

using Item = CompactSegmentInterpolatorTiming::Item;

class AlwaysReady : public PixelReady {
 public:
  bool ready(long long, long long) override { return true; }
};

}  // namespace

std::vector<Item> compact_segment_items(const Frame& frame, int capacity, const Config& cfg) {
  std::vector<Item> items;
  walk_scan_lines(frame.edges, frame.height, capacity, cfg.channels(frame.shading), [&](const ScanLine& sl) {
    for (const Segment& seg : sl.segments) {
      const auto [xs, xe] = SegmentInterpolator::pixels(seg, frame.width, cfg.x.frac_bits);
      items.push_back(Item{false, xs, xe});
    }
    items.push_back(Item{true, 0, 0});
  });
  return items;
}

CyclePrediction predict_compact_cycles(const Frame& frame, const Config& cfg, const CycleOptions& opt) {
  if (frame.width < 1 || frame.height < 1)  // the top asserts a_frame_size: no frame to time
    throw std::invalid_argument("cycle model: frame size " + std::to_string(frame.width) + "x" +
                                std::to_string(frame.height));
  const bool phong = frame.shading == ShadingMode::Phong;
  if (phong && cfg.lanes != 1)
    throw std::invalid_argument("cycle model: lanes: 2 is Gouraud only (the frame is Phong)");
  if (frame.smoothed())
    throw std::invalid_argument("cycle model: the compact top has no smoother (the frame is smoothed)");
  if (cfg.eq2)
    throw std::invalid_argument("cycle model: the compact top has no eq. (2) shade divider (config eq2)");
  if (opt.output != PixelOutput::FullFrame)
    throw std::invalid_argument("cycle model: the compact top has full-frame output only (sparse asked)");
  AlwaysReady always;
  PixelReady& consumer = opt.pixel_ready ? *opt.pixel_ready : always;
  const std::vector<Item> items = compact_segment_items(frame, opt.max_active_edges, cfg);
  const ChannelFormats formats = cfg.channels(frame.shading);

  CompactActiveEdgeListTiming list(opt.max_active_edges, formats, id_bits(cfg.max_edges));
  CompactSegmentFormerTiming former(id_bits(cfg.max_polygons));
  CompactSegmentInterpolatorTiming interp(formats.bits[fmt::ChanX], formats.bits[fmt::ChanZ],
                                          formats.bits[fmt::ChanR], rtl_timing::CompactQuotientBitsPerClock,
                                          cfg.lanes);
  CompactScanlineBufferTiming buffer(cfg.max_width, cfg.lanes);
  buffer.set_frame(frame.width, frame.height);
  // The clears after reset (the former's table, the buffer's marks), run with the pins at rest
  // for the clocks before the first beat, at most to their end (idle clocks after it change
  // nothing).
  const long long clears = std::max<long long>(1LL << id_bits(cfg.max_polygons), buffer.clear_clocks());
  const long long rest = opt.after_reset >= 0 ? std::min(opt.after_reset, clears) : clears;
  for (long long i = 0; i < rest; ++i) {
    former.clock(false, false, 0, false);
    buffer.clock(false, false, false);
  }
  // The Phong blocks' schedules count their 5-clock periods from reset whether or not they hold
  // a fragment: idle, only the phase matters, after_reset's clocks modulo the period.
  const bool narrow = cfg.phong == PhongFormat::Narrow;  // the narrow formats' blocks
  CompactScheduleTiming normalizer =
      narrow ? CompactScheduleTiming(CompactNormalizerNarrowTiming()) : CompactScheduleTiming(CompactNormalizerTiming());
  CompactScheduleTiming shader =
      narrow ? CompactScheduleTiming(CompactPhongShaderNarrowTiming()) : CompactScheduleTiming(CompactPhongShaderTiming());
  if (phong)
    for (long long i = 0; i < std::max(opt.after_reset, 0LL) % CompactScheduleTiming::Period; ++i) {
      normalizer.clock(false, true);
      shader.clock(false, true);
    }
  std::deque<bool> shading_eol;  // the marker flags of the beats inside the normalizer and shader

  // The glue: the fragment queue's entries (their marker flags), the pixel skid's slot; the edge
  // source's position.
  bool px_skid_full = false;
  int q_count = 0;
  std::array<bool, rtl_timing::FragQueueDepth> q_eol{};
  std::size_t next_record = 0, next_item = 0;
  bool eof_taken = false;
  long long offered_at = 0;  // the cycle the head beat is offered from (the edge source's pace)
  const std::size_t records = frame.edges.size();
  const long long frame_pixels = static_cast<long long>(frame.width) * frame.height;

  CyclePrediction out;
  long long taken = 0, last_progress = 0;
  CompactActiveEdgeListTiming::Inputs in;
  in.height = frame.height;
  for (long long t = 0;; ++t) {
    // ================= combinational, from the outputs back =================
    // The pixel skid offers its slot, else the line buffer's pixel; its ready is its empty slot.
    const bool top_valid = buffer.pixel_valid() || px_skid_full;
    const bool take = top_valid && consumer.ready(t, taken);
    const bool px_ready = !px_skid_full;
    // The queue's head goes to the line buffer (a marker waits on the reader); the queue's ready
    // is registered (not full).
    const bool q_valid = q_count > 0;
    const bool q_pop = q_valid && buffer.frag_ready(q_eol[0], px_ready);
    const bool q_ready = q_count != rtl_timing::FragQueueDepth;
    // The former's beat (the oldest item not yet taken) goes straight to the interpolator, whose
    // pins come from its registers (clock() returns them and takes the clock edge).
    const bool seg_valid = former.seg_valid();
    if (seg_valid && next_item >= items.size())
      throw std::logic_error("cycle model: the segment former offers more items than the twins' " +
                             std::to_string(items.size()));
    const Item offered = seg_valid ? items[next_item] : Item{};
    // Phong: the interpolator's beats go to the normalizer (its ready a flop), the normalizer's
    // to the shader, the shader's to the queue; Gouraud: the beats to the queue.
    const bool nm_ready = normalizer.ready(), nm_valid = normalizer.valid();
    const bool sh_ready = shader.ready(), sh_valid = shader.valid();
    const CompactSegmentInterpolatorTiming::Pins pins = interp.clock(seg_valid, offered, phong ? nm_ready : q_ready);
    const bool q_push = (phong ? sh_valid : pins.frag_valid) && q_ready;
    const bool former_seg_ready = pins.seg_ready;
    in.start = t == 0;
    in.edge_valid = !eof_taken && t >= offered_at;
    in.edge_eof = next_record == records;
    if (!in.edge_eof) in.edge = frame.edges[next_record];
    in.out_ready = former.edge_ready(former_seg_ready);
    const CompactActiveEdgeListTiming::Outputs ae = list.eval(in);
    const int poly = ae.edge ? ae.edge->rec.poly : 0;

    // ================= the clock edge =================
    if (in.edge_valid && ae.edge_ready) {
      if (in.edge_eof) eof_taken = true;
      else ++next_record;
      offered_at = std::max(offered_at + opt.edge_interval, t + opt.edge_gap);
      last_progress = t;
    }
    list.tick(in);
    former.clock(ae.out_valid, ae.out_eol, poly, former_seg_ready);
    if (seg_valid && pins.seg_ready) {
      ++next_item;
      last_progress = t;
    }
    buffer.clock(q_valid, q_valid && q_eol[0], px_ready);
    if (q_pop) {
      for (int i = 0; i + 1 < rtl_timing::FragQueueDepth; ++i) q_eol[std::size_t(i)] = q_eol[std::size_t(i) + 1];
      --q_count;
    }
    bool push_eol = pins.frag_eol;
    if (phong) {
      if (q_push) {
        push_eol = shading_eol.front();
        shading_eol.pop_front();
      }
      if (pins.frag_valid && nm_ready) {
        shading_eol.push_back(pins.frag_eol);
        last_progress = t;
      }
      normalizer.clock(pins.frag_valid, sh_ready);
      shader.clock(nm_valid, q_ready);
    }
    if (q_push) {
      q_eol[std::size_t(q_count++)] = push_eol;
      last_progress = t;
    }
    px_skid_full = top_valid && !take;
    if (take) {
      if (taken == 0) out.first_pixel = t;
      if (opt.take_cycles) opt.take_cycles->push_back(t);
      last_progress = t;
      if (++taken == frame_pixels) {
        if (next_item != items.size())
          throw std::logic_error("cycle model: the frame ended with " + std::to_string(items.size() - next_item) +
                                 " of the twins' items not taken");
        out.cycles = t + 1;
        out.pixels = taken;
        return out;
      }
    }
    if (t - last_progress > 10'000'000)
      throw std::logic_error("cycle model: no progress for 10^7 cycles at cycle " + std::to_string(t));
  }
}

}  // namespace watkins
