// phong_shader: Phong's shading rule per pixel, light and eye at infinity.
// S = Cp [cos(i)(1-d) + d] + W cos(s)^n (Phong 1975 eq. 3), cos(s) = R.E = 2(N.L)(N.E) - L.E
// (Phong's reflected vector, eqs. 4-8), cos(s)^n by square-and-multiply over the 8 bits of n;
// bit-exact twin of model/twins/phong_shader.hpp.
// Latency 42 cycles, one pixel per clock. Every stage registers valid and data; one global stall
// (stall_pipe): ready_o = ready_i || !valid_o (combinational from ready_i and the output valid
// flop only; with LookAhead a flop loaded a clock ahead from ready_next_i).
// Stages: dots (nl_p_q, ne_p_q) -> dot sums (ndl_q, nde_q) -> round (cosi_q, ne_q) -> partials
// (cn00_q .., fp0_q, fp1_q) -> sums (cne_q, fp_q) -> cos(s) and f (base0_q, acc0_q, f0_q) ->
// powers k = 0..7, each operands (fa_o_q) -> product (fa_p_q) -> copy (fa_c_q) -> round
// (fa_r_q) -> output operands (u_df*, u_wa* input registers) -> output partials (df0_q, df1_q,
// wa0_q, wa1_q) -> output sums (diff2_q, spec_q) -> level (rgb_q).
// Every product is registered on its own, in its multiplier block (mul18_reg: on the ECP5 the
// MULT18X18D's output register), a product wider than one 18 x 18 multiplier as partial
// products, the sums and roundings that use it one stage later (ECP5 MULT18 and iCE40 MAC16
// timing); the operands of the powers and of the output's products also enter their blocks'
// registers a stage before the product (mul18_reg InReg), and the powers' partial products are
// copied into the fabric before the round. Each stage's registers load only when the beat
// entering it is valid (en && its valid: one LUT, as en alone): a bubble's values are never
// read, so a simulator need not compute them (most clocks of a frame carry bubbles); a valid
// beat's values are the same. light_i / eye_i are frame constants: L.E is computed from them
// over stages 1 to 4 by the valid beats (one register per stage, not per pixel: every pixel in
// flight has the same value), so they must be stable from a frame's first pixel to its last
// output.
`include "watkins_assert.svh"

module phong_shader #(
  parameter int PayloadBits    = 1,     // carried alongside (pixel x, ...)
  parameter bit LookAhead      = 1'b0,  // stall_pipe's: ready from a flop
  localparam int UnitBits      = watkins_pkg::UnitBits,
  localparam int MaterialBits  = watkins_pkg::MaterialBits,
  localparam int ShininessBits = watkins_pkg::ShininessBits   // also the number of power stages
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
  input  logic                     ready_next_i, // LookAhead: ready_i on the next clock
  output logic                     ready_next_o  // ready_o on the next clock (from ready_next_i)
);
  // The comments write the two Phong formats as the model's formulas do: D and P.
  localparam int UnitFracBits     = watkins_pkg::UnitFracBits;       // 14
  localparam int DotBits          = watkins_pkg::PhongDotBits;       // D = 24
  localparam int PowBits          = watkins_pkg::PhongPowBits;       // P = 20
  localparam int MaterialFracBits = watkins_pkg::MaterialFracBits;
  // An exact dot product: 3 * 2^30 < 2^33.
  localparam int DotProductBits   = 2 * UnitBits + 2;
  // 2 cos(i) (N.E) - L.E, exact at 2D fraction bits.
  localparam int CosSExactBits    = 2 * DotBits + 6;
  // f = cos(i)(1-d) + d <= 1.
  localparam int DiffuseBits      = DotBits + MaterialFracBits + 1;
  // A level at D + MaterialFracBits fraction bits, plus the sum's carry.
  localparam int LevelSumBits     = DiffuseBits + 8 + 2;
  // The stages: 1 the dot products' six products, 2 their sums, 3 round, 4 cos(i)(N.E) and
  // cos(i)(1-d) as partial products, 5 their sums, 6 cos(s) and f, 7..38 the powers (an operand
  // stage, a product stage, a copy stage and a round stage per bit of n), 39 the operands of Cp f
  // and 255 W pow into their multiplier blocks, 40 their partial products, 41 their sums, 42
  // round and saturate.
  localparam int CosStage  = 6;  // acc0_q, base0_q, f0_q
  localparam int PowStages = 4;  // a power's operands, product, copy, round
  // power k: stages PowFirst + 4k .. + 4k + 3
  localparam int PowFirst  = CosStage + 1;
  // 38: g_pow[ShininessBits-1]'s round stage (fa_r_q)
  localparam int PowLast   = CosStage + PowStages * ShininessBits;
  localparam int Stages    = PowLast + 4;  // 42
  // A product wider than an 18 x 18 multiplier is split at bit SplitBits of an operand (17: the
  // low part fits the multiplier unsigned, with a zero sign bit), each partial product registered
  // straight from its block; x y = x1 y 2^SplitBits + x0 y (and the same for both operands
  // split).
  localparam int SplitBits = 17;

  // Valid, payload and the stall of every stage. The payload (the fragment's x, depth, ...) is
  // written once into a RAM, not shifted through every stage. ce[i]: stage i + 1's registers
  // load (the stall's en and the beat entering it, in stage i or on the input, is valid).
  logic [Stages-1:0] ce;
  /* verilator lint_off UNUSEDSIGNAL */
  logic              en;        // inside ce
  logic [Stages-1:0] v_unused;
  /* verilator lint_on UNUSEDSIGNAL */
  stall_pipe #(
    .Stages     (Stages),
    .PayloadBits(PayloadBits),
    .PayloadRam (1'b1),
    .LookAhead  (LookAhead)
  ) u_pipe (
    .clk_i, .rst_ni,
    .payload_i,
    .valid_i,
    .ready_o,
    .payload_o,
    .valid_o,
    .ready_i,
    .ready_next_i,
    .en_next_o(ready_next_o),
    .en_o     (en),
    .valid_q_o(v_unused),
    .ce_o     (ce)
  );
  // Stage i + 1's enable as a one-bit vector, read as g_ce[i].q[0] by the registers of this
  // module, the form of a mul18_reg's own test (its port ce_i, indexed): Verilator (5.006) merges
  // the tests of one enable into one only when their expressions are the same tree, and ce[i]
  // here and a multiplier block's ce_i[0] inlined differ in their index constant's width. One
  // test per stage, not two or three (the Phong top's instructions per cycle). The same LUT.
  for (genvar i = 0; i < Stages; i++) begin : g_ce
    /* verilator lint_off UNUSEDSIGNAL */
    logic [0:0] q;  // stages 39 and 40: their registers are all in multiplier blocks
    /* verilator lint_on UNUSEDSIGNAL */
    assign q = ce[i];
  end


  // The three products of each dot product of two Q2.14 vectors, exact (28 fraction bits), each
  // registered in its multiplier block (mul18_reg): N.L and N.E in stage 1, L.E (frame constant)
  // alongside. Component c at c * DotProductBits.
  logic [3*DotProductBits-1:0] nl_p_q, ne_p_q, le_p_q;
  for (genvar c = 0; c < 3; c++) begin : g_dot
    mul18_reg #(.ABits(UnitBits), .BBits(UnitBits), .ASigned(1'b1), .BSigned(1'b1),
                .PBits(DotProductBits)) u_nl (
      .clk_i, .ce_i(ce[0]), .a_i(normal_i[c*UnitBits +: UnitBits]),
      .b_i(light_i[c*UnitBits +: UnitBits]), .p_o(nl_p_q[c*DotProductBits +: DotProductBits]));
    mul18_reg #(.ABits(UnitBits), .BBits(UnitBits), .ASigned(1'b1), .BSigned(1'b1),
                .PBits(DotProductBits)) u_ne (
      .clk_i, .ce_i(ce[0]), .a_i(normal_i[c*UnitBits +: UnitBits]),
      .b_i(eye_i[c*UnitBits +: UnitBits]), .p_o(ne_p_q[c*DotProductBits +: DotProductBits]));
    mul18_reg #(.ABits(UnitBits), .BBits(UnitBits), .ASigned(1'b1), .BSigned(1'b1),
                .PBits(DotProductBits)) u_le (
      .clk_i, .ce_i(ce[0]), .a_i(light_i[c*UnitBits +: UnitBits]),
      .b_i(eye_i[c*UnitBits +: UnitBits]), .p_o(le_p_q[c*DotProductBits +: DotProductBits]));
  end
  function automatic logic signed [DotProductBits-1:0] sum3(
      input logic [3*DotProductBits-1:0] p);
    sum3 = signed'(p[0 +: DotProductBits]) + signed'(p[DotProductBits +: DotProductBits])
         + signed'(p[2*DotProductBits +: DotProductBits]);
  endfunction

  // round(v / 2^(2 UnitFracBits - D)), clamped to [lo, 2 - 2^-D] (lo = 0 or -2): stage 3 and L.E.
  // The clamp reads r's bits, not compares (a compare is a second carry chain after the add):
  // r is in [-2^(D+1), 2^(D+1) - 1] exactly when its bits from D + 1 up are all sign copies.
  function automatic logic signed [DotBits+1:0] round_dot(
      input logic signed [DotProductBits-1:0] v, input logic neg_ok);
    logic signed [DotProductBits-1:0] r;
    logic                             neg, fits;
    r    = (v + DotProductBits'(1 <<< (2 * UnitFracBits - DotBits - 1)))
           >>> (2 * UnitFracBits - DotBits);
    neg  = r[DotProductBits-1];
    fits = r[DotProductBits-1:DotBits+1] == '0 || r[DotProductBits-1:DotBits+1] == '1;
    if (neg && !neg_ok) round_dot = '0;                             // lo = 0
    else if (fits)      round_dot = r[DotBits+1:0];
    else if (neg)       round_dot = {1'b1, (DotBits+1)'(0)};        // lo = -2^(D+1)
    else                round_dot = {1'b0, {(DotBits+1){1'b1}}};    // hi = 2^(D+1) - 1 (*)
  endfunction
  // (*) hi < 2.0: the register's range, not 1.0 (see model).

  // ---- frame constant: cos(s)'s offset -L.E 2^D plus its rounding half, over stages 1 to 4 ------
  // Loaded by the valid beats like their own registers (not every clock: a simulator would compute
  // it every clock), but one register per stage: a pixel reads cs_k_q in stage 5, when it holds the
  // value of the pixel itself or of one behind it, the same for the whole frame. Every frame's
  // first pixel computes it.
  // Beside it the same offset less the clamp's two thresholds (cs_o_q: cos(s) > 1, cs_p_q:
  // cos(s) > 0), so stage 6 reads each test as the sign of a sum of its own (see there).
  localparam int CosSShift = 2 * DotBits - PowBits;  // cos(s)'s rounding shift
  logic signed [DotProductBits-1:0] le_s_q;
  logic signed [DotBits+1:0]        le_q;
  logic signed [CosSExactBits-1:0]  cs_k_q, cs_o_q, cs_p_q;
  always_ff @(posedge clk_i) begin
    if (g_ce[1].q[0]) le_s_q <= sum3(le_p_q);
    if (g_ce[2].q[0]) le_q   <= round_dot(le_s_q, 1'b1);
    if (g_ce[3].q[0]) begin
      cs_k_q <= CosSExactBits'(1 <<< (CosSShift - 1)) - (CosSExactBits'(le_q) <<< DotBits);
      cs_o_q <= CosSExactBits'(1 <<< (CosSShift - 1)) - (CosSExactBits'(le_q) <<< DotBits)
              - (CosSExactBits'((1 << PowBits) + 1) <<< CosSShift);
      cs_p_q <= CosSExactBits'(1 <<< (CosSShift - 1)) - (CosSExactBits'(le_q) <<< DotBits)
              - (CosSExactBits'(1) <<< CosSShift);
    end
  end

  // Pixel attributes travel alongside: g_X[i].q holds the pixel in stage i + 1 (the power
  // stages carry theirs in g_pow, beside the power's own registers). The per-stage registers
  // here and below are plain variables of generate blocks, not array elements: a simulator
  // (Verilator) keeps a pending-write flag and value per array element written under its own
  // enable and clears them on every evaluation. Same flops.
  // Cp, W and n travel in one word M = {Cp, W, n} per stage (one assignment per stage for a
  // simulator, not three: the Phong top's Verilator cost per cycle), its fields at ShininessLow,
  // SpecularLow, ReflectanceLow: n is last read by the final power stage, W by stage 38 (255 W),
  // Cp by stage 39.
  localparam int RgbBits          = watkins_pkg::RgbBits;
  localparam int ShininessLow     = 0;                             // n: M[ShininessLow +: ...]
  localparam int SpecularLow      = ShininessLow + ShininessBits;  // W: M[SpecularLow +: ...]
  localparam int ReflectanceLow   = SpecularLow + MaterialBits;    // Cp: M[ReflectanceLow +: ...]
  localparam int MaterialWordBits = ReflectanceLow + RgbBits;      // M
  for (genvar i = 0; i < CosStage; i++) begin : g_m
    logic [MaterialWordBits-1:0] q;  // a vector (yosys 0.23 and structs)
    if (i == 0) begin : g_in
      always_ff @(posedge clk_i) if (g_ce[0].q[0]) q <= {cp_i, w_i, shininess_i};
    end else begin : g_shift
      always_ff @(posedge clk_i) if (g_ce[i].q[0]) q <= g_m[i-1].q;
    end
  end
  for (genvar i = 0; i < CosStage - 1; i++) begin : g_d  // d: last read by stage 6
    logic [MaterialBits-1:0] q;
    if (i == 0) begin : g_in
      always_ff @(posedge clk_i)  // d <= 1.0
        if (g_ce[0].q[0])
          q <= (d_i > MaterialBits'(1 << MaterialFracBits)) ? MaterialBits'(1 << MaterialFracBits)
                                                            : d_i;
    end else begin : g_shift
      always_ff @(posedge clk_i) if (g_ce[i].q[0]) q <= g_d[i-1].q;
    end
  end

  // ---- stage 1: the products of N.L and N.E (g_dot above) ----------------------------------------

  // ---- stage 2: N.L and N.E, exact -------------------------------------------------------------
  logic signed [DotProductBits-1:0] ndl_q, nde_q;
  always_ff @(posedge clk_i) if (g_ce[1].q[0]) begin
    ndl_q <= sum3(nl_p_q);
    nde_q <= sum3(ne_p_q);
  end

  // ---- stage 3: cos(i) >= 0 (i > 90 degrees clamped, Phong p. 313), N.E ------------------
  logic signed [DotBits+1:0] cosi_q, ne_q;
  always_ff @(posedge clk_i) if (g_ce[2].q[0]) begin
    cosi_q <= round_dot(ndl_q, 1'b0);
    ne_q   <= round_dot(nde_q, 1'b1);
  end

  // ---- stage 4: the products cos(i)(N.E) and cos(i)(1-d), as partial products ------------------
  // cos(i) >= 0 (D + 1 bits unsigned) split into c1, c0; N.E (D + 2 bits signed) into n1
  // (signed), n0: cos(i)(N.E) = c1 n1 2^(2 SplitBits) + (c1 n0 + c0 n1) 2^SplitBits + c0 n0, four
  // multiplier blocks (the 26 x 26 product and its adders in one clock would be far too slow on
  // the ECP5).
  localparam int CosIHighBits  = DotBits + 1 - SplitBits;  // 8: c1, unsigned
  localparam int NDotEHighBits = DotBits + 2 - SplitBits;  // 9: n1, signed
  logic [SplitBits-1:0]                       c0, n0;
  logic [CosIHighBits-1:0]                    c1;
  logic signed [NDotEHighBits-1:0]            n1;
  logic [2*SplitBits-1:0]                     cn00_q;   // c0 n0
  logic signed [SplitBits+NDotEHighBits:0]    cn01_q;   // c0 n1
  logic [SplitBits+CosIHighBits-1:0]          cn10_q;   // c1 n0
  logic signed [CosIHighBits+NDotEHighBits:0] cn11_q;   // c1 n1
  logic [SplitBits+MaterialBits-1:0]          fp0_q;    // c0 (1-d)
  logic [CosIHighBits+MaterialBits-1:0]       fp1_q;    // c1 (1-d)
  logic                                       front_q;  // cos(i) > 0
  logic [MaterialBits-1:0]                    omd_q;    // 1 - d, 1.0 = 256 (stage 3's pixel)
  assign {c1, c0} = cosi_q[DotBits:0];
  assign {n1, n0} = ne_q;
  // 1 - d registered beside g_d[2] (from the same d), so the subtract's carry chain and its
  // route are not in front of the multiplier blocks' setup.
  always_ff @(posedge clk_i)
    if (g_ce[2].q[0]) omd_q <= MaterialBits'(1 << MaterialFracBits) - g_d[1].q;
  mul18_reg #(.ABits(SplitBits), .BBits(SplitBits)) u_cn00 (
    .clk_i, .ce_i(ce[3]), .a_i(c0), .b_i(n0), .p_o(cn00_q));
  mul18_reg #(.ABits(SplitBits), .BBits(NDotEHighBits), .BSigned(1'b1),
              .PBits(SplitBits+NDotEHighBits+1)) u_cn01 (
    .clk_i, .ce_i(ce[3]), .a_i(c0), .b_i(n1), .p_o(cn01_q));
  mul18_reg #(.ABits(CosIHighBits), .BBits(SplitBits)) u_cn10 (
    .clk_i, .ce_i(ce[3]), .a_i(c1), .b_i(n0), .p_o(cn10_q));
  mul18_reg #(.ABits(CosIHighBits), .BBits(NDotEHighBits), .BSigned(1'b1),
              .PBits(CosIHighBits+NDotEHighBits+1)) u_cn11 (
    .clk_i, .ce_i(ce[3]), .a_i(c1), .b_i(n1), .p_o(cn11_q));
  mul18_reg #(.ABits(SplitBits), .BBits(MaterialBits)) u_fp0 (
    .clk_i, .ce_i(ce[3]), .a_i(c0), .b_i(omd_q), .p_o(fp0_q));
  mul18_reg #(.ABits(CosIHighBits), .BBits(MaterialBits)) u_fp1 (
    .clk_i, .ce_i(ce[3]), .a_i(c1), .b_i(omd_q), .p_o(fp1_q));
  always_ff @(posedge clk_i) if (g_ce[3].q[0]) front_q <= cosi_q != '0;

  // ---- stage 5: cos(i)(N.E) and cos(i)(1-d), exact ---------------------------------------------
  logic signed [CosSExactBits-1:0] cne_q;
  logic [DiffuseBits-1:0]          fp_q;
  logic                            front5_q;
  always_ff @(posedge clk_i) if (g_ce[4].q[0]) begin
    cne_q    <= (CosSExactBits'(cn11_q) <<< (2 * SplitBits)) + CosSExactBits'(cn00_q)
              + (CosSExactBits'(cn01_q) <<< SplitBits) + (CosSExactBits'(cn10_q) <<< SplitBits);
    fp_q     <= DiffuseBits'(fp0_q) + (DiffuseBits'(fp1_q) << SplitBits);
    front5_q <= front_q;
  end

  // ---- stage 6: cos(s) = 2 cos(i)(N.E) - L.E in [0, 1] (P bits), f = cos(i)(1-d) + d -----------
  // cs = (2 cne + cs_k) >> CosSShift is cos(s) rounded; the clamp to [0, 2^P] and the test cs > 0
  // are three signs: cs < 0 iff the sum is negative, cs > 2^P iff the sum is at least
  // (2^P + 1) 2^CosSShift, cs > 0 iff it is at least 2^CosSShift (a floor is at least an integer
  // m exactly when its argument is at least m 2^CosSShift). Each is the sign bit of a
  // CosSExactBits-bit sum of its own (cs_o_q, cs_p_q), so no reduction over cs's bits follows an
  // add: three carry chains side by side, then one LUT per bit (reductions over cs's bits would
  // be four LUT levels after the chain).
  // Power k = 0..ShininessBits-1 (stages PowFirst + 4k to + 4k + 3): acc *= base if bit k of n,
  // base *= base, the operands registered in the multiplier blocks in the first stage, the
  // products in the second, again in the third, rounded in the fourth; acc0_q and base0_q start
  // them (stage 6), g_pow[k].fa_r_q's acc and g_pow[k].g_base.base_q are their results.
  logic [PowBits:0]       acc0_q, base0_q;
  logic [DiffuseBits-1:0] f0_q;  // f, then in g_pow[k].fa_*_q
  always_ff @(posedge clk_i) begin
    if (g_ce[CosStage-1].q[0]) begin
      /* verilator lint_off UNUSEDSIGNAL */
      // cs's bits below CosSShift and above P are not read
      logic signed [CosSExactBits-1:0] cs2, cs_o, cs_p;
      /* verilator lint_on UNUSEDSIGNAL */
      cs2  = (cne_q <<< 1) + cs_k_q;
      cs_o = (cne_q <<< 1) + cs_o_q;
      cs_p = (cne_q <<< 1) + cs_p_q;
      if (!cs_o[CosSExactBits-1])    base0_q <= (PowBits+1)'(1 << PowBits);  // cs > 2^P
      else if (cs2[CosSExactBits-1]) base0_q <= '0;                          // cs < 0
      else                           base0_q <= cs2[CosSShift +: PowBits+1];
      // A pixel facing away (cos(i) = 0) or with cos(s) = 0 starts from acc = 0: specular 0.
      acc0_q <= (front5_q && !cs_p[CosSExactBits-1]) ? (PowBits+1)'(1 << PowBits) : '0;  // cs > 0
      f0_q   <= fp_q + (DiffuseBits'(g_d[CosStage-2].q) << DotBits);
    end
  end

  // The products split at bit SplitBits into four partial products, each registered straight
  // from its multiplier block (a 21 x 21 product and its adder tree in one clock would limit the
  // shader on the ECP5); the round stage adds them:
  // x·y = {x1·y1, x0·y0} + (x0·y1 + x1·y0)·2^SplitBits.
  localparam int PowProductBits = 2 * PowBits + 3;
  localparam int PowHighBits    = PowBits + 1 - SplitBits;  // 4
  localparam int AccBits        = PowBits + 1;              // {f, acc}: acc at [AccBits-1:0],
  localparam int DiffuseAccBits = AccBits + DiffuseBits;    // f at [AccBits +: DiffuseBits]
  for (genvar k = 0; k < ShininessBits; k++) begin : g_pow
    // ce[OperandStage - 1]: the operand stage loads, ce[OperandStage] the product,
    // ce[OperandStage + 1] the copy, ce[OperandStage + 2] the round.
    localparam int OperandStage = PowFirst + PowStages * k;
    logic [2*SplitBits-1:0]           a00_q;         // low x low
    logic [SplitBits+PowHighBits-1:0] a01_q, a10_q;  // low x high
    logic [2*PowHighBits-1:0]         a11_q;         // high x high
    // acc travels with f in one word {f, acc} per stage (_o: operand stage, _p: product, _c:
    // copy, _r: round, where acc is the power's result), M in one of its own: the round stage
    // writes both words and reads n from M, so a simulator (Verilator) orders f's and M's
    // registers with the power's and merges each stage's enable tests into one (f in a register
    // chain of its own is ordered apart, under tests of its own; {f, M}, wider than 64 bits,
    // costs more to copy than it saves). Same flops.
    logic [DiffuseAccBits-1:0]   fa_in, fa_o_q, fa_p_q, fa_c_q, fa_r_q;
    /* verilator lint_off UNUSEDSIGNAL */
    logic [MaterialWordBits-1:0] m_in, m_o_q, m_p_q, m_c_q, m_r_q;  // n's bits below k are read
                                                                    // no more; the last power's
                                                                    // m_r_q only for Cp
    /* verilator lint_on UNUSEDSIGNAL */
    logic [PowBits:0]            base_in;
    logic [SplitBits-1:0]        x0, y0;
    logic [PowHighBits-1:0]      x1, y1;
    if (k == 0) begin : g_first
      assign fa_in   = {f0_q, acc0_q};
      assign m_in    = g_m[CosStage-1].q;
      assign base_in = base0_q;
    end else begin : g_next
      assign fa_in   = g_pow[k-1].fa_r_q;
      assign m_in    = g_pow[k-1].m_r_q;
      assign base_in = g_pow[k-1].g_base.base_q;
    end
    assign {x1, x0} = fa_in[AccBits-1:0];
    assign {y1, y0} = base_in;
    mul18_reg #(.ABits(SplitBits), .BBits(SplitBits), .InReg(1'b1)) u_a00 (
      .clk_i, .ce_i(ce[OperandStage:OperandStage-1]), .a_i(x0), .b_i(y0), .p_o(a00_q));
    mul18_reg #(.ABits(SplitBits), .BBits(PowHighBits), .InReg(1'b1)) u_a01 (
      .clk_i, .ce_i(ce[OperandStage:OperandStage-1]), .a_i(x0), .b_i(y1), .p_o(a01_q));
    mul18_reg #(.ABits(PowHighBits), .BBits(SplitBits), .InReg(1'b1)) u_a10 (
      .clk_i, .ce_i(ce[OperandStage:OperandStage-1]), .a_i(x1), .b_i(y0), .p_o(a10_q));
    mul18_reg #(.ABits(PowHighBits), .BBits(PowHighBits), .InReg(1'b1)) u_a11 (
      .clk_i, .ce_i(ce[OperandStage:OperandStage-1]), .a_i(x1), .b_i(y1), .p_o(a11_q));
    // The operand stage: acc and base enter the blocks' operand registers (mul18_reg InReg),
    // so a route from the fabric across the die (the Phong top's MULT18 blocks spread over it)
    // ends at a register, not at the multiplier's long input setup. acc also waits in fa_*_q,
    // for a bit of n that is clear.
    always_ff @(posedge clk_i) if (g_ce[OperandStage-1].q[0]) begin
      fa_o_q <= fa_in;
      m_o_q  <= m_in;
    end
    always_ff @(posedge clk_i) if (g_ce[OperandStage].q[0]) begin
      fa_p_q <= fa_o_q;
      m_p_q  <= m_o_q;
    end
    // The round stage: the sums only for the products it keeps (acc's for a set bit of n).
    // The copy stage: the multiplier blocks' outputs registered again in the fabric, so the
    // route from a block (long on the ECP5) is not in front of the round stage's adders.
    logic [2*SplitBits-1:0]           a00c_q;
    logic [SplitBits+PowHighBits-1:0] a01c_q, a10c_q;
    logic [2*PowHighBits-1:0]         a11c_q;
    always_ff @(posedge clk_i) if (g_ce[OperandStage+1].q[0]) begin
      a00c_q <= a00_q;
      a01c_q <= a01_q;
      a10c_q <= a10_q;
      a11c_q <= a11_q;
      fa_c_q <= fa_p_q;
      m_c_q  <= m_p_q;
    end
    always_ff @(posedge clk_i) if (g_ce[OperandStage+2].q[0]) begin
      /* verilator lint_off UNUSEDSIGNAL */
      logic [PowProductBits-1:0] pa;  // product <= 2^2P plus half: only [2P:P] is kept
      /* verilator lint_on UNUSEDSIGNAL */
      pa = PowProductBits'({a11c_q, a00c_q}) + (PowProductBits'(a01c_q) << SplitBits)
         + (PowProductBits'(a10c_q) << SplitBits) + PowProductBits'(1 << (PowBits - 1));
      fa_r_q <= {fa_c_q[AccBits +: DiffuseBits],  // acc: bit k of n picks
                 m_c_q[ShininessLow + k] ? pa[2*PowBits:PowBits] : fa_c_q[AccBits-1:0]};
      m_r_q  <= m_c_q;
    end
    // base^2, for the next power stage only (the last one has none).
    if (k + 1 < ShininessBits) begin : g_base
      logic [2*SplitBits-1:0]           b00_q;   // low x low
      logic [SplitBits+PowHighBits-1:0] b01_q;   // low x high (b10 = b01: a square)
      logic [2*PowHighBits-1:0]         b11_q;   // high x high
      logic [PowBits:0]                 base_q;  // base out
      mul18_reg #(.ABits(SplitBits), .BBits(SplitBits), .InReg(1'b1)) u_b00 (
        .clk_i, .ce_i(ce[OperandStage:OperandStage-1]), .a_i(y0), .b_i(y0), .p_o(b00_q));
      mul18_reg #(.ABits(SplitBits), .BBits(PowHighBits), .InReg(1'b1)) u_b01 (
        .clk_i, .ce_i(ce[OperandStage:OperandStage-1]), .a_i(y0), .b_i(y1), .p_o(b01_q));
      mul18_reg #(.ABits(PowHighBits), .BBits(PowHighBits), .InReg(1'b1)) u_b11 (
        .clk_i, .ce_i(ce[OperandStage:OperandStage-1]), .a_i(y1), .b_i(y1), .p_o(b11_q));
      logic [2*SplitBits-1:0]           b00c_q;
      logic [SplitBits+PowHighBits-1:0] b01c_q;
      logic [2*PowHighBits-1:0]         b11c_q;
      always_ff @(posedge clk_i) if (g_ce[OperandStage+1].q[0]) begin
        b00c_q <= b00_q;
        b01c_q <= b01_q;
        b11c_q <= b11_q;
      end
      always_ff @(posedge clk_i) if (g_ce[OperandStage+2].q[0]) begin
        /* verilator lint_off UNUSEDSIGNAL */
        logic [PowProductBits-1:0] pb;  // product <= 2^2P plus half: only [2P:P] is kept
        /* verilator lint_on UNUSEDSIGNAL */
        pb = PowProductBits'({b11c_q, b00c_q}) + (PowProductBits'(b01c_q) << (SplitBits + 1))
           + PowProductBits'(1 << (PowBits - 1));
        base_q <= pb[2*PowBits:PowBits];
      end
    end
  end

  // ---- stage 38 (the last power stage): 255 W, so W pow needs no multiply by 255 after it ----
  logic [MaterialBits+7:0] w255_q;  // 255 W < 2^17: one multiplier block with a SplitBits-bit
                                    // operand
  logic [MaterialBits-1:0] w_last;  // W in the last power's copy stage
  assign w_last = g_pow[ShininessBits-1].m_c_q[SpecularLow +: MaterialBits];
  always_ff @(posedge clk_i) if (g_ce[PowLast-1].q[0])
    w255_q <= ((MaterialBits+8)'(w_last) << 8) - (MaterialBits+8)'(w_last);

  // ---- stages 39, 40: Cp f per channel and 255 W cos(s)^n, as partial products ---------------
  // Stage 39 loads the operands into the multiplier blocks' registers (mul18_reg InReg), stage 40
  // the products: otherwise the last power's f and acc (fa_r_q) would reach the blocks' inputs
  // over a long route, in front of the multiplier's long input setup on the ECP5.
  // Channel c is byte c of rgb_t (B, G, R for c = 0, 1, 2) in Cp and in the shade alike: the
  // three channels are computed the same way, so the loop need not know which is which.
  // f (DiffuseBits bits) and pow (P + 1 bits) are split at SplitBits: two multiplier blocks each.
  localparam int DiffuseHighBits = DiffuseBits - SplitBits;   // 16
  localparam int AccHighBits     = PowBits + 1 - SplitBits;   // 4
  localparam int CpFLowBits      = SplitBits + 8;             // Cp f0
  localparam int CpFHighBits     = DiffuseHighBits + 8;       // Cp f1
  logic [3*CpFLowBits-1:0]               df0_q;  // Cp f0, channel c at c * CpFLowBits (vectors:
                                                 // see g_m)
  logic [3*CpFHighBits-1:0]              df1_q;  // Cp f1
  logic [MaterialBits+8+SplitBits-1:0]   wa0_q;  // 255 W pow0
  logic [MaterialBits+8+AccHighBits-1:0] wa1_q;  // 255 W pow1
  logic [DiffuseBits-1:0]                fl;
  logic [PowBits:0]                      al;
  logic [RgbBits-1:0]                    cpl;    // Cp
  assign fl  = g_pow[ShininessBits-1].fa_r_q[AccBits +: DiffuseBits];
  assign al  = g_pow[ShininessBits-1].fa_r_q[AccBits-1:0];
  assign cpl = g_pow[ShininessBits-1].m_r_q[ReflectanceLow +: RgbBits];
  for (genvar c = 0; c < 3; c++) begin : g_df
    mul18_reg #(.ABits(8), .BBits(SplitBits), .InReg(1'b1)) u_df0 (
      .clk_i, .ce_i(ce[PowLast+1:PowLast]), .a_i(cpl[c*8 +: 8]), .b_i(fl[SplitBits-1:0]),
      .p_o(df0_q[c*CpFLowBits +: CpFLowBits]));
    mul18_reg #(.ABits(8), .BBits(DiffuseHighBits), .InReg(1'b1)) u_df1 (
      .clk_i, .ce_i(ce[PowLast+1:PowLast]), .a_i(cpl[c*8 +: 8]),
      .b_i(fl[DiffuseBits-1:SplitBits]), .p_o(df1_q[c*CpFHighBits +: CpFHighBits]));
  end
  mul18_reg #(.ABits(MaterialBits+8), .BBits(SplitBits), .InReg(1'b1)) u_wa0 (
    .clk_i, .ce_i(ce[PowLast+1:PowLast]), .a_i(w255_q), .b_i(al[SplitBits-1:0]), .p_o(wa0_q));
  mul18_reg #(.ABits(MaterialBits+8), .BBits(AccHighBits), .InReg(1'b1)) u_wa1 (
    .clk_i, .ce_i(ce[PowLast+1:PowLast]), .a_i(w255_q), .b_i(al[PowBits:SplitBits]), .p_o(wa1_q));

  // ---- stage 41: Cp f and 255 W cos(s)^n (white highlight), D + MaterialFracBits fraction bits
  // The final rounding's half, 2^(D+MaterialFracBits-1), is set in Cp f's sum as a bit above
  // Cp f0 (< 2^(SplitBits+8) <= 2^(D+MaterialFracBits-1): an OR, no carry), so stage 42 adds two
  // operands, not three.
  localparam logic [LevelSumBits-1:0] Half = LevelSumBits'(1) << (DotBits + MaterialFracBits - 1);
  logic [3*LevelSumBits-1:0] diff2_q;  // Cp f plus the rounding half, channel c at
                                       // c * LevelSumBits
  logic [LevelSumBits-1:0]   spec_q;
  always_ff @(posedge clk_i) if (g_ce[PowLast+2].q[0]) begin
    for (int c = 0; c < 3; c++)
      diff2_q[c*LevelSumBits +: LevelSumBits]
          <= (LevelSumBits'(df0_q[c*CpFLowBits +: CpFLowBits]) | Half)
           + (LevelSumBits'(df1_q[c*CpFHighBits +: CpFHighBits]) << SplitBits);
    spec_q <= (LevelSumBits'(wa0_q) + (LevelSumBits'(wa1_q) << SplitBits)) << (DotBits - PowBits);
  end

  // ---- stage 42: level = saturate(round(Cp f + 255 W pow)) --------------------------------------
  logic [watkins_pkg::RgbBits-1:0] rgb_q;
  always_ff @(posedge clk_i) if (g_ce[PowLast+3].q[0]) begin
    for (int c = 0; c < 3; c++) begin
      logic [LevelSumBits-1:0] lvl;
      // diff2_q holds the rounding half
      lvl = (diff2_q[c*LevelSumBits +: LevelSumBits] + spec_q) >> (DotBits + MaterialFracBits);
      rgb_q[c*8 +: 8] <= (lvl > LevelSumBits'(255)) ? 8'd255 : lvl[7:0];
    end
  end

  assign rgb_o = rgb_q;

  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, {normal_i, cp_i, d_i, w_i, shininess_i, payload_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, {rgb_o, payload_o})
  `WATKINS_COVER(c_stall, valid_o && !ready_i)
endmodule
