// gray_sync: a Gray-coded counter carried into another clock domain (a multi-bit crossing).
// Latency 3 clocks of clk_i: two flip-flops sample the sender's Gray-code register, so a count
// sampled while it changes is the old count or the new one, never another (one bit changes per
// step); a third register holds its binary value (count_o registered), so the Gray-to-binary
// chain of XORs ends at a flip-flop instead of running into the receiver's compare;
// step_o (combinational, an equality of two registers: the second flip-flop and its previous
// value) says count_o advances at the next clock, so a receiver keeps a difference with the count
// in a register of its own without a carry chain.
// The sender keeps gray_i in a register of its own domain (no logic between it and meta_q).

module gray_sync #(
  parameter int unsigned Bits = 12
) (
  input  logic            clk_i,   // the receiving domain
  input  logic            rst_ni,  // active-low synchronous reset (the receiving domain's)
  input  logic [Bits-1:0] gray_i,  // the sender's Gray-code register
  output logic [Bits-1:0] count_o,      // the count, binary, 3 clocks late (a register)
  output logic            step_o   // count_o changes at the next clock
);
  (* async_reg = "true" *) logic [Bits-1:0] meta_q;
  (* async_reg = "true" *) logic [Bits-1:0] sync_q;

  logic [Bits-1:0] count_q;
  logic [Bits-1:0] sync_prev_q;  // sync_q a clock ago: the Gray code of count_q

  // Binary bit i is the XOR of Gray bits i and above.
  function automatic logic [Bits-1:0] gray_to_binary(logic [Bits-1:0] g);
    logic [Bits-1:0] b;
    b[Bits-1] = g[Bits-1];
    for (int i = Bits - 1; i > 0; i--) b[i-1] = b[i] ^ g[i-1];
    gray_to_binary = b;
  endfunction

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      meta_q  <= '0;
      sync_q  <= '0;
      count_q <= '0;
      sync_prev_q <= '0;
    end else begin
      meta_q  <= gray_i;  // crossing: Gray code, first of two flip-flops
      sync_q  <= meta_q;
      count_q <= gray_to_binary(sync_q);
      sync_prev_q <= sync_q;
    end
  end

  assign count_o = count_q;
  assign step_o  = sync_q != sync_prev_q;
endmodule
