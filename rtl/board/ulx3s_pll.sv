// ulx3s_pll: the board's three clocks from the 25 MHz oscillator, one EHXPLLL, one VCO
// (docs/reference/board.md, "Clocks"). No logic: the PLL's outputs are the clocks; locked_o is
// the PLL's LOCK (asynchronous to every domain: each reset synchronizer samples it).
//   phase detector = 25 MHz / CLKI_DIV 5 = 5 MHz (the ECP5 needs at least 3.125 MHz)
//   feedback from CLKOS3: 5 MHz = VCO / (CLKOS3_DIV 6 * CLKFB_DIV 21) -> VCO = 5 * 126 = 630 MHz
//   clk_tmds  = CLKOP  = 630 / 5  = 126 MHz   (5 x the pixel clock: 10 bits on ODDRX1F)
//   clk_pixel = CLKOS  = 630 / 25 = 25.2 MHz  (640 x 480 at 60 Hz: 800 x 525 x 60)
//   clk_pipe  = CLKOS2 = 630 / 8  = 78.75 MHz (25/8 of the pixel clock: 2,500 per video line)
//   CLKOS3    = 630 / 6  = 105 MHz  (feedback only)
// Every output has the same coarse phase (CPHASE 2 VCO cycles, as ecppll writes a 0-degree
// output), so the rising edges of all three clocks coincide every 8 pixel clocks.

module ulx3s_pll (
  input  logic clk_25mhz_i,
  output logic clk_tmds_o,
  output logic clk_pixel_o,
  output logic clk_pipe_o,
  output logic locked_o
);
  logic clk_fb;

  (* FREQUENCY_PIN_CLKI="25" *)
  (* FREQUENCY_PIN_CLKOP="126" *)
  (* FREQUENCY_PIN_CLKOS="25.2" *)
  (* FREQUENCY_PIN_CLKOS2="78.75" *)
  (* FREQUENCY_PIN_CLKOS3="105" *)
  (* ICP_CURRENT="12" *) (* LPF_RESISTOR="8" *) (* MFG_ENABLE_FILTEROPAMP="1" *) (* MFG_GMCREF_SEL="2" *)
  EHXPLLL #(
    .PLLRST_ENA      ("DISABLED"),
    .INTFB_WAKE      ("DISABLED"),
    .STDBY_ENABLE    ("DISABLED"),
    .DPHASE_SOURCE   ("DISABLED"),
    .OUTDIVIDER_MUXA ("DIVA"),
    .OUTDIVIDER_MUXB ("DIVB"),
    .OUTDIVIDER_MUXC ("DIVC"),
    .OUTDIVIDER_MUXD ("DIVD"),
    .CLKI_DIV        (5),
    .CLKOP_ENABLE    ("ENABLED"),
    .CLKOP_DIV       (5),
    .CLKOP_CPHASE    (2),
    .CLKOP_FPHASE    (0),
    .CLKOS_ENABLE    ("ENABLED"),
    .CLKOS_DIV       (25),
    .CLKOS_CPHASE    (2),
    .CLKOS_FPHASE    (0),
    .CLKOS2_ENABLE   ("ENABLED"),
    .CLKOS2_DIV      (8),
    .CLKOS2_CPHASE   (2),
    .CLKOS2_FPHASE   (0),
    .CLKOS3_ENABLE   ("ENABLED"),
    .CLKOS3_DIV      (6),
    .CLKOS3_CPHASE   (2),
    .CLKOS3_FPHASE   (0),
    .FEEDBK_PATH     ("CLKOS3"),
    .CLKFB_DIV       (21)
  ) u_ehxplll (  // the unused outputs left open
    /* verilator lint_off PINCONNECTEMPTY */
    .INTLOCK     (),
    .REFCLK      (),
    .CLKINTFB    (),
    /* verilator lint_on PINCONNECTEMPTY */
    .RST         (1'b0),
    .STDBY       (1'b0),
    .CLKI        (clk_25mhz_i),
    .CLKOP       (clk_tmds_o),
    .CLKOS       (clk_pixel_o),
    .CLKOS2      (clk_pipe_o),
    .CLKOS3      (clk_fb),
    .CLKFB       (clk_fb),
    .PHASESEL0   (1'b0),
    .PHASESEL1   (1'b0),
    .PHASEDIR    (1'b1),
    .PHASESTEP   (1'b1),
    .PHASELOADREG(1'b1),
    .PLLWAKESYNC (1'b0),
    .ENCLKOP     (1'b0),
    .ENCLKOS     (1'b0),
    .ENCLKOS2    (1'b0),
    .ENCLKOS3    (1'b0),
    .LOCK        (locked_o)
  );
endmodule
