// EHXPLLL: simulation stand-in for the Lattice ECP5 PLL (the synthesis flow uses the device's
// own). It computes nothing: the Verilated bench drives the four outputs and LOCK through the
// variables below (public: written from C++ through the model's root), on the board's time
// base (docs/reference/board.md: one tick = 1/1260 us; CLKOP toggles every 5 ticks, CLKOS every
// 25, CLKOS2 every 8, all rising at tick 0). Every parameter of the device cell is accepted and
// ignored.

/* verilator lint_off UNUSEDPARAM */
/* verilator lint_off UNUSEDSIGNAL */
module EHXPLLL #(
  parameter int    CLKI_DIV         = 1,
  parameter int    CLKFB_DIV        = 1,
  parameter int    CLKOP_DIV        = 8,
  parameter int    CLKOS_DIV        = 8,
  parameter int    CLKOS2_DIV       = 8,
  parameter int    CLKOS3_DIV       = 8,
  parameter string CLKOP_ENABLE     = "ENABLED",
  parameter string CLKOS_ENABLE     = "DISABLED",
  parameter string CLKOS2_ENABLE    = "DISABLED",
  parameter string CLKOS3_ENABLE    = "DISABLED",
  parameter int    CLKOP_CPHASE     = 0,
  parameter int    CLKOS_CPHASE     = 0,
  parameter int    CLKOS2_CPHASE    = 0,
  parameter int    CLKOS3_CPHASE    = 0,
  parameter int    CLKOP_FPHASE     = 0,
  parameter int    CLKOS_FPHASE     = 0,
  parameter int    CLKOS2_FPHASE    = 0,
  parameter int    CLKOS3_FPHASE    = 0,
  parameter string FEEDBK_PATH      = "CLKOP",
  parameter string CLKOP_TRIM_POL   = "RISING",
  parameter int    CLKOP_TRIM_DELAY = 0,
  parameter string CLKOS_TRIM_POL   = "RISING",
  parameter int    CLKOS_TRIM_DELAY = 0,
  parameter string OUTDIVIDER_MUXA  = "DIVA",
  parameter string OUTDIVIDER_MUXB  = "DIVB",
  parameter string OUTDIVIDER_MUXC  = "DIVC",
  parameter string OUTDIVIDER_MUXD  = "DIVD",
  parameter int    PLL_LOCK_MODE    = 0,
  parameter int    PLL_LOCK_DELAY   = 200,
  parameter string STDBY_ENABLE     = "DISABLED",
  parameter string REFIN_RESET      = "DISABLED",
  parameter string SYNC_ENABLE      = "DISABLED",
  parameter string INT_LOCK_STICKY  = "ENABLED",
  parameter string DPHASE_SOURCE    = "DISABLED",
  parameter string PLLRST_ENA       = "DISABLED",
  parameter string INTFB_WAKE       = "DISABLED"
) (
  input  logic CLKI, CLKFB,
  input  logic PHASESEL1, PHASESEL0, PHASEDIR, PHASESTEP, PHASELOADREG,
  input  logic STDBY, PLLWAKESYNC,
  input  logic RST, ENCLKOP, ENCLKOS, ENCLKOS2, ENCLKOS3,
  output logic CLKOP, CLKOS, CLKOS2, CLKOS3,
  output logic LOCK, INTLOCK,
  output logic REFCLK, CLKINTFB
);
  // Written by the bench (testbench/board/board_bench.hpp), never by this module.
  logic clkop  /*verilator public_flat_rw*/;
  logic clkos  /*verilator public_flat_rw*/;
  logic clkos2 /*verilator public_flat_rw*/;
  logic lock   /*verilator public_flat_rw*/;

  assign CLKOP    = clkop;
  assign CLKOS    = clkos;
  assign CLKOS2   = clkos2;
  assign CLKOS3   = 1'b0;  // the feedback path: nothing uses it in simulation
  assign LOCK     = lock;
  assign INTLOCK  = lock;
  assign REFCLK   = CLKI;
  assign CLKINTFB = 1'b0;
endmodule
/* verilator lint_on UNUSEDSIGNAL */
/* verilator lint_on UNUSEDPARAM */
