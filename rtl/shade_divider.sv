// shade_divider: Gouraud's eq. (2) per pixel, S = N / Z for three channels, exactly
// model/twins/shade_divider.hpp. N is a shade slot's interpolated word (AttrFracBits fraction
// bits, the vertex's S times its depth), Z the fragment's depth word (DepthBits bits, Z =
// depth / 2^DepthBits). The numerator saturates to NumBits = 8 + AttrFracBits unsigned bits (N
// >= 256 gives S >= 256 for any Z < 1; N < 0 gives 0); the divisor is max(depth, 1). 1/dz comes
// from span_reciprocal (the same block as the span's 1/dx, RecipBits = Eq2RecipBits mantissa
// bits): recip = floor(2^(2R-1) / m), p = floor(log2 dz). Then one multiply per channel and a
// shift by s = p + R + AttrFracBits - DepthBits: S = min(round_shift(n recip, s), 255) for
// s >= 1, and for s <= 0 (n recip 2^-s >= 2^(R-1) > 255) 255 when n is not 0, else 0.
// Latency 20 cycles (Eq2RecipBits + 4: the reciprocal's RecipBits + 2 stages, the multiply, the
// rounding). One global stall per pipe (stall_pipe: ready_o = ready_i || !valid_o; with LookAhead
// each pipe's stall is a flop loaded a clock ahead from ready_next_i); a stage's registers load
// only for a valid beat. payload_i rides along (in the reciprocal's payload RAM, then two
// stages of flops). One fragment per clock.
// Stages: in (numerators saturated, divisor) -> span_reciprocal (RecipBits + 2 stages) -> sm
// (n recip per channel, the shift) -> sr (shift, round, clamp: rgb_o).
`include "watkins_assert.svh"

module shade_divider #(
  parameter int unsigned DepthBits    = watkins_pkg::DepthBits,    // the fragment's depth word
  parameter int unsigned AttrBits     = watkins_pkg::ChannelBits,  // a shade slot's signed word
  parameter int unsigned AttrFracBits = watkins_pkg::FracBits,
  parameter int unsigned RecipBits    = watkins_pkg::Eq2RecipBits, // R: 1/dz's mantissa bits
  parameter int unsigned PayloadBits  = 1,
  parameter bit          LookAhead    = 1'b0
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic [DepthBits-1:0]   depth_i,
  input  logic [3*AttrBits-1:0]  num_i,        // {B, G, R} numerators, signed words
  input  logic [PayloadBits-1:0] payload_i,
  input  logic                   valid_i,
  output logic                   ready_o,
  output logic                   ready_next_o, // ready_o on the next clock (from ready_next_i)
  output watkins_pkg::rgb_t      rgb_o,
  output logic [PayloadBits-1:0] payload_o,
  output logic                   valid_o,
  input  logic                   ready_i,
  input  logic                   ready_next_i  // LookAhead: ready_i on the next clock
);
  localparam int unsigned ShadeBits    = watkins_pkg::ShadeBits;
  localparam int unsigned NumBits      = ShadeBits + AttrFracBits;        // saturated numerator
  localparam int unsigned DxBits       = DepthBits + 1;                   // the divisor, unsigned
  localparam int unsigned ExponentBits = $clog2(DxBits);                  // p
  localparam int unsigned ProdBits     = NumBits + RecipBits + 1;         // n recip
  localparam int          ShiftOffset  = RecipBits + AttrFracBits - DepthBits;  // may be negative
  // s - 1 for s >= 1 is below RecipBits + AttrFracBits (p < DepthBits).
  localparam int unsigned ShiftBits    = $clog2(RecipBits + AttrFracBits);
  localparam int unsigned CmpBits      = (AttrBits > NumBits + 1) ? AttrBits : NumBits + 1;

  // ---------------------------------------------------------------- in
  // clamp(N, 0, 2^NumBits - 1) from N's bits: 0 when the sign is set, the maximum when a bit at
  // or above NumBits is.
  logic [3*NumBits-1:0] num_sat;
  for (genvar c = 0; c < 3; c++) begin : g_sat
    logic signed [CmpBits-1:0] v;
    assign v = CmpBits'($signed(num_i[c*AttrBits +: AttrBits]));
    assign num_sat[c*NumBits +: NumBits] = v[CmpBits-1] ? '0
                                         : (|(v >> NumBits)) ? {NumBits{1'b1}}
                                                             : NumBits'(v);
  end
  logic [DxBits-1:0] dz;
  assign dz = (depth_i == '0) ? DxBits'(1) : DxBits'(depth_i);

  // ---------------------------------------------------------------- span_reciprocal
  logic [RecipBits:0]       rc_recip;
  logic [ExponentBits-1:0]  rc_p;
  logic [3*NumBits-1:0]     rc_n;
  logic [PayloadBits-1:0]   rc_payload;
  logic                     rc_valid, rc_ready, rc_ready_next;

  span_reciprocal #(
    .DxBits     (DxBits),
    .PayloadBits(3 * NumBits + PayloadBits),
    .LookAhead  (LookAhead),
    .RecipBits  (RecipBits)
  ) u_recip (
    .clk_i, .rst_ni,
    .dx_i        (dz),
    .payload_i   ({num_sat, payload_i}),
    .valid_i,
    .ready_o,
    .recip_o     (rc_recip),
    .p_o         (rc_p),
    .payload_o   ({rc_n, rc_payload}),
    .valid_o     (rc_valid),
    .ready_i     (rc_ready),
    .ready_next_i(rc_ready_next),
    .ready_next_o
  );

  // ---------------------------------------------------------------- sm, sr
  logic [1:0] ce;
  /* verilator lint_off UNUSEDSIGNAL */
  logic [1:0] v_unused;
  logic       en_unused;
  /* verilator lint_on UNUSEDSIGNAL */
  stall_pipe #(
    .Stages     (2),
    .PayloadBits(PayloadBits),
    .PayloadRam (1'b0),
    .LookAhead  (LookAhead)
  ) u_pipe (
    .clk_i, .rst_ni,
    .payload_i   (rc_payload),
    .valid_i     (rc_valid),
    .ready_o     (rc_ready),
    .payload_o,
    .valid_o,
    .ready_i,
    .ready_next_i,
    .en_next_o   (rc_ready_next),
    .en_o        (en_unused),
    .valid_q_o   (v_unused),
    .ce_o        (ce)
  );

  // sm: the products and the shift. s = p + ShiftOffset; sm_pos_q: s >= 1, sm_sh_q: s - 1.
  logic [3*ProdBits-1:0] sm_prod_q;
  logic                  sm_pos_q;
  logic [ShiftBits-1:0]  sm_sh_q;
  always_ff @(posedge clk_i) begin
    if (ce[0]) begin : sm_set
      logic signed [31:0] s;
      s = $signed(32'(rc_p)) + ShiftOffset;
      sm_pos_q <= s >= 1;
      sm_sh_q  <= ShiftBits'(s - 1);
      for (int c = 0; c < 3; c++)
        sm_prod_q[c*ProdBits +: ProdBits] <= ProdBits'(rc_n[c*NumBits +: NumBits]) * ProdBits'(rc_recip);
    end
  end

  // sr: round_shift(prod, s) = ((prod >> (s - 1)) + 1) >> 1, clamped to 255 from the bits above
  // the level's (prod < 2^(ProdBits-1), so the increment does not overflow).
  logic [3*ShadeBits-1:0] sr_rgb_q;  // {B, G, R}
  always_ff @(posedge clk_i) begin
    if (ce[1]) begin
      for (int c = 0; c < 3; c++) begin : sr_set
        logic [ProdBits-1:0] p, u, r;
        p = sm_prod_q[c*ProdBits +: ProdBits];
        u = p >> sm_sh_q;
        r = (u + 1'b1) >> 1;
        if (!sm_pos_q) sr_rgb_q[c*ShadeBits +: ShadeBits] <= (p != '0) ? '1 : '0;
        else sr_rgb_q[c*ShadeBits +: ShadeBits] <= (|(r >> ShadeBits)) ? '1 : ShadeBits'(r);
      end
    end
  end
  assign rgb_o.r = sr_rgb_q[0 +: ShadeBits];
  assign rgb_o.g = sr_rgb_q[ShadeBits +: ShadeBits];
  assign rgb_o.b = sr_rgb_q[2*ShadeBits +: ShadeBits];

  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, {depth_i, num_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, rgb_o)
  `WATKINS_COVER(c_saturate, valid_o && rgb_o.r == '1)
endmodule
