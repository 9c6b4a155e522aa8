// compact_scanline_buffer: scanline_buffer's per-pixel visibility and raster-order pixel stream
// with every per-pixel store in block RAM, for small parts. Drop-in for rtl/scanline_buffer.sv
// (the same ports, parameters and streams, plus lane 1's ports; values twin:
// model/twins/scanline_buffer.hpp; cycle twin: model/twins/compact_scanline_buffer_timing.hpp).
// Full-frame output only: sparse_i must be 0 (asserted in simulation).
// Two line banks (ping-pong): fragments of line y are depth-tested into the write bank (kept when
// the pixel is unwritten or strictly nearer; at equal depth tie_submission_i: 0 keeps the first
// arrival, 1 the smaller polygon id) while the read bank streams line y-1 out, x = 0..width-1;
// the end-of-line marker swaps the banks once the reader has taken the previous line's last
// pixel (in that clock at the earliest).
// Lanes (1 or 2): fragments per input beat. Lane 0 is frag_x_i, frag_depth_i, frag_rgb_i; at
// Lanes = 2 frag_pair_i says lane 1 holds the fragment at frag_x_i + 1 of the same polygon
// (frag_depth1_i, frag_rgb1_i), after lane 0 in stream order. The two are different pixels, so
// a beat is the same as its fragments one after the other. At Lanes = 1 lane 1's ports are unused.
// Storage: every RAM is Lanes ways by x, way p holding the x with x mod Lanes = p at x / Lanes
// (at Lanes = 2 the even x and the odd x), so a beat's fragments fall in different ways and each
// way tests and writes one fragment per clock on its own ports. Per bank and way a depth RAM of
// ceil(MaxWidth / Lanes) words {written, polygon id, depth}; per way one shade RAM of
// 2 * 2^WayBits words {bank, x / Lanes}; synchronous reads, one read and one write port each
// (EBR). The write bank's depth RAMs serve the writer (read for the test, written by a winner);
// the read bank's serve the reader (read for the written mark, written to clear it), so the
// written marks are cleared as they are read, through the read bank's otherwise idle write
// ports, with no clear pass and no mark in a flip-flop. The shade RAMs: the writer writes, the
// reader reads. The reader reads one pixel a clock, from the way of its x.
// Timing (cycle twin): after reset the block clears the marks of both banks, one address of every
// way per clock, ceil(MaxWidth / Lanes) clocks with frag_ready_o low; then a beat is taken every
// clock it is offered (the writer never stalls). A marker is taken when the reader is idle, or in
// the clock the reader loads the previous line's last pixel. The reader starts the clock after
// the marker: one clock reads pixel 0 into the RAMs' read registers, then each clock the output
// register can take a pixel (pixel_valid_o low or pixel_ready_i high) loads pixel x into it and
// reads pixel x + 1: a line takes width + 1 clocks at full rate, and its last pixel's load lets
// the next marker in.
// Latency: a fragment is read (accept clock), tested and written (next clock); a pixel is read one
// clock or more before the load that registers it.
// Registered: every pixel output. frag_ready_o is combinational from registers and pixel_ready_i
// only (low for a marker waiting on the reader, and during the clear after reset).
`include "watkins_assert.svh"

module compact_scanline_buffer #(
  parameter int unsigned MaxWidth   = watkins_pkg::DefaultMaxWidth,  // line-bank depth in pixels
  parameter int unsigned DepthBits  = watkins_pkg::DepthBits,   // depth word (the configuration's)
  parameter int unsigned PolyIdBits = watkins_pkg::PolyIdBits,  // polygon id (the configuration's)
  parameter int unsigned Lanes      = 1   // fragments per beat: 1 or 2 (then MaxWidth >= 2)
) (
  input  logic                              clk_i,
  input  logic                              rst_ni,
  input  logic [watkins_pkg::LineBits-1:0]  width_i,           // 1..MaxWidth, stable per frame
  input  logic [watkins_pkg::LineBits-1:0]  height_i,          // lines per frame, for
                                                               // pixel_last_o
  input  watkins_pkg::rgb_t                 background_i,      // shade of uncovered pixels
  /* verilator lint_off UNUSEDSIGNAL */
  input  logic                              sparse_i,          // must be 0: full frames only
  /* verilator lint_on UNUSEDSIGNAL */
  input  logic                              tie_submission_i,  // equal depth: smaller id wins;
                                                               // stable per frame
  input  logic [watkins_pkg::LineBits-1:0]  frag_x_i,          // lane 0's x, < width_i
  input  logic [DepthBits-1:0]              frag_depth_i,      // lane 0's; smaller is nearer
  input  logic [PolyIdBits-1:0]             frag_poly_i,       // polygon id: submission order;
                                                               // both lanes'
  input  watkins_pkg::rgb_t                 frag_rgb_i,        // lane 0's
  /* verilator lint_off UNUSEDSIGNAL */
  input  logic                              frag_pair_i,       // lane 1 holds a fragment at
                                                               // frag_x_i + 1; 0 on a marker
  input  logic [DepthBits-1:0]              frag_depth1_i,     // lane 1's
  input  watkins_pkg::rgb_t                 frag_rgb1_i,       // lane 1's
  /* verilator lint_on UNUSEDSIGNAL */
  input  logic                              frag_eol_i,        // end-of-line marker: the line is
                                                               // complete
  input  logic                              frag_valid_i,
  output logic                              frag_ready_o,
  output watkins_pkg::rgb_t                 pixel_rgb_o,
  output logic                              pixel_covered_o,
  output logic [watkins_pkg::LineBits-1:0]  pixel_x_o,
  output logic [watkins_pkg::LineBits-1:0]  pixel_y_o,
  output logic                              pixel_last_o,      // last pixel of the frame
  output logic                              pixel_valid_o,
  input  logic                              pixel_ready_i
);
  localparam int unsigned LineBits  = watkins_pkg::LineBits;
  localparam int unsigned RgbBits   = watkins_pkg::RgbBits;
  localparam int unsigned XBits     = (MaxWidth > 1) ? $clog2(MaxWidth) : 1;  // an x in a bank
  localparam int unsigned WayShift  = (Lanes == 2) ? 1 : 0;       // x / Lanes = x >> WayShift
  localparam int unsigned WayWords  = (MaxWidth + Lanes - 1) / Lanes;  // a way's depth
  localparam int unsigned WayBits   = (WayWords > 1) ? $clog2(WayWords) : 1;  // an x / Lanes
  localparam int unsigned KeyBits   = PolyIdBits + DepthBits;  // {polygon id, depth}
  localparam int unsigned WordBits  = 1 + KeyBits;             // {written, polygon id, depth}

  if (Lanes != 1 && Lanes != 2) begin : g_check_lanes
    $error("compact_scanline_buffer: Lanes must be 1 or 2");
  end
  if (Lanes == 2 && MaxWidth < 2) begin : g_check_width
    $error("compact_scanline_buffer: Lanes = 2 needs MaxWidth >= 2");
  end

  // ------------------------------------------------------------ control
  logic                wsel_q;     // bank being written; the reader uses the other one
  logic                clear_q;    // the clear after reset runs (rx_q is its address in a way)
  logic                rd_busy_q;  // a line is being read out
  logic                pf_q;       // pixel rx_q is in the RAMs' read registers
  logic [XBits-1:0]    rx_q;
  logic [LineBits-1:0] rline_q;

  logic frag_take, eol_take, eol_ok;
  logic rd_load, rd_read, rd_last, rd_lastline;
  logic [XBits-1:0] rx_next, rd_addr;
  logic [WayBits-1:0] rd_way_addr;  // rd_addr in its way
  logic [WayBits-1:0] rx_way_addr;  // rx_q in its way: the pixel loaded, or the address cleared
  // rx_q + 1 == width_i, from a flop: set from the reader's next x a clock ahead, so the
  // end-of-line decision (and frag_ready_o through it) has no compare in its clock.
  logic last_q;

  // x < width_i <= MaxWidth: the bank index is its low bits.
  /* verilator lint_off UNUSEDSIGNAL */
  logic [LineBits-1:0] frag_x;
  assign frag_x = frag_x_i;
  /* verilator lint_on UNUSEDSIGNAL */

  // The clear steps x by Lanes (one address of every way a clock), the reader by one pixel.
  if (Lanes == 2) begin : g_rx_step_two
    assign rx_next = rx_q + XBits'({clear_q, !clear_q});
  end else begin : g_rx_step_one
    assign rx_next = rx_q + 1'b1;
  end
  assign rd_last     = last_q;
  assign rd_lastline = rline_q + 1'b1 == height_i;
  // The output register takes a pixel when empty or emptied this clock.
  assign rd_load = pf_q && (!pixel_valid_o || pixel_ready_i);
  // Reads: pixel 0 on the line's first clock, pixel x + 1 with pixel x's load.
  assign rd_read = rd_busy_q && (!pf_q || (rd_load && !rd_last));
  assign rd_addr = pf_q ? rx_next : rx_q;
  assign rd_way_addr = WayBits'(rd_addr >> WayShift);
  assign rx_way_addr = WayBits'(rx_q >> WayShift);

  assign eol_ok       = !clear_q && (!rd_busy_q || (rd_load && rd_last));
  assign frag_ready_o = !clear_q && (!frag_eol_i || eol_ok);
  assign frag_take    = frag_valid_i && !frag_eol_i && !clear_q;
  assign eol_take     = frag_valid_i && frag_eol_i && eol_ok;

  // Nearer, or at equal depth by the tie rule (a strictly smaller id only: equal ids, one
  // polygon's own spans, keep the first arrival, as the model does).
  function automatic logic beats(input logic [KeyBits-1:0] t, input logic [KeyBits-1:0] o,
                                 input logic tie);
    beats = t[DepthBits-1:0] < o[DepthBits-1:0]
         || (tie && t[DepthBits-1:0] == o[DepthBits-1:0]
             && t[KeyBits-1:DepthBits] < o[KeyBits-1:DepthBits]);
  endfunction

  // ------------------------------------------------------------ ways
  // Each way is the whole writer and storage of its x: a beat's fragments are in different ways
  // and one pixel's fragments all in one, so per pixel a way sees them in stream order, one a
  // clock at most, as the single-lane block sees every fragment.
  logic [Lanes-1:0]              way_covered;  // the read bank's mark in each way's read register
  logic [Lanes*RgbBits-1:0]      way_rgb;      // each way's shade read register, way p at p RgbBits
  for (genvar p = 0; p < Lanes; p++) begin : g_way
    localparam logic Odd = p == 1;
    // This way's fragment of the beat: lane 0's when frag_x_i is in this way, else lane 1's.
    logic                take;
    logic [WayBits-1:0]  addr;
    logic [KeyBits-1:0]  key;
    logic [RgbBits-1:0]  rgb;
    logic                rd_here, rx_here;  // rd_addr, rx_q are in this way
    if (Lanes == 1) begin : g_one
      assign take    = frag_take;
      assign addr    = WayBits'(frag_x);
      assign key     = {frag_poly_i, frag_depth_i};
      assign rgb     = frag_rgb_i;
      assign rd_here = 1'b1;
      assign rx_here = 1'b1;
    end else begin : g_two
      logic lane0;  // lane 0's x is in this way
      assign lane0   = frag_x[0] == Odd;
      assign take    = frag_take && (lane0 || frag_pair_i);
      // The odd way's x is x or x + 1 with x even: x / 2 either way; the even way's is x, or
      // x + 1 with x odd: x / 2 + 1.
      assign addr    = WayBits'(frag_x >> 1) + WayBits'(!Odd && frag_x[0]);
      assign key     = {frag_poly_i, lane0 ? frag_depth_i : frag_depth1_i};
      assign rgb     = lane0 ? frag_rgb_i : frag_rgb1_i;
      assign rd_here = rd_addr[0] == Odd;
      assign rx_here = rx_q[0] == Odd;
    end

    // -------------------------------------------------------- writer
    // Accept: the write bank's depth word at the address is read. Test (t_*, the next clock): the
    // word from the RAM's read register -- or the word the fragment tested in the accept clock
    // wrote at the same address, which the read did not see (written on the same edge) -- against
    // the fragment; a winner writes its word and shade at the end of the clock. A marker takes an
    // input clock, so the accept and the test of one fragment see the same write bank (wsel_q).
    logic                t_valid_q, lw_valid_q;
    logic [WayBits-1:0]  t_x_q;
    logic [KeyBits-1:0]  t_key_q, lw_key_q;  // lw: the last clock's winner
    logic [RgbBits-1:0]  t_rgb_q;
    logic                t_fw_q;   // the fragment tested in the accept clock was at the same x
    logic                wins;
    logic [WordBits-1:0] dq0_q, dq1_q;  // each bank's read register
    logic [WordBits-1:0] old_word;

    always_ff @(posedge clk_i) begin
      if (!rst_ni) begin
        t_valid_q  <= 1'b0;
        lw_valid_q <= 1'b0;
      end else begin
        t_valid_q  <= take;
        lw_valid_q <= wins;
      end
      if (take) begin
        t_x_q   <= addr;
        t_key_q <= key;
        t_rgb_q <= rgb;
        t_fw_q  <= t_valid_q && t_x_q == addr;
      end
      lw_key_q <= t_key_q;
    end

    assign old_word = (t_fw_q && lw_valid_q) ? {1'b1, lw_key_q} : (wsel_q ? dq1_q : dq0_q);
    assign wins     = t_valid_q && (!old_word[WordBits-1]
                                    || beats(t_key_q, old_word[KeyBits-1:0], tie_submission_i));

    // -------------------------------------------------------- depth RAMs, one per bank
    // The write bank's ports belong to the writer, the read bank's to the reader (and both to
    // the clear after reset). The reader's write clears the mark of the pixel it loads while its
    // read fetches the next one, so a port never reads and writes one address in a clock.
    // (Written out per bank: two memories, each with its own read register.)
    logic [WordBits-1:0] mem0 [WayWords];
    logic [WordBits-1:0] mem1 [WayWords];
    logic                w0, w1;  // bank 0 / 1 is the write bank (not during the clear)
    logic                re0, re1, we0, we1, rd_re, rd_we;
    logic [WayBits-1:0]  ra0, ra1, wa0, wa1;
    assign w0    = !clear_q && !wsel_q;
    assign w1    = !clear_q && wsel_q;
    assign rd_re = rd_read && rd_here;
    assign rd_we = (rd_load && rx_here) || clear_q;
    assign re0   = w0 ? take : rd_re;
    assign re1   = w1 ? take : rd_re;
    assign ra0   = w0 ? addr : rd_way_addr;
    assign ra1   = w1 ? addr : rd_way_addr;
    assign we0   = w0 ? wins : rd_we;
    assign we1   = w1 ? wins : rd_we;
    assign wa0   = w0 ? t_x_q : rx_way_addr;
    assign wa1   = w1 ? t_x_q : rx_way_addr;
    // A clear writes the mark 0 (the rest of the word is then never read as a value).
    always_ff @(posedge clk_i) begin
      if (re0) dq0_q <= mem0[ra0];
      if (we0) mem0[wa0] <= {w0, t_key_q};
    end
    always_ff @(posedge clk_i) begin
      if (re1) dq1_q <= mem1[ra1];
      if (we1) mem1[wa1] <= {w1, t_key_q};
    end

    // -------------------------------------------------------- shade RAM
    logic [RgbBits-1:0] rgb_mem [2 << WayBits];  // {bank, x / Lanes}
    logic [RgbBits-1:0] rgb_q;
    always_ff @(posedge clk_i) begin
      if (wins) rgb_mem[{wsel_q, t_x_q}] <= t_rgb_q;
      if (rd_re) rgb_q <= rgb_mem[{!wsel_q, rd_way_addr}];
    end

    assign way_covered[p] = wsel_q ? dq0_q[WordBits-1] : dq1_q[WordBits-1];
    assign way_rgb[p*RgbBits +: RgbBits] = rgb_q;

    `WATKINS_COVER(c_same_x_back_to_back, take && t_valid_q && t_x_q == addr)
    `WATKINS_COVER(c_forwarded, t_valid_q && t_fw_q && lw_valid_q)
  end

  // ------------------------------------------------------------ reader
  // The loaded pixel (rx_q): its mark and shade from the read registers of its way, which the
  // reader read last (no read of that way since: the next read comes with this load).
  logic               covered;
  logic [RgbBits-1:0] loaded_rgb;
  if (Lanes == 1) begin : g_load_one
    assign covered    = way_covered[0];
    assign loaded_rgb = way_rgb;
  end else begin : g_load_two
    assign {covered, loaded_rgb} = rx_q[0] ? {way_covered[1], way_rgb[RgbBits +: RgbBits]}
                                           : {way_covered[0], way_rgb[0 +: RgbBits]};
  end
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      wsel_q        <= 1'b0;
      clear_q       <= 1'b1;
      rd_busy_q     <= 1'b0;
      pf_q          <= 1'b0;
      rx_q          <= '0;
      rline_q       <= '0;
      pixel_valid_o <= 1'b0;
    end else begin
      if (clear_q) begin
        rx_q <= rx_next;
        if (LineBits'(rx_way_addr) == LineBits'(WayWords - 1)) begin
          clear_q <= 1'b0;
          rx_q    <= '0;
        end
      end
      if (rd_read) pf_q <= 1'b1;
      if (rd_load) begin
        rx_q <= rx_next;
        if (rd_last) begin
          rd_busy_q <= 1'b0;
          pf_q      <= 1'b0;
          rx_q      <= '0;
          rline_q   <= rd_lastline ? '0 : rline_q + 1'b1;
        end
      end
      if (!pixel_valid_o || pixel_ready_i) pixel_valid_o <= rd_load;
      if (eol_take) begin
        wsel_q    <= !wsel_q;
        rd_busy_q <= 1'b1;
      end
    end
  end
  // x 0 when the reader is idle or loads a line's last pixel; x + 1 with any other load. While
  // the reader is idle rx_q is 0 and width_i may change (between frames): the flag follows it.
  always_ff @(posedge clk_i) begin
    if (!rd_busy_q || (rd_load && rd_last)) last_q <= width_i == LineBits'(1);
    else if (rd_load) last_q <= LineBits'(rx_q) + LineBits'(2) == width_i;
  end
  always_ff @(posedge clk_i) begin
    if (rd_load) begin
      pixel_rgb_o     <= covered ? loaded_rgb : background_i;
      pixel_covered_o <= covered;
      pixel_x_o       <= LineBits'(rx_q);
      pixel_y_o       <= rline_q;
      pixel_last_o    <= rd_last && rd_lastline;
    end
  end

  // The frame's inputs (sparse_i, width_i) hold while the block works on a frame, from its first
  // fragment or marker to its last pixel; between frames a top may leave them unset.
  `WATKINS_ASSERT(a_full_frame_only, frag_valid_i || pixel_valid_o |-> !sparse_i)
  `WATKINS_ASSERT_HOLD(a_in_hold, frag_valid_i, frag_ready_o, {frag_x_i, frag_depth_i, frag_poly_i,
    frag_rgb_i, frag_eol_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, pixel_valid_o, pixel_ready_i, {pixel_rgb_o, pixel_covered_o,
    pixel_last_o, pixel_x_o, pixel_y_o})
  `WATKINS_ASSERT(a_x_in_line, frag_valid_i && !frag_eol_i |-> frag_x_i < width_i)
  `WATKINS_ASSERT(a_width, frag_valid_i || pixel_valid_o |-> width_i >= LineBits'(1)
    && width_i <= LineBits'(MaxWidth))
  // Why one read register per bank serves both: the reader's prefetched pixel is loaded before
  // the swap hands its bank to the writer.
  `WATKINS_ASSERT(a_swap_after_last, eol_take |-> !pf_q || (rd_load && rd_last))
  `WATKINS_COVER(c_eol_waits, frag_valid_i && !frag_ready_o && !clear_q)
  `WATKINS_COVER(c_swap_on_last, eol_take && rd_busy_q)
  if (Lanes == 2) begin : g_lane1_checks
    `WATKINS_ASSERT_HOLD(a_in1_hold, frag_valid_i, frag_ready_o, {frag_pair_i, frag_depth1_i,
      frag_rgb1_i})
    `WATKINS_ASSERT(a_pair_in_line, frag_valid_i && !frag_eol_i && frag_pair_i
      |-> frag_x_i < width_i - 1'b1)
    `WATKINS_ASSERT(a_no_pair_on_marker, frag_valid_i && frag_eol_i |-> !frag_pair_i)
    `WATKINS_COVER(c_pair_from_odd_x, frag_take && frag_pair_i && frag_x_i[0])
  end
endmodule
