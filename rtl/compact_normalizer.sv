// compact_normalizer: the unit normal N/|N|, Q2.14, of an interpolated normal, over four 16 x 16
// multipliers (MAC16) in a fixed schedule of 5 clocks per normal, for small parts. Drop-in for
// rtl/normalizer.sv (the same ports and parameters; values twin: Normalizer::normalize,
// model/twins/normalizer.hpp; cycle twin: model/twins/compact_normalizer_timing.hpp).
// Timing: a period is 5 clocks (ph_q 0..4); a normal is taken on the last clock of a period
// (ready_o = ph_q == 4: a flop, never ready_i) and its unit vector is loaded into the output
// register on clock 31 after it (phase 1 of its seventh period). Every register of the block
// moves with one enable, low only in a phase-1 clock that must load the output while it holds a
// unit vector not taken: then the whole schedule waits a clock. Latency 33 cycles (from the take's
// clock to the first clock offered); at full rate one normal per 5 clocks.
// Registered: every output; every multiplier's operands and product (the MAC16's own registers).
// The schedule, clock t of a normal (t = 0 the clock after it is taken; each register is written
// once per period, so a value lives 5 clocks and is copied when read later):
//   t 0..2   |N_c|'s low 16 bits into multiplier A's operands, a component per clock
//   t 1..3   A: |N_c|_lo^2;  t 2..4: m = sum of |N_c|^2 (the high bits of |N_c| added beside)
//   t 5      j = leading zero pairs of m, null = (m == 0);  t 6: mant = top 20 bits of m << 2j
//   t 7      seed y0 = ROM[mant's top 10 bits] (block RAM)
//   t 9      A: y0^2  (operands t 8)
//   t 12..15 B: m'c * y0^2 as four 16 x 16 partial products;  t 13..16: u = 3 - round(m'c y0^2)
//   t 20, 21 A: y0 * u_lo, B: y0 * u_hi;  t 22: y = round(y0 u / 2)
//   t 24..26 C: N_c_lo * y_lo, D: N_c_lo * y_hi per component (N_c from the RAM, t 23..25)
//   t 25..27 p = N_c * y (the top 2 bits of N_c times y added beside);  t 26..28: the shift
//   t 27..29 round to Q2.14;  t 31: the output register
// N and the payload wait in one RAM (a word each, written in the take clock and t 0..2, read at
// t 22..24 and 30), not in registers per period.
`include "watkins_assert.svh"

module compact_normalizer #(
  parameter int PayloadBits = 1,     // carried alongside (pixel x, ...)
  /* verilator lint_off UNUSEDPARAM */
  parameter bit LookAhead   = 1'b0,  // accepted: ready_o is a flop here
  /* verilator lint_on UNUSEDPARAM */
  localparam int NormalBits = watkins_pkg::NormalInBits,  // a component of the normal in
  localparam int UnitBits   = watkins_pkg::UnitBits       // a component of the unit normal out
) (
  input  logic                    clk_i,
  input  logic                    rst_ni,
  input  logic [3*NormalBits-1:0] normal_i,   // {Nz, Ny, Nx}: signed, FracBits fraction bits
  input  logic [PayloadBits-1:0]  payload_i,
  input  logic                    valid_i,
  output logic                    ready_o,
  output logic [3*UnitBits-1:0]   unit_o,     // {Nz, Ny, Nx}: signed Q2.14, |unit| = 1
  output logic                    null_o,     // input was (0, 0, 0); unit_o is (0, 0, 0)
  output logic [PayloadBits-1:0]  payload_o,
  output logic                    valid_o,
  input  logic                    ready_i,
  /* verilator lint_off UNUSEDSIGNAL */
  input  logic                    ready_next_i,  // accepted: ready_o does not depend on ready_i
  /* verilator lint_on UNUSEDSIGNAL */
  output logic                    ready_next_o   // ready_o on the next clock
);
  // The comments write the formats as the model's formulas do: W, P, T, G and F.
  localparam int SquaredLengthBits = 2 * NormalBits;               // m: 36
  localparam int MantBits          = watkins_pkg::RsqrtMantBits;   // W = 20
  localparam int IndexBits         = watkins_pkg::RsqrtIndexBits;  // P = 10
  localparam int SeedBits          = watkins_pkg::RsqrtSeedBits;   // T = 14
  localparam int NewtonFracBits    = watkins_pkg::RsqrtNrBits;     // G = 24
  localparam int RsqrtBits         = watkins_pkg::RsqrtBits;       // F = 22
  localparam int MaxZeroPairs      = SquaredLengthBits / 2 - 1;    // the largest j: 17
  localparam int Periods           = 7;                            // periods a normal spends inside
  localparam int Slots             = 8;                            // RAM slots: >= Periods
  localparam int Digit             = 16;                           // a multiplier operand
  localparam int SeedWordBits      = SeedBits + 1;                 // y0 <= 2^15: 15 bits
  localparam int SeedSquareBits    = 2 * SeedWordBits;             // y0^2: 30 bits
  localparam int MantCentreBits    = MantBits + 1;                 // m'c = {mant, 1}: 21 bits
  localparam int UWordBits         = NewtonFracBits + 2;           // u < 4: 26 bits
  localparam int RsqrtWordBits     = RsqrtBits + 2;                // y <= 2: 24 bits
  localparam int UShift            = MantCentreBits + 2 * SeedBits - NewtonFracBits;  // 25
  localparam int YShift            = SeedBits + NewtonFracBits + 1 - RsqrtBits;       // 17
  // u = bits [UShift + G + 1 : UShift] of UConstant - m'c y0^2, which is never negative:
  // 3 2^G - floor((p + 2^(s-1)) / 2^s) = floor((3 2^(G+s) + 2^(s-1) - 1 - p) / 2^s), s = UShift.
  localparam int UDiffBits         = UShift + UWordBits;           // 51
  localparam logic [UDiffBits-1:0] UConstant =
      (UDiffBits'(3) << (NewtonFracBits + UShift)) + (UDiffBits'(1) << (UShift - 1)) - UDiffBits'(1);
  // p = N y: 43 bits signed; the shift by sh - 1 = F + 3 - j = MinShift + (MaxZeroPairs - j)
  // reads a window of ShiftedBits bits of p from bit MinShift up.
  localparam int ScaledBits        = NormalBits + RsqrtWordBits + 1;        // 43
  localparam int MinShift          = RsqrtBits + 3 - MaxZeroPairs;          // 8
  localparam int WindowBits        = ScaledBits - MinShift;                 // p >>> MinShift: 35
  localparam int ShiftedBits       = UnitBits + 1;                          // t: 17
  localparam int RamBits           = PayloadBits > NormalBits ? PayloadBits : NormalBits;
  localparam int SlotBits          = $clog2(Slots);

  // ---- the schedule's control ---------------------------------------------------------------
  logic [2:0]          ph_q;    // the clock within the period
  logic [SlotBits-1:0] pc_q;    // the period count: a normal in its k-th period has slot pc - k
  logic                en;      // every register of the block moves
  logic                tick;    // the last clock of a period: the normals move to their next
  logic                out_load;
  compact_schedule #(.Periods(Periods), .LoadPhase(1), .SlotBits(SlotBits)) u_schedule (
    .clk_i, .rst_ni, .valid_i, .ready_o, .ready_next_o, .valid_o, .ready_i,
    .ph_o(ph_q), .pc_o(pc_q), .en_o(en), .tick_o(tick), .load_o(out_load));

  // ---- N and the payload in one RAM: slot s holds {Nx, Ny, Nz, payload} at 4s .. 4s + 3 -----
  // Written: the payload in the take clock (the new slot, pc + 1), Nx, Ny, Nz at t 0..2 from the
  // input register. Read (synchronous, one read register): Nx, Ny, Nz at t 22..24 (period 4),
  // the payload at t 30 (period 6).
  logic [RamBits-1:0]      nram [4 * Slots];
  logic [RamBits-1:0]      rd_q;
  logic [3*NormalBits-1:0] n0_q;  // the normal, period 0
  logic [NormalBits-1:0]   n_sel; // its component ph_q (x, y, z at phases 0, 1, 2)
  logic                    we, re;
  logic [SlotBits+1:0]     wa, ra;
  logic [RamBits-1:0]      wd;
  always_comb begin
    case (ph_q)
      3'd0:    n_sel = n0_q[0 +: NormalBits];
      3'd1:    n_sel = n0_q[NormalBits +: NormalBits];
      default: n_sel = n0_q[2*NormalBits +: NormalBits];
    endcase
    we = ph_q != 3'd3;
    re = ph_q != 3'd1;
    wa = ph_q == 3'd4 ? {pc_q + 1'b1, 2'd3} : {pc_q, ph_q[1:0]};
    wd = ph_q == 3'd4 ? RamBits'(payload_i) : RamBits'(n_sel);
    ra = ph_q == 3'd0 ? {pc_q - SlotBits'(6), 2'd3} : {pc_q - SlotBits'(4), ph_q[1:0] - 2'd2};
  end
  always_ff @(posedge clk_i) if (en) begin
    if (we) nram[wa] <= wd;
    if (re) rd_q <= nram[ra];
  end
  always_ff @(posedge clk_i) if (tick) n0_q <= normal_i;

  // ---- multiplier A: |N_c|_lo^2 (products at t 1..3), y0^2 (t 9), y0 u_lo (t 20) -----------
  // Operands in phases 0..2 the squares, 3 y0, 4 y0 and u_lo.
  logic [2*Digit-1:0]      pa_q;
  logic [NormalBits-1:0]   sq_a;               // |N_c| <= 2^17
  logic [NormalBits-1:0]   sq_q, sq1_q;        // |N_c| beside its square's operands, product
  logic [SeedWordBits-1:0] y0m;                // y0, 0 for the null vector
  logic [SeedWordBits-1:0] y0_rom_q;           // the seed ROM's read register (t 8..12)
  logic [SeedWordBits-1:0] y0f_q, y0c_q, y0d_q;  // y0 at t 9..13, 14..18, 19..23
  logic [UWordBits-1:0]    u_q;                  // u at t 18..22
  logic                    nul_q;
  assign y0m  = nul_q ? '0 : y0_rom_q;
  assign sq_a = n_sel[NormalBits-1] ? -n_sel : n_sel;
  mac16_phased u_mac_a (
    .clk_i, .en_i(en), .ph_i(ph_q),
    .a_i({Digit'(y0d_q), Digit'(y0m), {3{sq_a[Digit-1:0]}}}),
    .b_i({u_q[Digit-1:0], Digit'(y0m), {3{sq_a[Digit-1:0]}}}),
    .p_o(pa_q));
  always_ff @(posedge clk_i) if (en) begin
    sq_q  <= sq_a;
    sq1_q <= sq_q;
  end

  // ---- m = Nx^2 + Ny^2 + Nz^2 at t 2..4: a^2 = lo^2 + hi lo 2^17 + hi^2 2^32 (hi = 2: lo = 0) ---
  logic [SquaredLengthBits-1:0] m_q;  // t 5..7
  always_ff @(posedge clk_i) if (en && ph_q >= 3'd2) begin
    logic [SquaredLengthBits-1:0] side;
    side = (sq1_q[Digit] ? (SquaredLengthBits'(sq1_q[Digit-1:0]) << (Digit + 1)) + (SquaredLengthBits'(1) << (2 * Digit))
                         : '0)
         | (sq1_q[Digit+1] ? SquaredLengthBits'(1) << (2 * Digit + 2) : '0);
    m_q <= (ph_q == 3'd2 ? '0 : m_q) + SquaredLengthBits'(pa_q) + side;
  end

  // ---- t 5: j and null; t 6: the even shift; t 7: the seed ------------------------------------
  logic [4:0]          j_q;
  logic [MantBits-1:0] mant_q;  // t 7..11
  always_ff @(posedge clk_i) if (en && ph_q == 3'd0) begin
    logic [4:0] j;
    j = '0;
    for (int p = 0; p < SquaredLengthBits / 2; p++)
      if (m_q[2*p +: 2] != 2'b00) j = 5'(MaxZeroPairs - p);
    j_q   <= j;
    nul_q <= m_q == '0;
  end
  always_ff @(posedge clk_i) if (en && ph_q == 3'd1) begin
    /* verilator lint_off UNUSEDSIGNAL */
    logic [SquaredLengthBits-1:0] shifted;  // only the top W bits are kept
    /* verilator lint_on UNUSEDSIGNAL */
    shifted = m_q << {j_q, 1'b0};
    mant_q <= shifted[SquaredLengthBits-1 -: MantBits];
  end

  // The seed ROM: rows 2^(P-2) .. 2^P - 1 (m' >= 1/4) at row - 2^(P-2); mant = 0 (the null
  // vector, the only m' below 1/4) reads past it and y0m is 0. y0 = round(2^T / sqrt(c)),
  // c = (2 idx + 1) / 2^(P+1): round(sqrt(q)) with q = 2^(2T+P+3) / (2 idx + 1) is
  // (floor(sqrt(q)) + 1) / 2, floor(sqrt(q)) the largest r with r^2 <= q, found bit by bit from
  // the top (q < 2^34: 17 bits).
  localparam int SeedRows = (1 << IndexBits) - (1 << (IndexBits - 2));  // 768
  function automatic logic [SeedWordBits-1:0] seed_of(input int idx);
    logic [63:0] q, r, c;
    q = (64'd1 << (2 * SeedBits + IndexBits + 3)) / 64'(2 * idx + 1);
    r = '0;
    for (int b = 16; b >= 0; b--) begin
      c = r | (64'd1 << b);
      if (c * c <= q) r = c;
    end
    c = (r + 64'd1) >> 1;
    seed_of = c[SeedWordBits-1:0];
  endfunction
  logic [SeedWordBits-1:0] seed_rom [SeedRows];
  initial for (int r = 0; r < SeedRows; r++) seed_rom[r] = seed_of(r + (1 << (IndexBits - 2)));
  always_ff @(posedge clk_i) if (en && ph_q == 3'd2) begin
    logic [IndexBits-1:0] idx;
    idx = mant_q[MantBits-1 -: IndexBits];
    y0_rom_q <= seed_rom[{idx[IndexBits-1 -: 2] - 2'd1, idx[IndexBits-3:0]}];
  end

  // ---- copies of the values read after their period ---------------------------------------
  logic [SeedSquareBits-1:0] s_q;   // y0^2, t 11..15
  logic [MantCentreBits-1:0] mc_q;  // m'c, t 11..15
  logic [4:0]                k_q, k1_q, k2_q, k3_q;  // MaxZeroPairs - j: t 11.., 16.., 21.., 26..30
  logic [Periods-3:0]        nulc_q;  // null at t 11, 16, 21, 26, 31 (.. + 4)
  always_ff @(posedge clk_i) if (en) begin
    if (ph_q == 3'd0) begin  // t 10, 15, 20, 25, 30
      s_q    <= pa_q[SeedSquareBits-1:0];
      mc_q   <= {mant_q, 1'b1};
      k_q    <= 5'(MaxZeroPairs) - j_q;
      k1_q   <= k_q;
      k2_q   <= k1_q;
      k3_q   <= k2_q;
      nulc_q <= {nulc_q[Periods-4:0], nul_q};
    end
    if (ph_q == 3'd3) begin  // t 8, 13, 18
      y0f_q <= y0m;
      y0c_q <= y0f_q;
      y0d_q <= y0c_q;
    end
  end

  // ---- multiplier B: m'c y0^2 (products at t 12..15), y0 u_hi (t 21) -------------------------
  // m'c = mc1 2^16 + mc0, y0^2 = s1 2^16 + s0: mc0 s0, mc0 s1, mc1 s0, mc1 s1 in phases 1..4.
  logic [2*Digit-1:0] pb_q;
  logic [Digit-1:0]   mc0, mc1, s0, s1;
  assign {mc1, mc0} = (2*Digit)'(mc_q);
  assign {s1, s0}   = (2*Digit)'(s_q);
  mac16_phased u_mac_b (
    .clk_i, .en_i(en), .ph_i(ph_q),
    .a_i({mc1, mc1, mc0, mc0, Digit'(y0d_q)}),
    .b_i({s1, s0, s1, s0, Digit'(u_q[UWordBits-1:Digit])}),
    .p_o(pb_q));

  // ---- u = UConstant - m'c y0^2 at t 13..16: the four partial products subtracted in turn ------
  logic [UDiffBits-1:0] ud_q;
  always_ff @(posedge clk_i) if (en && ph_q != 3'd2) begin
    logic [UDiffBits-1:0] base, sub;
    base = ph_q == 3'd3 ? UConstant : ud_q;
    case (ph_q)
      3'd3:          sub = UDiffBits'(pb_q);
      3'd4, 3'd0:    sub = UDiffBits'(pb_q) << Digit;
      default:       sub = UDiffBits'(pb_q) << (2 * Digit);
    endcase
    ud_q <= base - sub;
  end
  always_ff @(posedge clk_i) if (en && ph_q == 3'd2) u_q <= ud_q[UShift +: UWordBits];  // t 17

  // ---- y = round(y0 u / 2^YShift) at t 22 from y0 u_lo (t 20) and y0 u_hi (t 21) ---------------
  localparam int YProductBits = SeedWordBits + UWordBits + 1;
  logic [2*Digit-1:0]       ya_q;  // y0 u_lo, t 22
  logic [RsqrtWordBits-1:0] y_q;   // t 23..27
  always_ff @(posedge clk_i) if (en) begin
    if (ph_q == 3'd1) ya_q <= pa_q;
    if (ph_q == 3'd2) begin
      /* verilator lint_off UNUSEDSIGNAL */
      logic [YProductBits-1:0] yr;  // y <= 2: the top bits are zero
      /* verilator lint_on UNUSEDSIGNAL */
      yr = (YProductBits'(ya_q) + (YProductBits'(pb_q) << Digit) + (YProductBits'(1) << (YShift - 1))) >> YShift;
      y_q <= yr[RsqrtWordBits-1:0];
    end
  end

  // ---- multipliers C and D: N_c_lo y_lo and N_c_lo y_hi (operands t 23..25, products 24..26) --
  // N_c = nh 2^16 + nl (nh = N_c's top two bits, signed): N_c y = nl y_lo + (nl y_hi + nh y) 2^16,
  // nh y (0, y, -y or -2y) formed beside the operands and delayed with them. Both load every clock.
  localparam int SideBits = RsqrtWordBits + 3;  // nh y, signed: 27 bits
  /* verilator lint_off UNUSEDSIGNAL */
  logic [2*Digit-1:0]         pc_q2, pd_q;  // nl y_lo: bits below MinShift are not read; nl y_hi < 2^24
  /* verilator lint_on UNUSEDSIGNAL */
  logic signed [SideBits-1:0] side_q, side1_q;
  mac16_phased u_mac_c (
    .clk_i, .en_i(en), .ph_i(ph_q), .a_i({5{rd_q[Digit-1:0]}}), .b_i({5{y_q[Digit-1:0]}}), .p_o(pc_q2));
  mac16_phased u_mac_d (
    .clk_i, .en_i(en), .ph_i(ph_q), .a_i({5{rd_q[Digit-1:0]}}),
    .b_i({5{Digit'(y_q[RsqrtWordBits-1:Digit])}}), .p_o(pd_q));
  always_ff @(posedge clk_i) if (en) begin
    logic [1:0] nh;
    nh      = rd_q[NormalBits-1:Digit];
    side_q  <= (nh[0] ? SideBits'(y_q) : '0) - (nh[1] ? SideBits'(y_q) << 1 : '0);
    side1_q <= side_q;
  end

  // ---- t 25..27 p >>> MinShift; t 26..28 the shift; t 27..29 round: one component per clock ---
  logic signed [WindowBits-1:0]  p_q;
  logic signed [ShiftedBits-1:0] t_q;
  logic [UnitBits-1:0]           ux_q, uy_q, uz_q;
  always_ff @(posedge clk_i) if (en) begin
    logic signed [SideBits-1:0] hi;  // p >>> 16: |p| < 2^41
    /* verilator lint_off UNUSEDSIGNAL */
    logic [ShiftedBits:0]       r;   // (t + 1) >> 1: its top bits are sign copies
    /* verilator lint_on UNUSEDSIGNAL */
    hi  = signed'(SideBits'(pc_q2[2*Digit-1:Digit])) + signed'(SideBits'(pd_q[RsqrtWordBits-1:0])) + side1_q;
    p_q <= {hi[WindowBits-Digit+MinShift-1:0], pc_q2[Digit-1:MinShift]};
    t_q <= p_q[6'(k3_q) +: ShiftedBits];  // k3_q: t 26..30
    r   = ((ShiftedBits+1)'(t_q) + (ShiftedBits+1)'(1)) >> 1;
    case (ph_q)
      3'd2:    ux_q <= r[UnitBits-1:0];
      3'd3:    uy_q <= r[UnitBits-1:0];
      3'd4:    uz_q <= r[UnitBits-1:0];
      default: ;
    endcase
  end

  // ---- t 31: the output register ---------------------------------------------------------------
  logic                   null_q;
  logic [3*UnitBits-1:0]  unit_q;
  logic [PayloadBits-1:0] payload_q;
  always_ff @(posedge clk_i) if (out_load) begin
    unit_q    <= {uz_q, uy_q, ux_q};
    null_q    <= nulc_q[Periods-3];
    payload_q <= rd_q[PayloadBits-1:0];
  end
  assign unit_o    = unit_q;
  assign null_o    = null_q;
  assign payload_o = payload_q;

  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, {normal_i, payload_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, {unit_o, null_o, payload_o})
  `WATKINS_COVER(c_stall, !en)
endmodule
