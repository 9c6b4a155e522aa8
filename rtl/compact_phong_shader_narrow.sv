// compact_phong_shader_narrow: Phong's shading rule per pixel, S = Cp [cos(i)(1-d) + d] +
// W cos(s)^n (Phong 1975 eq. 3, cos(s) = 2(N.L)(N.E) - L.E), at the narrow Phong formats
// (docs/reference/compact-phong.md, "Narrow formats"): three 16 x 16 multipliers (MAC16) in a
// fixed schedule of 5 clocks per pixel and the power from compact_phong_power (its log and exp
// tables in block RAM, one MAC16 of its own, driven by this block's phase). The ports and parameters of rtl/compact_phong_shader.sv, so
// the compact top picks it by PhongNarrow alone (values twin: PhongShader::shade_narrow,
// model/twins/phong_shader.hpp; cycle twin: model/twins/compact_phong_shader_narrow_timing.hpp).
// Timing: a period is 5 clocks; a pixel is taken in a period's last clock (ready_o, a flop) and
// loaded into the output register on clock 40 after it (phase 0 of its ninth period); a load
// that finds the output holding a shade not taken stalls every register for a clock
// (compact_schedule), the power's included. Latency 42 cycles (the take's clock to the first
// clock offered); at full rate one pixel per 5 clocks. light_i and eye_i are frame constants: L.E
// is worked out from them in every period, so they must be stable from a frame's first take to
// its last shade. The normal, L and E are unit vectors (|N.L|, |N.E| < 1.5: cos(s)'s sum stays
// within the 32 bits of its accumulator).
// Registered: every output; every multiplier's operands and product (the MAC16's own registers,
// its adder summing the three products of a dot product and each addend).
// The multipliers, by the phase of their operands (t = -1 the take, phase 4; t = 5p + ph):
//   S1 (signed)    N.L (x, y, z at phases 0..2, the sum started at 2^12), L.E's x and y (3, 4;
//                  started at 2^11)
//   S2 (signed)    N.E (1..3, started at 2^13), L.E's z (0, added to S1's partial sum),
//                  cos(s) (4: cos_i's low 15 bits times ne, the addend 2^11 - le 2^12 and, for
//                  cos_i >= 2^15, ne 2^15)
//   U  (unsigned)  f = cos_i (256 - d) + d 2^15 + 2^7 (0), W pow (4, W 0 off the front),
//                  Cp_c fr + S' (1..3), S' = floor((255 W pow + 2^23) / 2^9): a level is
//                  (Cp_c fr + S') >> 15, saturated
// The pixel: t 4 cos_i; t 5 ne; t 9 cos(s)'s operands; t 11 cs; t 14 taken by compact_phong_power;
// t 30..34 the power; t 34 W pow; t 36..38 the levels' products; t 40 the output register.
// {W, Cp, payload} wait in one RAM (written at the take, read at t 33 and, the payload, t 39),
// fr in another (written at t 7, read at t 35); n and d in registers that move a period at a time.
`include "watkins_assert.svh"

module compact_phong_shader_narrow #(
  parameter int PayloadBits      = 1,     // carried alongside (pixel x, ...)
  /* verilator lint_off UNUSEDPARAM */
  parameter bit LookAhead        = 1'b0,  // accepted: ready_o is a flop here
  /* verilator lint_on UNUSEDPARAM */
  localparam int UnitBits        = watkins_pkg::UnitBits,
  localparam int MaterialBits    = watkins_pkg::MaterialBits,
  localparam int ShininessBits   = watkins_pkg::ShininessBits
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
  localparam int Periods   = 9;   // periods a pixel spends inside
  localparam int SlotBits  = 4;   // RAM slots: 16 >= Periods
  localparam int RgbBits   = watkins_pkg::RgbBits;
  localparam int MatFrac   = watkins_pkg::MaterialFracBits;  // 8
  localparam int CpwBits   = MaterialBits + RgbBits;         // {W, Cp}
  localparam int RamBits   = CpwBits + PayloadBits;          // {W, Cp, payload}
  localparam int U         = UnitBits;

  // ---- the schedule's control ---------------------------------------------------------------
  logic [2:0]          ph_q;
  logic [SlotBits-1:0] pc_q;
  logic                en, tick, out_load;
  compact_schedule #(.Periods(Periods), .LoadPhase(0), .SlotBits(SlotBits)) u_schedule (
    .clk_i, .rst_ni, .valid_i, .ready_o, .ready_next_o, .valid_o, .ready_i,
    .ph_o(ph_q), .pc_o(pc_q), .en_o(en), .tick_o(tick), .load_o(out_load));

  // ---- the take: N for period 0; d (clamped to 1.0) and n in registers a period at a time -------
  logic [3*U-1:0]           n0_q;
  logic [MaterialBits-1:0]  d0_q, d1_q;     // d in periods 0 and 1
  logic [ShininessBits-1:0] sh_q [3];       // n in periods 0..2
  always_ff @(posedge clk_i) if (tick) begin
    n0_q  <= normal_i;
    d0_q  <= d_i > MaterialBits'(1 << MatFrac) ? MaterialBits'(1 << MatFrac) : d_i;
    d1_q  <= d0_q;
    sh_q[0] <= shininess_i;
    sh_q[1] <= sh_q[0];
    sh_q[2] <= sh_q[1];
  end

  // ---- RAM A: {W, Cp, payload} by slot (written in the take clock to the new slot, pc + 1); read
  // in phase 3 for the pixel in period 6 ({W, Cp}) and phase 4 for the pixel in period 7 (the
  // payload, into the output register at phase 0) -------------------------------------------------
  logic [RamBits-1:0]  ram_a [1 << SlotBits];
  logic [RamBits-1:0]  rda_q;
  logic [SlotBits-1:0] raa;
  assign raa = ph_q == 3'd3 ? pc_q - SlotBits'(6) : pc_q - SlotBits'(7);
  always_ff @(posedge clk_i) if (en) begin
    if (ph_q == 3'd4) ram_a[pc_q + 1'b1] <= {w_i, cp_i, payload_i};
    if (ph_q == 3'd3 || ph_q == 3'd4) rda_q <= ram_a[raa];
  end
  logic [RgbBits-1:0] cp_q;  // Cp of the pixel in period 7 (loaded at the end of phase 4)
  always_ff @(posedge clk_i) if (en && ph_q == 3'd4) cp_q <= rda_q[PayloadBits +: RgbBits];

  // ---- RAM B: fr by slot (written at t 7, phase 2, period 1; read at t 35, phase 0, period 7) ---
  logic [15:0] ram_b [1 << SlotBits];
  logic [15:0] frd_q;         // fr of the pixel in period 7, phases 1..0
  logic [31:0] pu_q;          // U's product
  always_ff @(posedge clk_i) if (en) begin
    if (ph_q == 3'd2) ram_b[pc_q - 1'b1] <= pu_q[23:8];
    if (ph_q == 3'd0) frd_q <= ram_b[pc_q - SlotBits'(7)];
  end

  // ---- the operands of S1 and S2 by phase ------------------------------------------------------
  logic [U-1:0] nx, ny, nz, lx, ly, lz, ex, ey, ez;
  assign {nz, ny, nx} = n0_q;
  assign {lz, ly, lx} = light_i;
  assign {ez, ey, ex} = eye_i;
  logic [15:0] cos_q;          // cos_i, t 5..9
  logic [15:0] ne_q;           // ne, t 6..10
  logic [U-1:0] s1a, s1b, s2a, s2b;
  always_comb begin
    case (ph_q)
      3'd0:    begin s1a = nx; s1b = lx; s2a = lz;                 s2b = ez; end
      3'd1:    begin s1a = ny; s1b = ly; s2a = nx;                 s2b = ex; end
      3'd2:    begin s1a = nz; s1b = lz; s2a = ny;                 s2b = ey; end
      3'd3:    begin s1a = lx; s1b = ex; s2a = nz;                 s2b = ez; end
      default: begin s1a = ly; s1b = ey; s2a = {1'b0, cos_q[14:0]}; s2b = ne_q; end
    endcase
  end

  // ---- S1: N.L + 2^12 (products added at the ends of phases 1..3: read in phase 4), L.E's x and
  // y + 2^11 (ends of phases 4, 0: read by S2 in phase 1) -----------------------------------------
  logic signed [U-1:0] s1a_q, s1b_q, s2a_q, s2b_q;
  logic [31:0]         p1_q, p2_q, c1, c2;
  logic [20:0]         kcs_q;  // cos(s)'s addend, bits 31..11 (its low 11 bits are 0)
  assign c1 = ph_q == 3'd1 ? 32'd1 << 12 : ph_q == 3'd4 ? 32'd1 << 11 : p1_q;
  // S2: N.E + 2^13 (ends of phases 2..4: read in phase 0), cos(s) (end of phase 0: read in phase
  // 1), L.E = S1's partial sum + Lz Ez (end of phase 1: read in phase 2).
  always_comb begin
    case (ph_q)
      3'd2:    c2 = 32'd1 << 13;
      3'd0:    c2 = {kcs_q, 11'd0};
      3'd1:    c2 = p1_q;
      default: c2 = p2_q;
    endcase
  end
  always_ff @(posedge clk_i) if (en) begin
    s1a_q <= s1a;
    s1b_q <= s1b;
    s2a_q <= s2a;
    s2b_q <= s2b;
    p1_q  <= 32'($signed(s1a_q) * $signed(s1b_q)) + c1;
    p2_q  <= 32'($signed(s2a_q) * $signed(s2b_q)) + c2;
  end

  // ---- cos_i, ne, le, cs: rounded (the sums hold the rounding constants) and clamped ------------
  // cos_i = clamp(ndl >> 13, 0, 2^16 - 1) at phase 4; ne = clamp(nde >> 14, -2^15, 2^15 - 1) at
  // phase 0; le = clamp(LE >> 12, -2^17, 2^17 - 1) at phase 2 and -le at phase 3 (every period:
  // a frame constant); cs = clamp(P2 >> 12, 0, 2^16) at phase 1.
  logic [18:0] le_q;        // le, 19 bits signed (phase 3)
  logic [18:0] nle_q;       // -le, 19 bits signed (phase 4)
  logic [16:0] cs_q;        // cs, t 12..16
  logic        front_q [5]; // cos_i > 0 in periods 2..6
  always_ff @(posedge clk_i) if (en) begin
    case (ph_q)
      3'd4: begin
        logic signed [18:0] v;  // ndl >>> 13: |ndl| < 2^31
        v = 19'(signed'(p1_q) >>> 13);
        cos_q <= v < 0 ? 16'd0 : v > 19'sd65535 ? 16'hffff : v[15:0];
      end
      3'd0: begin
        logic signed [17:0] v;
        v = 18'(signed'(p2_q) >>> 14);
        ne_q <= v < -18'sd32768 ? 16'h8000 : v > 18'sd32767 ? 16'h7fff : v[15:0];
      end
      3'd2: begin
        logic signed [19:0] v;
        v    = 20'(signed'(p2_q) >>> 12);
        le_q <= v < -20'sd131072 ? -19'sd131072 : v > 20'sd131071 ? 19'sd131071 : v[18:0];
      end
      3'd3: nle_q <= -le_q;  // the spare clock between le and its use: the negation off S2's path
      3'd1: begin
        logic signed [19:0] v;
        v = 20'(signed'(p2_q) >>> 12);
        cs_q <= v < 0 ? 17'd0 : v > 20'sd65536 ? 17'd65536 : v[16:0];
      end
      default: ;
    endcase
  end
  // cos(s)'s addend at phase 4 (t 9, cos_q and ne_q this pixel's): 2^11 - le 2^12 + (cos_i >=
  // 2^15 ? ne 2^15 : 0), so S2's sum is cos_i ne - le 2^12 + 2^11 (cos_i ne is 2 cos(i)(N.E) at
  // 28 fraction bits).
  always_ff @(posedge clk_i) if (en && ph_q == 3'd4) begin
    logic [20:0] le_part, ne_part;  // bits 31..11: (2^11 - le 2^12) >> 11, ne 2^15 >> 11
    le_part = {nle_q[18], nle_q, 1'b1};
    ne_part = cos_q[15] ? {ne_q[15], ne_q, 4'd0} : 21'd0;
    kcs_q <= le_part + ne_part;
  end
  always_ff @(posedge clk_i) if (tick) begin
    front_q[0] <= cos_q != 16'd0;  // cos_q holds the pixel of period 1 until its tick
    for (int p = 1; p < 5; p++) front_q[p] <= front_q[p-1];
  end

  // ---- the power: taken at t 14 (cs of t 12..16, n of period 2), cos(s)^n at t 30..34 (the whole
  // of period 6) ----------------------------------------------------------------------------------
  /* verilator lint_off UNUSEDSIGNAL */
  logic        pw_valid;  // every period's take is read: a pixel's own valid bits are the schedule's
  /* verilator lint_on UNUSEDSIGNAL */
  logic [15:0] pow_q;
  compact_phong_power u_power (
    .clk_i, .rst_ni, .en_i(en), .ph_i(ph_q), .take_i(1'b1), .cs_i(cs_q), .n_i(sh_q[2]),
    .valid_o(pw_valid), .pow_o(pow_q));

  // ---- U: f (operands phase 0, t 5), W pow (phase 4, t 34), Cp_c fr + S' (phases 1..3, t 36..38) --
  logic [15:0] ua, ub;
  logic [31:0] uc;
  logic [15:0] ua_q, ub_q;
  logic [31:0] uc_q;
  logic [23:0] sp;            // S' from U's product (W pow) at t 36
  logic [23:0] sp_q;          // S', t 37..41
  logic [7:0]  cpc;
  logic [MaterialBits-1:0] omd;  // 256 - d of the pixel in period 1
  assign omd = MaterialBits'(1 << MatFrac) - d1_q;
  always_comb begin
    /* verilator lint_off UNUSEDSIGNAL */
    logic [32:0] x;           // 255 W pow + 2^23: S' is its bits from 9 up
    /* verilator lint_on UNUSEDSIGNAL */
    x  = ({1'b0, pu_q} << 8) - {1'b0, pu_q} + (33'd1 << 23);
    sp = x[32:9];
    case (ph_q)
      3'd1:    cpc = cp_q[16 +: 8];  // R
      3'd2:    cpc = cp_q[8 +: 8];   // G
      default: cpc = cp_q[0 +: 8];   // B
    endcase
    case (ph_q)
      3'd0: begin
        ua = cos_q;
        ub = 16'(omd);  // 1 - d, 0..256
        uc = (32'(d1_q) << 15) | 32'd128;
      end
      3'd4: begin
        ua = front_q[4] ? 16'(rda_q[PayloadBits + RgbBits +: MaterialBits]) : 16'd0;
        ub = pow_q;
        uc = 32'd0;
      end
      default: begin
        ua = 16'(cpc);
        ub = frd_q;
        uc = ph_q == 3'd1 ? 32'(sp) : 32'(sp_q);
      end
    endcase
  end
  always_ff @(posedge clk_i) if (en) begin
    ua_q <= ua;
    ub_q <= ub;
    uc_q <= uc;
    pu_q <= ua_q * ub_q + uc_q;
    if (ph_q == 3'd1) sp_q <= sp;
  end

  // ---- the levels: (Cp_c fr + S') >> 15 saturated at 255; R at t 38, G at t 39, B at t 40 ------
  logic [7:0] lv;
  assign lv = pu_q[31:23] != 9'd0 ? 8'hff : pu_q[22:15];
  logic [7:0] lr_q, lg_q;
  always_ff @(posedge clk_i) if (en) begin
    if (ph_q == 3'd3) lr_q <= lv;
    if (ph_q == 3'd4) lg_q <= lv;
  end

  // ---- the output register (t 40) ----------------------------------------------------------------
  watkins_pkg::rgb_t      rgb_q;
  logic [PayloadBits-1:0] payload_q;
  always_ff @(posedge clk_i) if (out_load) begin
    rgb_q     <= {lr_q, lg_q, lv};
    payload_q <= rda_q[PayloadBits-1:0];
  end
  assign rgb_o     = rgb_q;
  assign payload_o = payload_q;

  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, {normal_i, cp_i, d_i, w_i, shininess_i, payload_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, {rgb_o, payload_o})
  `WATKINS_COVER(c_stall, !en)
endmodule
