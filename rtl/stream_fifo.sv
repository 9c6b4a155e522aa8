// stream_fifo: a first-in first-out valid/ready buffer of Depth words.
// Latency 1 cycle: a word written is visible at the head on the next clock. Every output comes
// from a register: valid_o from its own flop (valid_q, kept equal to cnt_q != 0), data_o from a
// head register beside the slots (head_q), and ready_o ("not full") from its own flop (room_q,
// kept equal to cnt_q != Depth), so a parent's stall signal built on ready_o starts at a flop,
// not at a compare of the count. No combinational path from input to output. ready_next_o is
// ready_o on the next clock (room_q's next value), for a producer whose own ready is a flop
// loaded a clock ahead (stall_pipe's LookAhead).
`include "watkins_assert.svh"

module stream_fifo #(
  parameter int unsigned DataBits = 8,
  parameter int unsigned Depth    = 2
) (
  input  logic                clk_i,
  input  logic                rst_ni,   // active-low synchronous reset
  input  logic [DataBits-1:0] data_i,   // word to store
  input  logic                valid_i,
  output logic                ready_o,  // a slot is free
  output logic                ready_next_o,  // ready_o on the next clock
  output logic [DataBits-1:0] data_o,   // oldest word
  output logic                valid_o,  // the FIFO holds a word
  input  logic                ready_i
);
  localparam int unsigned PointerBits = (Depth > 1) ? $clog2(Depth) : 1;
  localparam int unsigned CountBits   = $clog2(Depth + 1);

  logic [DataBits-1:0]    mem_q [Depth];
  logic [PointerBits-1:0] wr_q, rd_q;
  logic [CountBits-1:0]   cnt_q;
  logic                room_q;  // cnt_q != Depth
  logic                valid_q; // cnt_q != 0
  logic [DataBits-1:0] head_q;  // mem_q[rd_q] whenever the FIFO holds a word (a_head)
  logic push, pop;

  assign ready_o = room_q;
  // valid_o from a flop, not a compare of the count: a consumer's pop decision starts at one
  // flop (the interpolator's stepper's enable needs no LUT for a compare of the count).
  assign valid_o = valid_q;
  assign data_o  = head_q;
  assign push    = valid_i && ready_o;
  assign pop     = valid_o && ready_i;
  // Full next clock: a push without a pop into the last free slot; a pop frees one.
  assign ready_next_o = (push && !pop) ? cnt_q != CountBits'(Depth - 1)
                      : (pop && !push) ? 1'b1 : room_q;

  // Pointers wrap at Depth, which need not be a power of two.
  function automatic logic [PointerBits-1:0] next_ptr(logic [PointerBits-1:0] p);
    next_ptr = (p == PointerBits'(Depth - 1)) ? '0 : p + 1'b1;
  endfunction

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      wr_q  <= '0;
      rd_q  <= '0;
      cnt_q <= '0;
      room_q <= 1'b1;
      valid_q <= 1'b0;
    end else begin
      if (push) wr_q <= next_ptr(wr_q);
      if (pop) rd_q <= next_ptr(rd_q);
      if (push && !pop) cnt_q <= cnt_q + 1'b1;
      else if (pop && !push) cnt_q <= cnt_q - 1'b1;
      room_q <= ready_next_o;
      // Empty next clock: a pop without a push of the last word; a push fills one.
      if (push && !pop) valid_q <= 1'b1;
      else if (pop && !push) valid_q <= cnt_q != CountBits'(1);
    end
  end

  // Storage needs no reset: a slot is read only after it has been written.
  always_ff @(posedge clk_i) begin
    if (push) mem_q[wr_q] <= data_i;
  end
  // The head from a register, not from a read of the slots after the read pointer's flop: a
  // consumer's logic on data_o then starts at a flop beside it (in both tops the fragment
  // queue's head feeds the scanline buffer's word pick, and a slot read in front of that pick
  // would be the tops' longest path). Same words, same cycles: on a pop the head takes the word
  // behind it (from its slot, or from data_i when that word is being pushed now); into an empty
  // FIFO, data_i.
  always_ff @(posedge clk_i) begin
    if (pop && cnt_q != CountBits'(1)) head_q <= mem_q[next_ptr(rd_q)];
    else if (push && (pop || !valid_o)) head_q <= data_i;
  end

  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, data_i)
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, data_o)
`ifdef WATKINS_ASSERT_ON
  // The head slot's word as a signal: Verilator 5.006 stops with an internal error on an array
  // read inside an assertion's property.
  logic [DataBits-1:0] head_slot;
  assign head_slot = mem_q[rd_q];
  `WATKINS_ASSERT(a_head, !valid_o || head_q == head_slot)
`endif
  `WATKINS_ASSERT(a_room, room_q == (cnt_q != CountBits'(Depth)))
  `WATKINS_ASSERT(a_valid, valid_q == (cnt_q != '0))
  `WATKINS_COVER(c_full, !ready_o)
endmodule
