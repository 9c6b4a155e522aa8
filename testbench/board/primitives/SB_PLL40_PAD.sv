// SB_PLL40_PAD: simulation stand-in for the iCE40 PLL fed from its pad (the synthesis flow uses the
// device's own). It computes nothing: the Verilated bench drives the global output and LOCK
// through the variables below (public: written from C++ through the model's root); on the
// iCEBreaker bench one clock toggles twice per pixel clock. Every parameter of the device cell is
// accepted and ignored.

/* verilator lint_off UNUSEDPARAM */
/* verilator lint_off UNUSEDSIGNAL */
module SB_PLL40_PAD #(
  parameter       FEEDBACK_PATH                  = "SIMPLE",
  parameter       DELAY_ADJUSTMENT_MODE_FEEDBACK = "FIXED",
  parameter       DELAY_ADJUSTMENT_MODE_RELATIVE = "FIXED",
  parameter       SHIFTREG_DIV_MODE              = 2'b00,
  parameter       FDA_FEEDBACK                   = 4'b0000,
  parameter       FDA_RELATIVE                   = 4'b0000,
  parameter       PLLOUT_SELECT                  = "GENCLK",
  parameter [3:0] DIVR                           = 4'b0000,
  parameter [6:0] DIVF                           = 7'b0000000,
  parameter [2:0] DIVQ                           = 3'b000,
  parameter [2:0] FILTER_RANGE                   = 3'b000,
  parameter       ENABLE_ICEGATE                 = 1'b0,
  parameter       TEST_MODE                      = 1'b0,
  parameter       EXTERNAL_DIVIDE_FACTOR         = 1
) (
  input  logic       PACKAGEPIN,
  output logic       PLLOUTCORE,
  output logic       PLLOUTGLOBAL,
  input  logic       EXTFEEDBACK,
  input  logic [7:0] DYNAMICDELAY,
  output logic       LOCK,
  input  logic       BYPASS,
  input  logic       RESETB,
  input  logic       LATCHINPUTVALUE,
  output logic       SDO,
  input  logic       SDI,
  input  logic       SCLK
);
  // Written by the bench (testbench/board/icebreaker_bench.hpp), never by this module.
  logic clk  /*verilator public_flat_rw*/;
  logic lock /*verilator public_flat_rw*/;

  assign PLLOUTCORE   = clk;
  assign PLLOUTGLOBAL = clk;
  assign LOCK         = lock;
  assign SDO          = 1'b0;
endmodule
/* verilator lint_on UNUSEDSIGNAL */
/* verilator lint_on UNUSEDPARAM */
