// compact_phong_power: cos(s)^n of the narrow Phong formats (twin: PhongShader::power_narrow;
// docs/reference/compact-phong.md) in a compact shader's fixed schedule of 5 clocks per input: one
// 16 x 16 multiplier (MAC16) for the three products (log interpolation, n lc, exp interpolation,
// in phases 3, 0 and 1 of successive periods), the log and the exp table in one block RAM each,
// each read twice per input (rows i and i + 1 in phases 1, 2 and 3, 4). The parent's schedule
// drives it: ph_i is its phase (0..4), en_i its enable (low: every register holds), take_i an
// input in a period's last clock (phase 4).
// Latency 16 clocks: the power of the input taken in clock t - 1 is pow_o in clocks t + 15 ..
// t + 19 (the whole of its fourth period), valid_o with it. Registered: pow_o, valid_o, every
// product (operands from registers, the product with its addend in one register); no block-RAM
// output feeds the multiplier. A value lives at most 5 clocks in its register (the next input
// writes it 5 clocks later), so fields that wait longer are copied once. The row registers count
// up between their two reads (no address multiplexer), and LG[i] and EH[i] share one register.
// The schedule, clock t of an input (t = -1 its take, phase 4; t = 5p + ph after it):
//   t -1     from cs_i: msb(cs), the log row i, the 8 bits d below it, K = 16 - msb
//   t 1, 2   LG[i], LG[i + 1] read (rows i and i + 1 mod 256)
//   t 3      the multiplier's operands: (LG[i+1] - LG[i]) mod 2^16, d, addend LG[i] 2^8 + 2^7
//   t 4      lx 2^8 = the product plus the addend
//   t 5      lc = K 2^16 - lx, the operands of n lc (lc or lc >> 5, n or n 2^5), kill (n > 16)
//   t 6      et = n lc
//   t 7      ei = et >> 16, the exp row and the 8 bits below it, kill (ei > 16)
//   t 8, 9   EH[i], EH[i + 1] read
//   t 10     (EH[i+1] - EH[i]) mod 2^16
//   t 11     the multiplier's operands: the slope, d, addend EH[i] 2^8 + 2^7
//   t 12     h 2^8 = the product plus the addend
//   t 13     2^17 - h
//   t 14     pow = min(round((2^17 - h) / 2^(ei + 1)), 2^16 - 1), 0 when killed or cs = 0
module compact_phong_power (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic        en_i,     // the parent's enable: every register moves
  input  logic [2:0]  ph_i,     // the parent's phase, 0..4
  input  logic        take_i,   // an input this clock (phase 4)
  input  logic [16:0] cs_i,     // cos(s), 16 fraction bits, 0..2^16
  input  logic [7:0]  n_i,      // n, 0..255
  output logic        valid_o,  // pow_o is the power of the input taken 16 clocks ago (.. 20)
  output logic [15:0] pow_o     // cos(s)^n, 16 fraction bits
);
  localparam int unsigned G = 30;  // fraction bits of the tables' integer algorithms

  // ---------------------------------------------------------------- the tables
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

  logic p0, p1, p2, p3, p4;
  assign p0 = ph_i == 3'd0;
  assign p1 = ph_i == 3'd1;
  assign p2 = ph_i == 3'd2;
  assign p3 = ph_i == 3'd3;
  assign p4 = ph_i == 3'd4;

  // ---------------------------------------------------------------- t -1: msb, row, fraction
  // Worked out from cs_i at the take, so cs itself is never held.
  logic [4:0]  e;    // msb(cs), 0 for cs = 0
  logic [15:0] x;    // the bits below cs's leading one, left-aligned
  always_comb begin
    e = '0;
    for (int b = 1; b <= 16; b++)
      if (cs_i[b]) e = 5'(b);
  end
  assign x = 16'(cs_i << (5'd16 - e));
  logic [7:0] i0_q, d0_q;  // t -1 .. 3
  logic [7:0] n_q;         // t -1 .. 0
  logic [4:0] k_q;
  logic       z_q;
  logic [7:0] n0_q;        // t 0 .. 5: the next take rewrites n_q, k_q and z_q at t 4
  logic [4:0] k0_q;
  logic       z0_q;

  // ---------------------------------------------------------------- the block RAMs
  logic [15:0] lg_rd_q, eh_rd_q, ta_q;
  logic [7:0]  i7_q, d7_q;  // the exp row and fraction: t 7 .. 11
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      lg_rd_q <= log_rom[i0_q];  // LG[i] at t 1, LG[i + 1] at t 2 (i0_q counts up at t 1)
      eh_rd_q <= exp_rom[i7_q];  // EH[i] at t 8, EH[i + 1] at t 9 (i7_q counts up at t 8)
    end
  end

  // ---------------------------------------------------------------- the multiplier
  // Operands in phase 3 (log), 0 (n lc) and 1 (exp); the product with its addend a clock later.
  logic [15:0] ma_q;
  logic [12:0] mb_q;
  logic [23:0] mc_q;
  logic [28:0] mp_q;

  // ---------------------------------------------------------------- t 5: lc and n lc's operands
  logic [16:0] lx;
  logic [20:0] lc;
  logic        lc_small;
  assign lx    = mp_q[24:8];
  assign lc    = {k0_q, 16'd0} - {4'd0, lx};
  assign lc_small = lc[20:16] == 5'd0;
  logic        kill5_q;  // t 5 .. 7

  // ---------------------------------------------------------------- t 7 .. 14: exp
  logic [4:0]  ei7_q, ei10_q;
  logic        kill7_q, kill10_q;
  // Every slope of both tables, (T[i+1] - T[i]) mod 2^16, is below 2^9 (LG's at most 369, EH's
  // 355), so their low 9 bits are the whole slope.
  logic [8:0]  lg_slope, slope10_q;
  assign lg_slope = lg_rd_q[8:0] - ta_q[8:0];
  logic [17:0] num_q;
  logic [17:0] sh;
  logic [16:0] r;
  assign sh = num_q >> ei10_q;
  assign r  = 17'((sh + 18'd1) >> 1);
  logic [3:0]  vp_q;   // an input's period: taken, 1, 2, 3
  logic [15:0] pow_q;
  assign pow_o   = pow_q;
  assign valid_o = vp_q[3];

  always_ff @(posedge clk_i) begin
    if (!rst_ni) vp_q <= '0;
    else if (en_i && p4) vp_q <= {vp_q[2:0], take_i};
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      if (p4 && take_i) begin  // t -1
        i0_q <= x[15:8];
        d0_q <= x[7:0];
        k_q  <= 5'd16 - e;
        n_q  <= n_i;
        z_q  <= cs_i == 17'd0;
      end
      if (p0) begin  // t 0
        k0_q <= k_q;
        n0_q <= n_q;
        z0_q <= z_q;
      end
      if (p1) i0_q <= i0_q + 8'd1;  // t 1: row i + 1 for t 2's read
      if (p3) i7_q <= i7_q + 8'd1;  // t 8
      // One register holds LG[i] (t 2 .. 3) and EH[i] (t 9 .. 11): their lives never meet.
      if (p2) ta_q <= lg_rd_q;  // t 2: LG[i]
      // The multiplier's operands.
      if (p3) begin  // t 3: the log interpolation
        ma_q <= {7'd0, lg_slope};
        mb_q <= 13'(d0_q);
        mc_q <= {ta_q, 8'd128};
      end else if (p0) begin  // t 5: n lc
        ma_q <= lc_small ? lc[15:0] : lc[20:5];
        mb_q <= lc_small ? 13'(n0_q) : {n0_q, 5'd0};
        mc_q <= '0;
      end else if (p1) begin  // t 11: the exp interpolation
        ma_q <= {7'd0, slope10_q};
        mb_q <= 13'(d7_q);
        mc_q <= {ta_q, 8'd128};
      end
      mp_q <= 29'(ma_q) * 29'(mb_q) + 29'(mc_q);
      if (p0) kill5_q <= z0_q || (!lc_small && n0_q > 8'd16);  // t 5
      if (p2) begin  // t 7: et = mp_q
        i7_q    <= mp_q[15:8];
        d7_q    <= mp_q[7:0];
        ei7_q   <= mp_q[20:16];
        kill7_q <= kill5_q || mp_q[28:16] > 13'd16;
      end
      if (p4) ta_q <= eh_rd_q;  // t 9: EH[i]
      if (p0) begin  // t 10
        slope10_q <= eh_rd_q[8:0] - ta_q[8:0];
        ei10_q    <= ei7_q;
        kill10_q  <= kill7_q;
      end
      if (p3) num_q <= 18'h20000 - 18'(mp_q[24:8]);  // t 13: 2^17 - h
      if (p4) pow_q <= kill10_q ? 16'd0 : (r[16] ? 16'hffff : r[15:0]);  // t 14
    end
  end
endmodule
