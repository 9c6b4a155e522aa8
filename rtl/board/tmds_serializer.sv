// tmds_serializer: one TMDS lane's 10:1 serializer, two bits per clk_tmds through an ODDRX1F.
// clk_tmds is 5 x clk_pixel from the same VCO with rising edges aligned (docs/reference/board.md,
// simulation time base: a pixel clock edge every 50 ticks, a clk_tmds edge every 10). A toggle in
// the pixel domain flips on every pixel clock; the tmds domain loads symbol_i into a 10-bit shift
// register on the first clk_tmds edge that sees the toggle changed (10 ticks after the pixel
// edge), then shifts two bits out per clk_tmds: D0 = bit 0, D1 = bit 1, so bit 0 of the symbol is
// first on the wire. Latency: a symbol registered on symbol_i by pixel edge m (tick 50 m) is in
// the shift register from tick 50 m + 10 and on the pad from tick 50 m + 20 (the ODDRX1F's
// capture edge): bit j for ticks [50 m + 20 + 5 j, 50 m + 25 + 5 j). Every path into the pad is
// registered (toggle, shift register, the ODDRX1F's own flops).
// The clock lane is this module fed the constant 10'b0000011111: high for bits 0..4, so its
// rising edge is the first bit of every data lane's symbol, as DVI requires.

module tmds_serializer (
  input  logic       clk_pixel_i,
  input  logic       clk_tmds_i,   // 5 x clk_pixel_i, same VCO, rising edges aligned
  input  logic       rst_ni,       // active-low, synchronous to clk_pixel_i
  input  logic [9:0] symbol_i,     // clk_pixel_i domain: a register's output
  output logic       pad_o         // to the pin: the ODDRX1F's Q
);
  // ---------------------------------------------------------------- pixel domain
  logic pixel_tgl_q;  // flips on every pixel clock out of reset
  always_ff @(posedge clk_pixel_i) begin
    if (!rst_ni) pixel_tgl_q <= 1'b0;
    else         pixel_tgl_q <= !pixel_tgl_q;
  end

  // ---------------------------------------------------------------- tmds domain
  // TMDS word load (clk_pixel -> clk_tmds): related clocks from one VCO, clk_tmds = 5 x
  // clk_pixel, so pixel_tgl_q, symbol_i and rst_ni reach these flops through synchronous paths
  // nextpnr times (launched on a pixel edge, taken one clk_tmds period later), not an asynchronous
  // crossing: no synchronizer. On the clk_tmds edge that coincides with a pixel edge the tmds
  // flops take the values from before it, so the load is always the edge 10 ticks after.
  logic       seen_tgl_q;  // pixel_tgl_q as of the last clk_tmds edge
  logic       load;
  logic [9:0] shift_q;
  assign load = pixel_tgl_q != seen_tgl_q;
  always_ff @(posedge clk_tmds_i) begin
    if (!rst_ni) begin
      seen_tgl_q <= 1'b0;
      shift_q    <= '0;
    end else begin
      seen_tgl_q <= pixel_tgl_q;
      shift_q    <= load ? symbol_i : {2'b00, shift_q[9:2]};
    end
  end

  // The bit pair for the next clk_tmds period; public so a Verilated bench can read the lane two
  // bits per clk_tmds without sampling the pad on both edges.
  logic d0 /*verilator public_flat_rd*/;
  logic d1 /*verilator public_flat_rd*/;
  assign d0 = shift_q[0];
  assign d1 = shift_q[1];

  ODDRX1F u_oddr (
    .D0  (d0),
    .D1  (d1),
    .SCLK(clk_tmds_i),
    .RST (1'b0),
    .Q   (pad_o)
  );
endmodule
