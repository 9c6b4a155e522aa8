// phong_power: cos(s)^n of the narrow Phong formats (docs/reference/compact-phong.md, "The power
// from block RAM"), exactly PhongShader::power_narrow (model/twins/phong_shader.hpp): -log2 cs
// from the log table with linear interpolation, times n, 2^-(that) from the exp table with linear
// interpolation; three products, two 256 x 16 block RAMs, each read twice per input (rows i and
// i + 1 in consecutive clocks). cs has 16 fraction bits (0..2^16), the power 16 (0..2^16 - 1);
// cs = 0 gives 0.
// Latency 15 clocks (the take's clock to the first clock valid_o is high). One input every other
// enabled clock: ready_o is a flop that toggles on every enabled clock, so two inputs are at least
// two clocks apart and the two reads of a table never meet. en_i moves every register (the
// parent's schedule enable); with it low the block holds. Every register is a flop; each product
// is registered in its multiplier, from registered operands, and no block-RAM output feeds a
// multiplier.
// Stages (a clock each): 0 the input | 1 msb, log row and fraction | 2 the log table's second
// read | 3 log slope | 4 log product operands | 5 log product | 6 lc and the n product's operands
// | 7 n lc | 8 exp row | 9 the exp table's second read | 10 exp slope | 11 exp product operands |
// 12 exp product | 13 2^17 - h | 14 the shift and round: pow_o.
module phong_power (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic        en_i,     // every register moves (the parent's schedule enable)
  input  logic        valid_i,  // cs_i and n_i are an input (taken when ready_o and en_i)
  output logic        ready_o,  // a flop: high every other enabled clock
  input  logic [16:0] cs_i,     // cos(s), 16 fraction bits, 0..2^16
  input  logic [7:0]  n_i,      // the exponent n, 0..255
  output logic        valid_o,
  output logic [15:0] pow_o     // cos(s)^n, 16 fraction bits
);
  localparam int unsigned Stages = 15;
  localparam int unsigned G = 30;  // fraction bits of the tables' integer algorithms

  // ---------------------------------------------------------------- the tables
  // The same integer algorithms as PhongPowerTables (model/twins/phong_shader.hpp), 64-bit words:
  // log_row(i) = round(2^16 log2(1 + i/256)), exp_row(i) = (2^17 - round(2^17 2^(-i/256))) mod
  // 2^16. Filled at elaboration, read synchronously, so synthesis maps each to one block RAM.
  function automatic logic [63:0] isqrt(input logic [63:0] v);
    logic [63:0] rem, root, b;
    rem  = v;
    root = '0;
    for (int i = 31; i >= 0; i--) begin
      b = 64'd1 << (2 * i);
      if (rem >= root + b) begin
        rem  = rem - (root + b);
        root = (root >> 1) + b;
      end else begin
        root = root >> 1;
      end
    end
    isqrt = root;
  endfunction

  /* verilator lint_off UNUSEDSIGNAL */
  function automatic logic [15:0] log_row(input int i);
    logic [63:0] x, r;
    x = (64'd256 + 64'(i)) << (G - 8);
    r = '0;
    for (int b = 0; b < 17; b++) begin
      x = (x * x) >> G;
      r = r << 1;
      if ((x >> (G + 1)) != 64'd0) begin
        r = r | 64'd1;
        x = x >> 1;
      end
    end
    r = (r + 64'd1) >> 1;
    log_row = r[15:0];
  endfunction

  function automatic logic [15:0] exp_row(input int i);
    logic [63:0] c, p, q;
    c = 64'd1 << (G - 1);
    p = 64'd1 << G;
    for (int b = 1; b <= 8; b++) begin
      c = isqrt(c << G);
      if (((i >> (8 - b)) & 1) != 0) p = (p * c) >> G;
    end
    q = (p + (64'd1 << (G - 18))) >> (G - 17);
    q = (64'd1 << 17) - q;
    exp_row = q[15:0];
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */

  logic [15:0] log_rom [256];
  logic [15:0] exp_rom [256];
  initial begin
    for (int i = 0; i < 256; i++) begin
      log_rom[i] = log_row(i);
      exp_rom[i] = exp_row(i);
    end
  end

  // ---------------------------------------------------------------- flow
  logic             rdy_q;
  logic [Stages-1:0] v_q;
  logic             take;
  assign take    = valid_i && rdy_q;
  assign ready_o = rdy_q;
  assign valid_o = v_q[Stages-1];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rdy_q <= 1'b1;
      v_q   <= '0;
    end else if (en_i) begin
      rdy_q <= !rdy_q;
      v_q   <= {v_q[Stages-2:0], take};
    end
  end

  // ---------------------------------------------------------------- 0: the input
  logic [16:0] cs0_q;
  logic [7:0]  n0_q;

  // ---------------------------------------------------------------- 1: msb, row and fraction
  // cs = x 2^(e - 16), x = cs << (16 - e) in [2^16, 2^17): the row is x[15:8], the fraction x[7:0].
  logic [4:0]  e0;   // msb(cs), 0 for cs = 0
  logic [15:0] x0;   // x's bits below its leading one
  always_comb begin
    e0 = '0;
    for (int b = 1; b <= 16; b++)
      if (cs0_q[b]) e0 = 5'(b);
  end
  assign x0 = 16'(cs0_q << (5'd16 - e0));

  logic [7:0] i1_q, d1_q, n1_q;
  logic [4:0] k1_q;   // 16 - e: the integer part of -log2 cs
  logic       z1_q;   // cs = 0

  // ---------------------------------------------------------------- 2, 3: the log table's reads
  logic [7:0]  i2_q, d2_q, n2_q;
  logic [4:0]  k2_q;
  logic        z2_q;
  logic [15:0] lg_rd_q;   // LG[i] in stage 2's clock, LG[i + 1] in stage 3's
  logic [7:0]  d3_q, n3_q;
  logic [4:0]  k3_q;
  logic        z3_q;
  logic [15:0] lga3_q;    // LG[i]

  // ---------------------------------------------------------------- 4, 5: the log product
  logic [15:0] slope4_q, lga4_q;  // (LG[i+1] - LG[i]) mod 2^16: row 255's successor is row 0
  logic [7:0]  d4_q, n4_q;
  logic [4:0]  k4_q;
  logic        z4_q;
  logic [23:0] p5_q;
  logic [15:0] lga5_q;
  logic [7:0]  n5_q;
  logic [4:0]  k5_q;
  logic        z5_q;

  // ---------------------------------------------------------------- 6: lc and n lc's operands
  // lx = LG[i] + round(slope d / 2^8) in [0, 2^16]; lc = k 2^16 - lx in [0, 16 2^16]. lc < 2^16:
  // n lc as it is; else n > 16 gives a power of 0, n <= 16 (n 2^5)(lc >> 5).
  logic [16:0] lx5;
  logic [20:0] lc5;
  logic        small5;
  assign lx5    = {1'b0, lga5_q} + 17'((p5_q + 24'd128) >> 8);
  assign lc5    = {k5_q, 16'd0} - {4'd0, lx5};
  assign small5 = lc5[20:16] == 5'd0;
  logic [15:0] a6_q;
  logic [12:0] b6_q;
  logic        kill6_q;

  // ---------------------------------------------------------------- 7: n lc
  logic [28:0] et7_q;   // 16 fraction bits
  logic        kill7_q;

  // ---------------------------------------------------------------- 8, 9: the exp table's reads
  logic [7:0]  i8_q, d8_q, i9_q, d9_q;
  logic [4:0]  ei8_q, ei9_q;
  logic        kill8_q, kill9_q;
  logic [15:0] eh_rd_q;   // EH[i] in stage 9's clock, EH[i + 1] in stage 10's
  logic [7:0]  d10_q;
  logic [4:0]  ei10_q;
  logic        kill10_q;
  logic [15:0] eha10_q;

  // ---------------------------------------------------------------- 11, 12: the exp product
  logic [15:0] slope11_q, eha11_q;
  logic [7:0]  d11_q;
  logic [4:0]  ei11_q;
  logic        kill11_q;
  logic [23:0] p12_q;
  logic [15:0] eha12_q;
  logic [4:0]  ei12_q;
  logic        kill12_q;

  // ---------------------------------------------------------------- 13, 14: 2^17 - h, the shift
  // h = EH[i] + round(slope d / 2^8) ~ 2^17 - 2^(17 - ef) in [0, 2^16]; pow = min(round(
  // (2^17 - h) / 2^(ei + 1)), 2^16 - 1) = min((((2^17 - h) >> ei) + 1) >> 1, 2^16 - 1).
  logic [16:0] h12;
  assign h12 = {1'b0, eha12_q} + 17'((p12_q + 24'd128) >> 8);
  logic [17:0] num13_q;
  logic [4:0]  ei13_q;
  logic        kill13_q;
  logic [17:0] sh13;
  logic [16:0] r13;
  assign sh13 = num13_q >> ei13_q;
  assign r13  = 17'((sh13 + 18'd1) >> 1);
  logic [15:0] pow14_q;
  assign pow_o = pow14_q;

  // The tables' addresses: rows i and i + 1 of the item in stage 1 or 2 (8 or 9); two items are
  // two clocks apart, so at most one of the two stages holds one.
  logic [7:0] lg_addr, eh_addr;
  assign lg_addr = v_q[1] ? i1_q : i2_q + 8'd1;
  assign eh_addr = v_q[8] ? i8_q : i9_q + 8'd1;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      lg_rd_q <= log_rom[lg_addr];
      eh_rd_q <= exp_rom[eh_addr];
    end
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      if (take) begin
        cs0_q <= cs_i;
        n0_q  <= n_i;
      end
      // 1
      i1_q <= x0[15:8];
      d1_q <= x0[7:0];
      k1_q <= 5'd16 - e0;
      n1_q <= n0_q;
      z1_q <= cs0_q == 17'd0;
      // 2
      i2_q <= i1_q;
      d2_q <= d1_q;
      k2_q <= k1_q;
      n2_q <= n1_q;
      z2_q <= z1_q;
      // 3
      lga3_q <= lg_rd_q;
      d3_q   <= d2_q;
      k3_q   <= k2_q;
      n3_q   <= n2_q;
      z3_q   <= z2_q;
      // 4
      slope4_q <= lg_rd_q - lga3_q;
      lga4_q   <= lga3_q;
      d4_q     <= d3_q;
      k4_q     <= k3_q;
      n4_q     <= n3_q;
      z4_q     <= z3_q;
      // 5
      p5_q   <= 24'(slope4_q) * 24'(d4_q);
      lga5_q <= lga4_q;
      n5_q   <= n4_q;
      k5_q   <= k4_q;
      z5_q   <= z4_q;
      // 6
      a6_q    <= small5 ? lc5[15:0] : lc5[20:5];
      b6_q    <= small5 ? 13'(n5_q) : {n5_q, 5'd0};
      kill6_q <= z5_q || (!small5 && n5_q > 8'd16);
      // 7
      et7_q   <= 29'(a6_q) * 29'(b6_q);
      kill7_q <= kill6_q;
      // 8
      i8_q    <= et7_q[15:8];
      d8_q    <= et7_q[7:0];
      ei8_q   <= et7_q[20:16];
      kill8_q <= kill7_q || et7_q[28:16] > 13'd16;
      // 9
      i9_q    <= i8_q;
      d9_q    <= d8_q;
      ei9_q   <= ei8_q;
      kill9_q <= kill8_q;
      // 10
      eha10_q  <= eh_rd_q;
      d10_q    <= d9_q;
      ei10_q   <= ei9_q;
      kill10_q <= kill9_q;
      // 11
      slope11_q <= eh_rd_q - eha10_q;
      eha11_q   <= eha10_q;
      d11_q     <= d10_q;
      ei11_q    <= ei10_q;
      kill11_q  <= kill10_q;
      // 12
      p12_q    <= 24'(slope11_q) * 24'(d11_q);
      eha12_q  <= eha11_q;
      ei12_q   <= ei11_q;
      kill12_q <= kill11_q;
      // 13
      num13_q  <= 18'h20000 - 18'(h12);
      ei13_q   <= ei12_q;
      kill13_q <= kill12_q;
      // 14
      pow14_q <= kill13_q ? 16'd0 : (r13[16] ? 16'hffff : r13[15:0]);
    end
  end
endmodule
