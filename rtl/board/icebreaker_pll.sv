// icebreaker_pll: the iCEBreaker's one clock, 25.125 MHz from the 12 MHz oscillator through the
// UP5K's SB_PLL40_PAD (docs/reference/board.md, "iCEBreaker"). No logic: the PLL's global output is
// the clock; locked_o is the PLL's LOCK (asynchronous: the reset synchronizer samples it).
//   f = 12 MHz * (DIVF 66 + 1) / (2^DIVQ 5 * (DIVR 0 + 1)) = 12 * 67 / 32 = 25.125 MHz
//   VCO = 12 MHz * 67 = 804 MHz (533..1066), phase detector 12 MHz (FILTER_RANGE 1: 10..19 MHz)
// The oscillator is on pin 35, the UP5K's PLL input pad, which SB_PLL40_PAD takes directly.

module icebreaker_pll (
  input  logic clk_12mhz_i,  // the oscillator's pad
  output logic clk_o,        // 25.125 MHz, on a global buffer
  output logic locked_o
);
  /* verilator lint_off PINCONNECTEMPTY */  // the core output, feedback and dynamic ports are unused
  SB_PLL40_PAD #(
    .FEEDBACK_PATH("SIMPLE"),
    .DIVR        (4'b0000),
    .DIVF        (7'b1000010),
    .DIVQ        (3'b101),
    .FILTER_RANGE(3'b001)
  ) u_sb_pll40_pad (
    .PACKAGEPIN     (clk_12mhz_i),
    .PLLOUTCORE     (),
    .PLLOUTGLOBAL   (clk_o),
    .EXTFEEDBACK    (1'b0),
    .DYNAMICDELAY   (8'd0),
    .LOCK           (locked_o),
    .BYPASS         (1'b0),
    .RESETB         (1'b1),
    .LATCHINPUTVALUE(1'b0),
    .SDO            (),
    .SDI            (1'b0),
    .SCLK           (1'b0)
  );
  /* verilator lint_on PINCONNECTEMPTY */
endmodule
