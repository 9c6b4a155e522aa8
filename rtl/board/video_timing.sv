// video_timing: the 640 x 480 at 60 Hz raster on clk_pixel (docs/reference/board.md, "Video
// timing"): h = 0..799 across a line, v = 0..524 down the frame; visible (de_o) when h < 640 and
// v < 480; hsync_no low for 656 <= h < 752, vsync_no low for 490 <= v < 492 (both active low).
// Every output is a register: h_o, v_o are the state, and de_o, hsync_no, vsync_no are loaded from
// the next (h, v) on the same edge, so all five describe the same pixel clock. After reset
// (synchronous, active low) h = v = 0, the first visible pixel.

module video_timing (
  input  logic       clk_i,     // clk_pixel
  input  logic       rst_ni,    // active-low synchronous reset
  output logic [9:0] h_o,       // pixel in the line, 0..799
  output logic [9:0] v_o,       // line in the frame, 0..524
  output logic       de_o,      // visible: h_o < 640 and v_o < 480
  output logic       hsync_no,  // low for 656 <= h_o < 752
  output logic       vsync_no   // low for 490 <= v_o < 492
);
  localparam logic [9:0] HVisible   = 10'd640;
  localparam logic [9:0] HSyncStart = 10'd656;  // after the 16-pixel front porch
  localparam logic [9:0] HSyncEnd   = 10'd752;  // a 96-pixel pulse, then a 48-pixel back porch
  localparam logic [9:0] HLast      = 10'd799;
  localparam logic [9:0] VVisible   = 10'd480;
  localparam logic [9:0] VSyncStart = 10'd490;  // after the 10-line front porch
  localparam logic [9:0] VSyncEnd   = 10'd492;  // a 2-line pulse, then a 33-line back porch
  localparam logic [9:0] VLast      = 10'd524;

  logic [9:0] h_q, v_q, h_d, v_d;
  logic       de_q, hsync_nq, vsync_nq;

  always_comb begin
    h_d = (h_q == HLast) ? '0 : h_q + 10'd1;
    v_d = v_q;
    if (h_q == HLast) v_d = (v_q == VLast) ? '0 : v_q + 10'd1;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      h_q      <= '0;
      v_q      <= '0;
      de_q     <= 1'b1;
      hsync_nq <= 1'b1;
      vsync_nq <= 1'b1;
    end else begin
      h_q      <= h_d;
      v_q      <= v_d;
      de_q     <= h_d < HVisible && v_d < VVisible;
      hsync_nq <= !(h_d >= HSyncStart && h_d < HSyncEnd);
      vsync_nq <= !(v_d >= VSyncStart && v_d < VSyncEnd);
    end
  end

  assign h_o      = h_q;
  assign v_o      = v_q;
  assign de_o     = de_q;
  assign hsync_no = hsync_nq;
  assign vsync_no = vsync_nq;
endmodule
