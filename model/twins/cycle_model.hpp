// Cycle model of rtl/watkins_top.sv: the cycles a frame takes on the RTL when nothing stalls it
// (edge beats offered back to back, pixel_ready_i always high), counted as the SystemC bench
// counts them: from the cycle the frame's first edge beat is offered to the cycle its last pixel
// is taken, inclusive (testbench/frame_driver.cpp, RtlFrame::cycles()).
//
// Not a closed formula: the handshakes between the stages decide the count (a line's edges wait
// for the segment former, spans queue in the interpolator's FIFO, an end-of-line marker waits at
// the ping-pong line buffer for the reader), so this is a clocked model of the pipeline's
// control only — every valid/ready register and counter of active_edge_list, edge_incrementer,
// segment_former, the segment skid (stream_skid), segment_interpolator (s0, span_reciprocal,
// sa .. sd, stream_fifo, stepper), [Phong: normalizer, phong_shader; Gouraud with cfg.eq2: the
// shade divider's reciprocal and tail, whatever frame.eq2 says], the fragment queue and
// scanline_buffer — driven by the twins' own streams (walk_scan_lines: each line's active edges
// with their retire flags, the segment former's pairing, each span's pixel range). No channel
// arithmetic runs per cycle, so it is exact and far faster than Verilator. A configuration with
// compact true is the compact top's: compact_cycle_model.hpp.
#pragma once

#include <vector>

#include "config.hpp"
#include "frame.hpp"
#include "formats.hpp"

namespace watkins {

// The latencies and depths of the RTL the cycle model clocks (rtl/*.sv; a change there must be
// made here too, and tests/cosim/test_cycle_model.cpp fails until it is).
namespace rtl_timing {
constexpr int RecipStages = fmt::RecipBits + 2;  // span_reciprocal: normalize + R+1 quotient bits
constexpr int InterpFifoDepth = 4;               // segment_interpolator's FifoDepth
constexpr int InterpTailStages = 8;              // segment_interpolator: sa, sm, sp, sh, sb, sc, sv, sd after the reciprocal
// normalizer (16): squares, sum, rsqrt_unit (fmt::RsqrtStages), partial products, sum, shift, round
constexpr int NormalizerStages = 2 + fmt::RsqrtStages + 4;
constexpr int ShaderStages = 42;                 // phong_shader: dots (3), cos(s) (3), 8 powers (4 each), 4 out
constexpr int SmootherStages = fmt::ShadeBits + 6;  // smoother: line read, window, pairs, sums, products, dividend, a divider
                                                    // stage per quotient bit
constexpr int FragQueueDepth = 2;                // watkins_top's u_frag_queue (registered ready)
// shade_divider (HasEq2, Gouraud): span_reciprocal of Eq2RecipBits (Config::eq2_recip_bits) + 2
// stages, then sm and sr; DividerStages at the default mantissa.
constexpr int DividerTailStages = 2;
constexpr int divider_recip_stages(int eq2_recip_bits) { return eq2_recip_bits + 2; }
constexpr int DividerStages = fmt::Eq2RecipBits + 2 + DividerTailStages;
}  // namespace rtl_timing

enum class PixelOutput { FullFrame, Sparse };  // watkins_top's sparse_i = 0 / 1

struct CyclePrediction {
  long long cycles = 0;       // first edge beat offered .. last pixel taken, inclusive
  long long first_pixel = 0;  // cycle (from the first beat offered, = 0) the first pixel is taken
  long long pixels = 0;       // beats on the pixel stream
};

// pixel_ready_i of the top as its consumer drives it, clock by clock.
class PixelReady {
 public:
  virtual ~PixelReady() = default;
  // pixel_ready_i in cycle `cycle` (counted as predict_cycles counts: 0 = the cycle the frame's
  // first edge beat is offered), the pixels (beats) taken in the cycles before it given. Asked
  // only in cycles the top offers a pixel (pixel_valid_o high: elsewhere the RTL ignores the
  // pin), in increasing cycle order, once per cycle; it must be a function of its arguments
  // and the consumer's own state.
  virtual bool ready(long long cycle, long long pixels_taken_before) = 0;
};

struct CycleOptions {
  PixelOutput output = PixelOutput::FullFrame;  // sparse_i (ignored for a smoothed frame)
  int max_active_edges = fmt::MaxActiveEdges;
  // The consumer's ready; null: always high (the results of the overload without options).
  PixelReady* pixel_ready = nullptr;
  // When not null: filled with the cycle each pixel (beat) is taken, in stream order.
  std::vector<long long>* take_cycles = nullptr;
  // The compact top (cfg.compact) clears its segment former's table (2^PolyIdBits clocks) and its
  // line buffer's marks (MaxWidth clocks) after reset, refusing input meanwhile: the clocks from
  // reset's release (its first clock with rst_ni high = 0) to the one the frame's first beat is
  // offered (the benches' edge source: 1); negative: the clears are over (a frame after another,
  // or long after reset). The pipelined top has no clears: ignored. The compact Phong top's
  // normalizer and shader count 5-clock periods from reset: their phase at the first beat is
  // after_reset modulo 5 (negative: 0).
  long long after_reset = -1;
  // The edge source's pace (a board's frame player): beat 0 (a record or the EOF beat) is offered
  // from cycle 0, and beat k + 1 from cycle max(O_k + edge_interval, T_k + edge_gap) on, O_k the
  // cycle beat k was first offered and T_k the cycle it was taken; each is held until taken. 1 and
  // 1: back to back, a beat every clock the top takes one (the benches' source, the ULX3S's frame
  // player). The iCEBreaker's SPRAM frame player: ceil(EdgeBits / 64) and 2.
  int edge_interval = 1;
  int edge_gap = 1;
};

// Predicts the frame's cycles on watkins_top with Phong = (frame.shading == Phong), sparse_i as
// `output` (ignored when frame.smooth_w != 0: a smoothed frame is emitted in full), starting idle (after reset or a finished frame), no input gaps and no output stalls.
// Throws CapacityError when the frame overflows an active-edge list of `max_active_edges`, and
// std::invalid_argument for an empty frame size. `cfg`: the configuration the frame was prepared
// for (its channel widths step the edges; its X fraction bits place the spans' pixel centres).
CyclePrediction predict_cycles(const Frame& frame, PixelOutput output,
                               int max_active_edges = fmt::MaxActiveEdges, const Config& cfg = Config{});

// The same frame clocked with the pixel path of watkins_top (scanline_buffer's pixel register,
// [smoother,] the pixel skid) under opt.pixel_ready: exact for any ready pattern, every cycle
// clocked (no cycles skipped). With a null pixel_ready and take_cycles it equals the overload
// above and records each pixel's take.
// cfg.compact: the compact top (compact_cycle_model.hpp), every cycle clocked whatever opt says.
CyclePrediction predict_cycles(const Frame& frame, const Config& cfg, const CycleOptions& opt);

}  // namespace watkins
