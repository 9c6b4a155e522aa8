// formal_stream.svh: the handshake rules every formal harness of tests/formal states, written
// once. Read by yosys 0.23 (`read_verilog -sv -formal`) only: immediate assert/assume in clocked
// and combinational blocks, $past and $stable; scripts/formal runs the proofs (sat -tempinduct).
// A harness declares `logic past_q` (0 in the first clock, then 1) with FORMAL_PAST, resets its
// DUT in the first clock, and leaves rst_ni free afterwards: a reset may come at any clock.
`ifndef FORMAL_STREAM_SVH
`define FORMAL_STREAM_SVH

// past_q: a previous clock exists, so $past is meaningful; the first clock is a reset.
`define FORMAL_PAST \
  logic past_q; \
  initial past_q = 1'b0; \
  always_ff @(posedge clk_i) past_q <= 1'b1; \
  always_comb if (!past_q) assume (!rst_ni);

// The environment obeys valid/ready on an input stream: a beat offered and not taken is offered
// again the next clock, unchanged (unless a reset came in between).
`define FORMAL_ASSUME_HOLD(valid, ready, data) \
  always_ff @(posedge clk_i) \
    if (past_q && $past(rst_ni && (valid) && !(ready))) assume ((valid) && $stable(data));

// The stage obeys valid/ready on its output stream, whatever the back-pressure: a beat offered
// and not taken is offered again the next clock, unchanged.
`define FORMAL_ASSERT_HOLD(valid, ready, data) \
  always_ff @(posedge clk_i) \
    if (past_q && $past(rst_ni && (valid) && !(ready))) assert ((valid) && $stable(data));

// Beats taken on a stream since the last reset, modulo 2^bits: the sequence number the next beat
// carries (the harnesses tag each input beat with it, and expect it back at the output).
`define FORMAL_COUNT(name, bits, valid, ready) \
  logic [(bits)-1:0] name; \
  always_ff @(posedge clk_i) \
    if (!rst_ni) name <= '0; \
    else if ((valid) && (ready)) name <= name + 1'b1;

`endif
