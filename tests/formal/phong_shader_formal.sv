// phong_shader_formal: proves rtl/phong_shader.sv (42 stages, a 6-bit payload) holds valid and its
// shade until ready, passes every beat once, in order, with its payload unchanged (each input beat
// carries its sequence number as payload), keeps ready_o = ready_i || !valid_o and holds at most
// 42 beats. stall_pipe_checker ties the payload RAM of its u_pipe to the tags in flight; the
// shading datapath, light and eye are free (values are the unit benches' business), and so are the
// products: scripts/formal reads tests/formal/mul18_reg_free.sv in place of rtl/mul18_reg.sv.
// LookAhead = 1 (the Phong top's): the environment gives ready_i a clock ahead on ready_next_i.
`include "formal_stream.svh"

module phong_shader_formal #(
  parameter int unsigned PayloadBits = 6,  // the tag: >= log2 of the RAM depth
  parameter bit          LookAhead   = 1'b0,  // the Phong top's setting is 1
  localparam int unsigned UnitBits      = watkins_pkg::UnitBits,
  localparam int unsigned MaterialBits  = watkins_pkg::MaterialBits,
  localparam int unsigned ShininessBits = watkins_pkg::ShininessBits,
  // phong_shader's pipe, from its own constants (yosys 0.23 reads no child's localparam): CosStage
  // stages to cos(s), PowStages per bit of n (a power's operands, product, copy, round), 4 out
  localparam int unsigned CosStage  = 6,
  localparam int unsigned PowStages = 4,
  localparam int unsigned Stages      = CosStage + PowStages * ShininessBits + 4,
  localparam int unsigned PointerBits = $clog2(Stages + 1),
  localparam int unsigned Depth       = 2 ** PointerBits
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic [3*UnitBits-1:0]    light_i,
  input  logic [3*UnitBits-1:0]    eye_i,
  input  logic [3*UnitBits-1:0]    normal_i,
  input  watkins_pkg::rgb_t      cp_i,
  input  logic [MaterialBits-1:0]  d_i,
  input  logic [MaterialBits-1:0]  w_i,
  input  logic [ShininessBits-1:0] shininess_i,
  input  logic [PayloadBits-1:0] payload_i,
  input  logic                   valid_i,
  input  logic                   ready_i,
  input  logic                   ready_next_i  // LookAhead: ready_i of the next clock
);
  logic                   ready_o, valid_o, ready_next_o;
  watkins_pkg::rgb_t      rgb_o;
  logic [PayloadBits-1:0] payload_o;
  phong_shader #(.PayloadBits(PayloadBits), .LookAhead(LookAhead)) u_dut (.*);

  `FORMAL_PAST
  `FORMAL_READY_AHEAD(LookAhead)
  `FORMAL_COUNT(n_in_q, PayloadBits, valid_i, ready_o)
  `FORMAL_COUNT(n_out_q, PayloadBits, valid_o, ready_i)
  `FORMAL_ASSUME_HOLD(in, valid_i, ready_o, {normal_i, cp_i, d_i, w_i, shininess_i, payload_i})
  `FORMAL_ASSERT_HOLD(out, valid_o, ready_i, {rgb_o, payload_o})

  `FORMAL_TAGGED_STAGE(Stages)

  // The internals of u_pipe (stall_pipe with PayloadRam) and the stall.
  `FORMAL_RAM_PIPE_PROBES
  `FORMAL_RAM_PIPE_WORDS_64

  `FORMAL_RAM_PIPE_CHECK
endmodule
