// rsqrt_unit: y ~ 1/sqrt(m') for m = 2^(4-2j) * m', m' in [1/4, 1): the normalizer's square root.
// Phong 1975 p. 317 asks for "a very fast mechanism for obtaining square roots": an even-shift
// normalization, a 768-row seed table and one Newton-Raphson step. Bit-exact twin of
// Normalizer::normalize_mantissa and RsqrtUnit::rsqrt_mant (model/twins/rsqrt_unit.hpp).
// Latency 10 cycles (Stages = watkins_pkg::RsqrtStages: the normalizer, the benches, the proof
// and the cycle model derive theirs from that one constant). Every stage is registered. No
// handshake: ce_i[k] loads stage k (the parent owns valid/ready and the stall, and gives each
// stage its clock enable: its stall_pipe's ce_o, low for a bubble, whose values nobody reads, so
// a simulator computes valid beats only; a unit bench may drive them all together).
// Stages: search (j1_q) -> shift and seed read (y0_2_q) -> seed (y0_3_q) -> seed square
// (y0sq_4_q) -> operands (the multipliers' input registers) -> products (p00_q ..) -> copy
// (p00c_q ..) -> u (u_q) -> y0 u (q0_q, q1_q) -> y (y_q).
// Registered where a clock would otherwise hold a long route: the leading-one search (stage 1)
// and the even shift (stage 2, straight into the seed ROM's address) are a clock apart; the ROM
// holds y0^2 beside y0 (tabulated, not multiplied), its output registered in the fabric twice
// more (stages 3 and 4); y0^2 enters the next products' blocks through their operand registers
// (no route from a block RAM or a block's output ends at a multiplier); the two Newton-Raphson
// products, wider than an 18 x 18 multiplier, are registered as partial products (the first's
// copied into the fabric a stage later, then summed; the second's summed and rounded a stage
// later).
module rsqrt_unit #(
  localparam int SquaredLengthBits = 2 * watkins_pkg::NormalInBits,  // m = Nx^2 + Ny^2 + Nz^2
  localparam int RsqrtBits         = watkins_pkg::RsqrtBits,         // F: fraction bits of y
  localparam int Stages            = watkins_pkg::RsqrtStages        // latency: stage k loads on
                                                                     // ce_i[k]
) (
  input  logic                         clk_i,
  input  logic [Stages:1]              ce_i,    // [k]: stage k's registers load
  input  logic [SquaredLengthBits-1:0] m_i,     // squared length, 2*FracBits fraction bits
  output logic [RsqrtBits+1:0]         y_o,     // 1/sqrt(m'c) with F fraction bits, in [1, 2];
                                                // 0 if null_o
  output logic [4:0]                   j_o,     // 1/sqrt(m) = y * 2^(j-2); 0 if null_o
  output logic                         null_o   // m == 0
);
  // The comments write the formats as the model's formulas do: W, P, T, G and F.
  localparam int MantBits       = watkins_pkg::RsqrtMantBits;   // W: mantissa bits of m'
  localparam int IndexBits      = watkins_pkg::RsqrtIndexBits;  // P: seed index bits
  localparam int SeedBits       = watkins_pkg::RsqrtSeedBits;   // T: seed fraction bits
  localparam int NewtonFracBits = watkins_pkg::RsqrtNrBits;     // G: fraction bits of m'c * y0^2
  // u's shift: m'c y0^2 to G fraction bits; y's: y0 u / 2 to F fraction bits.
  localparam int UShift = (MantBits + 1) + 2 * SeedBits - NewtonFracBits;
  localparam int YShift = SeedBits + NewtonFracBits + 1 - RsqrtBits;

  // floor(sqrt(v)) bit by bit, exactly Normalizer::isqrt for v < 2^34 (the seeds need v < 2^32:
  // v = 2^(2T+P+3) / (2 idx + 1) with idx >= 2^(P-2)); fewer steps keep elaboration quick.
  function automatic logic [63:0] isqrt(input logic [63:0] v);
    logic [63:0] rem, root, b;
    rem  = v;
    root = '0;
    for (int i = 16; i >= 0; i--) begin
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

  // Seed row idx: round(2^T / sqrt(c)), c = (2 idx + 1) / 2^(P+1) the centre of the row's
  // interval of m' (Normalizer::seed): round(sqrt(x)) = (floor(sqrt(4x)) + 1) / 2.
  /* verilator lint_off UNUSEDSIGNAL */
  function automatic logic [SeedBits:0] seed_fn(input int idx);
    logic [63:0] q, r;  // r < 2^(T+1): its top bits are zero
    q = (64'd1 << (2 * SeedBits + IndexBits + 3)) / 64'(2 * idx + 1);
    r = (isqrt(q) + 64'd1) >> 1;
    seed_fn = r[SeedBits:0];
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */

  // The seed ROM, one row per P-bit index, {y0^2, y0}, filled at elaboration (the same rows in
  // synthesis and simulation). y0^2 (2T fraction bits, exact) is tabulated beside the seed
  // instead of multiplied, so the RAM's output ends at fabric registers: a multiplier whose
  // operands come straight from the block RAM has the RAM's long clock-to-out and a route across
  // the die to the multiplier block in one clock. Rows below 2^(P-2) hold 0: only the null vector
  // (mant = 0) reads them, and y = 0 then makes every unit component 0 with no special case. Read
  // synchronously (stage 2's register), so synthesis maps it to block RAM (ECP5: 3 x DP16KD;
  // iCE40: 12 x SB_RAM40_4K) instead of a 1024-way mux.
  localparam int RowBits = 3 * SeedBits + 3;  // y0^2 (2T + 2 bits) and y0 (T + 1 bits)
  logic [RowBits-1:0] seed_rom [1 << IndexBits];
  initial begin
    for (int r = 0; r < (1 << (IndexBits - 2)); r++) seed_rom[r] = '0;
    for (int r = 1 << (IndexBits - 2); r < (1 << IndexBits); r++)
      seed_rom[r] = {(2 * SeedBits + 2)'(seed_fn(r)) * (2 * SeedBits + 2)'(seed_fn(r)), seed_fn(r)};
  end

  // The per-stage registers are plain variables (jN_q: stage N's), not arrays: a simulator
  // (Verilator) keeps a pending-write flag and value per written array element and clears them
  // on every evaluation. Same flops. The logic of a stage is computed inside its enabled
  // always_ff (the same logic in front of the same flops), so a simulator skips it with them.
  logic [SquaredLengthBits-1:0] m1_q;
  logic [4:0] j1_q, j2_q, j3_q, j4_q, j5_q, j6_q, j7_q, j8_q, j9_q, j10_q;
  logic       nul1_q, nul2_q, nul3_q, nul4_q, nul5_q, nul6_q, nul7_q, nul8_q, nul9_q, nul10_q;

  // ---- stage 1: the even shift 2j, j = the number of all-zero bit pairs above m's leading one ---
  // m' = (m << 2j) / 2^SquaredLengthBits in [1/4, 1). The search alone: the shift waits for
  // stage 2 (search, j and shift in one clock would limit the normalizer on the ECP5).
  always_ff @(posedge clk_i) if (ce_i[1]) begin
    logic [4:0] j1;  // (SquaredLengthBits - 1 - lead) / 2, lead the leading one's index; 0 for
                     // m = 0
    j1 = '0;
    for (int p = 0; p < SquaredLengthBits / 2; p++)
      if (m_i[2*p +: 2] != 2'b00) j1 = 5'(SquaredLengthBits / 2 - 1 - p);
    m1_q   <= m_i;
    j1_q   <= j1;
    nul1_q <= (m_i == '0);
  end

  // ---- stage 2: the shift m << 2j (only its top W bits are kept: truncation, as the model) and
  // the seed y0 read at its top P bits: the ROM's address comes from the shift's multiplexers ---
  logic [SeedBits:0]     y0_2_q, y0_3_q, y0_4_q, y0_5_q, y0_6_q, y0_7_q, y0_8_q;
  logic [2*SeedBits+1:0] y0sq_2_q, y0sq_3_q;  // y0^2 from the ROM, 2T fraction bits
  logic [MantBits:0]     mc2_q, mc3_q, mc4_q;  // m'c = mant + half an ulp: {mant, 1}, W+1
                                               // fraction bits
  always_ff @(posedge clk_i) if (ce_i[2]) begin
    /* verilator lint_off UNUSEDSIGNAL */
    logic [SquaredLengthBits-1:0] shifted;  // only the top W bits are kept
    /* verilator lint_on UNUSEDSIGNAL */
    logic [MantBits-1:0] mant;  // 0 for m = 0: reads ROM default 0 below
    shifted = m1_q << {j1_q, 1'b0};
    mant    = shifted[SquaredLengthBits-1 -: MantBits];
    {y0sq_2_q, y0_2_q} <= seed_rom[mant[MantBits-1 -: IndexBits]];
    mc2_q  <= {mant, 1'b1};
    j2_q   <= j1_q;
    nul2_q <= nul1_q;
  end

  // ---- stage 3: the seed and its square registered again -----------------------------------
  // The block RAM's clock-to-out (a large part of the clock on the ECP5) leaves room only for a
  // short route: these registers, placed beside the RAM, are all it feeds.
  always_ff @(posedge clk_i) if (ce_i[3]) begin
    y0_3_q <= y0_2_q;
    y0sq_3_q <= y0sq_2_q;
    mc3_q  <= mc2_q;
    j3_q   <= j2_q;
    nul3_q <= nul2_q;
  end

  // ---- stage 4: y0^2 registered once more, on its way from the RAM to the multiplier blocks ---
  logic [2*SeedBits+1:0] y0sq_4_q;
  always_ff @(posedge clk_i) if (ce_i[4]) begin
    y0sq_4_q <= y0sq_3_q;
    y0_4_q <= y0_3_q;
    mc4_q  <= mc3_q;
    j4_q   <= j3_q;
    nul4_q <= nul3_q;
  end

  // The wide products are split at bit SplitBits of each operand wider than 18 bits (the low
  // part fits a multiplier block unsigned), each partial product registered in its block
  // (mul18_reg): x y = x1 y1 2^(2 SplitBits) + (x1 y0 + x0 y1) 2^SplitBits + x0 y0.
  localparam int SplitBits = 17;

  // ---- stage 5: m'c and y0^2 in the next products' operand registers -------------------------
  // A multiplier block's output straight into another's multiplier has the second block's long
  // input setup after the route between the two, and among the Phong top's many MULT18 blocks
  // the placer puts them far apart: the products below register their operands first (mul18_reg
  // InReg), a stage of its own.
  always_ff @(posedge clk_i) if (ce_i[5]) begin
    y0_5_q  <= y0_4_q;
    j5_q    <= j4_q;
    nul5_q  <= nul4_q;
  end
  // ---- stage 6: m'c * y0^2 as four partial products ------------------------------------------
  localparam int MantCentreBits     = MantBits + 1;                 // m'c: 21 bits
  localparam int SeedSquareBits     = 2 * SeedBits + 2;             // y0^2: 30 bits
  localparam int MantCentreHighBits = MantCentreBits - SplitBits;   // 4
  localparam int SeedSquareHighBits = SeedSquareBits - SplitBits;   // 13
  logic [SplitBits-1:0]                             a0, b0;
  logic [MantCentreHighBits-1:0]                    a1;
  logic [SeedSquareHighBits-1:0]                    b1;
  logic [2*SplitBits-1:0]                           p00_q;
  logic [SplitBits+SeedSquareHighBits-1:0]          p01_q;
  logic [MantCentreHighBits+SplitBits-1:0]          p10_q;
  logic [MantCentreHighBits+SeedSquareHighBits-1:0] p11_q;
  assign {a1, a0} = mc4_q;
  assign {b1, b0} = y0sq_4_q;
  mul18_reg #(.ABits(SplitBits), .BBits(SplitBits), .InReg(1'b1)) u_p00 (
    .clk_i, .ce_i(ce_i[6:5]), .a_i(a0), .b_i(b0), .p_o(p00_q));
  mul18_reg #(.ABits(SplitBits), .BBits(SeedSquareHighBits), .InReg(1'b1)) u_p01 (
    .clk_i, .ce_i(ce_i[6:5]), .a_i(a0), .b_i(b1), .p_o(p01_q));
  mul18_reg #(.ABits(MantCentreHighBits), .BBits(SplitBits), .InReg(1'b1)) u_p10 (
    .clk_i, .ce_i(ce_i[6:5]), .a_i(a1), .b_i(b0), .p_o(p10_q));
  mul18_reg #(.ABits(MantCentreHighBits), .BBits(SeedSquareHighBits), .InReg(1'b1)) u_p11 (
    .clk_i, .ce_i(ce_i[6:5]), .a_i(a1), .b_i(b1), .p_o(p11_q));
  always_ff @(posedge clk_i) if (ce_i[6]) begin
    y0_6_q <= y0_5_q;
    j6_q   <= j5_q;
    nul6_q <= nul5_q;
  end

  // ---- stage 7: the partial products copied into the fabric -----------------------------------
  // The route out of a multiplier block (across the die in the Phong top) is then not in front
  // of the stage-8 adder tree, as the shader's copy stage does for its powers.
  logic [2*SplitBits-1:0]                           p00c_q;
  logic [SplitBits+SeedSquareHighBits-1:0]          p01c_q;
  logic [MantCentreHighBits+SplitBits-1:0]          p10c_q;
  logic [MantCentreHighBits+SeedSquareHighBits-1:0] p11c_q;
  always_ff @(posedge clk_i) if (ce_i[7]) begin
    p00c_q <= p00_q;
    p01c_q <= p01_q;
    p10c_q <= p10_q;
    p11c_q <= p11_q;
    y0_7_q <= y0_6_q;
    j7_q   <= j6_q;
    nul7_q <= nul6_q;
  end

  // ---- stage 8: u = 3 - round(m'c * y0^2), G fraction bits (|m'c y0^2 - 1| < 2^-9) ---------
  // One sum, one carry chain: with p = m'c y0^2 (UShift + G fraction bits) and s = UShift,
  // 3 * 2^G - floor((p + 2^(s-1)) / 2^s) = ceil((3 * 2^(G+s) - 2^(s-1) - p) / 2^s)
  //                                      = floor((3 * 2^(G+s) + 2^(s-1) - 1 - p) / 2^s),
  // so u is bits [s+G+1:s] of UConstant - p: the partial products subtracted in one adder tree,
  // one carry chain where the product, the rounding add and the subtract from 3 would be three.
  localparam int UDifferenceBits =
      (MantCentreBits + SeedSquareBits + 1 > UShift + NewtonFracBits + 2)
          ? MantCentreBits + SeedSquareBits + 1 : UShift + NewtonFracBits + 2;
  localparam logic [UDifferenceBits-1:0] UConstant =
      (UDifferenceBits'(3) << (NewtonFracBits + UShift)) + (UDifferenceBits'(1) << (UShift - 1))
      - UDifferenceBits'(1);
  logic [NewtonFracBits+1:0] u_q;
  always_ff @(posedge clk_i) if (ce_i[8]) begin
    /* verilator lint_off UNUSEDSIGNAL */
    logic [UDifferenceBits-1:0] ud;  // u * 2^s plus the remainder; only bits [s+G+1:s] are kept
    /* verilator lint_on UNUSEDSIGNAL */
    ud = UConstant - UDifferenceBits'({p11c_q, p00c_q})
       - (UDifferenceBits'(p01c_q) << SplitBits) - (UDifferenceBits'(p10c_q) << SplitBits);
    u_q    <= ud[UShift +: NewtonFracBits+2];
    y0_8_q <= y0_7_q;
    j8_q   <= j7_q;
    nul8_q <= nul7_q;
  end

  // ---- stage 9: y0 * u as two partial products (u split at SplitBits) -------------------------
  localparam int SeedWordBits = SeedBits + 1;           // y0: 15 bits
  localparam int UWordBits    = NewtonFracBits + 2;     // u: 26 bits
  localparam int UHighBits    = UWordBits - SplitBits;  // 9
  logic [SeedWordBits+SplitBits-1:0] q0_q;
  logic [SeedWordBits+UHighBits-1:0] q1_q;
  mul18_reg #(.ABits(SeedWordBits), .BBits(SplitBits)) u_q0 (
    .clk_i, .ce_i(ce_i[9]), .a_i(y0_8_q), .b_i(u_q[SplitBits-1:0]), .p_o(q0_q));
  mul18_reg #(.ABits(SeedWordBits), .BBits(UHighBits)) u_q1 (
    .clk_i, .ce_i(ce_i[9]), .a_i(y0_8_q), .b_i(u_q[UWordBits-1:SplitBits]), .p_o(q1_q));
  always_ff @(posedge clk_i) if (ce_i[9]) begin
    j9_q   <= j8_q;
    nul9_q <= nul8_q;
  end

  // ---- stage 10 (Stages): y = round(y0 * u / 2), F fraction bits: y <- y (3 - m' y^2) / 2 --
  localparam int YProductBits = SeedWordBits + UWordBits + 1;
  logic [RsqrtBits+1:0] y_q;
  always_ff @(posedge clk_i) if (ce_i[Stages]) begin
    logic [YProductBits-1:0] yprod;
    /* verilator lint_off UNUSEDSIGNAL */
    logic [YProductBits-1:0] yr;  // y <= 2: the top bits are zero
    /* verilator lint_on UNUSEDSIGNAL */
    yprod = YProductBits'(q0_q) + (YProductBits'(q1_q) << SplitBits);
    yr    = (yprod + (YProductBits'(1) << (YShift - 1))) >> YShift;
    y_q     <= yr[RsqrtBits+1:0];
    j10_q   <= j9_q;
    nul10_q <= nul9_q;
  end

  assign y_o    = y_q;
  assign j_o    = j10_q;
  assign null_o = nul10_q;
endmodule
