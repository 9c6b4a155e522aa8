// Cycle model of rtl/compact_segment_interpolator.sv: its control, clocked once per cycle with
// the same valid/ready inputs, no value arithmetic. Each clock takes what the RTL's ports carry
// in that cycle (seg_valid_i, the offered item's marker flag and pixel range, frag_ready_i),
// returns what the RTL shows in it (seg_ready_o, frag_valid_o, frag_eol_o, frag_x_o,
// frag_pair_o), and advances every control register as the RTL's clock edge does:
// - the offer's classification on its first clock (seen, needs a reciprocal);
// - divider: idle, a normalize clock (the clock after the offer's first), Iterations clocks of
//   steps, done until the item is taken;
// - setup: busy from a span's take until its last operation's w stage, issuing one digit per
//   clock through the o, p, x, s stages; the head (valid, marker, pixel range);
// - stepper: active, x, the span's end; the registered beat output. With Lanes = 2 a beat is a
//   pair of pixels (x, x + 1) while two or more are left, the span's last pixel alone otherwise,
//   and x advances by two.
// The item's pixel range is SegmentInterpolator::pixels() (empty when x_end <= x_start).
#pragma once

#include <algorithm>

#include "formats.hpp"

namespace watkins {

class CompactSegmentInterpolatorTiming {
 public:
  struct Item {
    bool eol = false;           // end-of-line marker
    int x_start = 0, x_end = 0;  // the span's pixels (clipped); empty when x_end <= x_start
  };
  struct Pins {
    bool seg_ready = false;  // seg_ready_o (meaningful while seg_valid_i)
    bool frag_valid = false, frag_eol = false;
    int frag_x = 0;
    bool frag_pair = false;  // the beat also holds the fragment at frag_x + 1 (Lanes = 2)
  };

  static constexpr int DigitBits = 16;
  static constexpr int Ops = 9;  // alpha0, four steps, four values

  // The RTL's parameters: XBits, ZBits, AttrBits, QuotientBitsPerClock, Lanes (1 or 2; RecipBits,
  // AlphaBits: the package's).
  CompactSegmentInterpolatorTiming(int x_bits, int z_bits, int attr_bits, int quotient_bits_per_clock = 2,
                                   int lanes = 1)
      : offset_digits_(digits(x_bits + 1)),
        z_digits_(digits(z_bits + 1)),
        attr_digits_(digits(attr_bits + 1)),
        iterations_((fmt::RecipBits + 1 + quotient_bits_per_clock - 1) / quotient_bits_per_clock),
        lanes_(lanes) {}

  // Clocks of issue per span (the o stage's busy clocks): the offset's digits and two passes over
  // the slots' digits.
  int issue_clocks() const { return offset_digits_ + 2 * (z_digits_ + 3 * attr_digits_); }
  // Clocks between two spans' takes while the stepper keeps up: the setup's (issue, four stages,
  // the head's pop, the next take) or the divider's (start, normalize, Iterations).
  int span_clocks() const { return std::max(issue_clocks() + 6, 3 + iterations_); }
  int iterations() const { return iterations_; }

  Pins clock(bool seg_valid, const Item& in, bool frag_ready) {
    const bool in_recip = !in.eol && in.x_end > in.x_start;
    Pins pins;
    pins.seg_ready = pk_seen_ && !m_busy_ && !h_valid_ && (d_done_ || !pk_recip_);
    pins.frag_valid = frag_valid_;
    pins.frag_eol = frag_eol_;
    pins.frag_x = frag_x_;
    pins.frag_pair = frag_pair_;
    const bool take = seg_valid && pins.seg_ready;
    const bool pk_recip = pk_recip_;
    const bool issue = m_busy_ && m_op_ != Ops;
    const bool out_free = !frag_valid_ || frag_ready;
    const bool emit_frag = out_free && st_active_;
    const bool one_left = st_x_ + 1 == st_xe_;
    const bool st_last = one_left || (lanes_ == 2 && st_x_ + 2 == st_xe_);
    const bool load = h_valid_ && !h_eol_ && (!st_active_ || (emit_frag && st_last));
    const bool emit_eol = out_free && !st_active_ && h_valid_ && h_eol_;
    const bool pop = load || emit_eol;
    const bool w_last = s_valid_ && s_op_ == Ops - 1;

    // Divider: normalizes on the clock after the offer's first (from the classification's flops).
    if (take) {
      d_run_ = d_done_ = false;
    } else if (!d_run_ && pk_seen_ && pk_recip_) {
      d_run_ = true;
      d_iter_ = iterations_;
    } else if (d_run_ && !d_done_) {
      if (d_iter_ == 1) d_done_ = true;
      --d_iter_;
    }

    // The offer's classification.
    if (!pk_seen_) pk_recip_ = in_recip;
    if (take) pk_seen_ = false;
    else if (seg_valid) pk_seen_ = true;

    // Setup: the stages, from the last to the first (each reads its predecessor's old value).
    s_valid_ = x_valid_;
    if (x_valid_) s_op_ = x_op_;
    x_valid_ = p_valid_ && p_last_;
    if (p_valid_ && p_last_) x_op_ = p_op_;
    p_valid_ = o_valid_;
    if (o_valid_) {
      p_op_ = o_op_;
      p_last_ = o_last_;
    }
    o_valid_ = issue;
    if (issue) {
      o_op_ = m_op_;
      o_last_ = m_dig_ == last_digit(m_op_);
    }
    if (take && pk_recip) m_busy_ = true;
    else if (w_last) m_busy_ = false;
    if (take) {
      m_op_ = 0;
      m_dig_ = 0;
      h_eol_ = in.eol;
      h_xs_ = in.x_start;
      h_xe_ = in.x_end;
    } else if (issue) {
      if (m_dig_ == last_digit(m_op_)) {
        ++m_op_;
        m_dig_ = 0;
      } else {
        ++m_dig_;
      }
    }

    // Head.
    if (take && in.eol) h_valid_ = true;
    else if (w_last) h_valid_ = true;
    else if (pop) h_valid_ = false;

    // Stepper and output register. A take and a load never share a clock (a take needs an empty
    // head, a load a full one), so the head's range is the one it held.
    const int st_x = st_x_;
    if (load) {
      st_active_ = true;
      st_x_ = h_xs_;
      st_xe_ = h_xe_;
    } else if (emit_frag) {
      st_x_ += lanes_;
    }
    if (emit_frag && st_last && !load) st_active_ = false;
    if (out_free) frag_valid_ = emit_frag || emit_eol;
    if (emit_frag) {
      frag_x_ = st_x;
      frag_eol_ = false;
      frag_pair_ = lanes_ == 2 && !one_left;
    } else if (emit_eol) {
      frag_eol_ = true;
      frag_pair_ = false;
    }
    return pins;
  }

 private:
  static int digits(int bits) { return (bits + DigitBits - 1) / DigitBits; }
  int last_digit(int op) const {
    if (op == 0) return offset_digits_ - 1;
    if (op == 1 || op == 5) return z_digits_ - 1;
    return attr_digits_ - 1;
  }

  int offset_digits_, z_digits_, attr_digits_, iterations_, lanes_;
  // The offered item: classified, and whether it needs a reciprocal.
  bool pk_seen_ = false, pk_recip_ = false;
  // Divider.
  bool d_run_ = false, d_done_ = false;
  int d_iter_ = 0;
  // Setup and its stages.
  bool m_busy_ = false;
  int m_op_ = 0, m_dig_ = 0;
  bool o_valid_ = false, o_last_ = false, p_valid_ = false, p_last_ = false, x_valid_ = false, s_valid_ = false;
  int o_op_ = 0, p_op_ = 0, x_op_ = 0, s_op_ = 0;
  // Head.
  bool h_valid_ = false, h_eol_ = false;
  int h_xs_ = 0, h_xe_ = 0;
  // Stepper and the fragment output register.
  bool st_active_ = false;
  int st_x_ = 0, st_xe_ = 0;
  bool frag_valid_ = false, frag_eol_ = false, frag_pair_ = false;
  int frag_x_ = 0;
};

}  // namespace watkins
