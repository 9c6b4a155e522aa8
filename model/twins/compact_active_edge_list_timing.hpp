// Cycle twin of rtl/compact_active_edge_list.sv: its control clocked once per cycle with the same
// inputs (start, height, the edge stream's valid/eof/record, the output's ready), giving the
// same handshakes on every clock (edge_ready, out_valid, out_eol, busy, overflow). Its timing
// depends on the data (how far each inserted record and each crossing edge moves), so the twin
// keeps the RTL's array of entries word for word (A[0..capacity-1] and the scratch word), steps
// them with the EdgeIncrementer twin and compares their (X, id) keys as the RTL does; the edge it
// presents is the RTL's out_* beat. No arithmetic of its own beyond the twin's step.
// The phases and their clocks are the RTL header's: INS (records of the line placed from the end
// of the list), OUT (the list streamed, stepped and compacted in place, then the marker), FIX (an
// insertion sort from the first crossing, only on a line with one and not the last).
#pragma once

#include <cstdint>
#include <vector>

#include "config.hpp"
#include "edge_incrementer.hpp"
#include "edge_record.hpp"

namespace watkins {

class CompactActiveEdgeListTiming {
 public:
  struct Inputs {
    bool start = false;
    int height = 1;             // height_i, stable while busy
    bool edge_valid = false;
    bool edge_eof = false;
    EdgeRecord edge;            // edge_i (its id is ignored: the block numbers records)
    bool out_ready = false;
  };
  struct Outputs {
    bool busy = false, edge_ready = false, out_valid = false, out_eol = false, overflow = false;
    const ActiveEdge* edge = nullptr;  // the presented edge's entry (out_valid && !out_eol)
  };

  // capacity = MaxActiveEdges; formats the entries' channel words and edge order; edge_id_bits
  // the RTL's EdgeIdBits (ids wrap at it).
  CompactActiveEdgeListTiming(int capacity, const ChannelFormats& formats, int edge_id_bits)
      : capacity_(capacity),
        id_mask_((1 << edge_id_bits) - 1),
        formats_(formats),
        signs_(EdgeIncrementer::signs(formats)),
        mem_(static_cast<std::size_t>(capacity) + 1) {}

  // rst_ni low for a clock: no frame, overflow cleared.
  void reset() {
    state_ = State::Idle;
    overflow_ = false;
  }

  Outputs eval(const Inputs& in) const {
    Comb c = comb(in);
    Outputs o;
    o.busy = state_ != State::Idle;
    o.edge_ready = c.take;
    o.out_valid = state_ == State::Out || state_ == State::Eol;
    o.out_eol = state_ != State::Out;
    o.overflow = overflow_;
    o.edge = state_ == State::Out ? &ram_ : nullptr;
    return o;
  }

  // One rising edge with these inputs.
  void tick(const Inputs& in) {
    if (in.start && state_ == State::Idle) {
      state_ = State::Ins;
      line_ = 0;
      cnt_ = 0;
      id_ = 0;
      return;
    }
    const Comb c = comb(in);
    ActiveEdge written;
    if (c.we) {
      if (c.w_rec) {
        written.rec = in.edge;
        written.rec.id = id_;
        written.remaining = in.edge.n;
      } else if (c.w_step) {
        written = stepped(ram_);
      } else {
        written = ram_;
      }
    }
    if (c.re && c.ra >= 0 && c.ra <= capacity_) ram_ = mem_[static_cast<std::size_t>(c.ra)];  // else unused
    if (c.we) mem_[static_cast<std::size_t>(c.wa)] = written;
    if (state_ == State::Eol && in.out_ready && !last_line(in)) ++line_;
    if (c.take && !in.edge_eof) id_ = (id_ + 1) & id_mask_;
    if (c.ov_set) overflow_ = true;
    state_ = c.state;
    cnt_ = c.cnt;
    kept_ = c.kept;
    rd_ = c.rd;
    pos_ = c.pos;
    first_ = c.first;
    cross_ = c.cross;
    max_ = c.max;
    cmp_ = c.cmp;
  }

  int line() const { return line_; }

 private:
  enum class State { Idle, Ins, Shift, Place, Out, Eol, Fix, Scan, FShift, FPlace, Drain };
  struct Key {
    i64 x = 0;  // the X word, signed
    int id = 0;
    bool operator<(const Key& o) const { return x != o.x ? x < o.x : id < o.id; }
  };
  // The next state and the RAM's ports for one clock (the RTL's always_comb).
  struct Comb {
    State state;
    int cnt, kept, rd, pos, first;
    bool cross;
    Key max, cmp;
    bool re = false, we = false, w_rec = false, w_step = false, take = false, ov_set = false;
    int ra = 0, wa = 0;
  };

  static Key key(const ActiveEdge& e) { return {e.rec.value[fmt::ChanX], e.rec.id}; }
  ActiveEdge stepped(const ActiveEdge& e) const {
    ActiveEdge s = e;
    if (formats_.edge_order == 3)
      EdgeIncrementer::step<3>(s, signs_);
    else
      EdgeIncrementer::step<1>(s, signs_);
    return s;
  }
  bool last_line(const Inputs& in) const { return line_ + 1 == in.height; }

  Comb comb(const Inputs& in) const {
    Comb c{state_, cnt_, kept_, rd_, pos_, first_, cross_, max_, cmp_};
    const bool past = in.edge_eof || in.edge.y0 > line_;
    const bool late = !in.edge_eof && in.edge.y0 < line_;
    const bool full = cnt_ == capacity_;
    const Key kram = key(ram_);
    switch (state_) {
      case State::Idle:
        break;
      case State::Ins:
        c.cmp = Key{in.edge.value[fmt::ChanX], id_};  // the record's key, for the shift
        // The ports do not wait for the head's compare: a list with entries reads A[0] (the head
        // past the line) or A[L-1], an empty one has the record written at A[0].
        c.re = cnt_ != 0, c.ra = past ? 0 : cnt_ - 1;
        c.we = cnt_ == 0, c.wa = 0, c.w_rec = true;
        if (!in.edge_valid) break;
        if (past) {
          c.rd = 0, c.kept = 0, c.cross = false;
          c.state = cnt_ == 0 ? State::Eol : State::Out;
        } else if (late || full) {
          c.take = true;
          c.ov_set = !late;
        } else if (cnt_ == 0) {
          c.take = true, c.cnt = 1;
        } else {
          c.pos = cnt_ - 1;
          c.state = State::Shift;
        }
        break;
      case State::Shift:
        c.we = true, c.wa = pos_ + 1, c.re = true, c.ra = pos_ - 1;
        if (kram < cmp_)
          c.w_rec = true, c.take = true, c.cnt = cnt_ + 1, c.state = State::Ins;
        else if (pos_ == 0)
          c.state = State::Place;
        else
          c.pos = pos_ - 1;
        break;
      case State::Place:
        c.we = true, c.wa = 0, c.w_rec = true, c.take = true, c.cnt = cnt_ + 1, c.state = State::Ins;
        break;
      case State::Out:
        if (!in.out_ready) break;
        c.re = true, c.ra = rd_ + 1, c.rd = rd_ + 1;
        if (ram_.remaining > 1) {
          const Key ks = key(stepped(ram_));
          c.we = true, c.wa = kept_, c.w_step = true, c.kept = kept_ + 1;
          if (kept_ == 0 || (!cross_ && !(ks < max_)))
            c.max = ks;
          else if (!cross_)
            c.cross = true, c.first = kept_;
        }
        if (rd_ + 1 == cnt_) c.state = State::Eol;
        break;
      case State::Eol:
        if (!in.out_ready) break;
        c.cnt = kept_;
        if (last_line(in))
          c.state = State::Drain;
        else
          c.state = c.cross ? State::Fix : State::Ins;  // c.cross: with the last edge's compare
        break;
      case State::Fix:
        c.cmp = max_;  // the scan's first entry is compared with the maximum before A[first]
        c.re = true, c.ra = first_, c.rd = first_, c.state = State::Scan;
        break;
      case State::Scan:
        c.we = true, c.wa = capacity_;  // every scanned entry to the scratch word
        c.cmp = kram;  // the greatest so far, or the one moving back
        if (kram < cmp_) {
          c.re = true, c.ra = rd_ - 1, c.pos = rd_ - 1, c.state = State::FShift;
        } else {
          c.max = kram, c.rd = rd_ + 1;
          if (rd_ + 1 == cnt_)
            c.state = State::Ins;
          else
            c.re = true, c.ra = rd_ + 1;
        }
        break;
      case State::FShift:
        c.re = true, c.we = true, c.wa = pos_ + 1;  // ram_q moves up on every clock
        if (kram < cmp_)
          c.ra = capacity_, c.pos = pos_ + 1, c.state = State::FPlace;
        else if (pos_ == 0)
          c.ra = capacity_, c.state = State::FPlace;
        else
          c.ra = pos_ - 1, c.pos = pos_ - 1;
        break;
      case State::FPlace:
        c.cmp = max_;  // the scan's next entry is compared with the maximum again
        c.we = true, c.wa = pos_;
        if (rd_ + 1 == cnt_)
          c.state = State::Ins;
        else
          c.re = true, c.ra = rd_ + 1, c.rd = rd_ + 1, c.state = State::Scan;
        break;
      case State::Drain:
        if (!in.edge_valid) break;
        c.take = true;
        if (in.edge_eof) c.state = State::Idle;
        break;
    }
    return c;
  }

  int capacity_;
  int id_mask_;
  ChannelFormats formats_;
  EdgeIncrementer::Signs signs_;
  std::vector<ActiveEdge> mem_;  // A[0..capacity-1], the scratch word at capacity
  ActiveEdge ram_;               // the read register
  State state_ = State::Idle;
  bool overflow_ = false;
  int line_ = 0, cnt_ = 0, kept_ = 0, rd_ = 0, pos_ = 0, first_ = 0, id_ = 0;
  bool cross_ = false;
  // max_: the greatest key of the entries before (OUT, FIX); cmp_: the key ram_ is compared with
  // (the record's in the shift, the maximum or the greatest scanned so far in the scan, the
  // moving entry's in FIX's shift), loaded per state as the RTL's cmp_q.
  Key max_, cmp_;
};

}  // namespace watkins
