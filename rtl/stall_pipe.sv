// stall_pipe: the valid and payload shift of a Stages-deep pipeline with one global stall, the
// idiom of span_reciprocal, normalizer and phong_shader: every stage advances together on en_o,
// which the parent also uses to enable its own datapath registers, so they stay in step.
// Latency Stages; valid (reset) and payload (not reset) registered in every stage;
// ready_o = en_o = ready_i || !valid_o, combinational from ready_i and the last valid flop only
// (a bubble anywhere in the pipe is not squeezed out while the output waits).
`include "watkins_assert.svh"

module stall_pipe #(
  parameter int unsigned Stages      = 2,  // pipeline depth, >= 1
  parameter int unsigned PayloadBits = 1   // carried alongside, unchanged
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,       // active-low synchronous reset (valid only)
  input  logic [PayloadBits-1:0] payload_i,
  input  logic                   valid_i,
  output logic                   ready_o,
  output logic [PayloadBits-1:0] payload_o,    // payload_i of the beat leaving the last stage
  output logic                   valid_o,
  input  logic                   ready_i,
  output logic                   en_o          // every stage advances this clock (the parent's too)
);
  logic [Stages-1:0]      valid_q;
  logic [PayloadBits-1:0] payload_q [Stages];

  assign en_o    = ready_i || !valid_q[Stages-1];
  assign ready_o = en_o;

  // A shift rather than {valid_q[Stages-2:0], valid_i}, which Stages = 1 would not allow.
  always_ff @(posedge clk_i) begin
    if (!rst_ni) valid_q <= '0;
    else if (en_o) valid_q <= (valid_q << 1) | Stages'(valid_i);
  end

  always_ff @(posedge clk_i) begin
    if (en_o) begin
      payload_q[0] <= payload_i;
      for (int s = 1; s < Stages; s++) payload_q[s] <= payload_q[s-1];
    end
  end

  assign valid_o   = valid_q[Stages-1];
  assign payload_o = payload_q[Stages-1];

  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, payload_i)
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, payload_o)
endmodule
