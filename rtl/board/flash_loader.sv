// flash_loader: copies the iCEBreaker's scene bank from the board's SPI flash into the SPRAM bank
// after reset (docs/reference/board.md, "iCEBreaker"). It wakes the flash (Release Power-down,
// 0xAB: harmless when it is awake), keeps its select high GapClocks (tRES1 is 3 us), then reads
// 4 Words bytes pairs from byte FlashAddress on (Read Data, 0x03, a 24-bit address) and writes
// pair k, its first byte the low one, to lane k mod 4 of SPRAM word k div 4. SPI mode 0 at clk_i / 2:
// spi_sck_o is high every other clock, the command's bits change on its falling edges and the
// flash's are sampled at its rising ones. Clock 0 is the first with rst_ni high: the wake-up is
// clocks 0 .. 15, the gap 16 .. 15 + GapClocks, the read command the next 64 clocks, then each
// pair 32 clocks, written in its last; done_o is high from clock LoadClocks = 80 + GapClocks +
// 128 Words on and stays high. Registered: every output.

module flash_loader #(
  parameter int unsigned Words        = 1536,     // SPRAM words of 64 bits to load, at most 16,384
  parameter int unsigned FlashAddress = 'h20000,  // the scene's first byte in the flash
  parameter int unsigned GapClocks    = 128,      // a power of two, at least 2
  localparam int unsigned AddrBits = 14
) (
  input  logic                clk_i,
  input  logic                rst_ni,      // active-low synchronous reset: starts the load
  output logic                spi_ss_no,   // the flash's select (FLASH_SSB)
  output logic                spi_sck_o,   // its clock (FLASH_SCK)
  output logic                spi_mosi_o,  // to the flash (FLASH_IO0)
  input  logic                spi_miso_i,  // from the flash (FLASH_IO1)
  output logic                wr_en_o,     // the bank's write port
  output logic [1:0]          wr_lane_o,
  output logic [AddrBits-1:0] wr_addr_o,
  output logic [15:0]         wr_data_o,
  output logic                done_o       // the bank holds the scene
);
  localparam logic [7:0]  WakeCmd  = 8'hAB;
  localparam logic [31:0] ReadCmd  = {8'h03, 24'(FlashAddress)};
  localparam int unsigned GapBits  = $clog2(GapClocks);

  typedef enum logic [1:0] {SWake, SGap, SRead, SDone} state_e;
  state_e              state_q;
  logic                sck_q, ss_nq, mosi_q;
  logic [4:0]          bit_q;   // the command's bits sent, or the pair's bits received
  logic                data_q;  // the read command is sent: the flash's bits come
  logic [GapBits-1:0]  gap_q;
  logic [15:0]         pair_q;  // the bits received, first one highest
  logic                wr_q;
  logic [1:0]          lane_q;
  logic [AddrBits-1:0] addr_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q <= SWake;
      sck_q   <= 1'b0;
      ss_nq   <= 1'b0;
      mosi_q  <= WakeCmd[7];
      bit_q   <= '0;
      data_q  <= 1'b0;
      gap_q   <= '0;
      wr_q    <= 1'b0;
      lane_q  <= '0;
      addr_q  <= '0;
    end else begin
      wr_q <= 1'b0;
      unique case (state_q)
        SWake: begin
          sck_q <= !sck_q;
          if (sck_q) begin  // SCK falls: the next bit, or the command is over
            bit_q  <= bit_q + 1'b1;
            mosi_q <= WakeCmd[3'(~bit_q[2:0] - 1'b1)];
            if (bit_q == 5'd7) begin
              ss_nq   <= 1'b1;
              state_q <= SGap;
            end
          end
        end
        SGap: begin
          gap_q <= gap_q + 1'b1;
          if (gap_q == '1) begin
            ss_nq   <= 1'b0;
            mosi_q  <= ReadCmd[31];
            bit_q   <= '0;
            state_q <= SRead;
          end
        end
        SRead: begin
          sck_q <= !sck_q;
          if (!data_q && sck_q) begin  // SCK falls: the command's next bit
            bit_q  <= bit_q + 1'b1;
            mosi_q <= ReadCmd[~(bit_q + 1'b1)];
            if (bit_q == 5'd31) data_q <= 1'b1;
          end
          if (data_q && !sck_q) begin  // SCK rises: the flash's bit
            pair_q <= {pair_q[14:0], spi_miso_i};
            bit_q  <= {1'b0, bit_q[3:0] + 1'b1};
            wr_q   <= bit_q[3:0] == 4'd15;
          end
          if (wr_q) begin  // the pair is written in this clock: the next one's place
            lane_q <= lane_q + 1'b1;
            if (lane_q == 2'd3) addr_q <= addr_q + 1'b1;
            if (lane_q == 2'd3 && addr_q == AddrBits'(Words - 1)) begin
              ss_nq   <= 1'b1;
              state_q <= SDone;
            end
          end
        end
        SDone: sck_q <= 1'b0;
        default: state_q <= SDone;
      endcase
    end
  end

  assign spi_ss_no  = ss_nq;
  assign spi_sck_o  = sck_q;
  assign spi_mosi_o = mosi_q;
  assign wr_en_o    = wr_q;
  assign wr_lane_o  = lane_q;
  assign wr_addr_o  = addr_q;
  assign wr_data_o  = {pair_q[7:0], pair_q[15:8]};  // the first byte is the low one
  assign done_o     = state_q == SDone;

  if (Words < 1 || Words > 16384) begin : g_check_words
    $error("flash_loader: Words must be 1 .. 16384");
  end
  if (GapClocks < 2 || (GapClocks & (GapClocks - 1)) != 0) begin : g_check_gap
    $error("flash_loader: GapClocks must be a power of two, at least 2");
  end
endmodule
