// compact_normalizer_narrow: the unit normal N/|N|, Q2.14, at the narrow Phong formats
// (docs/reference/compact-phong.md, "Narrow formats"), over two 16 x 16 multipliers (MAC16) in a
// fixed schedule of 5 clocks per normal, 1/sqrt from a 256 x 16 block-RAM table with linear
// interpolation. The ports and parameters of rtl/compact_normalizer.sv, so the compact top picks
// it by PhongNarrow alone (values twin: Normalizer::normalize_narrow, model/twins/normalizer.hpp;
// cycle twin: model/twins/compact_normalizer_narrow_timing.hpp).
// Timing: a period is 5 clocks; a normal is taken in a period's last clock (ready_o, a flop) and
// its unit vector is loaded into the output register on clock 13 after it (phase 3 of its third
// period); a load that finds the output holding a unit vector not taken stalls every register
// for a clock (compact_schedule). Latency 15 cycles (the take's clock to the first clock
// offered); at full rate one normal per 5 clocks.
// Registered: every output; every multiplier's operands and product (the MAC16's own registers,
// its accumulator and its adder where the sum is the multiplier's: m, the interpolation, n y).
// The schedule, clock t of a normal (t = -1 its take, phase 4; t = 5p + ph after it):
//   t -1, 0, 1  n_c = clamp(round(N_c / 2)) of x (from normal_i), y, z into A's operands and the
//               n chain; A accumulates n_c^2 (its accumulator reset in phase 4): m at t 3
//   t 3, 4      m normalized by zero pairs (16 and 8 bits, then 4 and 2): j, M = m << 2j, the
//               table row k and the 16 bits d below it; T[k] read at t 4, T[k + 1] at t 5
//   t 7         B: (T[k] - T[k+1]) d + {~T, 2^15} (d's top bit weighs -2^16 in the signed
//               product; ~T is ~T[k] or, for d >= 2^15, ~T[k+1] = ~T[k] + the slope): y' =
//               T[k] - round(slope d / 2^16) = ~(the sum's top 16 bits), at t 9
//   t 9, 10, 11 B: n_c (y' - 2^15) + 3 n_c 2^15 = n_c y (y = 2^16 + y'), 32 bits and n_c's sign
//   t 11..13    unit_c = round(n_c y / 2^(18 - j)): a window of 17 bits and one rounding add; x, y
//               registered, z into the output register at t 13
`include "watkins_assert.svh"

module compact_normalizer_narrow #(
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
  output logic                    null_o,     // n_c all 0 (the input rounds to (0, 0, 0)); unit 0
  output logic [PayloadBits-1:0]  payload_o,
  output logic                    valid_o,
  input  logic                    ready_i,
  /* verilator lint_off UNUSEDSIGNAL */
  input  logic                    ready_next_i,  // accepted: ready_o does not depend on ready_i
  /* verilator lint_on UNUSEDSIGNAL */
  output logic                    ready_next_o   // ready_o on the next clock
);
  localparam int Periods = 3;  // periods a normal spends inside
  localparam int Chain   = 6;  // n chain words: a component waits from its take to its n y
  localparam int NBits   = 16; // n_c: 15 fraction bits

  // ---- the schedule's control ---------------------------------------------------------------
  logic [2:0] ph_q;
  /* verilator lint_off UNUSEDSIGNAL */
  logic [1:0] pc_unused;  // the slots of a RAM this block does not have
  /* verilator lint_on UNUSEDSIGNAL */
  logic       en, tick, out_load;
  compact_schedule #(.Periods(Periods), .LoadPhase(3), .SlotBits(2)) u_schedule (
    .clk_i, .rst_ni, .valid_i, .ready_o, .ready_next_o, .valid_o, .ready_i,
    .ph_o(ph_q), .pc_o(pc_unused), .en_o(en), .tick_o(tick), .load_o(out_load));

  // ---- the input: x from normal_i in the take clock, y and z from n0_q at phases 0 and 1 ------
  logic [NormalBits-1:0] n0_lo_q, n0_hi_q;  // y then z in n0_lo_q; z in n0_hi_q
  logic [NormalBits-1:0] nin;
  always_ff @(posedge clk_i) if (en) begin
    if (tick) begin
      n0_lo_q <= normal_i[NormalBits +: NormalBits];
      n0_hi_q <= normal_i[2*NormalBits +: NormalBits];
    end else if (ph_q == 3'd0) begin
      n0_lo_q <= n0_hi_q;
    end
  end
  assign nin = ph_q == 3'd4 ? normal_i[0 +: NormalBits] : n0_lo_q;

  // n_c = clamp(round_shift(N_c, 1), -2^15, 2^15 - 1)
  logic signed [NBits-1:0] nc;
  always_comb begin
    logic signed [NormalBits:0] r;  // (N + 1) >>> 1: [-2^16, 2^16]
    r = (signed'({nin[NormalBits-1], nin}) + (NormalBits+1)'(1)) >>> 1;
    if (r[NormalBits:NBits-1] != {(NormalBits-NBits+2){r[NormalBits]}})
      nc = r[NormalBits] ? {1'b1, (NBits-1)'(0)} : {1'b0, {(NBits-1){1'b1}}};
    else
      nc = r[NBits-1:0];
  end

  // ---- the n chain: n_c enters in phases 4, 0, 1 and leaves chain[Chain-1] for n y nine clocks
  // later, in the same phases --------------------------------------------------------------------
  logic [NBits-1:0] chain_q [Chain];
  logic             shift_n;
  assign shift_n = ph_q == 3'd4 || ph_q == 3'd0 || ph_q == 3'd1;
  always_ff @(posedge clk_i) if (en && shift_n) begin
    chain_q[0] <= nc;
    for (int i = 1; i < Chain; i++) chain_q[i] <= chain_q[i-1];
  end

  // ---- multiplier A: m = nx^2 + ny^2 + nz^2 in its accumulator ----------------------------------
  // Operands loaded in phases 4, 0, 1; the accumulator is reset at the end of phase 4 and adds a
  // product every other clock: m is read in phase 3 (what it adds at the end of phase 3 is not).
  logic signed [NBits-1:0] a_a_q;
  logic [31:0]             pa_q;
  always_ff @(posedge clk_i) if (en) begin
    a_a_q <= nc;
    if (ph_q == 3'd4) pa_q <= '0;
    else pa_q <= pa_q + 32'($signed(a_a_q) * $signed(a_a_q));
  end

  // ---- t 3, 4: m's leading zero pairs, M = m << 2j; the row and the interpolation fraction ----
  logic [31:0] m1_q;   // m shifted by 16 and 8 bits as its top bits are zero
  logic [1:0]  jh_q;   // j's top two bits
  always_ff @(posedge clk_i) if (en && ph_q == 3'd3) begin
    logic [31:0] s1;
    s1     = pa_q[31:16] == 16'd0 ? pa_q << 16 : pa_q;
    m1_q   <= s1[31:24] == 8'd0 ? s1 << 8 : s1;
    jh_q   <= {pa_q[31:16] == 16'd0, s1[31:24] == 8'd0};
  end
  /* verilator lint_off UNUSEDSIGNAL */
  logic [31:0] mm;     // M = m << 2j (phase 4): its 7 low bits are below d
  /* verilator lint_on UNUSEDSIGNAL */
  logic [3:0]  jn;     // j
  logic [7:0]  kn;     // the row
  logic [15:0] dn;     // the 16 bits of M below the row
  always_comb begin
    logic [31:0] s3;
    s3 = m1_q[31:28] == 4'd0 ? m1_q << 4 : m1_q;
    mm = s3[31:30] == 2'd0 ? s3 << 2 : s3;
    jn = {jh_q, m1_q[31:28] == 4'd0, s3[31:30] == 2'd0};
    kn = mm[31] ? {1'b1, mm[30:24]} : {1'b0, mm[29:23]};
    dn = mm[31] ? mm[23:8] : mm[22:7];
  end

  // Registers of the period that ends the normalization (loaded at the end of phase 4): the row,
  // d, j and null; j and null again for the period of the rounding.
  logic [7:0]  k_q;
  logic [15:0] d_q;
  logic [3:0]  j0_q, j1_q;
  logic        nul0_q, nul1_q;
  always_ff @(posedge clk_i) if (tick) begin
    k_q    <= kn;
    d_q    <= dn;
    j0_q   <= jn;
    j1_q   <= j0_q;
    nul0_q <= mm[31:30] == 2'd0;  // m = 0: the only m whose M is below 2^30
    nul1_q <= nul0_q;
  end

  // ---- the rsqrt table: T[k] = round(2^16 (1/sqrt(x_k) - 1)) at the row's start x_k = a_k 2^-9
  // (a_k = 128 + k below row 128, 2k from it), ((isqrt(floor(2^43 / a_k)) + 1) >> 1) - 2^16,
  // row 0 saturated at 2^16 - 1: RsqrtUnit::narrow_row (model/twins/rsqrt_unit.hpp). Filled at
  // elaboration, read synchronously: one block RAM. T[k] read in phase 4, T[k + 1] in phase 0
  // (row 255's successor T[256] = 0 is forced, not read).
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
  function automatic logic [15:0] rsqrt_row(input int k);
    logic [63:0] a, r;
    a = k < 128 ? 64'(k) + 64'd128 : 64'(k) << 1;
    r = ((isqrt((64'd1 << 43) / a) + 64'd1) >> 1) - (64'd1 << 16);
    rsqrt_row = r > 64'hffff ? 16'hffff : r[15:0];
  endfunction
  logic [15:0] rsqrt_rom [256];
  initial for (int k = 0; k < 256; k++) rsqrt_rom[k] = rsqrt_row(k);

  logic [15:0] t_rd_q;   // T[k] in phase 0, T[k + 1] from phase 1 to the next phase 4
  logic [15:0] t0_q;     // T[k], phases 1..0
  logic        last_q;   // k = 255: T[k + 1] is 0
  logic [7:0]  ra;
  assign ra = ph_q == 3'd4 ? kn : k_q + 8'd1;
  always_ff @(posedge clk_i) if (en) begin
    if (ph_q == 3'd4 || ph_q == 3'd0) t_rd_q <= rsqrt_rom[ra];
    if (ph_q == 3'd0) begin
      t0_q   <= t_rd_q;
      last_q <= k_q == 8'hff;
    end
  end
  logic [15:0] t1;       // T[k + 1]
  assign t1 = last_q ? 16'd0 : t_rd_q;

  // ---- multiplier B: the interpolation (operands in phase 2), n y (phases 4, 0, 1) ----------------
  // Both signed. The interpolation: slope s = T[k] - T[k+1] in 0..511 times d read as signed,
  // s d_signed = s d - s 2^16 d[15], so the added constant {~T, 2^15} takes ~T[k+1] = ~T[k] + s
  // (mod 2^16) for d[15]: the sum is s d + 2^15 + ~T[k] 2^16 modulo 2^32, which is below 2^32, and
  // its top 16 bits are ~y'. n y: y'' = y' - 2^15 (y''s top bit flipped) is a signed operand,
  // and n y = n y'' + 3n 2^15; the product's b operand holds y'' for the three components.
  logic signed [NBits-1:0] b_a_q, b_b_q;
  logic [31:0]             b_c_q;
  /* verilator lint_off UNUSEDSIGNAL */
  logic [31:0]             pb_q;   // n y's low 2 bits are below every window
  /* verilator lint_on UNUSEDSIGNAL */
  logic [NBits-1:0]        ny;     // n of the component whose n y starts
  logic [NBits:0]          n3;     // 3n's low 17 bits
  assign ny = chain_q[Chain-1];
  assign n3 = {ny[NBits-1], ny} + {ny, 1'b0};
  always_ff @(posedge clk_i) if (en) begin
    if (ph_q == 3'd2) begin
      b_a_q <= t0_q - t1;
      b_b_q <= d_q;
      b_c_q <= {d_q[15] ? ~t1 : ~t0_q, 1'b1, 15'd0};
    end else begin
      b_a_q <= ny;
      b_c_q <= {n3, 15'd0};
    end
    if (ph_q == 3'd4) b_b_q <= {pb_q[31], ~pb_q[30:16]};
    pb_q <= 32'($signed(b_a_q) * $signed(b_b_q)) + b_c_q;
  end

  // ---- unit_c = round_shift(n y, 18 - j): bits from 17 - j of V = {n's sign, pb} and one add ---
  logic [1:0]           sg_q;   // n's sign beside b's operands, then beside the product
  logic [UnitBits-1:0]  un;     // this clock's component
  always_ff @(posedge clk_i) if (en) sg_q <= {sg_q[0], ny[NBits-1]};
  always_comb begin
    logic signed [45:0] w;  // V >> 2, sign-extended for the shift by 15 - j
    /* verilator lint_off UNUSEDSIGNAL */
    logic signed [45:0] sw; // t = its low 17 bits
    logic [17:0]        r;  // t + 1: its low bit is dropped
    /* verilator lint_on UNUSEDSIGNAL */
    w  = 46'(signed'({sg_q[1], pb_q[31:2]}));
    sw = w >>> ~j1_q;
    r  = {sw[16], sw[16:0]} + 18'd1;
    un = r[UnitBits:1];
  end
  logic [UnitBits-1:0] ux_q, uy_q;
  always_ff @(posedge clk_i) if (en) begin
    if (ph_q == 3'd1) ux_q <= un;
    if (ph_q == 3'd2) uy_q <= un;
  end

  // ---- the payload, a period at a time, and the output register (t 13) ---------------------------
  logic [PayloadBits-1:0] pay_q [Periods];
  always_ff @(posedge clk_i) if (tick) begin
    pay_q[0] <= payload_i;
    for (int p = 1; p < Periods; p++) pay_q[p] <= pay_q[p-1];
  end
  logic                   null_q;
  logic [3*UnitBits-1:0]  unit_q;
  logic [PayloadBits-1:0] payload_q;
  always_ff @(posedge clk_i) if (out_load) begin
    unit_q    <= {un, uy_q, ux_q};
    null_q    <= nul1_q;
    payload_q <= pay_q[Periods-1];
  end
  assign unit_o    = unit_q;
  assign null_o    = null_q;
  assign payload_o = payload_q;

  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, {normal_i, payload_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, {unit_o, null_o, payload_o})
  `WATKINS_COVER(c_stall, !en)
endmodule
