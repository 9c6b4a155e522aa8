// ODDRX1F: simulation stand-in for the Lattice ECP5 output DDR cell (the synthesis flow uses the
// device's own; yosys knows it as a black box). D0 and D1 are captured on the rising edge of SCLK;
// Q is the captured D0 for the first half of the SCLK period (SCLK high) and the captured D1 for
// the second (SCLK low), so a bit pair presented before rising edge n is on the pin from edge n to
// edge n + 1. RST (active high) clears the captured bits on the rising edge. A bench reads Q after
// the eval of each SCLK edge.

module ODDRX1F #(
  /* verilator lint_off UNUSEDPARAM */
  parameter string GSR = "ENABLED"  // the device's global set/reset: no effect here
  /* verilator lint_on UNUSEDPARAM */
) (
  input  logic D0,    // sent while SCLK is high
  input  logic D1,    // sent while SCLK is low
  input  logic SCLK,
  input  logic RST,
  output logic Q
);
  logic d0_q, d1_q;

  always_ff @(posedge SCLK) begin
    if (RST) begin
      d0_q <= 1'b0;
      d1_q <= 1'b0;
    end else begin
      d0_q <= D0;
      d1_q <= D1;
    end
  end
  assign Q = SCLK ? d0_q : d1_q;
endmodule
