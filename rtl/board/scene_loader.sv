// scene_loader: the host link's packets (docs/reference/board.md, "Host link") into the scene
// bank the frame player is not reading, and the bank swap.
// A packet is the magic "WKFR", then B (one byte: the word's bytes, ceil(WordBits / 8)), W (two
// bytes, little-endian: the words), W words of B bytes little-endian, and the CRC-32/ISO-HDLC of
// everything after the magic (four bytes, little-endian). Each word is written to the inactive
// bank the clock after its last byte (wr_* registered: word k to address k). A packet whose B
// differs, whose W is not in 8 .. BankWords, whose CRC fails, that has a byte with a framing
// error, or that pauses 2^TimeoutBits clocks between two bytes is dropped and counted
// (error_count_o, saturating); the loader then looks for the next magic. A good packet counts in
// frame_count_o and asks for a swap; the swap happens on the next begin_i (the frame player
// starting a frame), so the player reads the new bank from that frame on. A packet accepted past
// its header while a swap waits cancels it: its words go to the same inactive bank, and the
// newer frame is shown if it arrives whole (the shown bank is never written). Registered: every
// output.

module scene_loader #(
  parameter int unsigned BankWords   = 512,  // per bank, a power of two
  parameter int unsigned WordBits    = 64,   // the bank's word (the top's EdgeBits)
  parameter int unsigned TimeoutBits = 20,   // a pause of 2^TimeoutBits clocks drops a packet
  localparam int unsigned AddrBits = $clog2(BankWords)
) (
  input  logic                clk_i,
  input  logic                rst_ni,         // active-low synchronous reset
  input  logic [7:0]          byte_i,
  input  logic                byte_valid_i,   // one clock per byte
  input  logic                byte_error_i,   // with byte_valid_i: a framing error
  input  logic                begin_i,        // one clock: the frame player starts a frame
  output logic                bank_active_o,  // the bank the frame player reads
  output logic                wr_en_o,        // the inactive bank's write port
  output logic                wr_bank_o,
  output logic [AddrBits-1:0] wr_addr_o,
  output logic [WordBits-1:0] wr_data_o,
  output logic [15:0]         frame_count_o,  // good packets (wraps)
  output logic [15:0]         error_count_o   // dropped packets (saturates)
);
  localparam int unsigned WordBytes = (WordBits + 7) / 8;
  localparam int unsigned PadBits   = 8 * WordBytes - WordBits;
  localparam int unsigned CountBits = AddrBits + 1;  // W up to BankWords
  localparam logic [31:0] Magic     = 32'h52464b57;  // "WKFR" as it arrives: 'W' first, lowest
  // CRC-32/ISO-HDLC (reflected, polynomial 0xEDB88320, initial all ones, final XOR all ones):
  // run over the data and its own CRC the register holds this residue.
  localparam logic [31:0] Residue   = 32'hdebb20e3;
  localparam logic [31:0] Poly      = 32'hedb88320;

  typedef enum logic [2:0] {Hunt, Bytes, Low, High, Words, Check} state_e;
  state_e state_q;

  logic [23:0]                magic_q;   // the last three bytes, the latest highest
  logic [31:0]                crc_q;
  logic [15:0]                w_q;       // W
  logic [7:0]                 w_low_q;
  logic [CountBits-1:0]       word_q;    // words received
  logic [$clog2(WordBytes + 1)-1:0] byte_q;  // bytes of the word received
  logic [1:0]                 crc_byte_q;
  logic [8*WordBytes-9:0]     assemble_q;  // the word's bytes so far, the latest highest
  logic [TimeoutBits-1:0]     idle_q;    // clocks since the last byte of a packet
  logic                       swap_q;    // a good packet waits for begin_i
  logic                       bank_q;
  logic                       wr_en_q;
  logic [AddrBits-1:0]        wr_addr_q;
  logic [8*WordBytes-1:0]     wr_data_q;
  logic [15:0]                frames_q, errors_q;
  logic                       drop, accept, good;
  logic [31:0]                crc_next;
  logic [8*WordBytes-1:0]     assembled;

  function automatic logic [31:0] crc32_byte(logic [31:0] crc, logic [7:0] b);
    logic [31:0] c;
    c = crc ^ {24'h0, b};
    for (int i = 0; i < 8; i++) c = c[0] ? (c >> 1) ^ Poly : c >> 1;
    crc32_byte = c;
  endfunction

  assign crc_next  = crc32_byte(crc_q, byte_i);
  assign assembled = {byte_i, assemble_q};

  // The events of this clock.
  always_comb begin
    drop   = 1'b0;
    accept = 1'b0;
    good   = 1'b0;
    if (state_q != Hunt) begin
      if (byte_valid_i && byte_error_i) drop = 1'b1;
      else if (!byte_valid_i && idle_q == '1) drop = 1'b1;
      else if (byte_valid_i) begin
        unique case (state_q)
          Bytes: drop = byte_i != 8'(WordBytes);
          High: begin
            if ({byte_i, w_low_q} < 16'd8 || {byte_i, w_low_q} > 16'(BankWords)) drop = 1'b1;
            else accept = 1'b1;
          end
          Check: if (crc_byte_q == 2'd3) begin
            if (crc_next == Residue) good = 1'b1;
            else drop = 1'b1;
          end
          default: ;
        endcase
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q  <= Hunt;
      magic_q  <= '0;
      swap_q   <= 1'b0;
      bank_q   <= 1'b0;
      wr_en_q  <= 1'b0;
      frames_q <= '0;
      errors_q <= '0;
    end else begin
      wr_en_q <= 1'b0;
      if (byte_valid_i) magic_q <= {byte_i, magic_q[23:8]};
      if (drop) begin
        state_q <= Hunt;
        if (errors_q != '1) errors_q <= errors_q + 16'd1;
      end else if (byte_valid_i) begin
        unique case (state_q)
          Hunt: if ({byte_i, magic_q} == Magic && !byte_error_i) state_q <= Bytes;
          Bytes: state_q <= Low;
          Low: state_q <= High;
          High: state_q <= Words;  // accept
          Words: if (byte_q == ($bits(byte_q))'(WordBytes - 1)) begin
            wr_en_q <= 1'b1;
            if (word_q == CountBits'(w_q - 16'd1)) state_q <= Check;
          end
          Check: if (good) begin
            state_q  <= Hunt;
            frames_q <= frames_q + 16'd1;
          end
          default: state_q <= Hunt;
        endcase
      end
      // A packet past its header cancels a waiting swap (its words go to the same bank); a
      // good packet asks for one; the frame player's start takes it.
      if (good) swap_q <= 1'b1;
      else if (accept) swap_q <= 1'b0;
      else if (begin_i && swap_q) begin
        swap_q <= 1'b0;
        bank_q <= !bank_q;
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (byte_valid_i || state_q == Hunt) idle_q <= '0;
    else if (idle_q != '1) idle_q <= idle_q + 1'b1;
    if (byte_valid_i) begin
      crc_q <= crc_next;
      unique case (state_q)
        Hunt: crc_q <= '1;  // the CRC starts after the magic
        Low: w_low_q <= byte_i;
        High: begin
          w_q    <= {byte_i, w_low_q};
          word_q <= '0;
          byte_q <= '0;
        end
        Words: begin
          assemble_q <= assembled[8*WordBytes-1:8];
          if (byte_q == ($bits(byte_q))'(WordBytes - 1)) begin
            byte_q     <= '0;
            word_q     <= word_q + 1'b1;
            wr_addr_q  <= word_q[AddrBits-1:0];
            wr_data_q  <= assembled;
            crc_byte_q <= '0;
          end else begin
            byte_q <= byte_q + 1'b1;
          end
        end
        Check: crc_byte_q <= crc_byte_q + 2'd1;
        default: ;
      endcase
    end
  end

  assign bank_active_o = bank_q;
  assign wr_en_o       = wr_en_q;
  assign wr_bank_o     = !bank_q;
  assign wr_addr_o     = wr_addr_q;
  assign wr_data_o     = wr_data_q[WordBits-1:0];
  assign frame_count_o = frames_q;
  assign error_count_o = errors_q;

  // The word's pad bits above WordBits (zero from the host) are not stored.
  if (PadBits > 0) begin : g_pad
    logic unused_pad;
    assign unused_pad = ^wr_data_q[8*WordBytes-1:WordBits];
  end
  if ((BankWords & (BankWords - 1)) != 0 || BankWords < 16 || BankWords > 32768) begin : g_check_words
    $error("scene_loader: BankWords must be a power of two in 16 .. 32768");
  end
endmodule
