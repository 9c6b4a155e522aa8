// compact_phong_shader: Phong's shading rule per pixel, S = Cp [cos(i)(1-d) + d] + W cos(s)^n
// (Phong 1975 eq. 3, cos(s) = 2(N.L)(N.E) - L.E, the power by square-and-multiply over the 8
// bits of n), over twelve 16 x 16 multipliers (MAC16) in a fixed schedule of 5 clocks per
// pixel. Drop-in for rtl/phong_shader.sv (the same ports and parameters; values twin:
// PhongShader::shade, model/twins/phong_shader.hpp; cycle twin:
// model/twins/compact_phong_shader_timing.hpp).
// Timing: a period is 5 clocks; a pixel is taken in a period's last clock (ready_o, a flop) and
// loaded into the output register on clock 63 after it (phase 3 of its thirteenth period); a
// load that finds the output holding a shade not taken stalls every register for a clock
// (compact_schedule). Latency 65 cycles (from the take's clock to the first clock offered); at
// full rate one pixel per 5 clocks. light_i and eye_i are frame constants: L.E is worked out from
// them in every period, so they must be stable from 10 clocks before a frame's first pixel is
// taken to its last shade.
// Registered: every output; every multiplier's operands and product (the MAC16's own registers).
// The schedule, clock t of a pixel (t = 0 the clock after the take; a register is written once
// per period, so a value lives 5 clocks and is copied when it is read later):
//   t 0..2    F1: N_c L_c, F2: N_c E_c (operands; products t 1..3);  t 2..4: N.L, N.E
//   t 5       cos(i) = round(N.L) >= 0, N.E rounded (D = 24 fraction bits)
//   t 6..9    F3: cos(i) (N.E + 2) as four partial products (N.E offset to be unsigned; the
//             offset's cos(i) 2^(D+1) starts the sum);  t 8..11: cos(i)(N.E)
//   t 9, 10   F2: cos(i)_hi (1-d), F3: cos(i)_lo (1-d);  t 11, 12: f = cos(i)(1-d) + d
//   t 12      cos(s) = clamp(round(2 cos(i)(N.E) - L.E)) and the power's start: base, acc
//   t 13..57  power step k = 0..7 over clocks 13 + 5k .. 19 + 5k: base^2 (two partial products)
//             and acc base (three; acc unchanged for a clear bit k of n); the first step's acc
//             base is a select (acc is 0 or 1.0), the last needs no base^2: the two share one
//             multiplier, the other six have one each
//   t 50..52  Cp, W and f from the RAM;  t 53..59  B1, B2: Cp_c f (two partial products per
//             channel) and 255 W cos(s)^n (two), their sums;  t 59..61 the levels, rounded and
//             saturated;  t 63 the output register
// The payload, Cp with W, and f wait in one RAM (a word each per slot, sixteen slots), n and d in
// registers that move a period at a time.
`include "watkins_assert.svh"

module compact_phong_shader #(
  parameter int PayloadBits      = 1,     // carried alongside (pixel x, ...)
  /* verilator lint_off UNUSEDPARAM */
  parameter bit LookAhead        = 1'b0,  // accepted: ready_o is a flop here
  /* verilator lint_on UNUSEDPARAM */
  localparam int UnitBits        = watkins_pkg::UnitBits,
  localparam int MaterialBits    = watkins_pkg::MaterialBits,
  localparam int ShininessBits   = watkins_pkg::ShininessBits   // also the number of power steps
) (
  input  logic                     clk_i,
  input  logic                     rst_ni,
  input  logic [3*UnitBits-1:0]    light_i,      // {Lz, Ly, Lx}: unit, Q2.14, constant per frame
  input  logic [3*UnitBits-1:0]    eye_i,        // {Ez, Ey, Ex}: unit, Q2.14, constant per frame
  input  logic [3*UnitBits-1:0]    normal_i,     // {Nz, Ny, Nx}: unit normal, Q2.14 (normalizer)
  input  watkins_pkg::rgb_t        cp_i,         // reflectance Cp, 8-bit (255 = 1.0)
  input  logic [MaterialBits-1:0]  d_i,          // diffuse coefficient d, 1.0 = 256 (clamped to 1)
  input  logic [MaterialBits-1:0]  w_i,          // specular coefficient W, 1.0 = 256
  input  logic [ShininessBits-1:0] shininess_i,  // exponent n, 0..255
  input  logic [PayloadBits-1:0]   payload_i,
  input  logic                     valid_i,
  output logic                     ready_o,
  output watkins_pkg::rgb_t        rgb_o,        // shade, 8-bit levels, saturated
  output logic [PayloadBits-1:0]   payload_o,
  output logic                     valid_o,
  input  logic                     ready_i,
  /* verilator lint_off UNUSEDSIGNAL */
  input  logic                     ready_next_i, // accepted: ready_o does not depend on ready_i
  /* verilator lint_on UNUSEDSIGNAL */
  output logic                     ready_next_o  // ready_o on the next clock
);
  // The comments write the two Phong formats as the model's formulas do: D and P.
  localparam int UnitFracBits     = watkins_pkg::UnitFracBits;      // 14
  localparam int DotBits          = watkins_pkg::PhongDotBits;      // D = 24
  localparam int PowBits          = watkins_pkg::PhongPowBits;      // P = 20
  localparam int MaterialFracBits = watkins_pkg::MaterialFracBits;  // 8
  localparam int RgbBits          = watkins_pkg::RgbBits;
  localparam int Digit            = 16;                             // a multiplier operand
  localparam int Periods          = 13;                             // periods a pixel spends inside
  localparam int SlotBits         = 4;                              // 16 RAM slots >= Periods
  localparam int DotProductBits   = 2 * UnitBits + 2;               // N.L exact: 34 bits signed
  localparam int CosBits          = DotBits + 2;                    // cos(i), N.E: 26 bits signed
  localparam int CosSExactBits    = 2 * DotBits + 6;                // 2 cos(i)(N.E) - L.E exact
  localparam int CosSShift        = 2 * DotBits - PowBits;          // cos(s)'s rounding shift: 28
  localparam int DiffuseBits      = DotBits + MaterialFracBits + 1; // f <= 2: 33 bits
  localparam int PowWordBits      = PowBits + 1;                    // base, acc <= 1.0: 21 bits
  localparam int PowSumBits       = 2 * PowBits + 3;                // a power product and its half
  localparam int LevelSumBits     = DiffuseBits + 8 + 2;            // Cp f + 255 W pow, 43 bits
  localparam int OutFracBits      = DotBits + MaterialFracBits;     // 32
  localparam int WideBits         = MaterialBits + 8;               // 255 W: 17 bits
  localparam int RamBits          = PayloadBits > DiffuseBits ? PayloadBits : DiffuseBits;
  localparam logic [PowWordBits-1:0] One = PowWordBits'(1) << PowBits;

  // ---- the schedule's control ---------------------------------------------------------------
  logic [2:0]          ph_q;
  logic [SlotBits-1:0] pc_q;
  logic                en, tick, out_load;
  compact_schedule #(.Periods(Periods), .LoadPhase(3), .SlotBits(SlotBits)) u_schedule (
    .clk_i, .rst_ni, .valid_i, .ready_o, .ready_next_o, .valid_o, .ready_i,
    .ph_o(ph_q), .pc_o(pc_q), .en_o(en), .tick_o(tick), .load_o(out_load));

  // ---- the take: N, and n with d (clamped to 1.0) in the registers that move a period a time --
  localparam int MatBits = ShininessBits + MaterialBits;  // {n, d}
  logic [3*UnitBits-1:0]           n0_q;
  logic [MaterialBits+RgbBits-1:0] cw0_q;  // {W, Cp}, into the RAM at t 0
  logic [MatBits-1:0]              mat_q [Periods-2];  // [p]: {n, d} of the pixel in period p
  always_ff @(posedge clk_i) if (tick) begin
    n0_q     <= normal_i;
    cw0_q    <= {w_i, cp_i};
    mat_q[0] <= {shininess_i, d_i > MaterialBits'(1 << MaterialFracBits)
                              ? MaterialBits'(1 << MaterialFracBits) : d_i};
    for (int p = 1; p < Periods - 2; p++) mat_q[p] <= mat_q[p-1];
  end

  // ---- the RAM: slot s holds the payload, {W, Cp} and f at 4s, 4s + 1, 4s + 2 ------------------
  // Written: the payload in the take clock, {W, Cp} at t 0, f at t 13. Read: {W, Cp} at t 50,
  // f at t 51, the payload at t 62 (one read register).
  logic [RamBits-1:0]     sram [4 * (1 << SlotBits)];
  logic [RamBits-1:0]     rd_q;
  logic                   we, re;
  logic [SlotBits+1:0]    wa, ra;
  logic [RamBits-1:0]     wd;
  logic [DiffuseBits-1:0] f_q;  // f, t 13..16
  always_comb begin
    we = ph_q == 3'd4 || ph_q == 3'd0 || ph_q == 3'd3;
    re = ph_q <= 3'd2;
    case (ph_q)
      3'd4:    begin wa = {pc_q + 1'b1, 2'd0};           wd = RamBits'(payload_i); end
      3'd0:    begin wa = {pc_q, 2'd1};                  wd = RamBits'(cw0_q); end
      default: begin wa = {pc_q - SlotBits'(2), 2'd2};   wd = RamBits'(f_q); end
    endcase
    case (ph_q)
      3'd0:    ra = {pc_q - SlotBits'(10), 2'd1};
      3'd1:    ra = {pc_q - SlotBits'(10), 2'd2};
      default: ra = {pc_q - SlotBits'(12), 2'd0};
    endcase
  end
  always_ff @(posedge clk_i) if (en) begin
    if (we) sram[wa] <= wd;
    if (re) rd_q <= sram[ra];
  end

  // ---- F1, F2 (signed): N.L and N.E at t 0..2, L.E (frame constant) at phases 3, 4; F2 also
  // cos(i)_hi (1 - d) at t 9 ------------------------------------------------------------------
  logic signed [CosBits-1:0] cosi_q, ne_q;  // t 6..10
  logic [MaterialBits-1:0]   omd1, omd2;    // 1 - d of the pixel in period 1 (t 9), 2 (t 10)
  logic signed [2*Digit-1:0] pf1_q, pf2_q;
  logic [Digit-1:0]          nx, ny, nz, lx, ly, lz, ex, ey, ez;
  assign {nz, ny, nx} = n0_q;
  assign {lz, ly, lx} = light_i;
  assign {ez, ey, ex} = eye_i;
  assign omd1 = MaterialBits'(1 << MaterialFracBits) - mat_q[1][MaterialBits-1:0];
  assign omd2 = MaterialBits'(1 << MaterialFracBits) - mat_q[2][MaterialBits-1:0];
  mac16_phased #(.Signed(1'b1)) u_f1 (
    .clk_i, .en_i(en), .ph_i(ph_q), .a_i({ly, lx, nz, ny, nx}), .b_i({ey, ex, lz, ly, lx}), .p_o(pf1_q));
  mac16_phased #(.Signed(1'b1)) u_f2 (
    .clk_i, .en_i(en), .ph_i(ph_q), .a_i({Digit'(cosi_q[CosBits-2:Digit]), lz, nz, ny, nx}),
    .b_i({Digit'(omd1), ez, ez, ey, ex}), .p_o(pf2_q));

  // round(v / 2^(2 UnitFracBits - D)), clamped to [0 or -2, 2 - 2^-D]: the register's range.
  localparam logic signed [DotProductBits-1:0] DotHalf = DotProductBits'(1 << (2 * UnitFracBits - DotBits - 1));
  localparam logic signed [DotProductBits-1:0] DotHi   = (DotProductBits'(1) <<< (CosBits - 1)) - 1;
  localparam logic signed [DotProductBits-1:0] DotLo   = -(DotProductBits'(1) <<< (CosBits - 1));
  function automatic logic signed [CosBits-1:0] round_dot(
      input logic signed [DotProductBits-1:0] v, input logic neg_ok);
    logic signed [DotProductBits-1:0] r;
    r = (v + DotHalf) >>> (2 * UnitFracBits - DotBits);
    if (r < 0 && !neg_ok) round_dot = '0;
    else if (r < DotLo)   round_dot = DotLo[CosBits-1:0];
    else if (r > DotHi)   round_dot = DotHi[CosBits-1:0];
    else                  round_dot = r[CosBits-1:0];
  endfunction

  // N.L and N.E at t 2..4; cos(i) and N.E at t 5. L.E from the products of phases 3 and 4:
  // its sum at phases 0 and 1, rounded at 2, cos(s)'s offsets at 3.
  logic signed [DotProductBits-1:0] ndl_q, nde_q, les_q;
  logic signed [CosBits-1:0]        le_q;
  logic signed [CosSExactBits-1:0]  cs_k_q, cs_o_q, cs_p_q;  // as phong_shader's
  always_ff @(posedge clk_i) if (en) begin
    if (ph_q >= 3'd2) begin
      ndl_q <= (ph_q == 3'd2 ? '0 : ndl_q) + DotProductBits'(pf1_q);
      nde_q <= (ph_q == 3'd2 ? '0 : nde_q) + DotProductBits'(pf2_q);
    end
    if (ph_q == 3'd0) begin
      cosi_q <= round_dot(ndl_q, 1'b0);
      ne_q   <= round_dot(nde_q, 1'b1);
      les_q  <= DotProductBits'(pf1_q) + DotProductBits'(pf2_q);
    end
    if (ph_q == 3'd1) les_q <= les_q + DotProductBits'(pf1_q);
    if (ph_q == 3'd2) le_q <= round_dot(les_q, 1'b1);
    if (ph_q == 3'd3) begin
      cs_k_q <= CosSExactBits'(1 <<< (CosSShift - 1)) - (CosSExactBits'(le_q) <<< DotBits);
      cs_o_q <= CosSExactBits'(1 <<< (CosSShift - 1)) - (CosSExactBits'(le_q) <<< DotBits)
              - (CosSExactBits'((1 << PowBits) + 1) <<< CosSShift);
      cs_p_q <= CosSExactBits'(1 <<< (CosSShift - 1)) - (CosSExactBits'(le_q) <<< DotBits)
              - (CosSExactBits'(1) <<< CosSShift);
    end
  end

  // ---- F3 (unsigned): cos(i) (N.E + 2) at t 6..9, cos(i)_lo (1 - d) at t 10 -------------------
  // cos(i)(N.E) = cos(i)(N.E + 2) - cos(i) 2^(D+1): the offset's product starts the sum.
  logic [CosBits-1:0]     nep;  // N.E + 2, unsigned
  logic [2*Digit-1:0]     pf3_q;
  logic [Digit-1:0]       c0, c1, e0, e1;
  assign nep = ne_q + (CosBits'(1) << (CosBits - 1));
  assign c0  = cosi_q[Digit-1:0];
  assign c1  = Digit'(cosi_q[CosBits-2:Digit]);
  assign e0  = nep[Digit-1:0];
  assign e1  = Digit'(nep[CosBits-1:Digit]);
  mac16_phased u_f3 (
    .clk_i, .en_i(en), .ph_i(ph_q), .a_i({c1, c1, c0, c0, c0}), .b_i({e1, e0, e1, e0, Digit'(omd2)}),
    .p_o(pf3_q));

  // cos(i)(N.E) at t 8..11 (readable t 12); f at t 11, 12 (readable t 13..16).
  logic signed [CosSExactBits-1:0] cne_q;
  logic                            front_q;  // cos(i) > 0, t 11..15
  always_ff @(posedge clk_i) if (en) begin
    case (ph_q)
      3'd3:    cne_q <= CosSExactBits'(pf3_q) - (CosSExactBits'(cosi_q) <<< (CosBits - 1));
      3'd4, 3'd0: cne_q <= cne_q + (CosSExactBits'(pf3_q) <<< Digit);
      3'd1:    cne_q <= cne_q + (CosSExactBits'(pf3_q) <<< (2 * Digit));
      default: ;
    endcase
    if (ph_q == 3'd0) front_q <= cosi_q != '0;
    if (ph_q == 3'd1)
      f_q <= (DiffuseBits'(pf2_q[2*MaterialBits-1:0]) << Digit)
           + (DiffuseBits'(mat_q[2][MaterialBits-1:0]) << DotBits);
    if (ph_q == 3'd2) f_q <= f_q + DiffuseBits'(pf3_q[Digit+MaterialBits-1:0]);
  end

  // ---- t 12: cos(s) in [0, 1] (P bits) and the power's start ------------------------------------
  // cs = (2 cos(i)(N.E) + cs_k) >> CosSShift is cos(s) rounded; cs > 1.0, cs < 0 and cs > 0 are the
  // signs of three sums (phong_shader's stage 6).
  logic [PowWordBits-1:0] base0_q, acc0_q;  // t 13..17
  always_ff @(posedge clk_i) if (en && ph_q == 3'd2) begin
    /* verilator lint_off UNUSEDSIGNAL */
    logic signed [CosSExactBits-1:0] cs2, cs_o, cs_p;  // cs's bits below CosSShift and above P
    /* verilator lint_on UNUSEDSIGNAL */
    cs2  = (cne_q <<< 1) + cs_k_q;
    cs_o = (cne_q <<< 1) + cs_o_q;
    cs_p = (cne_q <<< 1) + cs_p_q;
    if (!cs_o[CosSExactBits-1])    base0_q <= One;
    else if (cs2[CosSExactBits-1]) base0_q <= '0;
    else                           base0_q <= cs2[CosSShift +: PowWordBits];
    acc0_q <= (front_q && !cs_p[CosSExactBits-1]) ? One : '0;
  end

  // ---- P0..P7: power step k at t 13 + 5k .. 19 + 5k ------------------------------------------
  // Operands at phases 3, 4, 0, 1, 2: b_lo b_lo, b_lo b_hi, a_lo b_lo, a_lo b_hi, a_hi b_lo (hi:
  // the top 5 bits; hi x hi in the fabric). base^2 = sq's [2P:P] (sq at phases 0, 1), acc base =
  // ml's (ml at phases 2, 3, 4; a clear bit k loads acc << P instead). The next step reads base
  // from basec_q (phase 2) and acc straight from ml_q (its phases 0..2). The first step's acc is 0
  // or 1.0, so its acc base is a select; the last step's base^2 is not needed: the two share one
  // multiplier (g_pow[0]'s base^2 in phases 3, 4, g_pow[7]'s acc base in 0..2).
  localparam int LastStep = ShininessBits - 1;
  logic [2*Digit-1:0] p07_q;  // the shared multiplier's product
  for (genvar k = 0; k < ShininessBits; k++) begin : g_pow
    logic [PowWordBits-1:0] b, a;
    logic                   nbit;
    logic [2*Digit-1:0]     p;
    /* verilator lint_off UNUSEDSIGNAL */
    logic [PowSumBits-1:0]  ml_q;     // only [2P:P] is read
    /* verilator lint_on UNUSEDSIGNAL */
    if (k == 0) begin : g_first
      assign b = base0_q;
      assign a = acc0_q;
    end else begin : g_next
      assign b = g_pow[k-1].g_square.basec_q;
      assign a = g_pow[k-1].ml_q[PowBits +: PowWordBits];
    end
    assign nbit = mat_q[3+k][MaterialBits+k];
    if (k == 0 || k == LastStep) begin : g_shared
      assign p = p07_q;
    end else begin : g_own
      mac16_phased u_p (
        .clk_i, .en_i(en), .ph_i(ph_q),
        .a_i({b[Digit-1:0], b[Digit-1:0], Digit'(a[PowWordBits-1:Digit]), a[Digit-1:0], a[Digit-1:0]}),
        .b_i({Digit'(b[PowWordBits-1:Digit]), b[Digit-1:0], b[Digit-1:0], Digit'(b[PowWordBits-1:Digit]), b[Digit-1:0]}),
        .p_o(p));
    end
    if (k < LastStep) begin : g_square
      logic [PowSumBits-1:0]  sq_q;
      logic [PowWordBits-1:0] basec_q;
      always_ff @(posedge clk_i) if (en) begin
        if (ph_q == 3'd0)
          sq_q <= PowSumBits'(p) + (PowSumBits'(b[PowWordBits-1:Digit] * b[PowWordBits-1:Digit]) << (2 * Digit))
                + PowSumBits'(1 << (PowBits - 1));
        if (ph_q == 3'd1) sq_q <= sq_q + (PowSumBits'(p) << (Digit + 1));
        if (ph_q == 3'd2) basec_q <= sq_q[PowBits +: PowWordBits];
      end
    end
    if (k == 0) begin : g_select
      always_ff @(posedge clk_i) if (en && ph_q == 3'd2)
        ml_q <= (nbit && a[PowBits]) ? PowSumBits'(b) << PowBits : PowSumBits'(a) << PowBits;
    end else begin : g_multiply
      always_ff @(posedge clk_i) if (en) begin
        case (ph_q)
          3'd2: ml_q <= nbit ? PowSumBits'(p) + (PowSumBits'(a[PowWordBits-1:Digit] * b[PowWordBits-1:Digit]) << (2 * Digit))
                             + PowSumBits'(1 << (PowBits - 1))
                           : PowSumBits'(a) << PowBits;
          3'd3, 3'd4: if (nbit) ml_q <= ml_q + (PowSumBits'(p) << Digit);
          default: ;
        endcase
      end
    end
  end
  logic [PowWordBits-1:0] b0, a7, b7;
  assign b0 = g_pow[0].b;
  assign a7 = g_pow[LastStep].a;
  assign b7 = g_pow[LastStep].b;
  mac16_phased u_p07 (
    .clk_i, .en_i(en), .ph_i(ph_q),
    .a_i({b0[Digit-1:0], b0[Digit-1:0], Digit'(a7[PowWordBits-1:Digit]), a7[Digit-1:0], a7[Digit-1:0]}),
    .b_i({Digit'(b0[PowWordBits-1:Digit]), b0[Digit-1:0], b7[Digit-1:0], Digit'(b7[PowWordBits-1:Digit]), b7[Digit-1:0]}),
    .p_o(p07_q));

  // ---- the output products: Cp, W, f from the RAM; B1, B2 (unsigned) --------------------------
  logic [MaterialBits+RgbBits-1:0] cw_q;    // {W, Cp}, t 52..56
  logic [DiffuseBits-1:0]          fo_q;    // f, t 53..57
  logic [WideBits-1:0]             w255_q;  // 255 W, t 53..57
  logic [15:0]                     cp12_q;  // Cp's bytes 1 and 2, t 57..61
  logic                            f2_q;    // f's top bit, t 57..61
  logic [PowWordBits-1:0]          pw;      // cos(s)^n, t 55..57
  assign pw = g_pow[ShininessBits-1].ml_q[PowBits +: PowWordBits];
  always_ff @(posedge clk_i) if (en) begin
    if (ph_q == 3'd1) cw_q <= rd_q[MaterialBits+RgbBits-1:0];
    if (ph_q == 3'd2) begin
      fo_q   <= rd_q[DiffuseBits-1:0];
      w255_q <= (WideBits'(cw_q[RgbBits +: MaterialBits]) << 8) - WideBits'(cw_q[RgbBits +: MaterialBits]);
    end
    if (ph_q == 3'd1) begin  // t 56
      cp12_q <= cw_q[8 +: 16];
      f2_q   <= fo_q[DiffuseBits-1];
    end
  end
  logic [2*Digit-1:0] pb1_q, pb2_q;
  logic [Digit-1:0]   cp0, cp1, cp2, f0, f1;
  assign cp0 = Digit'(cw_q[0 +: 8]);
  assign cp1 = Digit'(cw_q[8 +: 8]);
  assign cp2 = Digit'(cp12_q[8 +: 8]);
  assign f0  = fo_q[Digit-1:0];
  assign f1  = fo_q[2*Digit-1:Digit];
  mac16_phased u_b1 (
    .clk_i, .en_i(en), .ph_i(ph_q), .a_i({cp0, cp0, cp2, cp1, cp1}), .b_i({f1, f0, f0, f1, f0}),
    .p_o(pb1_q));
  mac16_phased u_b2 (
    .clk_i, .en_i(en), .ph_i(ph_q), .a_i({cp2, cp2, cp2, w255_q[Digit-1:0], w255_q[Digit-1:0]}),
    .b_i({f1, f1, f1, Digit'(pw[PowWordBits-1:Digit]), pw[Digit-1:0]}), .p_o(pb2_q));

  // ---- the levels: Cp_c f + 2^31 per channel (t 55..59), 255 W pow (t 57, 58), then
  // saturate((Cp_c f + 2^31 + 255 W pow 2^(D-P)) >> 32) for channels 0, 1, 2 at t 59, 60, 61 ----
  localparam logic [LevelSumBits-1:0] Half = LevelSumBits'(1) << (OutFracBits - 1);
  logic [LevelSumBits-1:0] d0_q, d1_q, d2_q, spec_q;
  logic [7:0]              r0_q, r1_q, r2_q;
  always_ff @(posedge clk_i) if (en) begin
    logic [LevelSumBits-1:0] dsel, lvl;
    case (ph_q)
      3'd0: d0_q <= LevelSumBits'(pb1_q) + Half
                  + (fo_q[DiffuseBits-1] ? LevelSumBits'(cw_q[0 +: 8]) << (2 * Digit) : '0);
      3'd1: d0_q <= d0_q + (LevelSumBits'(pb1_q) << Digit);
      3'd2: begin
        d1_q   <= LevelSumBits'(pb1_q) + Half + (f2_q ? LevelSumBits'(cp12_q[0 +: 8]) << (2 * Digit) : '0);
        spec_q <= LevelSumBits'(pb2_q) + (w255_q[WideBits-1] ? LevelSumBits'(pw) << Digit : '0);
      end
      3'd3: begin
        d1_q   <= d1_q + (LevelSumBits'(pb1_q) << Digit);
        spec_q <= spec_q + (LevelSumBits'(pb2_q) << Digit);
      end
      default: d2_q <= LevelSumBits'(pb1_q) + (LevelSumBits'(pb2_q) << Digit) + Half
                     + (f2_q ? LevelSumBits'(cp12_q[8 +: 8]) << (2 * Digit) : '0);
    endcase
    case (ph_q)
      3'd4:    dsel = d0_q;
      3'd0:    dsel = d1_q;
      default: dsel = d2_q;
    endcase
    lvl = (dsel + (spec_q << (DotBits - PowBits))) >> OutFracBits;
    case (ph_q)
      3'd4: r0_q <= lvl > LevelSumBits'(255) ? 8'd255 : lvl[7:0];
      3'd0: r1_q <= lvl > LevelSumBits'(255) ? 8'd255 : lvl[7:0];
      3'd1: r2_q <= lvl > LevelSumBits'(255) ? 8'd255 : lvl[7:0];
      default: ;
    endcase
  end

  // ---- t 63: the output register -----------------------------------------------------------------
  logic [RgbBits-1:0]     rgb_q;
  logic [PayloadBits-1:0] payload_q;
  always_ff @(posedge clk_i) if (out_load) begin
    rgb_q     <= {r2_q, r1_q, r0_q};
    payload_q <= rd_q[PayloadBits-1:0];
  end
  assign rgb_o     = rgb_q;
  assign payload_o = payload_q;

  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, {normal_i, cp_i, d_i, w_i, shininess_i, payload_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, {rgb_o, payload_o})
  `WATKINS_COVER(c_stall, !en)
endmodule
