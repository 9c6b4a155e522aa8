// scanline_buffer_formal: proves rtl/scanline_buffer.sv (MaxWidth 4, 2-bit depth and id, full mode)
// holds valid and the whole pixel beat until ready, and emits every pixel of every marked line
// once, in raster order: each end-of-line marker taken owes width pixels, each pixel taken pays
// one, and the pixels owed are the reader's (the rest of its line, plus the beat on the output);
// every beat carries the next position expected (x = 0..width-1, then the next line, y wrapping at
// height) and pixel_last_o exactly on the frame's last pixel. Fragments are never refused; a marker
// waits only while the reader is busy or a fragment is in the write side's read step. Frame settings (width 1..MaxWidth, height >= 1, full mode)
// are constant; fragments are anywhere in the line, any depth, polygon and shade, either tie rule;
// the shades themselves (the depth test) are the unit bench's business.
`include "formal_stream.svh"

module scanline_buffer_formal #(
  localparam int unsigned MaxWidth   = 4,
  localparam int unsigned DepthBits  = 2,
  localparam int unsigned PolyIdBits = 2,
  localparam int unsigned LineBits   = watkins_pkg::LineBits
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  input  logic [LineBits-1:0]   width_i,
  input  logic [LineBits-1:0]   height_i,
  input  watkins_pkg::rgb_t    background_i,
  input  logic [LineBits-1:0]   frag_x_i,
  input  logic                 tie_submission_i,
  input  logic [DepthBits-1:0] frag_depth_i,
  input  logic [PolyIdBits-1:0] frag_poly_i,
  input  watkins_pkg::rgb_t    frag_rgb_i,
  input  logic                 frag_eol_i,
  input  logic                 frag_valid_i,
  input  logic                 pixel_ready_i
);
  logic              sparse_i;
  logic              frag_ready_o, pixel_covered_o, pixel_last_o, pixel_valid_o;
  watkins_pkg::rgb_t pixel_rgb_o;
  logic [LineBits-1:0]     pixel_x_o, pixel_y_o;
  assign sparse_i = 1'b0;
  scanline_buffer #(.MaxWidth(MaxWidth), .DepthBits(DepthBits), .PolyIdBits(PolyIdBits)) u_dut (.*);

  `FORMAL_PAST
  `FORMAL_ASSUME_HOLD(in, frag_valid_i, frag_ready_o, {frag_x_i, frag_depth_i, frag_poly_i, frag_rgb_i,
    frag_eol_i})
  `FORMAL_ASSERT_HOLD(out, pixel_valid_o, pixel_ready_i, {pixel_rgb_o, pixel_covered_o, pixel_last_o,
    pixel_x_o, pixel_y_o})

  // Frame settings are constant (immediate assume: it must hold on the clock it speaks of).
  logic [LineBits-1:0] width_q, height_q;
  always_ff @(posedge clk_i) begin
    width_q  <= width_i;
    height_q <= height_i;
  end
  always_comb if (past_q) assume (width_i == width_q && height_i == height_q);

  // The position of the next pixel out, and the pixels owed.
  logic          pix_fire, eol_fire;
  logic [LineBits-1:0] ex_q, ey_q;
  logic [3:0]    owed_q;  // <= MaxWidth + 1
  assign pix_fire = pixel_valid_o && pixel_ready_i;
  assign eol_fire = frag_valid_i && frag_ready_o && frag_eol_i;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      ex_q   <= '0;
      ey_q   <= '0;
      owed_q <= '0;
    end else begin
      owed_q <= owed_q + (eol_fire ? 4'(width_i) : 4'd0) - 4'(pix_fire);
      if (pix_fire) begin
        ex_q <= (ex_q == width_i - 1'b1) ? '0 : ex_q + 1'b1;
        if (ex_q == width_i - 1'b1) ey_q <= (ey_q == height_i - 1'b1) ? '0 : ey_q + 1'b1;
      end
    end
  end

  // The reader's next position: after the beat on the output, if there is one.
  logic [LineBits-1:0] nx, ny;
  always_comb begin
    nx = ex_q;
    ny = ey_q;
    if (pixel_valid_o) begin
      nx = (ex_q == width_i - 1'b1) ? '0 : ex_q + 1'b1;
      if (ex_q == width_i - 1'b1) ny = (ey_q == height_i - 1'b1) ? '0 : ey_q + 1'b1;
    end
  end

  (* hierconn *) logic          \u_dut.rd_busy_q ;
  (* hierconn *) logic          \u_dut.a_valid_q ;
  (* hierconn *) logic [LineBits-1:0] \u_dut.rx_q ;
  (* hierconn *) logic [LineBits-1:0] \u_dut.rline_q ;
  (* hierconn *) logic          \u_dut.rx_end_q ;
  (* hierconn *) logic          \u_dut.last_line_q ;

  always_comb begin
    assume (width_i >= LineBits'(1) && width_i <= LineBits'(MaxWidth)
            && height_i >= LineBits'(1));
    if (frag_valid_i && !frag_eol_i) assume (frag_x_i < width_i);
    if (rst_ni) begin
      // Every pixel of every marked line, once, in raster order, and the frame's last flagged.
      if (pixel_valid_o)
        assert (pixel_x_o == ex_q && pixel_y_o == ey_q
                && pixel_last_o == (ex_q == width_i - 1'b1 && ey_q == height_i - 1'b1));
      assert (32'(owed_q) == (\u_dut.rd_busy_q ? 32'(width_i - \u_dut.rx_q ) : 0)
                             + 32'(pixel_valid_o));
      assert (owed_q <= 4'(MaxWidth + 1));
      // A fragment is always taken; a marker waits only while the reader owes the previous line,
      // or for one clock behind a fragment in the write side's read step.
      assert (frag_ready_o || (frag_eol_i && (\u_dut.rd_busy_q || \u_dut.a_valid_q )));
      // Induction invariants: the reader is at the next position (at x = 0 between lines) and
      // the position is inside the frame.
      assert (\u_dut.rline_q == ny && ey_q < height_i && ex_q < width_i);
      if (\u_dut.rd_busy_q ) assert (\u_dut.rx_q == nx);
      else assert (nx == '0 && \u_dut.rx_q == '0);  // x = 0 is set as a line ends, not by the marker
      // The reader's registered decisions: the line's last pixel and the frame's last line.
      if (\u_dut.rd_busy_q ) assert (\u_dut.rx_end_q == (\u_dut.rx_q == width_i - 1'b1));
      assert (\u_dut.last_line_q == (\u_dut.rline_q == height_i - 1'b1));
    end
  end
endmodule
