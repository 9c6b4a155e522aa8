// scanline_buffer: per-pixel visibility of one scan line (model/twins/scanline_buffer.cpp) and the
// raster-order pixel stream. Two line buffers (ping-pong): fragments of line y are depth-tested
// into one (kept when the pixel is empty or strictly nearer; first arrival wins ties) while the
// other streams line y-1 out, pixel x = 0..width-1, clearing each pixel as it is read. The
// end-of-line marker swaps the buffers once the reader has taken the previous line's last pixel.
// Write side: one fragment per clock, read-modify-write with asynchronous reads, so back-to-back
// fragments to the same x see each other without forwarding; frag_ready_o is combinational
// (low only for a marker waiting on the reader). Read side: pixel output registered, latency 1.
// Sparse mode (sparse_i, stable per frame): the reader emits only the covered pixels of a line,
// in raster order, one per clock: a find-next-written search (priority encoder over the read
// bank's written bits at and above the current x) picks the next one, and the line ends with its
// last covered pixel; a line with no covered pixel costs one cycle and emits nothing. The frame's
// last beat (pixel_last_o) is the last covered pixel of the last line; when the last line has no
// covered pixel (in particular when the frame covers none), a terminating beat with
// pixel_covered_o = 0, background rgb, at (width-1, height-1) carries pixel_last_o instead.
// pixel_x_o / pixel_y_o give every beat's position in both modes.
`include "watkins_assert.svh"

module scanline_buffer #(
  parameter int unsigned MaxWidth  = watkins_pkg::DefaultMaxWidth,  // line-buffer depth in pixels
  parameter int unsigned DepthBits = watkins_pkg::DepthBits         // depth word (the configuration's)
) (
  input  logic                              clk_i,
  input  logic                              rst_ni,
  input  logic [watkins_pkg::LineBits-1:0]  width_i,        // 1..MaxWidth, stable per frame
  input  logic [watkins_pkg::LineBits-1:0]  height_i,       // lines per frame, for pixel_last_o
  input  watkins_pkg::rgb_t                 background_i,   // shade of uncovered pixels
  input  logic                              sparse_i,       // covered pixels only, stable per frame
  input  logic [watkins_pkg::LineBits-1:0]  frag_x_i,       // < width_i
  input  logic [DepthBits-1:0] frag_depth_i,   // smaller is nearer
  input  watkins_pkg::rgb_t                 frag_rgb_i,
  input  logic                              frag_eol_i,     // end-of-line marker: the line is complete
  input  logic                              frag_valid_i,
  output logic                              frag_ready_o,
  output watkins_pkg::rgb_t                 pixel_rgb_o,
  output logic                              pixel_covered_o,
  output logic [watkins_pkg::LineBits-1:0]  pixel_x_o,
  output logic [watkins_pkg::LineBits-1:0]  pixel_y_o,
  output logic                              pixel_last_o,   // last pixel of the frame
  output logic                              pixel_valid_o,
  input  logic                              pixel_ready_i
);
  localparam int unsigned LB       = watkins_pkg::LineBits;
  localparam int unsigned AddrBits = $clog2(2 * MaxWidth);  // both banks

  // Bank b holds pixel x at address b * MaxWidth + x. Shades as plain vectors, not rgb_t: yosys
  // 0.23 mishandles arrays of structs.
  logic [DepthBits-1:0] depth_q [2 * MaxWidth];
  logic [watkins_pkg::RgbBits-1:0]   rgb_q   [2 * MaxWidth];
  logic [2 * MaxWidth - 1:0]         written_q;  // flops: cleared by reset and by reading

  logic          wsel_q;           // bank being written; the reader uses the other one
  logic          rd_busy_q;
  logic [LB-1:0] rx_q, rline_q;

  // x < width_i <= MaxWidth, so its high bits are zero.
  /* verilator lint_off UNUSEDSIGNAL */
  function automatic logic [AddrBits-1:0] addr(logic bank, logic [LB-1:0] x);
    addr = bank ? AddrBits'(MaxWidth) + AddrBits'(x) : AddrBits'(x);
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */

  // ------------------------------------------------------------ read-side search (sparse)
  // The read bank's written bits at or above rx_q; the lowest one is the next covered pixel.
  logic [MaxWidth-1:0] rbits, cand, rest, lowbit;
  logic [LB-1:0]       nx;
  logic                found, more;

  assign rbits  = wsel_q ? written_q[MaxWidth-1:0] : written_q[2*MaxWidth-1:MaxWidth];
  assign cand   = rbits & ({MaxWidth{1'b1}} << rx_q);
  assign rest   = cand & (cand - 1'b1);   // cand without its lowest bit
  assign lowbit = cand ^ rest;            // one-hot: the next written x
  assign found  = |cand;
  assign more   = |rest;

  // One-hot to binary: bit b of nx is set when lowbit hits an x whose bit b is set (a constant
  // mask per bit: LB wide AND-reduce-ORs instead of a MaxWidth-step loop).
  for (genvar b = 0; b < LB; b++) begin : g_enc
    logic [MaxWidth-1:0] xmask;
    for (genvar i = 0; i < MaxWidth; i++) begin : g_bit
      assign xmask[i] = ((i >> b) & 1) != 0;
    end
    assign nx[b] = |(lowbit & xmask);
  end

  // ------------------------------------------------------------ write side
  logic          frag_fire, wins, rd_load, rd_step, rd_emit, rd_last, rd_lastline, eol_ok;
  logic [LB-1:0]       rd_x;
  logic [AddrBits-1:0] wa, ra;

  assign rd_lastline = rline_q == height_i - 1'b1;
  // Full mode: every x. Sparse: the next covered x; an empty line emits nothing unless it is the
  // frame's last (then the terminating beat at width-1).
  assign rd_x      = sparse_i ? (found ? nx : width_i - 1'b1) : rx_q;
  assign rd_emit   = !sparse_i || found || rd_lastline;
  assign wa        = addr(wsel_q, frag_x_i);
  assign ra        = addr(!wsel_q, rd_x);
  assign rd_step   = rd_busy_q && (!rd_emit || !pixel_valid_o || pixel_ready_i);
  assign rd_load   = rd_step && rd_emit;
  assign rd_last   = sparse_i ? !more : (rx_q == width_i - 1'b1);
  // The marker may swap in the cycle the reader takes its last pixel (it reads the old bank).
  assign eol_ok       = !rd_busy_q || (rd_step && rd_last);
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
      if (rd_load) written_q[ra] <= 1'b0;
      if (rd_step) begin
        rx_q <= rd_x + 1'b1;
        if (rd_last) begin
          rd_busy_q <= 1'b0;
          rline_q   <= rd_lastline ? '0 : rline_q + 1'b1;
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
      pixel_x_o       <= rd_x;
      pixel_y_o       <= rline_q;
      pixel_last_o    <= rd_last && rd_lastline;
    end
  end

  `WATKINS_ASSERT_HOLD(a_in_hold, frag_valid_i, frag_ready_o, {frag_x_i, frag_depth_i, frag_rgb_i,
    frag_eol_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, pixel_valid_o, pixel_ready_i, {pixel_rgb_o, pixel_covered_o,
    pixel_last_o, pixel_x_o, pixel_y_o})
  `WATKINS_ASSERT(a_sparse_covered, rd_load && sparse_i && !(rd_last && rd_lastline) |-> found)
  `WATKINS_ASSERT(a_sparse_one_hot, $onehot0(lowbit))
  `WATKINS_COVER(c_sparse_empty_line, rd_step && !rd_emit)
  `WATKINS_ASSERT(a_x_in_line, frag_valid_i && !frag_eol_i |-> frag_x_i < width_i)
  `WATKINS_COVER(c_same_x_back_to_back,
    frag_fire && !frag_eol_i && $past(frag_fire && !frag_eol_i) && frag_x_i == $past(frag_x_i))
  `WATKINS_COVER(c_eol_waits, frag_valid_i && !frag_ready_o)
endmodule
