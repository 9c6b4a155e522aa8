// stall_pipe: the valid and payload shift of a Stages-deep pipeline with one global stall.
// The idiom of span_reciprocal, normalizer and phong_shader: every stage advances together on
// en_o, which the parent also uses to enable its own datapath registers, so they stay in step.
// Latency: Stages cycles (the parameter). Valid (reset) is registered in every stage. ready_o =
// en_o = ready_i || !valid_o (a bubble anywhere in the pipe is not squeezed out while the output
// waits): combinational from ready_i and the last valid flop, or with LookAhead a flop of its
// own, loaded with that value a clock ahead from the consumer's ready_next_i (ready_i on the next
// clock). Same cycles either way (a_en).
// Stages: valid_q[0] -> valid_q[1] -> ... -> valid_q[Stages-1], each loaded on en_o (ce_o[s]
// for the parent's stage s).
// LookAhead keeps the consumer's ready off the path into this pipe's enable and out through
// ready_o to the producer: in the Phong top the fragment queue's ready would otherwise cross the
// shader and the normalizer into the interpolator in one clock. en_next_o, en_o on the next
// clock, is the ready_next_i of a LookAhead producer. With LookAhead the flop is kept in copies,
// one per CopyStages stages, each enabling its own stages' ce_o: a single flop's route to every
// stage's enable across a deep pipe (the span reciprocal's 26 stages) is long.
// PayloadRam = 0: the payload (not reset) shifts through a register per stage. PayloadRam = 1
// (Stages >= 2): the payload is written once into a small RAM as it enters and read out in
// order (the pipe never reorders), synchronous read one clock ahead into payload_o's register
// (written while a beat is offered, read as a beat enters the last stage): a wide payload costs
// one RAM word per beat in flight instead of Stages registers, and maps to block RAM
// (SB_RAM40_4K, DP16KD). Same latency and values either way.
`include "watkins_assert.svh"

module stall_pipe #(
  parameter int unsigned Stages      = 2,  // pipeline depth, >= 1
  parameter int unsigned PayloadBits = 1,  // carried alongside, unchanged
  parameter bit          PayloadRam  = 1'b0, // 1: keep the payload in a RAM, not in every stage
  parameter bit          LookAhead   = 1'b0, // 1: en_o from a flop loaded from ready_next_i
  parameter int unsigned CopyStages  = 8     // LookAhead: stages enabled by each copy of the flop
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,       // active-low synchronous reset (valid only)
  input  logic [PayloadBits-1:0] payload_i,
  input  logic                   valid_i,
  output logic                   ready_o,
  output logic [PayloadBits-1:0] payload_o,    // payload_i of the beat leaving the last stage
  output logic                   valid_o,
  input  logic                   ready_i,
  input  logic                   ready_next_i, // LookAhead: ready_i's value on the next clock
  output logic                   en_next_o,    // en_o's value on the next clock (from ready_next_i)
  output logic                   en_o,         // every stage advances this clock (the parent's too)
  output logic [Stages-1:0]      valid_q_o,    // the beat in stage s (s + 1 clocks in) is valid
  output logic [Stages-1:0]      ce_o          // stage s loads: en_o and the beat entering it is valid
);
  logic [Stages-1:0]      valid_q;
  logic [Stages-1:0]      en_stage;  // en_o as stage s's clock enable reads it (a copy of it)

  // The valid entering each stage (on the input, or in the stage before): the stage loads it
  // when the pipe advances (ce_o), and the last stage's is its valid on the next clock then.
  logic [Stages-1:0] entering;
  assign entering = (valid_q << 1) | Stages'(valid_i);
  // The last stage's valid on the next clock, and en_o then.
  logic valid_next;
  assign valid_next = en_o ? entering[Stages-1] : valid_q[Stages-1];
  assign en_next_o = ready_next_i || !valid_next;
  if (LookAhead) begin : g_ahead
    // Copy c enables stages [c CopyStages, (c + 1) CopyStages); copy 0 is en_o. Each copy's next
    // state is computed from the copy itself (its own pick of the last valid), so the copies are
    // not identical logic and yosys keeps them apart (opt_merge merges equal flops).
    localparam int unsigned Copies     = (Stages + CopyStages - 1) / CopyStages;
    logic [Copies-1:0] en_q;  // each ready_i || !valid_q[Stages-1], a clock ahead (a_en, a_en_copies)
    for (genvar c = 0; c < Copies; c++) begin : g_copy
      logic valid_next_c;  // valid_next, picked by this copy
      assign valid_next_c = en_q[c] ? entering[Stages-1] : valid_q[Stages-1];
      always_ff @(posedge clk_i) begin
        if (!rst_ni) en_q[c] <= 1'b1;  // no beat in flight
        else en_q[c] <= ready_next_i || !valid_next_c;
      end
    end
    for (genvar s = 0; s < Stages; s++) begin : g_stage_en
      assign en_stage[s] = en_q[s / CopyStages];
    end
    assign en_o = en_q[0];
    `WATKINS_ASSERT(a_en_copies, en_q == {Copies{en_q[0]}})
  end else begin : g_now
    assign en_o     = ready_i || !valid_q[Stages-1];
    assign en_stage = {Stages{en_o}};
  end
  assign ready_o = en_o;
  // Per-stage clock enables for a parent that loads a stage's datapath registers only for a
  // valid beat (a bubble leaves them as they were: no value a valid beat reads changes, and a
  // simulator skips the stage). One LUT from en_o's own inputs (with LookAhead, its stage's copy).
  assign valid_q_o = valid_q;
  assign ce_o      = en_stage & entering;

  // A shift rather than {valid_q[Stages-2:0], valid_i}, which Stages = 1 would not allow.
  always_ff @(posedge clk_i) begin
    if (!rst_ni) valid_q <= '0;
    else if (en_o) valid_q <= entering;
  end

  assign valid_o = valid_q[Stages-1];

  if (PayloadRam) begin : g_ram
    // At most Stages beats are in flight, so Depth > Stages entries never overwrite one that is
    // still to be read. A beat is written when it enters and its entry read from the clock it
    // reaches the last stage on; it entered at least Stages - 1 >= 1 clocks before (write first).
    localparam int unsigned PointerBits = $clog2(Stages + 1);
    localparam int unsigned Depth       = 2 ** PointerBits;
    // no_rw_check: a read that loads out_q never meets the write of its own slot (a_no_collision:
    // the beat it reads entered a clock or more before, and wr_q is past every beat in flight),
    // so yosys need not build its read-during-write emulation around a block RAM: a mux on every
    // output bit behind the RAM's long clock-to-out, a register per bit and an address compare.
    (* no_rw_check *) logic [PayloadBits-1:0] mem [Depth];
    logic [PointerBits-1:0] wr_q, rd_q, rd_inc_q, rd_next, rd_addr;
    logic [PayloadBits-1:0] out_q;

    // rd_q + 1 kept in its own register, so the next read pointer is a 2:1 pick by the handshake
    // (ready_i is the parent's stall signal, with a large fan-out) and no add follows it.
    // valid_o && en_o is valid_o && ready_i (en_o = ready_i || !valid_o): with LookAhead it reads
    // this pipe's own flop, not the parent's stall, whose LUT yosys would share with the parent's
    // first stage enable (tail_en && valid_o: equal logic is merged) and place among that stage's
    // registers, far from this pointer.
    assign rd_next = (valid_o && en_o) ? rd_inc_q : rd_q;
    always_ff @(posedge clk_i) begin
      if (!rst_ni) begin
        wr_q     <= '0;
        rd_q     <= '0;
        rd_inc_q <= PointerBits'(1);
      end else begin
        if (en_o && valid_i) wr_q <= wr_q + 1'b1;
        rd_q     <= rd_next;
        rd_inc_q <= rd_next + 1'b1;
      end
    end
    `WATKINS_ASSERT(a_rd_inc, rd_inc_q == rd_q + 1'b1)
    `WATKINS_ASSERT(a_no_collision, (valid_i && ce_o[Stages-1]) |-> rd_addr != wr_q)
    // Written whenever a beat is offered (valid_i), stalled or not: slot wr_q holds no beat in
    // flight until wr_q moves past it (a beat entering is written the clock it enters), so
    // writing it while stalled is harmless, and the RAM's write enable is a valid, not the
    // parent's stall signal. out_q loads as the last stage does (ce_o[Stages-1]: the pipe
    // advances and a beat is in the stage before), with that beat's word: rd_q + 1 when a beat
    // leaves the last stage (it does whenever the pipe advances with valid_o), else rd_q. The
    // read address is thus picked by a flop (valid_o), and the stall reaches out_q's enable
    // only; a simulator copies the (wide) payload only for the clocks a beat arrives.
    assign rd_addr = valid_o ? rd_inc_q : rd_q;
    always_ff @(posedge clk_i) begin
      if (valid_i) mem[wr_q] <= payload_i;
      if (ce_o[Stages-1]) out_q <= mem[rd_addr];  // the beat arriving in the last stage
    end
    assign payload_o = out_q;
  end else begin : g_shift
    logic [PayloadBits-1:0] payload_q [Stages];
    always_ff @(posedge clk_i) begin
      if (en_o) begin
        payload_q[0] <= payload_i;
        for (int s = 1; s < Stages; s++) payload_q[s] <= payload_q[s-1];
      end
    end
    assign payload_o = payload_q[Stages-1];
  end

  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, payload_i)
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, payload_o)
  `WATKINS_ASSERT(a_ram_depth, !PayloadRam || Stages >= 2)
  // LookAhead: the flop is the enable it stands for (the consumer's ready_next_i was right).
  `WATKINS_ASSERT(a_en, en_o == (ready_i || !valid_q[Stages-1]))
endmodule
