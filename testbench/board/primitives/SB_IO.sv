// SB_IO: simulation stand-in for the iCE40 I/O cell, output side only (the synthesis flow uses the
// device's own). PIN_TYPE[5:2] selects the output: 4'b0101 registered (D_OUT_0 taken on the
// rising edge of OUTPUT_CLK, on the pad until the next one), 4'b0100 DDR (D_OUT_0 taken on the
// rising edge and on the pad while OUTPUT_CLK is high, D_OUT_1 taken on the falling edge and on
// the pad while it is low), 4'b0110 simple (D_OUT_0 straight to the pad). The input side reads
// 0; the pad is an output here.

/* verilator lint_off UNUSEDPARAM */
/* verilator lint_off UNUSEDSIGNAL */
module SB_IO #(
  parameter [5:0] PIN_TYPE          = 6'b000000,
  parameter [0:0] PULLUP            = 1'b0,
  parameter [0:0] NEG_TRIGGER       = 1'b0,
  parameter       IO_STANDARD       = "SB_LVCMOS"
) (
  output logic PACKAGE_PIN,
  input  logic LATCH_INPUT_VALUE,
  input  logic CLOCK_ENABLE,
  input  logic INPUT_CLK,
  input  logic OUTPUT_CLK,
  input  logic OUTPUT_ENABLE,
  input  logic D_OUT_0,
  input  logic D_OUT_1,
  output logic D_IN_0,
  output logic D_IN_1
);
  logic rise_q = 1'b0, fall_q = 1'b0;

  always_ff @(posedge OUTPUT_CLK) rise_q <= D_OUT_0;
  always_ff @(negedge OUTPUT_CLK) fall_q <= D_OUT_1;

  always_comb begin
    unique case (PIN_TYPE[5:2])
      4'b0100: PACKAGE_PIN = OUTPUT_CLK ? rise_q : fall_q;
      4'b0110: PACKAGE_PIN = D_OUT_0;
      default: PACKAGE_PIN = rise_q;
    endcase
  end
  assign D_IN_0 = 1'b0;
  assign D_IN_1 = 1'b0;
endmodule
/* verilator lint_on UNUSEDSIGNAL */
/* verilator lint_on UNUSEDPARAM */
