// stall_pipe_formal: proves rtl/stall_pipe.sv (Stages <= 4 with the payload in flops, <= 3 with
// PayloadRam: the words probed below) holds valid and payload until ready, passes every beat once,
// in order, unchanged, keeps ready_o = en_o = ready_i || !valid_o, and holds at most Stages beats,
// and (PayloadRam) never reads the RAM slot written on the same clock. Each input beat carries its
// sequence number as payload; stall_pipe_checker ties the stages to it. LookAhead: the environment
// gives ready_i a clock ahead (ready_next_i), and the enable flop must equal ready_i || !valid_o on
// every clock, and so must each of its copies (the per-stage enables below read them).
`include "formal_stream.svh"

module stall_pipe_formal #(
  parameter int unsigned Stages      = 3,
  parameter int unsigned PayloadBits = 3,     // > log2(Stages + 1)
  parameter bit          PayloadRam  = 1'b0,
  parameter bit          LookAhead   = 1'b0,
  parameter int unsigned CopyStages  = 8      // LookAhead: < Stages gives the enable flop copies
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic [PayloadBits-1:0] payload_i,
  input  logic                   valid_i,
  input  logic                   ready_i,
  input  logic                   ready_next_i
);
  localparam int unsigned PointerBits = $clog2(Stages + 1);
  localparam int unsigned Depth   = 2 ** PointerBits;

  logic                   ready_o, valid_o, en_o, en_next_o;
  logic [PayloadBits-1:0] payload_o;
  logic [Stages-1:0]      valid_q_o, ce_o;
  stall_pipe #(.Stages(Stages), .PayloadBits(PayloadBits), .PayloadRam(PayloadRam),
               .LookAhead(LookAhead), .CopyStages(CopyStages)) u_dut (.*);

  // The per-stage enables: a stage loads exactly when the pipe advances and the beat entering it
  // (on the input, or in the stage before) is valid; the last stage's valid is valid_o.
  for (genvar s = 0; s < Stages; s++) begin : g_ce
    if (s == 0) begin : g_first
      always_comb if (rst_ni) assert (ce_o[0] == (en_o && valid_i));
    end else begin : g_next
      always_comb if (rst_ni) assert (ce_o[s] == (en_o && valid_q_o[s-1]));
    end
  end
  always_comb if (rst_ni) assert (valid_q_o[Stages-1] == valid_o);

  `FORMAL_PAST
  `FORMAL_READY_AHEAD(LookAhead)
  `FORMAL_COUNT(n_in_q, PayloadBits, valid_i, ready_o)
  `FORMAL_COUNT(n_out_q, PayloadBits, valid_o, ready_i)
  `FORMAL_ASSUME_HOLD(in, valid_i, ready_o, payload_i)
  `FORMAL_ASSERT_HOLD(out, valid_o, ready_i, payload_o)

  always_comb begin
    if (valid_i) assume (payload_i == n_in_q);
    if (rst_ni) begin
      if (valid_o) assert (payload_o == n_out_q);
      assert (ready_o == (ready_i || !valid_o) && en_o == ready_o);
      assert (PayloadBits'(n_in_q - n_out_q) <= PayloadBits'(Stages));
    end
  end

  // The internals (absent words stay undriven and unused).
  (* hierconn *) logic [Stages-1:0] \u_dut.valid_q ;
  (* hierconn *) logic [PointerBits-1:0] \u_dut.g_ram.wr_q ;
  (* hierconn *) logic [PointerBits-1:0] \u_dut.g_ram.rd_q ;
  (* hierconn *) logic [PointerBits-1:0] \u_dut.g_ram.rd_inc_q ;
  (* hierconn *) logic [PointerBits-1:0] \u_dut.g_ram.rd_addr ;
  (* hierconn *) logic [PayloadBits-1:0] \u_dut.g_ram.out_q ;
  logic [4*PayloadBits-1:0] shift_q;
  logic [8*PayloadBits-1:0] mem;  // Depth <= 8 (Stages = 4 with flops); words 4..7 unused
  assign mem[8*PayloadBits-1:4*PayloadBits] = '0;
  `FORMAL_WORD(shift_q, PayloadBits, 0, \u_dut.g_shift.payload_q[0] )
  `FORMAL_WORD(shift_q, PayloadBits, 1, \u_dut.g_shift.payload_q[1] )
  `FORMAL_WORD(shift_q, PayloadBits, 2, \u_dut.g_shift.payload_q[2] )
  `FORMAL_WORD(shift_q, PayloadBits, 3, \u_dut.g_shift.payload_q[3] )
  `FORMAL_WORD(mem, PayloadBits, 0, \u_dut.g_ram.mem[0] )
  `FORMAL_WORD(mem, PayloadBits, 1, \u_dut.g_ram.mem[1] )
  `FORMAL_WORD(mem, PayloadBits, 2, \u_dut.g_ram.mem[2] )
  `FORMAL_WORD(mem, PayloadBits, 3, \u_dut.g_ram.mem[3] )

  // rd_q + 1 precomputed (read address picked, not added, by the handshake). A read that loads
  // out_q never addresses the slot written on the same clock (the RAM is no_rw_check: yosys
  // builds no read-during-write logic, and a block RAM's output on a collision is undefined).
  if (PayloadRam) begin : g_rd_inc
    always_comb if (rst_ni) assert (\u_dut.g_ram.rd_inc_q == \u_dut.g_ram.rd_q + 1'b1);
    always_comb if (rst_ni && valid_i && ce_o[Stages-1])
      assert (\u_dut.g_ram.rd_addr != \u_dut.g_ram.wr_q );
  end

  stall_pipe_checker #(.Stages(Stages), .PayloadBits(PayloadBits), .PayloadRam(PayloadRam)) u_check (
    .clk_i,
    .rst_ni,
    .en_i        (en_o),
    .n_in_i      (n_in_q),
    .n_out_i     (n_out_q),
    .valid_q_i   (\u_dut.valid_q ),
    .shift_q_i   (shift_q[Stages*PayloadBits-1:0]),
    .wr_q_i      (\u_dut.g_ram.wr_q ),
    .rd_q_i      (\u_dut.g_ram.rd_q ),
    .mem_i       (mem[Depth*PayloadBits-1:0]),
    .out_q_i     (\u_dut.g_ram.out_q )
  );
endmodule
