// Cycle twin of rtl/compact_segment_former.sv: its control, clocked once per cycle with the same
// handshake inputs and the polygon id of the edge offered (which decides whether the edge closes a
// segment, and so whether it is offered on the output), no values (the segments' values are
// SegmentFormer's, segment_former.hpp). It says in which cycles the block takes an edge
// (edge_ready_o) and offers a segment or marker (seg_valid_o), so a bench holds the RTL to it cycle
// for cycle and a cycle model of the compact top composes it.
//
// The clock, as the RTL's header states it: after reset the table is cleared, one entry per clock,
// 2^PolyIdBits clocks with edge_ready_o low. Then an edge is taken when the block is not deciding
// and the output is empty or taken in that clock; the next clock decides it; a closing edge's
// segment or a marker is offered from the clock after that.
#pragma once

#include <vector>

namespace watkins {

class CompactSegmentFormerTiming {
 public:
  // The state right after reset (the first clock with rst_ni high is the clear's first).
  explicit CompactSegmentFormerTiming(int poly_id_bits)
      : entries_(1 << poly_id_bits), open_(static_cast<std::size_t>(entries_), false) {}

  // This clock's edge_ready_o, with seg_ready_i = seg_ready.
  bool edge_ready(bool seg_ready) const { return !clear_ && !decide_ && (!seg_valid_ || seg_ready); }
  // This clock's seg_valid_o.
  bool seg_valid() const { return seg_valid_; }

  // One clock edge with the inputs of the clock: edge_valid_i, edge_eol_i, edge_poly_i and
  // seg_ready_i.
  void clock(bool edge_valid, bool eol, int poly, bool seg_ready) {
    const bool take = edge_valid && edge_ready(seg_ready);
    if (clear_ && ++cleared_ == entries_) clear_ = false;
    if (seg_ready) seg_valid_ = false;
    if (decide_) seg_valid_ = d_eol_ || d_closes_;
    decide_ = take;
    if (take) {
      d_eol_ = eol;
      d_closes_ = false;
      if (eol) {
        for (const int p : touched_) open_[static_cast<std::size_t>(p)] = false;
        touched_.clear();
      } else {
        auto o = open_[static_cast<std::size_t>(poly)];
        d_closes_ = o;
        open_[static_cast<std::size_t>(poly)] = !o;
        touched_.push_back(poly);
      }
    }
  }

 private:
  int entries_;
  bool clear_ = true;  // the clear after reset
  int cleared_ = 0;
  bool decide_ = false;  // the edge taken last clock is paired in this one
  bool d_eol_ = false, d_closes_ = false;
  bool seg_valid_ = false;
  std::vector<bool> open_;    // polygon id -> an edge of it is open on this line
  std::vector<int> touched_;  // the ids open_ changed for on this line
};

}  // namespace watkins
