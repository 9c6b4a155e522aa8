// span_reciprocal_formal: proves rtl/span_reciprocal.sv (26 stages, a 4-bit payload, 6-bit dx)
// holds valid and its whole output until ready, passes every beat once, in order, with its payload
// unchanged (each input beat carries its sequence number as payload), keeps ready_o =
// ready_i || !valid_o and holds at most 26 beats. stall_pipe_checker ties the payload RAM of its
// u_pipe to the tags in flight.
`include "formal_stream.svh"

module span_reciprocal_formal #(
  parameter int unsigned DxBits      = 6,
  parameter int unsigned PayloadBits = 5,  // the tag: > log2(Stages + 1)
  localparam int unsigned RecipBits  = watkins_pkg::RecipBits,
  localparam int unsigned ExpBits    = $clog2(DxBits),
  localparam int unsigned Stages     = RecipBits + 2,  // span_reciprocal's pipe
  localparam int unsigned PtrBits    = $clog2(Stages + 1),
  localparam int unsigned Depth      = 2 ** PtrBits
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic [DxBits-1:0]      dx_i,
  input  logic [PayloadBits-1:0] payload_i,
  input  logic                   valid_i,
  input  logic                   ready_i
);
  logic                   ready_o, valid_o;
  logic [RecipBits:0]     recip_o;
  logic [ExpBits-1:0]     p_o;
  logic [PayloadBits-1:0] payload_o;
  span_reciprocal #(.DxBits(DxBits), .PayloadBits(PayloadBits)) u_dut (.*);

  `FORMAL_PAST
  `FORMAL_COUNT(n_in_q, PayloadBits, valid_i, ready_o)
  `FORMAL_COUNT(n_out_q, PayloadBits, valid_o, ready_i)
  `FORMAL_ASSUME_HOLD(in, valid_i, ready_o, {dx_i, payload_i})
  `FORMAL_ASSERT_HOLD(out, valid_o, ready_i, {recip_o, p_o, payload_o})

  `FORMAL_TAGGED_STAGE(Stages)

  // The internals of u_pipe (stall_pipe with PayloadRam).
  `FORMAL_RAM_PIPE_PROBES
  `FORMAL_WORD(mem, PayloadBits, 0, \u_dut.u_pipe.g_ram.mem[0] )
  `FORMAL_WORD(mem, PayloadBits, 1, \u_dut.u_pipe.g_ram.mem[1] )
  `FORMAL_WORD(mem, PayloadBits, 2, \u_dut.u_pipe.g_ram.mem[2] )
  `FORMAL_WORD(mem, PayloadBits, 3, \u_dut.u_pipe.g_ram.mem[3] )
  `FORMAL_WORD(mem, PayloadBits, 4, \u_dut.u_pipe.g_ram.mem[4] )
  `FORMAL_WORD(mem, PayloadBits, 5, \u_dut.u_pipe.g_ram.mem[5] )
  `FORMAL_WORD(mem, PayloadBits, 6, \u_dut.u_pipe.g_ram.mem[6] )
  `FORMAL_WORD(mem, PayloadBits, 7, \u_dut.u_pipe.g_ram.mem[7] )
  `FORMAL_WORD(mem, PayloadBits, 8, \u_dut.u_pipe.g_ram.mem[8] )
  `FORMAL_WORD(mem, PayloadBits, 9, \u_dut.u_pipe.g_ram.mem[9] )
  `FORMAL_WORD(mem, PayloadBits, 10, \u_dut.u_pipe.g_ram.mem[10] )
  `FORMAL_WORD(mem, PayloadBits, 11, \u_dut.u_pipe.g_ram.mem[11] )
  `FORMAL_WORD(mem, PayloadBits, 12, \u_dut.u_pipe.g_ram.mem[12] )
  `FORMAL_WORD(mem, PayloadBits, 13, \u_dut.u_pipe.g_ram.mem[13] )
  `FORMAL_WORD(mem, PayloadBits, 14, \u_dut.u_pipe.g_ram.mem[14] )
  `FORMAL_WORD(mem, PayloadBits, 15, \u_dut.u_pipe.g_ram.mem[15] )
  `FORMAL_WORD(mem, PayloadBits, 16, \u_dut.u_pipe.g_ram.mem[16] )
  `FORMAL_WORD(mem, PayloadBits, 17, \u_dut.u_pipe.g_ram.mem[17] )
  `FORMAL_WORD(mem, PayloadBits, 18, \u_dut.u_pipe.g_ram.mem[18] )
  `FORMAL_WORD(mem, PayloadBits, 19, \u_dut.u_pipe.g_ram.mem[19] )
  `FORMAL_WORD(mem, PayloadBits, 20, \u_dut.u_pipe.g_ram.mem[20] )
  `FORMAL_WORD(mem, PayloadBits, 21, \u_dut.u_pipe.g_ram.mem[21] )
  `FORMAL_WORD(mem, PayloadBits, 22, \u_dut.u_pipe.g_ram.mem[22] )
  `FORMAL_WORD(mem, PayloadBits, 23, \u_dut.u_pipe.g_ram.mem[23] )
  `FORMAL_WORD(mem, PayloadBits, 24, \u_dut.u_pipe.g_ram.mem[24] )
  `FORMAL_WORD(mem, PayloadBits, 25, \u_dut.u_pipe.g_ram.mem[25] )
  `FORMAL_WORD(mem, PayloadBits, 26, \u_dut.u_pipe.g_ram.mem[26] )
  `FORMAL_WORD(mem, PayloadBits, 27, \u_dut.u_pipe.g_ram.mem[27] )
  `FORMAL_WORD(mem, PayloadBits, 28, \u_dut.u_pipe.g_ram.mem[28] )
  `FORMAL_WORD(mem, PayloadBits, 29, \u_dut.u_pipe.g_ram.mem[29] )
  `FORMAL_WORD(mem, PayloadBits, 30, \u_dut.u_pipe.g_ram.mem[30] )
  `FORMAL_WORD(mem, PayloadBits, 31, \u_dut.u_pipe.g_ram.mem[31] )

  `FORMAL_RAM_PIPE_CHECK
endmodule
