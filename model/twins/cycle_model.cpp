#include "cycle_model.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "compact_cycle_model.hpp"
#include "scan_lines.hpp"
#include "segment_interpolator.hpp"

namespace watkins {
namespace {

using namespace rtl_timing;

// What the control of each stage reads from the data, per scan line, from the twins.
struct Streams {
  std::vector<int> line_begin;       // active edges of line y: [line_begin[y], line_begin[y+1])
  std::vector<std::uint8_t> retire;  // the edge ends after this line (edge_incrementer retire_o)
  std::vector<std::uint8_t> closes;  // the edge closes a segment (segment_former hit)
  struct Item {                      // segment_former output: a segment, or a line's end marker
    bool eol = false;
    int pixels = 0;                  // span pixels (0: empty span, dropped before the FIFO)
  };
  std::vector<Item> items;
  std::vector<int> read_steps;       // scanline_buffer reader steps per line
  std::vector<std::uint8_t> read_emits;  // each step emits a pixel (sparse: the line covers one)
  std::vector<int> record_y0;        // the edge-record stream
};

Streams front_half(const Frame& frame, bool sparse, int capacity, const Config& cfg) {
  const int x_frac_bits = cfg.x.frac_bits;
  Streams s;
  s.line_begin.reserve(std::size_t(frame.height) + 1);
  s.read_steps.reserve(std::size_t(frame.height));
  std::vector<int> open;  // polygons with an unpaired edge on this line
  std::vector<std::pair<int, int>> spans;
  walk_scan_lines(frame.edges, frame.height, capacity, cfg.channels(frame.shading), [&](const ScanLine& sl) {
    s.line_begin.push_back(static_cast<int>(s.retire.size()));
    open.clear();
    for (const ActiveEdge& e : sl.active.edges()) {
      s.retire.push_back(e.remaining <= 1);
      const auto it = std::find(open.begin(), open.end(), e.rec.poly);
      s.closes.push_back(it != open.end());
      if (it != open.end()) open.erase(it);
      else open.push_back(e.rec.poly);
    }
    spans.clear();
    for (const Segment& seg : sl.segments) {
      // Timing needs only the span's pixels, not setup()'s reciprocal and values.
      const auto [xs, xe] = SegmentInterpolator::pixels(seg, frame.width, x_frac_bits);
      s.items.push_back(Streams::Item{false, xe - xs});
      if (xe > xs) spans.emplace_back(xs, xe);
    }
    s.items.push_back(Streams::Item{true, 0});
    if (!sparse) {
      s.read_steps.push_back(frame.width);
      s.read_emits.push_back(1);
      return;
    }
    // Covered pixels = the union of the line's spans (a fragment always writes an empty pixel).
    std::sort(spans.begin(), spans.end());
    int covered = 0, reach = 0;
    for (const auto& [a, b] : spans) {
      const int from = std::max(a, reach);
      if (b > from) covered += b - from;
      reach = std::max(reach, b);
    }
    s.read_steps.push_back(std::max(covered, 1));  // an empty line costs one step
    s.read_emits.push_back(covered > 0);
  });
  s.line_begin.push_back(static_cast<int>(s.retire.size()));
  s.record_y0.reserve(frame.edges.size());
  for (const EdgeRecord& r : frame.edges) s.record_y0.push_back(r.y0);
  return s;
}

// A Stages-deep stall_pipe carrying one flag per beat (the end-of-line marker).
struct StallPipe {
  std::uint64_t valid = 0, eol = 0;
  int stages = 0;
  bool out_valid() const { return (valid >> (stages - 1)) & 1; }
  bool out_eol() const { return (eol >> (stages - 1)) & 1; }
  void shift(bool v, bool e) {
    const std::uint64_t mask = (std::uint64_t{1} << stages) - 1;
    valid = ((valid << 1) | std::uint64_t(v)) & mask;
    eol = ((eol << 1) | std::uint64_t(v && e)) & mask;
  }
};

// pixel_ready_i held high.
class AlwaysReady : public PixelReady {
 public:
  bool ready(long long, long long) override { return true; }
};

}  // namespace

CyclePrediction predict_cycles(const Frame& frame, PixelOutput output, int max_active_edges,
                               const Config& cfg) {
  CycleOptions opt;
  opt.output = output;
  opt.max_active_edges = max_active_edges;
  return predict_cycles(frame, cfg, opt);
}

CyclePrediction predict_cycles(const Frame& frame, const Config& cfg, const CycleOptions& opt) {
  if (cfg.compact) return predict_compact_cycles(frame, cfg, opt);
  const PixelOutput output = opt.output;
  const int max_active_edges = opt.max_active_edges;
  // Exact: the pixel path is clocked (the scanline buffer's pixel register, the smoother, the
  // pixel skid, the consumer's ready) and every cycle is run. Otherwise pixel_ready_i is high,
  // so the skid never fills and a smoothed frame's output follows from its input in closed form.
  const bool paced = opt.edge_interval > 1 || opt.edge_gap > 1;
  const bool exact = opt.pixel_ready != nullptr || opt.take_cycles != nullptr || paced;
  AlwaysReady always;
  PixelReady& consumer = opt.pixel_ready ? *opt.pixel_ready : always;
  if (frame.width < 1 || frame.height < 1)  // the top asserts a_frame_size: no frame to time
    throw std::invalid_argument("cycle model: frame size " + std::to_string(frame.width) + "x" +
                                std::to_string(frame.height));
  const bool smooth = frame.smoothed();
  const bool sparse = output == PixelOutput::Sparse && !smooth;
  // Smoothing: the smoother's pixel i comes from its column i + width + 1 (the buffer's pixel of
  // that raster index, or a flush step after the buffer's last): the cycle that pixel is loaded.
  const long long smooth_lead = static_cast<long long>(frame.width) + 1;
  long long lead_load = -1;
  const bool phong = frame.shading == ShadingMode::Phong;
  // Two stall pipes after the interpolator: the normalizer and the shader (Phong), or the shade
  // divider's reciprocal and its tail (a Gouraud top with the eq. (2) divider, every frame).
  const bool divided = !phong && cfg.eq2;
  const bool piped = phong || divided;
  const Streams st = front_half(frame, sparse, max_active_edges, cfg);
  const int height = frame.height;
  const std::size_t records = st.record_y0.size();

  // ---- active_edge_list (+ edge_incrementer): as after the start cycle 0 (start_i high).
  bool frame_q = true, drain_q = false;
  int line_q = 0, rd_q = 0, cnt_stream = 0, cnt_fill = 0;
  bool out_done_q = false, inc_done_q = false, eol_sent_q = false;
  std::size_t next_record = 0;
  bool eof_taken = false;
  long long offered_at = 0;  // the cycle the head beat is offered from (the edge source's pace)
  bool st_valid = false, st_retire = false;  // the edge_incrementer's output (st_valid, st_retire)
  bool ord1_q = false, ord2_q = false, ord3_q = false;  // the sorted insertion's three stages
  bool swap_q = false;                       // the swap, decided a cycle before it acts
  // ---- segment_former: its input and pairing registers (the edge and whether pairing it emits)
  // and its output, all three moved by one enable
  bool sf_in_valid = false, sf_in_emits = false;  // in_valid_q; the edge closes or is a marker
  bool sf_pr_valid = false, sf_pr_emits = false;  // pr_valid_q; the same for the pairing register
  bool seg_valid = false;                         // seg_valid_o
  // ---- watkins_top's segment skid (stream_skid): its slot holds a segment s0 refused
  bool skid_full = false;
  // ---- segment_interpolator: s0, span_reciprocal, sa .. sd, FIFO, stepper. Items pass every
  // stage in order, so a stage's item is its position in st.items, counted where it leaves.
  bool s0_valid_q = false;
  std::uint64_t recip_valid = 0;
  const std::uint64_t recip_mask = (std::uint64_t{1} << RecipStages) - 1;
  std::size_t recip_out = 0;  // items that left the reciprocal
  // The setup stages after the reciprocal (sa, sm, sp, sh, sb, sc, sv, sd), all enabled by tail_en; the
  // last is sd.
  std::array<bool, InterpTailStages> tail_valid{};
  std::array<std::size_t, InterpTailStages> tail_item{};
  constexpr int Sd = InterpTailStages - 1;
  std::size_t fifo[InterpFifoDepth] = {};
  int fifo_head = 0, fifo_count = 0;
  bool step_active = false;
  int step_left = 0;
  bool frag_valid = false, frag_eol = false;  // frag_valid_o, frag_eol_o
  // ---- Phong: normalizer -> phong_shader
  // ---- or the shade divider: span_reciprocal -> sm, sr
  StallPipe norm{0, 0, phong ? NormalizerStages : divider_recip_stages(cfg.eq2_recip_bits)},
      shade{0, 0, phong ? ShaderStages : DividerTailStages};
  // ---- the fragment queue (stream_fifo) in front of the scanline buffer: each entry's marker flag
  int q_count = 0;
  std::array<bool, FragQueueDepth> q_eol{};
  // ---- scanline_buffer: a fragment in its read step (a marker waits behind it), the reader
  bool sb_read_q = false;
  bool sb_swap_q = false;  // sparse: the swap's second clock, the reader's registers handed over
  bool rd_busy_q = false;
  int rd_left = 0, rline_q = 0, lines_written = 0;
  bool reader_done = false;  // the last line's last step was taken
  // ---- exact: scanline_buffer's pixel_valid_o, the smoother, the pixel skid's full_q
  bool sb_valid = false, px_full = false;
  std::uint64_t sm_pipe = 0;  // the smoother's stages, one valid bit each (v2 .. dv_q[DivStages])
  const std::uint64_t sm_mask = (std::uint64_t{1} << SmootherStages) - 1;
  long long sm_lead = 0, sm_emitted = 0, sm_in = 0;  // lead_q; pixels emitted; input beats taken
  bool sm_flush = false;
  const long long frame_pixels = static_cast<long long>(frame.width) * frame.height;
  long long loads = 0, taken = 0;

  // Every register but the two down-counters (reader steps, stepper pixels left). When a cycle
  // leaves all of them as they were and only counts down, the cycles after it repeat it until a
  // counter reaches the value that changes a handshake: those are skipped in one go (a line read
  // out behind a stalled pipeline, a long span behind full queues).
  auto key = [&] {
    return std::make_tuple(frame_q, drain_q, line_q, rd_q, cnt_stream, cnt_fill, out_done_q, inc_done_q,
                           eol_sent_q, next_record, eof_taken, st_valid, st_retire,
                           ord1_q, ord2_q, ord3_q, swap_q, sf_in_valid, sf_in_emits, sf_pr_valid, sf_pr_emits, seg_valid,
                           skid_full, s0_valid_q, recip_valid, recip_out, tail_valid, tail_item, fifo[0], fifo[1], fifo[2], fifo[3], fifo_head, fifo_count, step_active,
                           frag_valid, frag_eol, norm.valid, norm.eol, shade.valid, shade.eol, q_count,
                           q_eol, sb_read_q, sb_swap_q, rd_busy_q, rline_q, lines_written);
  };
  static_assert(InterpFifoDepth == 4, "key() lists the FIFO's words");

  CyclePrediction out;
  long long last_progress = 0;
  for (long long t = 1;; ++t) {
    // ================= combinational, from the outputs back =================
    // The pixel path: the reader steps unless its pixel register holds a pixel its consumer
    // (the smoother or the skid) refuses; the skid's ready is its empty slot, the smoother's
    // its enable outside the flush.
    const bool rd_emit = rd_busy_q && (st.read_emits[std::size_t(rline_q)] || rline_q == height - 1);
    bool rd_step = rd_busy_q, take = false, sb_ready = true, sm_en = true, top_valid = false;
    if (exact) {
      const bool sm_valid_o = smooth && ((sm_pipe >> (SmootherStages - 1)) & 1);
      const bool px_ready = !px_full;
      top_valid = (smooth ? sm_valid_o : sb_valid) || px_full;
      take = top_valid && consumer.ready(t, taken);
      sm_en = !sm_valid_o || px_ready;
      sb_ready = smooth ? sm_en && !sm_flush : px_ready;
      rd_step = rd_busy_q && (!rd_emit || !sb_valid || sb_ready);
    }
    const bool rd_last = rd_busy_q && rd_left == 1;
    const bool eol_ok = !sb_read_q && !sb_swap_q && (!rd_busy_q || (rd_step && rd_last));
    const bool sh_valid = piped ? shade.out_valid() : frag_valid;
    const bool sh_eol = piped ? shade.out_eol() : frag_eol;
    // The queue's head goes to the scanline buffer, which refuses only a marker waiting on the
    // reader; the queue's ready is registered (not full).
    const bool q_valid = q_count > 0;
    const bool eol_fire = q_valid && q_eol[0] && eol_ok;
    const bool q_pop = q_valid && (!q_eol[0] || eol_ok);
    const bool sh_ready = q_count != FragQueueDepth;
    const bool q_push = sh_valid && sh_ready;
    bool fr_ready = sh_ready, en_shade = false, en_norm = false;
    if (piped) {
      en_shade = sh_ready || !shade.out_valid();
      en_norm = en_shade || !norm.out_valid();
      fr_ready = en_norm;
    }
    // stepper and FIFO head
    const bool head_valid = fifo_count > 0;
    const Streams::Item& head = st.items[head_valid ? fifo[fifo_head] : 0];
    const bool out_free = !frag_valid || fr_ready;
    const bool from_head = !step_active && head_valid && !head.eol;
    const bool emit_frag = out_free && (step_active || from_head);
    const bool emit_eol = out_free && !step_active && head_valid && head.eol;
    const bool pop = emit_eol || (emit_frag && from_head);
    // sd -> FIFO (the RTL's sd_valid_q, sd_keep; its tail_en is a flop loaded a clock ahead,
    // a_tail_en: the same value as computed here)
    const bool sd_valid = tail_valid[Sd];
    const Streams::Item& sd = st.items[sd_valid ? tail_item[Sd] : 0];
    const bool sd_keep = sd.eol || sd.pixels > 0;
    const bool fifo_ready = fifo_count != InterpFifoDepth;
    const bool push = sd_valid && sd_keep && fifo_ready;
    const bool tail_en = !sd_valid || !sd_keep || fifo_ready;
    // reciprocal, s0, segment skid, segment former
    const bool rc_valid = (recip_valid >> (RecipStages - 1)) & 1;
    const bool en_recip = tail_en || !rc_valid;
    const bool seg_ready = !s0_valid_q || en_recip;  // the interpolator's seg_ready_o
    // The skid passes the former's segment when its slot is empty.
    const bool sk_valid = skid_full || seg_valid;
    // edge_ready_o, the enable of all three registers: the skid's ready is its empty slot (a flop)
    const bool sf_ready = !skid_full || !seg_valid;
    // active-edge list output
    const bool streaming = frame_q && !drain_q && line_q != 0;
    const bool have_edge = streaming && rd_q < cnt_stream;
    const std::size_t g = have_edge ? std::size_t(st.line_begin[line_q - 1] + rd_q) : 0;
    const bool ae_valid = (have_edge && !out_done_q) || (streaming && !have_edge && !eol_sent_q);
    const bool ae_fire = ae_valid && sf_ready;
    const bool inc_fire = have_edge && !inc_done_q;  // the incrementer is always ready
    const bool advance = have_edge && (out_done_q || ae_fire) && (inc_done_q || inc_fire);
    // active-edge list input
    const bool edge_valid = !eof_taken && t >= offered_at;
    const bool head_eof = next_record == records;
    const int y0 = head_eof ? 0 : st.record_y0[next_record];
    const bool ins_step = st_valid && !st_retire;
    const bool head_edge = edge_valid && !head_eof;
    const bool live = frame_q && !drain_q;
    const bool take_new = live && head_edge && line_q < height && y0 == line_q && !ins_step;
    const bool drop_late = live && head_edge && y0 < line_q;
    const bool edge_ready = take_new || drop_late || (drain_q && edge_valid);
    const bool ins_valid = ins_step || take_new;
    const bool src_done = line_q == height || (edge_valid && (head_eof || y0 > line_q));
    // The swap is decided a cycle before it acts (swap_q), once the incrementer's stage and the
    // insertion's three are empty. (The stream's read ahead costs no cycle: the RAM reads the next
    // line's first entry on the clock the swap is decided.)
    const bool swap_now = live && (line_q == 0 || eol_sent_q) && !st_valid && !ord1_q &&
                          !ord2_q && !ord3_q && src_done && !swap_q;
    const bool swap = swap_q;

    // ================= registers =================
    const bool rd_counts = rd_busy_q && !rd_last;
    const bool step_counts = emit_frag && !from_head;
    // (Worth a look only when a counter has some way to go.)
    const bool may_repeat = !exact && ((rd_counts && rd_left > 8) || (step_counts && step_left > 8));
    decltype(key()) before;
    if (may_repeat) before = key();
    // scanline_buffer reader (not exact: pixel_ready_i high, it steps every cycle it is busy)
    if (rd_step) {
      if (rd_emit) {  // rd_load
        if (exact) {
          ++loads;
        } else {
          if (out.pixels == smooth_lead) lead_load = t;
          if (out.pixels++ == 0) out.first_pixel = t + 1;
        }
      }
      if (rd_last) {
        if (rline_q == height - 1) {
          if (!exact) {
            out.cycles = t + 2;  // the pixel loaded now is taken next cycle; cycle 0 counts
            break;
          }
          reader_done = true;
        } else {
          ++rline_q;
        }
        rd_busy_q = false;
      } else {
        --rd_left;
      }
    }
    if (exact) {
      // The pixel register loads when its pixel leaves or it is empty; the skid holds a pixel
      // offered and not taken; the smoother's stages move together on its enable, a column
      // entering on each input beat and, after the frame's last, on each flush step.
      const bool in_fire = smooth && sb_valid && sb_ready;
      const bool adv = smooth && sm_en && (sm_flush || sb_valid);
      if (!sb_valid || sb_ready) sb_valid = rd_step && rd_emit;
      px_full = top_valid && !take;
      if (smooth && sm_en) {
        const bool emit0 = sm_lead == smooth_lead;
        sm_pipe = ((sm_pipe << 1) | std::uint64_t(adv && emit0)) & sm_mask;
        if (adv) {
          if (!emit0) ++sm_lead;
          if (in_fire && sm_in == frame_pixels - 1) sm_flush = true;
          if (emit0 && ++sm_emitted == frame_pixels) sm_lead = sm_emitted = 0, sm_flush = false;
        }
      }
      if (in_fire) ++sm_in;
      if (take) {
        if (taken == 0) out.first_pixel = t;
        if (opt.take_cycles) opt.take_cycles->push_back(t);
        ++taken;
        last_progress = t;
        if (smooth ? taken == frame_pixels : reader_done && taken == loads) {
          out.cycles = t + 1;
          out.pixels = taken;
          break;
        }
      }
    }
    // The marker's swap starts the reader on the next clock in full mode; in sparse mode on the
    // one after (swap_q: the search's registers are handed over in between).
    if (sb_swap_q) {
      sb_swap_q = false;
      rd_busy_q = true;
    }
    if (eol_fire) {
      if (lines_written >= height) throw std::logic_error("cycle model: more line markers than lines");
      if (sparse) sb_swap_q = true;
      else rd_busy_q = true;
      rd_left = st.read_steps[std::size_t(lines_written++)];
    }
    // fragment queue
    sb_read_q = q_pop && !q_eol[0];
    if (q_pop) {
      for (int i = 0; i + 1 < FragQueueDepth; ++i) q_eol[std::size_t(i)] = q_eol[std::size_t(i) + 1];
      --q_count;
    }
    if (q_push) q_eol[std::size_t(q_count++)] = sh_eol;
    // Phong or divider pipes (each stage's valid shifts on its own enable)
    if (piped) {
      const bool nv = norm.out_valid(), ne = norm.out_eol();
      if (en_norm) norm.shift(frag_valid, frag_eol);
      if (en_shade) shade.shift(nv, ne);
    }
    // stepper
    if (out_free) frag_valid = emit_frag || emit_eol;
    if (emit_frag) {
      frag_eol = false;
      const int left = (from_head ? head.pixels : step_left) - 1;
      step_left = left;
      step_active = left > 0;
    } else if (emit_eol) {
      frag_eol = true;
    }
    // FIFO
    if (pop) {
      fifo_head = (fifo_head + 1) % InterpFifoDepth;
      --fifo_count;
    }
    if (push) {
      fifo[(fifo_head + fifo_count) % InterpFifoDepth] = tail_item[Sd];
      ++fifo_count;
    }
    // sa -> ... -> sd, reciprocal, s0
    if (tail_en) {
      for (int s = Sd; s > 0; --s) {
        tail_valid[s] = tail_valid[s - 1];
        tail_item[s] = tail_item[s - 1];
      }
      tail_valid[0] = rc_valid;
      if (rc_valid) tail_item[0] = recip_out++;
    }
    if (en_recip) recip_valid = ((recip_valid << 1) | std::uint64_t(s0_valid_q)) & recip_mask;
    if (seg_ready) s0_valid_q = sk_valid;
    skid_full = sk_valid && !seg_ready;
    // segment former
    if (sf_ready) {
      seg_valid = sf_pr_valid && sf_pr_emits;
      sf_pr_valid = sf_in_valid;
      sf_pr_emits = sf_in_emits;
      sf_in_valid = ae_fire;
      sf_in_emits = ae_fire && (!have_edge || st.closes[g]);
    }
    // edge incrementer (it takes the list's output register)
    st_valid = inc_fire;
    if (inc_fire) st_retire = st.retire[g];
    // active-edge list
    if (advance) {
      ++rd_q;
      out_done_q = inc_done_q = false;
    } else {
      if (ae_fire && have_edge) out_done_q = true;
      if (inc_fire) inc_done_q = true;
    }
    if (ae_fire && !have_edge) eol_sent_q = true;
    if (edge_valid && edge_ready) {
      if (head_eof) eof_taken = true;
      else ++next_record;
      offered_at = std::max(offered_at + opt.edge_interval, t + opt.edge_gap);
      last_progress = t;
    }
    if (ins_valid) ++cnt_fill;
    ord3_q = ord2_q;
    ord2_q = ord1_q;
    ord1_q = ins_valid;  // (front_half throws on an overflow, so every insertion is written)
    swap_q = swap_now;
    if (swap) {
      if (line_q == height) {
        drain_q = true;
      } else {
        const int want = st.line_begin[std::size_t(line_q) + 1] - st.line_begin[std::size_t(line_q)];
        if (cnt_fill != want)
          throw std::logic_error("cycle model: line " + std::to_string(line_q) + " holds " +
                                 std::to_string(cnt_fill) + " active edges, the twin " + std::to_string(want));
        cnt_stream = cnt_fill;
        cnt_fill = 0;
        ++line_q;
        rd_q = 0;
        eol_sent_q = false;
      }
    }
    if (drain_q && edge_valid && head_eof) frame_q = drain_q = false;
    if (ae_fire || eol_fire || push) last_progress = t;
    if (may_repeat && key() == before) {
      long long n = std::numeric_limits<long long>::max();
      if (rd_counts) n = std::min<long long>(n, rd_left - 1);
      if (step_counts) n = std::min<long long>(n, step_left - 1);
      if (n > 0) {
        t += n;
        if (rd_counts) {
          rd_left -= static_cast<int>(n);
          if (st.read_emits[std::size_t(rline_q)] || rline_q == height - 1) {
            // Loads at the skipped cycles t - n + 1 .. t: pixels out.pixels .. out.pixels + n - 1.
            if (smooth_lead >= out.pixels && smooth_lead < out.pixels + n)
              lead_load = t - n + 1 + (smooth_lead - out.pixels);
            out.pixels += n;
          }
        }
        if (step_counts) step_left -= static_cast<int>(n);
        last_progress = t;
      }
    }
    if (t - last_progress > 10'000'000)
      throw std::logic_error("cycle model: no progress for 10^7 cycles at cycle " + std::to_string(t));
  }
  if (smooth && !exact) {
    // The buffer's last pixel is taken at cycles - 1; the width + 1 flush steps follow one per
    // clock, and each column's pixel leaves SmootherStages clocks after it entered.
    const long long n = out.pixels;
    const long long last_taken = out.cycles - 1;
    out.first_pixel = lead_load >= 0 ? lead_load + 1 + SmootherStages
                                     : last_taken + (smooth_lead - n + 1) + SmootherStages;
    out.cycles = last_taken + smooth_lead + SmootherStages + 1;
  }
  return out;
}

}  // namespace watkins
