// scanline_buffer: per-pixel visibility of one scan line (model/scanline_buffer.cpp) and the
// raster-order pixel stream. Two line buffers (ping-pong): fragments of line y are depth-tested
// into one (kept when the pixel is empty or strictly nearer; first arrival wins ties) while the
// other streams line y-1 out, pixel x = 0..width-1, clearing each pixel as it is read. The
// end-of-line marker swaps the buffers once the reader has taken the previous line's last pixel.
// Write side: one fragment per clock, read-modify-write with asynchronous reads, so back-to-back
// fragments to the same x see each other without forwarding; frag_ready_o is combinational
// (low only for a marker waiting on the reader). Read side: pixel output registered, latency 1.
module scanline_buffer #(
  parameter int unsigned MaxWidth = 1024
) (
  input  logic                              clk_i,
  input  logic                              rst_ni,
  input  logic [watkins_pkg::LineBits-1:0]  width_i,        // 1..MaxWidth, stable per frame
  input  logic [watkins_pkg::LineBits-1:0]  height_i,       // lines per frame, for pixel_last_o
  input  logic [23:0]                       background_i,   // {R,G,B} of uncovered pixels
  input  logic [watkins_pkg::LineBits-1:0]  frag_x_i,       // < width_i
  input  logic [watkins_pkg::DepthBits-1:0] frag_depth_i,   // smaller is nearer
  input  logic [23:0]                       frag_rgb_i,
  input  logic                              frag_eol_i,     // end-of-line marker: the line is complete
  input  logic                              frag_valid_i,
  output logic                              frag_ready_o,
  output logic [23:0]                       pixel_rgb_o,
  output logic                              pixel_covered_o,
  output logic                              pixel_last_o,   // last pixel of the frame
  output logic                              pixel_valid_o,
  input  logic                              pixel_ready_i
);
  localparam int unsigned LB = watkins_pkg::LineBits;
  localparam int unsigned AB = $clog2(2 * MaxWidth);

  // Bank b holds pixel x at address b * MaxWidth + x.
  logic [watkins_pkg::DepthBits-1:0] depth_q [2 * MaxWidth];
  logic [23:0]                       rgb_q   [2 * MaxWidth];
  logic [2 * MaxWidth - 1:0]         written_q;  // flops: cleared by reset and by reading

  logic          wsel_q;           // bank being written; the reader uses the other one
  logic          rd_busy_q;
  logic [LB-1:0] rx_q, rline_q;

  // x < width_i <= MaxWidth, so its high bits are zero.
  /* verilator lint_off UNUSEDSIGNAL */
  function automatic logic [AB-1:0] addr(logic bank, logic [LB-1:0] x);
    addr = bank ? AB'(MaxWidth) + AB'(x) : AB'(x);
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */

  // ------------------------------------------------------------ write side
  logic          frag_fire, wins, rd_load, rd_last, eol_ok;
  logic [AB-1:0] wa, ra;

  assign wa        = addr(wsel_q, frag_x_i);
  assign ra        = addr(!wsel_q, rx_q);
  assign rd_load   = rd_busy_q && (!pixel_valid_o || pixel_ready_i);
  assign rd_last   = rx_q == width_i - 1'b1;
  // The marker may swap in the cycle the reader takes its last pixel (it reads the old bank).
  assign eol_ok       = !rd_busy_q || (rd_load && rd_last);
  assign frag_ready_o = !frag_eol_i || eol_ok;
  assign frag_fire    = frag_valid_i && frag_ready_o;
  assign wins         = !written_q[wa] || (frag_depth_i < depth_q[wa]);

  always_ff @(posedge clk_i) begin
    if (frag_fire && !frag_eol_i && wins) begin
      depth_q[wa] <= frag_depth_i;
      rgb_q[wa]   <= frag_rgb_i;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      written_q     <= '0;
      wsel_q        <= 1'b0;
      rd_busy_q     <= 1'b0;
      rx_q          <= '0;
      rline_q       <= '0;
      pixel_valid_o <= 1'b0;
    end else begin
      // Reader and writer always use different banks, so their updates never collide.
      if (frag_fire && !frag_eol_i && wins) written_q[wa] <= 1'b1;
      if (rd_load) begin
        written_q[ra] <= 1'b0;
        rx_q <= rx_q + 1'b1;
        if (rd_last) begin
          rd_busy_q <= 1'b0;
          rline_q   <= (rline_q == height_i - 1'b1) ? '0 : rline_q + 1'b1;
        end
      end
      if (!pixel_valid_o || pixel_ready_i) pixel_valid_o <= rd_load;
      if (frag_fire && frag_eol_i) begin
        wsel_q    <= !wsel_q;
        rd_busy_q <= 1'b1;
        rx_q      <= '0;
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (rd_load) begin
      pixel_rgb_o     <= written_q[ra] ? rgb_q[ra] : background_i;
      pixel_covered_o <= written_q[ra];
      pixel_last_o    <= rd_last && (rline_q == height_i - 1'b1);
    end
  end

`ifndef SYNTHESIS
  a_in_hold: assert property (@(posedge clk_i) disable iff (!rst_ni)
    frag_valid_i && !frag_ready_o |=> frag_valid_i && $stable({frag_x_i, frag_depth_i, frag_rgb_i, frag_eol_i}));
  a_out_hold: assert property (@(posedge clk_i) disable iff (!rst_ni)
    pixel_valid_o && !pixel_ready_i |=> pixel_valid_o && $stable({pixel_rgb_o, pixel_covered_o, pixel_last_o}));
  a_x_in_line: assert property (@(posedge clk_i) disable iff (!rst_ni)
    frag_valid_i && !frag_eol_i |-> frag_x_i < width_i);
  c_same_x_back_to_back: cover property (@(posedge clk_i) disable iff (!rst_ni)
    frag_fire && !frag_eol_i && $past(frag_fire && !frag_eol_i) && frag_x_i == $past(frag_x_i));
  c_eol_waits: cover property (@(posedge clk_i) disable iff (!rst_ni) frag_valid_i && !frag_ready_o);
`endif
endmodule
