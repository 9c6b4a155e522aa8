// icebreaker_top: the iCEBreaker board top (docs/reference/board.md, "iCEBreaker"): watkins_top
// replays the scene bank once per video frame and races the beam into a LineSlots-line buffer
// that the 640 x 480 at 60 Hz output reads, with no frame buffer, on the 12-bit DVI Pmod (PMOD
// 1A/1B: parallel RGB 4:4:4 into the Pmod's TFP410, which serializes it; no TMDS in the FPGA).
// One clock, 25.125 MHz (icebreaker_pll), runs everything: flash loader, video timing, frame
// player, scene bank, watkins_top, both line-buffer ports and the deadline check, so no signal
// crosses a clock domain (no Gray-code or toggle synchronizers: the line counts are compared where
// they are kept). The scene bank is the UP5K's four SPRAMs (spram_scene_bank), which nothing
// initializes: after reset flash_loader copies it from the board's SPI flash (byte FlashAddress
// on, where `watkins board build` puts it after the bitstream), and the rest of the board runs
// from the clock after the copy. Reset: released two clocks after the PLL locks with the button
// (btn_n, low when pressed) up, which starts the copy; the rest's reset a register, released
// LoadClocks + 1 clocks later (flash_loader's contract).
// Video side latency: the (h, v) state of a clock addresses the line buffer; its pixel (the
// buffer's read register) and that state's de/hsync/vsync, delayed one register to match, are the
// Pmod's outputs' D inputs on the next clock, and the SB_IO output registers put them on the pins
// one clock later (2 clocks from the state). dvi_clk is the clock inverted by a DDR SB_IO, so it
// rises mid-way between two data edges.
// Ports are named as rtl/board/icebreaker_top.pcf names the pins.
// Parameters: every watkins_top parameter, passed through with watkins_top's defaults (so
// `watkins_gen_pkg --params F --shading S` -G lists apply here too; the UP5K takes the compact
// top, Compact = 1 with Smoothing = 0, docs/reference/compact.md); Doubling D (1: the frame is 640 x 480; 2: 320 x 240, each
// pixel and line shown twice); LineSlots; BankWords (the scene bank's words, each ceil(EdgeBits /
// 64) SPRAM words); FlashAddress (the bank's first byte in the flash).

module icebreaker_top #(
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
  parameter int unsigned BankWords      = 512,  // the scene bank's words, a power of two
  parameter int unsigned FlashAddress   = 'h20000  // its first byte in the SPI flash
) (
  input  logic       clk_12mhz,  // the 12 MHz oscillator (pin 35)
  input  logic       btn_n,      // the user button, low when pressed: reset
  output logic       ledr_n,     // red LED, low lit: a line missed its deadline (sticky)
  output logic       ledg_n,     // green LED, low lit: toggles every video frame
  output logic       dvi_clk,
  output logic       dvi_hsync,
  output logic       dvi_vsync,
  output logic       dvi_de,
  output logic [3:0] dvi_r,
  output logic [3:0] dvi_g,
  output logic [3:0] dvi_b,
  output logic       flash_ss_n,  // the SPI flash (FLASH_SSB, FLASH_SCK, FLASH_IO0, FLASH_IO1)
  output logic       flash_sck,
  output logic       flash_mosi,
  input  logic       flash_miso
);
  localparam int unsigned XBits    = XIntBits + XFracBits;
  localparam int unsigned ZBits    = DepthIntBits + DepthFracBits;
  localparam int unsigned AttrBits = AttrIntBits + AttrFracBits;
  localparam int unsigned EdgeBits = watkins_pkg::edge_bits(XBits, ZBits, AttrBits, PolyIdBits, MaterialIdBits,
                                                            EdgeOrder);
  localparam int unsigned LineBits     = watkins_pkg::LineBits;
  localparam int unsigned UnitBits     = watkins_pkg::UnitBits;
  localparam int unsigned CountBits    = 12;  // LineCountBits: w, r, s
  localparam int unsigned SlotBits     = $clog2(LineSlots);
  localparam int unsigned PixelXBits   = $clog2(MaxWidth);
  localparam int unsigned SpramAddrBits = 14;
  localparam int unsigned Parts        = (EdgeBits + 63) / 64;  // SPRAM words a bank word
  localparam int unsigned MissedBits   = 16;
  localparam int unsigned PmodBits     = 12;  // 4 bits a channel, the top four of the pipeline's 8

  // ------------------------------------------------------------ the clock and its reset
  logic clk, locked;

  icebreaker_pll u_pll (
    .clk_12mhz_i(clk_12mhz),
    .clk_o      (clk),
    .locked_o   (locked)
  );

  // Two flip-flops on the asynchronous lock and button.
  logic run;  // the PLL is locked and the button is up
  assign run = locked && btn_n;
  (* async_reg = "true" *) logic [1:0] rst_q;
  logic rst_load_n;  // the flash loader's reset
  always_ff @(posedge clk) rst_q <= {rst_q[0], run};
  assign rst_load_n = rst_q[1];

  // ------------------------------------------------------------ the scene from the flash
  logic                     load_done, bank_wr_en;
  logic [1:0]               bank_wr_lane;
  logic [SpramAddrBits-1:0] bank_wr_addr;
  logic [15:0]              bank_wr_data;

  flash_loader #(.Words(BankWords * Parts), .FlashAddress(FlashAddress)) u_flash_loader (
    .clk_i     (clk),
    .rst_ni    (rst_load_n),
    .spi_ss_no (flash_ss_n),
    .spi_sck_o (flash_sck),
    .spi_mosi_o(flash_mosi),
    .spi_miso_i(flash_miso),
    .wr_en_o   (bank_wr_en),
    .wr_lane_o (bank_wr_lane),
    .wr_addr_o (bank_wr_addr),
    .wr_data_o (bank_wr_data),
    .done_o    (load_done)
  );

  // The rest of the board runs once the bank holds the scene.
  logic rst_n;
  always_ff @(posedge clk) rst_n <= rst_load_n && load_done;

  // ------------------------------------------------------------ video timing, frame request, line
  // counts, the deadline
  logic [9:0] h, v;
  logic       de, hsync_n, vsync_n;

  video_timing u_video_timing (
    .clk_i   (clk),
    .rst_ni  (rst_n),
    .h_o     (h),
    .v_o     (v),
    .de_o    (de),
    .hsync_no(hsync_n),
    .vsync_no(vsync_n)
  );

  logic                  request_toggle_q /*verilator public_flat_rd*/;  // flips at each frame's last visible pixel
  logic                  start_pulse /*verilator public_flat_rd*/;       // the clock after it: play a frame
  logic                  armed_q;  // a frame was requested since reset
  logic [CountBits-1:0]  w_q /*verilator public_flat_rd*/;  // written lines
  logic [CountBits-1:0]  r_q /*verilator public_flat_rd*/;  // released lines
  logic [CountBits-1:0]  s_q /*verilator public_flat_rd*/;  // shown (started) lines
  logic [SlotBits-1:0]   show_slot_q;
  logic [MissedBits-1:0] missed_count_q /*verilator public_flat_rd*/;
  logic                  missed_q;
  logic                  last_visible, release_line, start_line;
  logic                  line_missed /*verilator public_flat_rd*/;  // this clock starts a line not complete
  logic [CountBits-1:0]  ahead;  // w_q - s_q: lines complete and not yet started

  // Every event is decided on the (h, v) state of the clock that makes it, as on the ULX3S top.
  assign last_visible = h == 10'd639 && v == 10'd479;
  // The last pixel of a rendered line is read: h = 639 on its last video line.
  assign release_line = armed_q && h == 10'd639 && v < 10'd480 && (Doubling == 1 || v[0]);
  // The video starts rendered line y: h = 799 on video line D y - 1 (v = 524 for line 0).
  assign start_line = armed_q && h == 10'd799 && (v == 10'd524 || (v < 10'd479 && (Doubling == 1 || v[0])));
  assign ahead       = w_q - s_q;
  assign line_missed = start_line && $signed(ahead) <= 0;

  logic start_q;
  assign start_pulse = start_q;

  always_ff @(posedge clk) begin
    if (!rst_n) begin
      request_toggle_q <= 1'b0;
      start_q          <= 1'b0;
      armed_q          <= 1'b0;
      r_q              <= '0;
      s_q              <= '0;
      show_slot_q      <= '0;
      missed_count_q   <= '0;
      missed_q         <= 1'b0;
    end else begin
      start_q <= last_visible;
      if (last_visible) begin
        request_toggle_q <= !request_toggle_q;
        armed_q          <= 1'b1;
      end
      if (release_line) r_q <= r_q + 1'b1;
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

  // ------------------------------------------------------------ frame player, scene bank, pipeline
  logic                     rd_en;
  logic [SpramAddrBits-1:0] rd_addr;
  logic [63:0]              rd_data;
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
  /* verilator lint_off UNUSEDSIGNAL */  // each channel's low four bits: the Pmod shows the top four
  watkins_pkg::rgb_t        pixel_rgb;
  /* verilator lint_on UNUSEDSIGNAL */
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

  // One bank, no host link: the scene the flash holds.
  spram_scene_bank u_scene_bank (
    .clk_i    (clk),
    .rd_en_i  (rd_en),
    .rd_addr_i(rd_addr),
    .rd_data_o(rd_data),
    .wr_en_i  (bank_wr_en),
    .wr_lane_i(bank_wr_lane),
    .wr_addr_i(bank_wr_addr),
    .wr_data_i(bank_wr_data)
  );

  spram_frame_player #(.BankWords(BankWords), .EdgeBits(EdgeBits), .MaterialIdBits(MaterialIdBits)) u_frame_player (
    .clk_i           (clk),
    .rst_ni          (rst_n),
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
    .clk_i           (clk),
    .rst_ni          (rst_n),
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

  // Back-pressure (line_credit): the slot of the line being written is free, (w - r) < S,
  // counted by line_done (+1) and release_line (-1, a decode of the video counters).
  logic [LineBits-1:0]  last_x_q;
  assign pixel_fire  = pixel_valid && pixel_ready;
  assign line_done   = pixel_fire && pixel_x == last_x_q;
  assign frame_done  = pixel_fire && pixel_last;
  line_credit #(.CountBits(CountBits), .LineSlots(LineSlots)) u_line_credit (
    .clk_i    (clk),
    .rst_ni   (rst_n),
    .take_i   (line_done),
    .release_i(release_line),
    .ready_o  (pixel_ready)
  );

  always_ff @(posedge clk) begin
    last_x_q <= width - 1'b1;
    if (!rst_n) begin
      w_q      <= '0;
    end else begin
      if (line_done) w_q <= w_q + 1'b1;
    end
  end

  // ------------------------------------------------------------ the line buffer and the Pmod
  logic [PmodBits-1:0] wr_rgb, rd_rgb;
  // The Pmod shows 4 bits a channel: the top four of each 8-bit level (red 23:20, green 15:12,
  // blue 7:4), so the buffer keeps those only.
  assign wr_rgb = {pixel_rgb[23:20], pixel_rgb[15:12], pixel_rgb[7:4]};

  line_buffer #(.Slots(LineSlots), .MaxWidth(MaxWidth), .DataBits(PmodBits)) u_line_buffer (
    .clk_wr_i (clk),
    .wr_en_i  (pixel_fire),
    .wr_slot_i(w_q[SlotBits-1:0]),
    .wr_x_i   (pixel_x[PixelXBits-1:0]),
    .wr_data_i(wr_rgb),
    .clk_rd_i (clk),
    .rd_slot_i(show_slot_q),
    .rd_x_i   (PixelXBits'(h / 10'(Doubling))),
    .rd_data_o(rd_rgb)
  );

  // The Pmod's D inputs: the buffer's pixel of the previous clock's (h, v) and that clock's de and
  // syncs, delayed to match.
  logic                pmod_de_q /*verilator public_flat_rd*/;
  logic                pmod_hsync_nq /*verilator public_flat_rd*/;
  logic                pmod_vsync_nq /*verilator public_flat_rd*/;
  logic [PmodBits-1:0] pmod_rgb /*verilator public_flat_rd*/;
  always_ff @(posedge clk) begin
    if (!rst_n) begin
      pmod_de_q     <= 1'b0;
      pmod_hsync_nq <= 1'b1;
      pmod_vsync_nq <= 1'b1;
    end else begin
      pmod_de_q     <= de;
      pmod_hsync_nq <= hsync_n;
      pmod_vsync_nq <= vsync_n;
    end
  end
  assign pmod_rgb = rd_rgb;

  // The 15 signals leave through the I/O cells' output registers (PIN_TYPE 0101_00), so every pin
  // changes the same delay after the clock's rising edge, wherever the logic is placed.
  logic [14:0] pmod_d, pmod_pin;
  assign pmod_d = {pmod_hsync_nq, pmod_vsync_nq, pmod_de_q, pmod_rgb};
  /* verilator lint_off PINCONNECTEMPTY */
  for (genvar i = 0; i < 15; i++) begin : g_pmod_io
    SB_IO #(.PIN_TYPE(6'b010100)) u_sb_io (
      .PACKAGE_PIN      (pmod_pin[i]),
      .LATCH_INPUT_VALUE(1'b0),
      .CLOCK_ENABLE     (1'b1),
      .INPUT_CLK        (1'b0),
      .OUTPUT_CLK       (clk),
      .OUTPUT_ENABLE    (1'b1),
      .D_OUT_0          (pmod_d[i]),
      .D_OUT_1          (1'b0),
      .D_IN_0           (),
      .D_IN_1           ()
    );
  end
  // dvi_clk: the clock inverted, from a DDR I/O cell (PIN_TYPE 0100_00: D_OUT_0 while the clock
  // is high, D_OUT_1 while it is low). The TFP410 takes the data on dvi_clk's rising edge, which
  // is the clock's falling edge: half a period (19.9 ns) after the pins changed and before they
  // change again, from I/O registers like the data's, so the setup and hold do not depend on
  // placement.
  SB_IO #(.PIN_TYPE(6'b010000)) u_dvi_clk_io (
    .PACKAGE_PIN      (dvi_clk),
    .LATCH_INPUT_VALUE(1'b0),
    .CLOCK_ENABLE     (1'b1),
    .INPUT_CLK        (1'b0),
    .OUTPUT_CLK       (clk),
    .OUTPUT_ENABLE    (1'b1),
    .D_OUT_0          (1'b0),
    .D_OUT_1          (1'b1),
    .D_IN_0           (),
    .D_IN_1           ()
  );
  /* verilator lint_on PINCONNECTEMPTY */
  assign {dvi_hsync, dvi_vsync, dvi_de, dvi_r, dvi_g, dvi_b} = pmod_pin;

  // ------------------------------------------------------------ LEDs (active low)
  assign ledg_n = !request_toggle_q;  // toggles every video frame
  assign ledr_n = !missed_q;          // a line missed its deadline (sticky until reset)

  if (Doubling != 1 && Doubling != 2) begin : g_check_doubling
    $error("icebreaker_top: Doubling must be 1 or 2");
  end
  if (LineSlots < 2 || (LineSlots & (LineSlots - 1)) != 0) begin : g_check_slots
    $error("icebreaker_top: LineSlots must be a power of two, at least 2");
  end
endmodule
