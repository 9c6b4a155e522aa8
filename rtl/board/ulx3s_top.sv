// ulx3s_top: the ULX3S board top (docs/reference/board.md): watkins_top, unchanged, replays the
// active scene bank once per video frame and races the beam into a LineSlots-line buffer that the
// 640 x 480 at 60 Hz DVI output reads, with no frame buffer. Bank 0 starts with the scene; the
// host link (ftdi_txd, 8N1 at Baud) writes frames into the other bank and swaps them.
// Clocks (ulx3s_pll): clk_pipe 78.75 MHz (frame player, scene bank, watkins_top, line-buffer
// write), clk_pixel 25.2 MHz (video timing, line-buffer read, TMDS encoders), clk_tmds 126 MHz
// (serializers, reset from the pixel domain). clk_pipe and clk_pixel each have a reset, released
// two of their clocks after the PLL locks with btn[0] (PWR, low when pressed) up.
// Video side latency: the (h, v) state of a pixel clock addresses the line buffer; its pixel and
// that state's de/hsync/vsync, delayed one register to match, reach the encoders' inputs on the
// next pixel clock (1 clock), and their symbols the serializers one clock later.
// Ports are named as the ULX3S constraint file names them (rtl/board/ulx3s_top.lpf).
// Parameters: every watkins_top parameter, passed through (so `watkins_gen_pkg --params F
// --shading S` -G lists apply here too); Doubling D (1: the frame is 640 x 480; 2: 320 x 240,
// each pixel and line shown twice); LineSlots; BankWords (per bank); BankFile (bank 0's
// $readmemh file, `watkins board image`); Baud (the host link's serial rate).

module ulx3s_top #(
  parameter int unsigned MaxActiveEdges = watkins_pkg::MaxActiveEdges,
  parameter int unsigned MaxWidth       = 320,
  parameter int          Phong          = 0,
  parameter int unsigned XIntBits       = watkins_pkg::ChannelBits - watkins_pkg::FracBits,
  parameter int unsigned XFracBits      = watkins_pkg::FracBits,
  parameter int unsigned DepthIntBits   = watkins_pkg::ChannelBits - watkins_pkg::FracBits,
  parameter int unsigned DepthFracBits  = watkins_pkg::FracBits,
  parameter int unsigned AttrIntBits    = watkins_pkg::ChannelBits - watkins_pkg::FracBits,
  parameter int unsigned AttrFracBits   = watkins_pkg::FracBits,
  parameter int unsigned DepthBits      = watkins_pkg::DepthBits,
  parameter int unsigned PolyIdBits     = watkins_pkg::PolyIdBits,
  parameter int unsigned MaterialIdBits = watkins_pkg::MaterialIdBits,
  parameter int unsigned EdgeIdBits     = watkins_pkg::EdgeIdBits,
  parameter int unsigned EdgeOrder      = 1,
  parameter int          Smoothing      = 1,
  parameter int          HasEq2         = 0,
  parameter int unsigned Eq2RecipBits   = watkins_pkg::Eq2RecipBits,
  parameter int          Compact        = 0,
  parameter int unsigned Lanes          = 1,
  parameter int          PhongNarrow    = 0,    // 1: the compact Phong top's narrow formats
  parameter int unsigned Doubling       = 2,    // 1 or 2
  parameter int unsigned LineSlots      = 2,    // line-buffer lines, a power of two
  parameter int unsigned BankWords      = 512,  // words per scene bank, a power of two
  parameter              BankFile       = "",   // bank 0's $readmemh file
  parameter int unsigned Baud           = 3_000_000  // the host link's serial rate (8N1)
) (
  input  logic       clk_25mhz,
  /* verilator lint_off UNUSEDSIGNAL */  // btn[6:1] are spare
  input  logic [6:0] btn,
  output logic [7:0] led,
  output logic [3:0] gpdi_dp,     // 0 blue, 1 green, 2 red, 3 clock (the _dn pins follow)
  output logic       ftdi_rxd,    // to the FT231X (idle high)
  input  logic       ftdi_txd,    // from the FT231X
  /* verilator lint_on UNUSEDSIGNAL */
  output logic       wifi_gpio0   // high: the ESP32 leaves the board out of reset
);
  localparam int unsigned XBits    = XIntBits + XFracBits;
  localparam int unsigned ZBits    = DepthIntBits + DepthFracBits;
  localparam int unsigned AttrBits = AttrIntBits + AttrFracBits;
  localparam int unsigned EdgeBits = watkins_pkg::edge_bits(XBits, ZBits, AttrBits, PolyIdBits, MaterialIdBits,
                                                            EdgeOrder);
  localparam int unsigned LineBits      = watkins_pkg::LineBits;
  localparam int unsigned UnitBits      = watkins_pkg::UnitBits;
  localparam int unsigned CountBits     = 12;  // LineCountBits: w, r, s
  localparam int unsigned SlotBits      = $clog2(LineSlots);
  localparam int unsigned PixelXBits    = $clog2(MaxWidth);
  localparam int unsigned BankAddrBits  = $clog2(BankWords);
  localparam int unsigned MissedBits    = 16;

  function automatic logic [CountBits-1:0] binary_to_gray(logic [CountBits-1:0] b);
    binary_to_gray = b ^ (b >> 1);
  endfunction

  // ------------------------------------------------------------ clocks and resets
  logic clk_tmds, clk_pixel, clk_pipe, locked;

  ulx3s_pll u_pll (
    .clk_25mhz_i(clk_25mhz),
    .clk_tmds_o (clk_tmds),
    .clk_pixel_o(clk_pixel),
    .clk_pipe_o (clk_pipe),
    .locked_o   (locked)
  );

  // crossing: reset synchronizers, two flip-flops per domain on the asynchronous lock and button.
  logic run;  // the PLL is locked and PWR is not pressed
  assign run = locked && btn[0];
  (* async_reg = "true" *) logic [1:0] rst_pipe_q, rst_pixel_q;
  logic rst_pipe_n, rst_pixel_n;
  always_ff @(posedge clk_pipe) rst_pipe_q <= {rst_pipe_q[0], run};
  always_ff @(posedge clk_pixel) rst_pixel_q <= {rst_pixel_q[0], run};
  assign rst_pipe_n  = rst_pipe_q[1];
  assign rst_pixel_n = rst_pixel_q[1];

  // ------------------------------------------------------------ clk_pixel: video timing, frame
  // request, released and shown line counts, the deadline
  logic [9:0] h, v;
  logic       de, hsync_n, vsync_n;

  video_timing u_video_timing (
    .clk_i   (clk_pixel),
    .rst_ni  (rst_pixel_n),
    .h_o     (h),
    .v_o     (v),
    .de_o    (de),
    .hsync_no(hsync_n),
    .vsync_no(vsync_n)
  );

  logic                 request_toggle_q /*verilator public_flat_rd*/;  // flips at each frame's last visible pixel
  logic                 armed_q;           // a frame was requested since reset
  logic [CountBits-1:0] r_q /*verilator public_flat_rd*/, r_gray_q;  // released lines
  logic [CountBits-1:0] s_q /*verilator public_flat_rd*/;            // shown (started) lines
  logic [CountBits-1:0] w_sync;            // written lines, in this domain
  logic [SlotBits-1:0]  show_slot_q;
  logic [MissedBits-1:0] missed_count_q /*verilator public_flat_rd*/;
  logic                 missed_q;
  logic                 last_visible, release_line, start_line;
  logic                 line_missed /*verilator public_flat_rd*/;  // this clock starts a line not complete
  logic [CountBits-1:0] ahead;  // w_sync - s_q: lines complete and not yet started

  // Every event is decided on the (h, v) state of the clock that makes it.
  assign last_visible = h == 10'd639 && v == 10'd479;
  // The last pixel of a rendered line is read: h = 639 on its last video line.
  assign release_line = armed_q && h == 10'd639 && v < 10'd480 && (Doubling == 1 || v[0]);
  // The video starts rendered line y: h = 799 on video line D y - 1 (v = 524 for line 0).
  assign start_line = armed_q && h == 10'd799 && (v == 10'd524 || (v < 10'd479 && (Doubling == 1 || v[0])));
  assign ahead       = w_sync - s_q;
  assign line_missed = start_line && $signed(ahead) <= 0;

  always_ff @(posedge clk_pixel) begin
    if (!rst_pixel_n) begin
      request_toggle_q <= 1'b0;
      armed_q          <= 1'b0;
      r_q              <= '0;
      r_gray_q         <= '0;
      s_q              <= '0;
      show_slot_q      <= '0;
      missed_count_q   <= '0;
      missed_q         <= 1'b0;
    end else begin
      if (last_visible) begin
        request_toggle_q <= !request_toggle_q;
        armed_q          <= 1'b1;
      end
      if (release_line) begin
        r_q      <= r_q + 1'b1;
        r_gray_q <= binary_to_gray(r_q + 1'b1);
      end
      if (start_line) begin
        s_q         <= s_q + 1'b1;
        show_slot_q <= s_q[SlotBits-1:0];
      end
      if (line_missed) begin
        missed_q <= 1'b1;
        if (missed_count_q != '1) missed_count_q <= missed_count_q + 1'b1;
      end
    end
  end

  // ------------------------------------------------------------ clk_pipe: frame player, scene
  // bank, pipeline, written line count
  logic                 start_pulse /*verilator public_flat_rd*/;
  logic [CountBits-1:0] w_q /*verilator public_flat_rd*/, w_gray_q;
  /* verilator lint_off UNUSEDSIGNAL */  // line_credit follows the released count's steps instead
  logic [CountBits-1:0] r_sync;  // released lines, in this domain
  /* verilator lint_on UNUSEDSIGNAL */
  logic                 r_step;  // r_sync advances at the next clock (one release)

  // crossing: toggle (frame request, clk_pixel -> clk_pipe)
  toggle_sync u_request_sync (
    .clk_i   (clk_pipe),
    .rst_ni  (rst_pipe_n),
    .toggle_i(request_toggle_q),
    .pulse_o (start_pulse)
  );
  // crossing: Gray code (released count, clk_pixel -> clk_pipe)
  gray_sync #(.Bits(CountBits)) u_released_sync (
    .clk_i  (clk_pipe),
    .rst_ni (rst_pipe_n),
    .gray_i      (r_gray_q),
    .count_o(r_sync),
    .step_o (r_step)
  );
  // crossing: Gray code (written count, clk_pipe -> clk_pixel)
  /* verilator lint_off UNUSEDSIGNAL */  // the video side compares w_sync itself, at 25.2 MHz
  logic                 w_step;
  /* verilator lint_on UNUSEDSIGNAL */
  gray_sync #(.Bits(CountBits)) u_written_sync (
    .clk_i  (clk_pixel),
    .rst_ni (rst_pixel_n),
    .gray_i      (w_gray_q),
    .count_o(w_sync),
    .step_o (w_step)
  );

  logic                     rd_en;
  logic [BankAddrBits-1:0]  rd_addr;
  logic [EdgeBits-1:0]      rd_data;
  logic [LineBits-1:0]      width, height;
  watkins_pkg::rgb_t        background;
  logic                     tie_submission, eq2;
  logic [watkins_pkg::SmoothWBits-1:0] smooth_w;
  logic [3*UnitBits-1:0]    light, eye;
  logic                     material_we;
  logic [MaterialIdBits-1:0] material_addr;
  watkins_pkg::rgb_t        material_cp;
  logic [watkins_pkg::MaterialBits-1:0]  material_d, material_w;
  logic [watkins_pkg::ShininessBits-1:0] material_n;
  logic [EdgeBits-1:0]      edge_data;
  logic                     edge_eof, edge_valid, edge_ready;
  watkins_pkg::rgb_t        pixel_rgb;
  logic                     pixel_last, pixel_valid, pixel_ready;
  logic [LineBits-1:0]      pixel_x;
  // Read by the bench only: the frame is full (every pixel, in raster order), and a scene the
  // board build accepts fits the active-edge list.
  /* verilator lint_off UNUSEDSIGNAL */
  logic                     pixel_covered;
  logic [LineBits-1:0]      pixel_y;
  logic                     overflow /*verilator public_flat_rd*/;
  /* verilator lint_on UNUSEDSIGNAL */
  logic                     pixel_fire, frame_done;
  logic                     line_done /*verilator public_flat_rd*/;  // this clock takes a line's last pixel
  logic                     frame_begin /*verilator public_flat_rd*/;

  // The host link (docs/reference/board.md, "Host link"): frames from the FT231X into the bank
  // the frame player is not reading, the banks swapped when the player begins a frame.
  logic                    bank_active /*verilator public_flat_rd*/;
  logic                    bank_we, bank_wr_bank;
  logic [BankAddrBits-1:0] bank_wr_addr;
  logic [EdgeBits-1:0]     bank_wr_data;
  logic [15:0]             link_frames /*verilator public_flat_rd*/;  // good packets
  logic [15:0]             link_errors /*verilator public_flat_rd*/;  // dropped packets

  // crossing: the asynchronous serial line, two flip-flops inside host_link's uart_rx.
  host_link #(.ClockHz(78_750_000), .Baud(Baud), .BankWords(BankWords), .WordBits(EdgeBits)) u_host_link (
    .clk_i        (clk_pipe),
    .rst_ni       (rst_pipe_n),
    .rx_i         (ftdi_txd),
    .begin_i      (frame_begin),
    .bank_active_o(bank_active),
    .wr_en_o      (bank_we),
    .wr_bank_o    (bank_wr_bank),
    .wr_addr_o    (bank_wr_addr),
    .wr_data_o    (bank_wr_data),
    .frame_count_o(link_frames),
    .error_count_o(link_errors)
  );

  scene_bank #(.Words(BankWords), .Bits(EdgeBits), .File(BankFile)) u_scene_bank (
    .clk_i    (clk_pipe),
    .rd_en_i  (rd_en),
    .rd_bank_i(bank_active),
    .rd_addr_i(rd_addr),
    .rd_data_o(rd_data),
    .wr_en_i  (bank_we),
    .wr_bank_i(bank_wr_bank),
    .wr_addr_i(bank_wr_addr),
    .wr_data_i(bank_wr_data)
  );

  frame_player #(.BankWords(BankWords), .EdgeBits(EdgeBits), .MaterialIdBits(MaterialIdBits)) u_frame_player (
    .clk_i           (clk_pipe),
    .rst_ni          (rst_pipe_n),
    .start_i         (start_pulse),
    .frame_done_i    (frame_done),
    .begin_o         (frame_begin),
    .rd_en_o         (rd_en),
    .rd_addr_o       (rd_addr),
    .rd_data_i       (rd_data),
    .width_o         (width),
    .height_o        (height),
    .background_o    (background),
    .tie_submission_o(tie_submission),
    .eq2_o           (eq2),
    .smooth_w_o      (smooth_w),
    .light_o         (light),
    .eye_o           (eye),
    .material_we_o   (material_we),
    .material_addr_o (material_addr),
    .material_cp_o   (material_cp),
    .material_d_o    (material_d),
    .material_w_o    (material_w),
    .material_n_o    (material_n),
    .edge_o          (edge_data),
    .edge_eof_o      (edge_eof),
    .edge_valid_o    (edge_valid),
    .edge_ready_i    (edge_ready)
  );

  watkins_top #(
    .MaxActiveEdges(MaxActiveEdges), .MaxWidth(MaxWidth), .Phong(Phong),
    .XIntBits(XIntBits), .XFracBits(XFracBits), .DepthIntBits(DepthIntBits), .DepthFracBits(DepthFracBits),
    .AttrIntBits(AttrIntBits), .AttrFracBits(AttrFracBits), .DepthBits(DepthBits), .PolyIdBits(PolyIdBits),
    .MaterialIdBits(MaterialIdBits), .EdgeIdBits(EdgeIdBits), .EdgeOrder(EdgeOrder), .Smoothing(Smoothing),
    .HasEq2(HasEq2), .Eq2RecipBits(Eq2RecipBits), .Compact(Compact), .Lanes(Lanes),
    .PhongNarrow(PhongNarrow)
  ) u_watkins_top (
    .clk_i           (clk_pipe),
    .rst_ni          (rst_pipe_n),
    .width_i         (width),
    .height_i        (height),
    .background_i    (background),
    .sparse_i        (1'b0),  // every pixel: the line buffer is filled in raster order
    .tie_submission_i(tie_submission),
    .smooth_w_i      (smooth_w),
    .eq2_i           (eq2),
    .edge_i          (edge_data),
    .edge_eof_i      (edge_eof),
    .edge_valid_i    (edge_valid),
    .edge_ready_o    (edge_ready),
    .pixel_rgb_o     (pixel_rgb),
    .pixel_covered_o (pixel_covered),
    .pixel_x_o       (pixel_x),
    .pixel_y_o       (pixel_y),
    .pixel_last_o    (pixel_last),
    .pixel_valid_o   (pixel_valid),
    .pixel_ready_i   (pixel_ready),
    .overflow_o      (overflow),
    .light_i         (light),
    .eye_i           (eye),
    .material_we_i   (material_we),
    .material_addr_i (material_addr),
    .material_cp_i   (material_cp),
    .material_d_i    (material_d),
    .material_w_i    (material_w),
    .material_n_i    (material_n)
  );

  // Back-pressure (line_credit): the slot of the line being written is free, (w - r_sync) < S,
  // counted by line_done (+1) and gray_sync's step (-1: one release at most a video line), so no
  // adder follows the handshake. The frame's last x is a register too (the width is stable for
  // the frame long before its first pixel).
  logic [LineBits-1:0]  last_x_q;
  assign pixel_fire  = pixel_valid && pixel_ready;
  assign line_done   = pixel_fire && pixel_x == last_x_q;
  assign frame_done  = pixel_fire && pixel_last;
  line_credit #(.CountBits(CountBits), .LineSlots(LineSlots)) u_line_credit (
    .clk_i    (clk_pipe),
    .rst_ni   (rst_pipe_n),
    .take_i   (line_done),
    .release_i(r_step),
    .ready_o  (pixel_ready)
  );

  always_ff @(posedge clk_pipe) last_x_q <= width - 1'b1;

  always_ff @(posedge clk_pipe) begin
    if (!rst_pipe_n) begin
      w_q      <= '0;
      w_gray_q <= '0;
    end else if (line_done) begin
      w_q      <= w_q + 1'b1;
      w_gray_q <= binary_to_gray(w_q + 1'b1);
    end
  end

  // ------------------------------------------------------------ the line buffer and the encoders
  logic [SlotBits-1:0]   rd_slot;
  logic [PixelXBits-1:0] rd_x;
  logic [23:0]           rd_rgb;
  assign rd_slot = show_slot_q;
  assign rd_x    = PixelXBits'(h / 10'(Doubling));

  line_buffer #(.Slots(LineSlots), .MaxWidth(MaxWidth), .DataBits(24)) u_line_buffer (
    .clk_wr_i (clk_pipe),
    .wr_en_i  (pixel_fire),
    .wr_slot_i(w_q[SlotBits-1:0]),
    .wr_x_i   (pixel_x[PixelXBits-1:0]),
    .wr_data_i(pixel_rgb),
    .clk_rd_i (clk_pixel),
    .rd_slot_i(rd_slot),
    .rd_x_i   (rd_x),
    .rd_data_o(rd_rgb)
  );

  // The encoders' inputs: the buffer's pixel of the previous clock's (h, v) and that clock's
  // de and syncs, delayed to match.
  logic        enc_de_q /*verilator public_flat_rd*/;
  logic        enc_hsync_nq /*verilator public_flat_rd*/;
  logic        enc_vsync_nq /*verilator public_flat_rd*/;
  logic [23:0] enc_rgb /*verilator public_flat_rd*/;
  always_ff @(posedge clk_pixel) begin
    if (!rst_pixel_n) begin
      enc_de_q     <= 1'b0;
      enc_hsync_nq <= 1'b1;
      enc_vsync_nq <= 1'b1;
    end else begin
      enc_de_q     <= de;
      enc_hsync_nq <= hsync_n;
      enc_vsync_nq <= vsync_n;
    end
  end
  assign enc_rgb = rd_rgb;

  logic [9:0] symbol_blue, symbol_green, symbol_red;
  // In blanking the blue lane carries {c1, c0} = {vsync, hsync}; green and red carry 00.
  tmds_encoder u_encoder_blue (
    .clk_i(clk_pixel), .rst_ni(rst_pixel_n), .data_i(enc_rgb[7:0]), .de_i(enc_de_q),
    .c0_i(enc_hsync_nq), .c1_i(enc_vsync_nq), .symbol_o(symbol_blue));
  tmds_encoder u_encoder_green (
    .clk_i(clk_pixel), .rst_ni(rst_pixel_n), .data_i(enc_rgb[15:8]), .de_i(enc_de_q),
    .c0_i(1'b0), .c1_i(1'b0), .symbol_o(symbol_green));
  tmds_encoder u_encoder_red (
    .clk_i(clk_pixel), .rst_ni(rst_pixel_n), .data_i(enc_rgb[23:16]), .de_i(enc_de_q),
    .c0_i(1'b0), .c1_i(1'b0), .symbol_o(symbol_red));

  // The TMDS word load is a synchronous transfer clk_pixel -> clk_tmds (one VCO, clk_tmds = 5 x
  // clk_pixel), timed by nextpnr: not a crossing.
  tmds_serializer u_serializer_blue (
    .clk_pixel_i(clk_pixel), .clk_tmds_i(clk_tmds), .rst_ni(rst_pixel_n), .symbol_i(symbol_blue), .pad_o(gpdi_dp[0]));
  tmds_serializer u_serializer_green (
    .clk_pixel_i(clk_pixel), .clk_tmds_i(clk_tmds), .rst_ni(rst_pixel_n), .symbol_i(symbol_green), .pad_o(gpdi_dp[1]));
  tmds_serializer u_serializer_red (
    .clk_pixel_i(clk_pixel), .clk_tmds_i(clk_tmds), .rst_ni(rst_pixel_n), .symbol_i(symbol_red), .pad_o(gpdi_dp[2]));
  // The clock lane: the pixel clock as five ones then five zeros (bit 0 first).
  tmds_serializer u_serializer_clock (
    .clk_pixel_i(clk_pixel), .clk_tmds_i(clk_tmds), .rst_ni(rst_pixel_n), .symbol_i(10'b0000011111),
    .pad_o(gpdi_dp[3]));

  // ------------------------------------------------------------ board I/O
  // led[0] frame shown, led[1] a line missed (sticky), led[2] link error (sticky: the host link
  // dropped a packet), led[3] PLL locked, led[7:4] the missed-line count's low bits.
  assign led        = {missed_count_q[3:0], locked, link_errors != 16'd0, missed_q, request_toggle_q};
  assign ftdi_rxd   = 1'b1;  // the FPGA's transmit line: idle
  assign wifi_gpio0 = 1'b1;

  if (Doubling != 1 && Doubling != 2) begin : g_check_doubling
    $error("ulx3s_top: Doubling must be 1 or 2");
  end
  if (LineSlots < 2 || (LineSlots & (LineSlots - 1)) != 0) begin : g_check_slots
    $error("ulx3s_top: LineSlots must be a power of two, at least 2");
  end
endmodule
