// toggle_sync: an event carried into another clock domain as a toggle.
// The sender flips a register once per event; two flip-flops on clk_i sample it and a third
// holds the previous sample, so pulse_o is high for exactly one clock per flip, 3 clocks after
// it (registered: the XOR of two flip-flops). Events must be at least 3 receiving clocks apart.

module toggle_sync (
  input  logic clk_i,     // the receiving domain
  input  logic rst_ni,    // active-low synchronous reset (the receiving domain's)
  input  logic toggle_i,  // the sender's toggle register
  output logic pulse_o    // one clock per flip of toggle_i
);
  (* async_reg = "true" *) logic meta_q;
  (* async_reg = "true" *) logic sync_q;
  logic last_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      meta_q <= 1'b0;
      sync_q <= 1'b0;
      last_q <= 1'b0;
    end else begin
      meta_q <= toggle_i;  // crossing: toggle, first of two flip-flops
      sync_q <= meta_q;
      last_q <= sync_q;    // edge detector
    end
  end

  assign pulse_o = sync_q ^ last_q;
endmodule
