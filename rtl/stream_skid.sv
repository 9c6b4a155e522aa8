// stream_skid: a one-beat skid buffer that cuts a valid/ready stream's ready path.
// Latency 0 cycles: while the skid slot is empty, data_i and valid_i pass straight to the
// output; when the consumer stalls (valid_o && !ready_i), the beat on the output (taken from the
// producer on that clock, as ready_o was high) is held in the skid register and offered from
// there until taken, while ready_o is low.
// Registered: ready_o = "skid slot empty" comes straight from a flop (full_q), so ready_i
// reaches only full_q's next state, never the producer. Not registered: valid_o = valid_i ||
// full_q and data_o (a 2:1 mux on full_q) are combinational from the input.
// Throughput: one beat per clock to the consumer; the producer is refused on the clock after each
// stall that fills the slot, the clock the slot drains (cycle model:
// model/twins/cycle_model.cpp). No value twin: it moves no value.
// The skid register loads on every clock it is empty and a beat is offered (valid_i, not
// ready_i): its enable reads full_q and the producer's valid, which is a flop in watkins_top
// (segment_former's seg_valid_o), and a simulator copies the word only on offered beats.
`include "watkins_assert.svh"

module stream_skid #(
  parameter int unsigned DataBits = 8
) (
  input  logic                clk_i,
  input  logic                rst_ni,   // active-low synchronous reset
  input  logic [DataBits-1:0] data_i,   // beat from the producer
  input  logic                valid_i,
  output logic                ready_o,  // the skid slot is empty (a flop)
  output logic [DataBits-1:0] data_o,   // the held beat, else data_i
  output logic                valid_o,
  input  logic                ready_i
);
  logic                full_q;  // the skid slot holds a beat the consumer has not taken
  logic [DataBits-1:0] skid_q;

  assign ready_o = !full_q;
  assign valid_o = valid_i || full_q;
  assign data_o  = full_q ? skid_q : data_i;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) full_q <= 1'b0;
    // Empty: a beat passed through and not taken stays in the slot. Full: it leaves when taken
    // (the producer is refused meanwhile).
    else full_q <= valid_o && !ready_i;
  end

  // A beat offered while empty is copied whether or not it is taken: the slot is read only once
  // full_q says it holds the beat that was refused.
  always_ff @(posedge clk_i) begin
    if (!full_q && valid_i) skid_q <= data_i;
  end

  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, data_i)
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, data_o)
  // No drop: a beat offered and refused is in the slot on the next clock. No duplicate: a
  // beat taken from the slot leaves it, and the producer's next beat waits behind it.
  `WATKINS_ASSERT(a_no_drop, valid_o && !ready_i |=> full_q && data_o == $past(data_o))
  `WATKINS_ASSERT(a_no_dup, full_q && ready_i |=> !full_q)
  `WATKINS_COVER(c_skid_full, full_q)
  `WATKINS_COVER(c_skid_drain, full_q && ready_i)
endmodule
