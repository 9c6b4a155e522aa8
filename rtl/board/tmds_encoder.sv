// tmds_encoder: one DVI 1.0 TMDS lane's encoder, exactly model/board/tmds.hpp (TmdsEncoder).
// Latency 1 cycle: symbol_o and the running disparity are registers loaded every clock from
// data_i, de_i, c0_i, c1_i (no combinational path from input to output); one symbol per clock.
// With de_i high the byte becomes a transition-minimized word q_m (an XOR or XNOR chain, XNOR when
// the byte has more than four ones or exactly four with bit 0 clear; q_m[8] set for XOR), then a
// DC-balanced symbol: bits 7:0 sent inverted (bit 9 set) when that moves the running disparity
// (ones minus zeros sent since the last blanking) toward zero. With de_i low the symbol is the
// control token of {c1_i, c0_i} and the disparity returns to 0, as DVI 1.0 specifies. Bit 0 of
// symbol_o is the first bit on the wire. The disparity stays even and within [-8, 8] (5 bits).

module tmds_encoder (
  input  logic       clk_i,
  input  logic       rst_ni,    // active-low synchronous reset: disparity 0, the {0, 0} token
  input  logic [7:0] data_i,    // the pixel byte, sent while de_i is high
  input  logic       de_i,      // data enable: high in the visible area
  input  logic       c0_i,      // control pair sent in blanking (the blue lane: hsync, vsync)
  input  logic       c1_i,
  output logic [9:0] symbol_o   // bit 0 first on the wire
);
  // The control tokens as 10-bit words, bit 9 down to bit 0 (DVI 1.0 lists them bit 0 first).
  localparam logic [9:0] Control00 = 10'b1101010100;
  localparam logic [9:0] Control01 = 10'b0010101011;
  localparam logic [9:0] Control10 = 10'b0101010100;
  localparam logic [9:0] Control11 = 10'b1010101011;

  logic [9:0]        symbol_q, symbol_d;
  logic signed [4:0] cnt_q, cnt_d;  // running disparity

  // ---------------------------------------------------------------- transition minimizing
  logic [3:0] data_ones;
  logic       use_xnor;
  logic [7:0] q_m;
  logic       q8;  // q_m[8]: set for the XOR chain
  always_comb begin
    data_ones = '0;
    for (int i = 0; i < 8; i++) data_ones = data_ones + {3'b0, data_i[i]};
  end
  assign use_xnor = data_ones > 4'd4 || (data_ones == 4'd4 && !data_i[0]);
  assign q8 = !use_xnor;
  logic chain;  // the chain's running bit: q_m[i] = q_m[i-1] ^ data_i[i] (XNOR: inverted)
  always_comb begin
    chain  = data_i[0];
    q_m[0] = chain;
    for (int i = 1; i < 8; i++) begin
      chain  = chain ^ data_i[i] ^ use_xnor;
      q_m[i] = chain;
    end
  end

  // ---------------------------------------------------------------- DC balance
  logic [3:0]        q_m_ones;
  logic signed [4:0] n;  // ones minus zeros of q_m[7:0], in [-8, 8]
  always_comb begin
    q_m_ones = '0;
    for (int i = 0; i < 8; i++) q_m_ones = q_m_ones + {3'b0, q_m[i]};
  end
  assign n = $signed({q_m_ones, 1'b0}) - 5'sd8;

  logic signed [4:0] q8_twice;  // 2 q_m[8]
  logic signed [4:0] not_q8_twice;  // 2 (1 - q_m[8])
  assign q8_twice     = q8 ? 5'sd2 : 5'sd0;
  assign not_q8_twice = q8 ? 5'sd0 : 5'sd2;

  always_comb begin
    if (!de_i) begin
      unique case ({c1_i, c0_i})
        2'b00:   symbol_d = Control00;
        2'b01:   symbol_d = Control01;
        2'b10:   symbol_d = Control10;
        default: symbol_d = Control11;
      endcase
      cnt_d = '0;
    end else if (cnt_q == 5'sd0 || n == 5'sd0) begin
      symbol_d = {!q8, q8, q8 ? q_m : ~q_m};
      cnt_d    = q8 ? cnt_q + n : cnt_q - n;
    end else if ((cnt_q > 5'sd0) == (n > 5'sd0)) begin
      symbol_d = {1'b1, q8, ~q_m};
      cnt_d    = cnt_q + q8_twice - n;
    end else begin
      symbol_d = {1'b0, q8, q_m};
      cnt_d    = cnt_q - not_q8_twice + n;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      symbol_q <= Control00;
      cnt_q    <= '0;
    end else begin
      symbol_q <= symbol_d;
      cnt_q    <= cnt_d;
    end
  end
  assign symbol_o = symbol_q;
endmodule
