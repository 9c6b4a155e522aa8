// phong_shader: Phong's shading rule S = Cp [cos(i)(1-d) + d] + W cos(s)^n (Phong 1975 eq. 3)
// per pixel, light and eye at infinity, cos(s) = R.E = 2(N.L)(N.E) - L.E (Phong's reflected
// vector, eqs. 4-8), cos(s)^n by square-and-multiply over the 8 bits of n; bit-exact twin of
// model/twins/phong_shader.hpp. Latency 13, one pixel per clock; every stage registers valid and data;
// one global stall (stall_pipe): ready_o = ready_i || !valid_o (combinational from ready_i and the
// output valid flop only). light_i / eye_i are frame constants: L.E is registered from them every
// clock (le_q), so they must be stable from one clock before a frame's first pixel to its last
// output.
`include "watkins_assert.svh"

module phong_shader #(
  parameter int PayloadBits    = 1,                           // carried alongside (pixel x, ...)
  localparam int UB            = watkins_pkg::UnitBits,
  localparam int MaterialBits  = watkins_pkg::MaterialBits,
  localparam int ShininessBits = watkins_pkg::ShininessBits   // also the number of power stages
) (
  input  logic                     clk_i,
  input  logic                     rst_ni,
  input  logic [3*UB-1:0]          light_i,      // {Lz, Ly, Lx}: unit, Q2.14, constant per frame
  input  logic [3*UB-1:0]          eye_i,        // {Ez, Ey, Ex}: unit, Q2.14, constant per frame
  input  logic [3*UB-1:0]          normal_i,     // {Nz, Ny, Nx}: unit normal, Q2.14 (normalizer)
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
  input  logic                     ready_i
);
  // The comments write the two Phong formats as the model's formulas do: D and P.
  localparam int UF       = watkins_pkg::UnitFracBits;      // 14
  localparam int DotBits  = watkins_pkg::PhongDotBits;      // D = 24
  localparam int PowBits  = watkins_pkg::PhongPowBits;      // P = 20
  localparam int MF       = watkins_pkg::MaterialFracBits;
  localparam int DW       = 2 * UB + 2;                     // exact dot product: 3 * 2^30 < 2^33
  localparam int CW       = 2 * DotBits + 6;                // 2 cos(i) (N.E) - L.E at 2D fraction bits
  localparam int FW       = DotBits + MF + 1;               // f = cos(i)(1-d) + d <= 1
  localparam int LW       = FW + 8 + 2;                     // a level at D + MF fraction bits, plus sum
  localparam int PowFirst = 3;                              // acc_q[0] sits in stage 3 (u_pipe.valid_q[2])
  localparam int Stages   = PowFirst + ShininessBits + 2;   // 13: dots, round, cos(s), 8 powers, 2 out

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

  // Exact dot product of two Q2.14 vectors (28 fraction bits).
  function automatic logic signed [DW-1:0] dot3(input logic [3*UB-1:0] a, input logic [3*UB-1:0] b);
    logic signed [DW-1:0] acc, x, y;
    acc = '0;
    for (int c = 0; c < 3; c++) begin
      x   = DW'(signed'(a[c*UB +: UB]));  // sign-extended to DW
      y   = DW'(signed'(b[c*UB +: UB]));
      acc = acc + x * y;
    end
    dot3 = acc;
  endfunction

  // round(v / 2^(2UF-D)), clamped to [lo, 2 - 2^-D] (lo = 0 or -2): stage 2 and L.E.
  function automatic logic signed [DotBits+1:0] round_dot(input logic signed [DW-1:0] v,
                                                          input logic neg_ok);
    logic signed [DW-1:0] r, hi, lo;  // all signed: the comparisons below are signed
    hi = DW'((1 <<< (DotBits + 1)) - 1);  // < 2.0: the register's range, not 1.0 (see model)
    lo = neg_ok ? -hi - DW'(1) : DW'(0);
    r  = (v + DW'(1 <<< (2 * UF - DotBits - 1))) >>> (2 * UF - DotBits);
    if (r > hi)      round_dot = hi[DotBits+1:0];
    else if (r < lo) round_dot = lo[DotBits+1:0];
    else             round_dot = r[DotBits+1:0];
  endfunction

  // ---- frame constant: L.E, D fraction bits -----------------------------------------------------
  logic signed [DotBits+1:0] le_q;
  always_ff @(posedge clk_i) le_q <= round_dot(dot3(light_i, eye_i), 1'b1);

  // Pixel attributes travel alongside: index s holds the pixel in stage s+1 (u_pipe.valid_q[s]).
  localparam int AttrLast = PowFirst + ShininessBits - 1;  // 10: stage 11 feeds stage 12
  logic [watkins_pkg::RgbBits-1:0] cp_q [AttrLast+1];  // vectors: yosys 0.23 and struct arrays
  logic [MaterialBits-1:0]         w_q  [AttrLast+1];
  logic [ShininessBits-1:0]        n_q  [AttrLast];    // last read by the final power stage
  always_ff @(posedge clk_i) if (en) begin
    cp_q[0]      <= cp_i;
    w_q[0]       <= w_i;
    n_q[0]       <= shininess_i;
    for (int s = 1; s <= AttrLast; s++) begin
      cp_q[s] <= cp_q[s-1];
      w_q[s]  <= w_q[s-1];
    end
    for (int s = 1; s < AttrLast; s++) n_q[s] <= n_q[s-1];
  end

  // ---- stage 1: N.L and N.E, exact -------------------------------------------------------------
  logic signed [DW-1:0]    ndl_q, nde_q;
  logic [MaterialBits-1:0] d1_q;
  always_ff @(posedge clk_i) if (en) begin
    ndl_q <= dot3(normal_i, light_i);
    nde_q <= dot3(normal_i, eye_i);
    d1_q  <= (d_i > MaterialBits'(1 << MF)) ? MaterialBits'(1 << MF) : d_i;  // d <= 1.0
  end

  // ---- stage 2: cos(i) >= 0 (i > 90 degrees clamped, Phong p. 313), N.E ------------------
  logic signed [DotBits+1:0] cosi_q, ne_q;
  logic [MaterialBits-1:0]   d2_q;
  always_ff @(posedge clk_i) if (en) begin
    cosi_q <= round_dot(ndl_q, 1'b0);
    ne_q   <= round_dot(nde_q, 1'b1);
    d2_q   <= d1_q;
  end

  // ---- stage 3: cos(s) = 2 cos(i)(N.E) - L.E in [0, 1] (P bits), f = cos(i)(1-d) + d -----------
  logic signed [CW-1:0]    cs2, csr, ci_w, ne_w, le_w;
  logic [PowBits:0]        cs;
  logic [FW-1:0]           f;
  logic [MaterialBits-1:0] omd;  // 1 - d, 1.0 = 256
  always_comb begin
    ci_w = CW'(cosi_q);
    ne_w = CW'(ne_q);
    le_w = CW'(le_q);
    cs2  = ((ci_w * ne_w) <<< 1) - (le_w <<< DotBits);
    csr  = (cs2 + CW'(1 <<< (2 * DotBits - PowBits - 1))) >>> (2 * DotBits - PowBits);
    if (csr > CW'(1 <<< PowBits)) cs = (PowBits+1)'(1 << PowBits);
    else if (csr < 0)             cs = '0;
    else                          cs = csr[PowBits:0];
    omd = MaterialBits'(1 << MF) - d2_q;
    f   = FW'(cosi_q[DotBits:0]) * FW'(omd) + (FW'(d2_q) << DotBits);
  end

  // Power stages k = 0..ShininessBits-1 (stage PowFirst + k): acc *= base if bit k of n,
  // base *= base.
  logic [PowBits:0] acc_q  [ShininessBits+1];
  logic [PowBits:0] base_q [ShininessBits];
  logic [FW-1:0]    f_q    [ShininessBits+1];
  always_ff @(posedge clk_i) if (en) begin
    // A pixel facing away (cos(i) = 0) or with cos(s) = 0 starts from acc = 0: specular 0.
    acc_q[0]  <= (cosi_q != '0 && cs != '0) ? (PowBits+1)'(1 << PowBits) : '0;
    base_q[0] <= cs;
    f_q[0]    <= f;
  end

  for (genvar k = 0; k < ShininessBits; k++) begin : g_pow
    /* verilator lint_off UNUSEDSIGNAL */
    logic [2*PowBits+2:0] pa, pb;  // products <= 2^2P plus half: only [2P:P] is kept
    /* verilator lint_on UNUSEDSIGNAL */
    always_comb begin
      pa = (2*PowBits+3)'(acc_q[k])  * (2*PowBits+3)'(base_q[k]) + (2*PowBits+3)'(1 << (PowBits - 1));
      pb = (2*PowBits+3)'(base_q[k]) * (2*PowBits+3)'(base_q[k]) + (2*PowBits+3)'(1 << (PowBits - 1));
    end
    always_ff @(posedge clk_i) if (en) begin
      acc_q[k+1] <= n_q[PowFirst - 1 + k][k] ? pa[2*PowBits:PowBits] : acc_q[k];
      f_q[k+1]   <= f_q[k];
    end
    if (k + 1 < ShininessBits) begin : g_base
      always_ff @(posedge clk_i) if (en) base_q[k+1] <= pb[2*PowBits:PowBits];
    end
  end

  // ---- stage 12: Cp f per channel, 255 W cos(s)^n (white highlight), D + MF fraction bits ------
  // Channel c is byte c of rgb_t (B, G, R for c = 0, 1, 2) in Cp and in the shade alike: the
  // three channels are computed the same way, so the loop need not know which is which.
  logic [LW-1:0] diff_q [3];
  logic [LW-1:0] spec_q;
  always_ff @(posedge clk_i) if (en) begin
    for (int c = 0; c < 3; c++)
      diff_q[c] <= LW'(cp_q[AttrLast][c*8 +: 8]) * LW'(f_q[ShininessBits]);
    spec_q <= (LW'(8'd255) * LW'(w_q[AttrLast]) * LW'(acc_q[ShininessBits])) << (DotBits - PowBits);
  end

  // ---- stage 13: level = saturate(round(Cp f + 255 W pow)) --------------------------------------
  logic [watkins_pkg::RgbBits-1:0] rgb_q;
  always_ff @(posedge clk_i) if (en) begin
    for (int c = 0; c < 3; c++) begin
      logic [LW-1:0] lvl;
      lvl = (diff_q[c] + spec_q + (LW'(1) << (DotBits + MF - 1))) >> (DotBits + MF);
      rgb_q[c*8 +: 8] <= (lvl > LW'(255)) ? 8'd255 : lvl[7:0];
    end
  end

  assign rgb_o = rgb_q;

  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, {normal_i, cp_i, d_i, w_i, shininess_i, payload_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, {rgb_o, payload_o})
  `WATKINS_COVER(c_stall, valid_o && !ready_i)
endmodule
