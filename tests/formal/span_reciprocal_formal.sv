// span_reciprocal_formal: proves rtl/span_reciprocal.sv (26 stages, a 5-bit payload, 6-bit dx)
// holds valid and its whole output until ready, passes every beat once, in order, with its payload
// unchanged (each input beat carries its sequence number as payload), keeps ready_o =
// ready_i || !valid_o and holds at most 26 beats. stall_pipe_checker ties the payload RAM of its
// u_pipe to the tags in flight. LookAhead = 1 (the interpolator's): the environment gives ready_i
// a clock ahead on ready_next_i.
`include "formal_stream.svh"

module span_reciprocal_formal #(
  parameter int unsigned DxBits      = 6,
  parameter int unsigned PayloadBits = 5,  // the tag: > log2(Stages + 1)
  parameter bit          LookAhead   = 1'b0,  // the interpolator's setting is 1
  localparam int unsigned RecipBits    = watkins_pkg::RecipBits,
  localparam int unsigned ExponentBits = $clog2(DxBits),
  localparam int unsigned Stages       = RecipBits + 2,  // span_reciprocal's pipe
  localparam int unsigned PointerBits = $clog2(Stages + 1),
  localparam int unsigned Depth       = 2 ** PointerBits
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic [DxBits-1:0]      dx_i,
  input  logic [PayloadBits-1:0] payload_i,
  input  logic                   valid_i,
  input  logic                   ready_i,
  input  logic                   ready_next_i  // LookAhead: ready_i of the next clock
);
  logic                   ready_o, valid_o, ready_next_o;
  logic [RecipBits:0]     recip_o;
  logic [ExponentBits-1:0] p_o;
  logic [PayloadBits-1:0] payload_o;
  span_reciprocal #(.DxBits(DxBits), .PayloadBits(PayloadBits), .LookAhead(LookAhead)) u_dut (.*);

  `FORMAL_PAST
  `FORMAL_READY_AHEAD(LookAhead)
  `FORMAL_COUNT(n_in_q, PayloadBits, valid_i, ready_o)
  `FORMAL_COUNT(n_out_q, PayloadBits, valid_o, ready_i)
  `FORMAL_ASSUME_HOLD(in, valid_i, ready_o, {dx_i, payload_i})
  `FORMAL_ASSERT_HOLD(out, valid_o, ready_i, {recip_o, p_o, payload_o})

  `FORMAL_TAGGED_STAGE(Stages)

  // The internals of u_pipe (stall_pipe with PayloadRam).
  `FORMAL_RAM_PIPE_PROBES
  `FORMAL_RAM_PIPE_WORDS_32

  `FORMAL_RAM_PIPE_CHECK
endmodule
