// normalizer_formal: proves rtl/normalizer.sv (16 stages, a 5-bit payload) holds valid and its whole
// output until ready, passes every beat once, in order, with its payload unchanged (each input
// beat carries its sequence number as payload), keeps ready_o = ready_i || !valid_o and holds at
// most 16 beats. stall_pipe_checker ties the payload RAM of its u_pipe to the tags in flight; the
// normal's datapath is free (its values are the unit benches' business), and so are the products:
// scripts/formal reads tests/formal/mul18_reg_free.sv in place of rtl/mul18_reg.sv. LookAhead = 1
// (the Phong top's): the environment gives ready_i a clock ahead on ready_next_i.
`include "formal_stream.svh"

module normalizer_formal #(
  parameter int unsigned PayloadBits = 5,  // the tag: >= log2 of the RAM depth (32 for 16 stages)
  parameter bit          LookAhead   = 1'b0,  // the Phong top's setting is 1
  localparam int unsigned NormalBits  = watkins_pkg::NormalInBits,
  localparam int unsigned UnitBits    = watkins_pkg::UnitBits,
  // normalizer's pipe (16): squares, sum, the rsqrt unit, partial products, sum, shift, round
  localparam int unsigned Stages      = 2 + watkins_pkg::RsqrtStages + 4,
  localparam int unsigned PointerBits = $clog2(Stages + 1),
  localparam int unsigned Depth       = 2 ** PointerBits
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic [3*NormalBits-1:0] normal_i,
  input  logic [PayloadBits-1:0] payload_i,
  input  logic                   valid_i,
  input  logic                   ready_i,
  input  logic                   ready_next_i  // LookAhead: ready_i of the next clock
);
  logic                   ready_o, valid_o, ready_next_o;
  logic [3*UnitBits-1:0]  unit_o;
  logic                   null_o;
  logic [PayloadBits-1:0] payload_o;
  normalizer #(.PayloadBits(PayloadBits), .LookAhead(LookAhead)) u_dut (.*);

  `FORMAL_PAST
  `FORMAL_READY_AHEAD(LookAhead)
  `FORMAL_COUNT(n_in_q, PayloadBits, valid_i, ready_o)
  `FORMAL_COUNT(n_out_q, PayloadBits, valid_o, ready_i)
  `FORMAL_ASSUME_HOLD(in, valid_i, ready_o, {normal_i, payload_i})
  `FORMAL_ASSERT_HOLD(out, valid_o, ready_i, {unit_o, null_o, payload_o})

  `FORMAL_TAGGED_STAGE(Stages)

  // The internals of u_pipe (stall_pipe with PayloadRam) and the stall.
  `FORMAL_RAM_PIPE_PROBES
  `FORMAL_RAM_PIPE_WORDS_32

  `FORMAL_RAM_PIPE_CHECK
endmodule
