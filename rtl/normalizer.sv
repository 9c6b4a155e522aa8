// normalizer: the unit normal N/|N|, Q2.14, of an interpolated normal.
// Phong 1975 eqs. 6-8 need a unit N; p. 317 asks for "a very fast mechanism for obtaining square
// roots". Bit-exact twin of model/twins/normalizer.hpp: m = Nx^2+Ny^2+Nz^2 exact, 1/sqrt(m) by
// rsqrt_unit (even shift, seed table, one Newton-Raphson step), N * 1/sqrt(m) rounded and
// saturated to UnitBits. The null vector (m = 0) gives (0, 0, 0) with null_o set; any m > 0 gives
// a unit vector.
// Latency 16 cycles (2 + watkins_pkg::RsqrtStages + 4), one normal per clock. Every stage
// registers valid and data; every product is registered in its multiplier block (mul18_reg: on
// the ECP5 the MULT18X18D's output register; the final one as partial products split at an
// 18 x 18 multiplier), its sums, shift and round a stage later each; one global stall
// (stall_pipe): ready_o = ready_i || !valid_o (combinational from ready_i and the output valid
// flop only; with LookAhead a flop loaded a clock ahead from ready_next_i).
// Stages: squares (g_sq) -> sum (m_q) -> rsqrt (u_rsqrt, RsqrtStages of them) -> partials
// (pl_q, ph_q) -> product (p_q) -> shift (t_q) -> round (unit_q).
// Each stage's registers load only when the beat entering it is valid (en && its valid: one LUT,
// as en alone): a bubble's values are never read, so a simulator need not compute them (most
// clocks of a frame carry bubbles); a valid beat's values are the same.
`include "watkins_assert.svh"

module normalizer #(
  parameter int PayloadBits = 1,     // carried alongside (pixel x, ...)
  parameter bit LookAhead   = 1'b0,  // stall_pipe's: ready from a flop
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
  input  logic                    ready_next_i,  // LookAhead: ready_i on the next clock
  output logic                    ready_next_o   // ready_o on the next clock (from ready_next_i)
);
  localparam int SquaredLengthBits = 2 * NormalBits;                // m: 36, m < 3 * 2^34
  localparam int RsqrtBits         = watkins_pkg::RsqrtBits;        // F below: fraction bits of y
  localparam int RsqrtLatency      = watkins_pkg::RsqrtStages;      // rsqrt_unit's latency (10)
  // squares, sum, rsqrt, partials, sum, shift, round
  localparam int Stages            = 2 + RsqrtLatency + 4;
  localparam int ScaledBits        = NormalBits + RsqrtBits + 3;    // N * y, signed, plus a
                                                                    // rounding guard bit

  // Valid, payload and the stall of every stage. The payload (the fragment's x, depth, ...) is
  // written once into a RAM, not shifted through every stage. ce[s]: stage s's registers load
  // (the stall's en and the beat entering stage s is valid); the rsqrt unit's stages take theirs.
  logic [Stages-1:0] ce;
  /* verilator lint_off UNUSEDSIGNAL */
  logic              en;     // inside ce
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


  // ---- stage 0: Nx^2, Ny^2, Nz^2, exact, each registered from its multiplier block -------------
  // ---- stage 1: m = Nx^2 + Ny^2 + Nz^2 (the squares and their sum a clock apart) ---------------
  for (genvar c = 0; c < 3; c++) begin : g_sq  // a generate block, not an array: see g_n below
    logic signed [NormalBits-1:0] n;
    logic [SquaredLengthBits-1:0] q;  // <= 2^34: non-negative
    assign n = normal_i[c*NormalBits +: NormalBits];
    mul18_reg #(.ABits(NormalBits), .BBits(NormalBits), .ASigned(1'b1), .BSigned(1'b1),
                .PBits(SquaredLengthBits)) u_sq (
      .clk_i, .ce_i(ce[0]), .a_i(n), .b_i(n), .p_o(q));  // exact
  end

  logic [SquaredLengthBits-1:0] m_q;
  always_ff @(posedge clk_i) if (ce[1]) m_q <= g_sq[0].q + g_sq[1].q + g_sq[2].q;

  // ---- stages 2..RsqrtLatency+1 (11): y = 1/sqrt(m') with 1/sqrt(m) = y * 2^(j-2) ----------------
  logic [RsqrtBits+1:0] y;
  logic [4:0]   j;
  logic         nul;
  rsqrt_unit u_rsqrt (
    .clk_i  (clk_i),
    .ce_i   (ce[RsqrtLatency+1:2]),  // rsqrt stage k is stage k + 1 here
    .m_i    (m_q),
    .y_o    (y),
    .j_o    (j),
    .null_o (nul)
  );

  // N waits alongside the rsqrt pipe (stage 0 .. stage 11). The per-stage and per-component
  // registers are plain variables of generate blocks, not array elements: a simulator
  // (Verilator) keeps a pending-write flag and value per written array element and clears them
  // on every evaluation. Same flops.
  for (genvar s = 0; s <= RsqrtLatency + 1; s++) begin : g_n
    logic [3*NormalBits-1:0] q;
    if (s == 0) begin : g_in
      always_ff @(posedge clk_i) if (ce[0]) q <= normal_i;
    end else begin : g_shift
      always_ff @(posedge clk_i) if (ce[s]) q <= g_n[s-1].q;
    end
  end

  // ---- stage 12: N * y as two partial products, y split at bit RsqrtSplit ---------------------
  // N (NormalBits signed) times y (RsqrtBits + 2 unsigned) is wider than one 18 x 18 multiplier
  // block; each partial product is registered straight from its block, summed a stage later (the
  // product, its adder, the shift and the round in one clock would limit the Phong top).
  // The shift is registered as MaxZeroPairs - j (see stage 14), computed here off the rsqrt's
  // output.
  // ---- stage 13: p = N * y, exact (FracBits + F fraction bits) ----------------------------------
  // ---- stage 14: t = floor(p / 2^(F+3-j)), the shift alone --------------------------------------
  // ---- stage 15: unit = saturate((t + 1) >> 1): Q2.14 ---------------------------------------------
  // 1/sqrt(m) = y 2^(j-2) and N carries 16 fraction bits, so the rounding shift to 14 is
  // sh = F + 4 - j, in [F-13, F+4]: always a right shift. round(p / 2^sh) = floor((p + 2^(sh-1)) /
  // 2^sh) = floor((floor(p / 2^(sh-1)) + 1) / 2): the shift by sh - 1 first (stage 14), then one
  // increment and a shift by one (stage 15), the same value as round_shift's add-then-shift.
  // sh - 1 >= MinShift, so stage 14 drops MinShift bits by wiring and shifts by MaxZeroPairs - j
  // in [0, MaxZeroPairs].
  localparam int RsqrtWordBits = RsqrtBits + 2;                // y
  localparam int RsqrtSplit    = 17;                           // fits an 18 x 18 multiplier as {0, y}
  localparam int RsqrtHighBits = RsqrtWordBits - RsqrtSplit;   // 7
  localparam int MaxZeroPairs  = (SquaredLengthBits - 1) / 2;  // rsqrt_unit's largest j: 17
  localparam int MinShift      = RsqrtBits + 3 - MaxZeroPairs; // sh - 1 at j = MaxZeroPairs: 8
  localparam int ShiftedBits   = ScaledBits - MinShift;        // t, signed
  logic [4:0] sh12_q, sh13_q;  // MaxZeroPairs - j
  logic       nul12_q, nul13_q, nul14_q, nul15_q;
  always_ff @(posedge clk_i) if (ce[RsqrtLatency+2]) begin
    sh12_q  <= 5'(MaxZeroPairs) - j;
    nul12_q <= nul;
  end
  always_ff @(posedge clk_i) if (ce[RsqrtLatency+3]) begin
    sh13_q  <= sh12_q;
    nul13_q <= nul12_q;
  end
  always_ff @(posedge clk_i) if (ce[RsqrtLatency+4]) nul14_q <= nul13_q;
  always_ff @(posedge clk_i) if (ce[RsqrtLatency+5]) nul15_q <= nul14_q;

  for (genvar c = 0; c < 3; c++) begin : g_comp
    logic signed [NormalBits-1:0]               n;
    logic signed [NormalBits+RsqrtSplit-1:0]    pl_q;   // N * y[RsqrtSplit-1:0]
    logic signed [NormalBits+RsqrtHighBits-1:0] ph_q;   // N * y[RsqrtWordBits-1:RsqrtSplit]
    logic signed [ScaledBits-1:0]               p_q;
    logic signed [ShiftedBits-1:0]              t_q;
    logic [UnitBits-1:0]                        unit_q;
    assign n = signed'(g_n[RsqrtLatency+1].q[c*NormalBits +: NormalBits]);
    mul18_reg #(.ABits(NormalBits), .BBits(RsqrtSplit), .ASigned(1'b1),
                .PBits(NormalBits+RsqrtSplit)) u_pl (
      .clk_i, .ce_i(ce[RsqrtLatency+2]), .a_i(n), .b_i(y[RsqrtSplit-1:0]), .p_o(pl_q));
    mul18_reg #(.ABits(NormalBits), .BBits(RsqrtHighBits), .ASigned(1'b1),
                .PBits(NormalBits+RsqrtHighBits)) u_ph (
      .clk_i, .ce_i(ce[RsqrtLatency+2]), .a_i(n), .b_i(y[RsqrtWordBits-1:RsqrtSplit]),
      .p_o(ph_q));
    always_ff @(posedge clk_i)
      if (ce[RsqrtLatency+3]) p_q <= (ScaledBits'(ph_q) <<< RsqrtSplit) + ScaledBits'(pl_q);
    always_ff @(posedge clk_i) if (ce[RsqrtLatency+4]) begin
      /* verilator lint_off UNUSEDSIGNAL */
      logic signed [ScaledBits-1:0] ps;  // p >>> MinShift: its top MinShift bits are sign copies
      /* verilator lint_on UNUSEDSIGNAL */
      ps = p_q >>> MinShift;
      t_q <= signed'(ps[ShiftedBits-1:0]) >>> sh13_q;
    end
    // Saturation when r's bits above UnitBits - 1 are not all copies of its sign: bit tests, not
    // compares (a compare would be a second carry chain after the increment).
    always_ff @(posedge clk_i) if (ce[RsqrtLatency+5]) begin
      logic signed [ShiftedBits:0] r;
      r = ((ShiftedBits+1)'(t_q) + (ShiftedBits+1)'(1)) >>> 1;
      if (r[ShiftedBits:UnitBits-1] == '0 || r[ShiftedBits:UnitBits-1] == '1)
        unit_q <= r[UnitBits-1:0];
      else if (!r[ShiftedBits]) unit_q <= UnitBits'((1 << (UnitBits - 1)) - 1);
      else                      unit_q <= UnitBits'(1 << (UnitBits - 1));
    end
  end

  assign unit_o = {g_comp[2].unit_q, g_comp[1].unit_q, g_comp[0].unit_q};
  assign null_o = nul15_q;

  // The payload's hold is checked once, by u_pipe (stall_pipe's a_in_hold and a_out_hold: the
  // same valid and ready): a simulator keeps a sampled copy of every signal an assertion reads.
  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, normal_i)
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, {unit_o, null_o})
  `WATKINS_COVER(c_stall, valid_o && !ready_i)
  `WATKINS_COVER(c_null, valid_o && null_o)
endmodule
