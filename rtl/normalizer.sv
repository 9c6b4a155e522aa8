// normalizer: unit normal N/|N| in Q2.14 from an interpolated normal (Phong 1975 eqs. 6-8 need
// a unit N; p. 317 asks for "a very fast mechanism for obtaining square roots"), bit-exact twin
// of model/twins/normalizer.hpp. m = Nx^2+Ny^2+Nz^2 exact, 1/sqrt(m) by rsqrt_unit (even shift, seed
// table, one Newton-Raphson step), N * 1/sqrt(m) rounded and saturated to UnitBits.
// Latency 8, one normal per clock; every stage registers valid and data; one global stall
// (stall_pipe): ready_o = ready_i || !valid_o (combinational from ready_i and the output valid
// flop only).
// The null vector (m = 0) gives (0, 0, 0) with null_o set; any m > 0 gives a unit vector.
`include "watkins_assert.svh"

module normalizer #(
  parameter int PayloadBits = 1,                              // carried alongside (pixel x, ...)
  localparam int NB = watkins_pkg::NormalInBits,
  localparam int UB = watkins_pkg::UnitBits
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic [3*NB-1:0]        normal_i,   // {Nz, Ny, Nx}: signed, FracBits fraction bits
  input  logic [PayloadBits-1:0] payload_i,
  input  logic                   valid_i,
  output logic                   ready_o,
  output logic [3*UB-1:0]        unit_o,     // {Nz, Ny, Nx}: signed Q2.14, |unit| = 1
  output logic                   null_o,     // input was (0, 0, 0); unit_o is (0, 0, 0)
  output logic [PayloadBits-1:0] payload_o,
  output logic                   valid_o,
  input  logic                   ready_i
);
  localparam int MBits      = 2 * NB;                   // 36: m < 3 * 2^34
  localparam int RsqrtBits  = watkins_pkg::RsqrtBits;   // F below: fraction bits of y
  localparam int RDelay     = 5;                        // rsqrt_unit latency
  localparam int Stages     = 1 + RDelay + 2;           // squares, rsqrt, product, round
  localparam int ScaledBits = NB + RsqrtBits + 3;       // N * y, signed, plus a rounding guard bit

  // Valid, payload and the stall of every stage; the registers below advance on its en.
  logic en;
  // The payload (the fragment's x, depth, ...) is written once into a RAM, not shifted through
  // every stage.
  stall_pipe #(
    .Stages     (Stages),
    .PayloadBits(PayloadBits),
    .PayloadRam (1'b1)
  ) u_pipe (
    .clk_i, .rst_ni,
    .payload_i,
    .valid_i,
    .ready_o,
    .payload_o,
    .valid_o,
    .ready_i,
    .en_o     (en)
  );

  // ---- stage 0: m = Nx^2 + Ny^2 + Nz^2, exact ------------------------------------------------
  logic signed [MBits-1:0] sq [3];
  logic        [MBits-1:0] m;
  always_comb begin
    for (int c = 0; c < 3; c++) begin
      logic signed [NB-1:0] n;
      n     = signed'(normal_i[c*NB +: NB]);
      sq[c] = n * n;  // both operands extended to MBits: exact, <= 2^34
    end
    m = unsigned'(sq[0]) + unsigned'(sq[1]) + unsigned'(sq[2]);
  end

  logic [MBits-1:0] m_q;
  always_ff @(posedge clk_i) if (en) m_q <= m;

  // ---- stages 1..5: y = 1/sqrt(m') with 1/sqrt(m) = y * 2^(j-2) --------------------------------
  logic [RsqrtBits+1:0] y;
  logic [4:0]   j;
  logic         nul;
  rsqrt_unit u_rsqrt (
    .clk_i  (clk_i),
    .en_i   (en),
    .m_i    (m_q),
    .y_o    (y),
    .j_o    (j),
    .null_o (nul)
  );

  // N waits alongside the rsqrt pipe (stage 0 .. stage 5). The per-stage and per-component
  // registers are plain variables of generate blocks, not array elements: a simulator
  // (Verilator) keeps a pending-write flag and value per written array element and clears them
  // on every evaluation. Same flops.
  for (genvar s = 0; s <= RDelay; s++) begin : g_n
    logic [3*NB-1:0] q;
    if (s == 0) begin : g_in
      always_ff @(posedge clk_i) if (en) q <= normal_i;
    end else begin : g_shift
      always_ff @(posedge clk_i) if (en) q <= g_n[s-1].q;
    end
  end

  // ---- stage 6: p = N * y, exact (FracBits + F fraction bits) ----------------------------------
  // ---- stage 7: unit = saturate(round(p / 2^(F+4-j))): Q2.14 -----------------------------------
  // 1/sqrt(m) = y 2^(j-2) and N carries 16 fraction bits, so the shift to 14 is F + 4 - j, in
  // [F-13, F+4]: always a right shift. round = add half, arithmetic shift (round_shift).
  logic [4:0]      j6_q;
  logic            nul6_q;
  logic [4:0]      sh;
  logic [3*UB-1:0] unit;
  always_ff @(posedge clk_i) if (en) begin
    j6_q   <= j;
    nul6_q <= nul;
  end
  assign sh = 5'(RsqrtBits + 4) - j6_q;

  for (genvar c = 0; c < 3; c++) begin : g_comp
    logic signed [ScaledBits-1:0] p_q;
    logic signed [ScaledBits-1:0] r;
    always_ff @(posedge clk_i) if (en) p_q <= signed'(g_n[RDelay].q[c*NB +: NB]) * signed'({1'b0, y});
    always_comb begin
      r = (p_q + (ScaledBits'(1) << (sh - 5'd1))) >>> sh;
      if (r > ScaledBits'((1 << (UB - 1)) - 1)) unit[c*UB +: UB] = UB'((1 << (UB - 1)) - 1);
      else if (r < -ScaledBits'(1 << (UB - 1))) unit[c*UB +: UB] = UB'(1 << (UB - 1));
      else                                      unit[c*UB +: UB] = r[UB-1:0];
    end
  end

  logic [3*UB-1:0] unit_q;
  logic            nul7_q;
  always_ff @(posedge clk_i) if (en) begin
    unit_q <= unit;
    nul7_q <= nul6_q;
  end

  assign unit_o = unit_q;
  assign null_o = nul7_q;

  // The payload's hold is checked once, by u_pipe (stall_pipe's a_in_hold and a_out_hold: the
  // same valid and ready): a simulator keeps a sampled copy of every signal an assertion reads.
  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, normal_i)
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, {unit_o, null_o})
  `WATKINS_COVER(c_stall, valid_o && !ready_i)
  `WATKINS_COVER(c_null, valid_o && null_o)
endmodule
