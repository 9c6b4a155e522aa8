// segment_interpolator: span setup for each segment E..F, then one fragment per pixel.
// Alpha stepping, exactly model/twins/segment_interpolator.cpp (setup(), fragment(), step()).
// Latency 37 cycles from a segment to its first fragment. Every stage output is registered; the
// setup stages' one stall signal (tail_en) is a flop, loaded a clock ahead from the FIFO's next
// ready. One segment per clock into the setup, one fragment per clock out of the stepper.
// Stages: s0 -> span_reciprocal (26 stages) -> sa -> sm -> sp -> sh -> sb -> sc -> sv -> sd ->
// FIFO -> stepper (frag_*_o).
// - s0: first pixel centres, dx, offset, deltas.
// - sa: alpha's and the steps' multiplier operands, deltas in 17-bit pieces when wider than a
//   MULT18, each registered in its multiplier block; sm: those partial products, in their
//   blocks' output registers.
// - sp: alpha0's sum; each delta piece's pair of step partial products added; the pixel range's
//   and the empty test's compares. sh: alpha0's shift; the steps' sums of their pieces; the
//   clamp to the screen and the empty test applied.
// - sb: round, clamp alpha0; the steps' shifts. sc: value partial products, in their blocks'
//   registers too; the steps saturated.
// - sv: each delta piece's pair of value partial products added. sd: the pieces' sums with E and
//   the rounding constant: the value E + round(delta*alpha0).
// - Empty spans are dropped before the FIFO. The stepper emits one fragment per clock from a
//   registered output, taking a span's first pixel straight from the FIFO head, so consecutive
//   spans (even of one pixel) leave no bubble and a span's setup hides behind the previous
//   spans' pixels.
// A setup stage's registers load only for a valid beat (the stall and the valid entering the
// stage), and their values are computed inside that enable: a simulator evaluates the setup only
// on the clocks a span passes; the hardware is the same flops and logic.
// End-of-line markers pass through in order. Each fragment carries its segment's polygon id
// (the scanline_buffer's equal-depth rule) and material id, and both readings of the three
// attribute channels: frag_rgb_o (Gouraud shade levels) and frag_normal_o (Phong normal, the
// channel rescaled to FracBits fraction bits and saturated to NormalInBits); a top uses one
// and synthesis drops the other. AttrOut = 1 adds frag_attr_o, the three attribute words
// themselves (the shade divider's numerators, Gouraud's eq. (2)), stored with the span's head in
// the FIFO; AttrOut = 0 leaves it 0 and stores nothing.
// Widths from the configuration (model/twins/segment_interpolator.hpp lists them): slot words
// XBits (X, XFracBits fraction bits), ZBits (depth), AttrBits (slots 2..4); every delta, product,
// FIFO word and stepper register is sized per slot from its own word. "Interpolated vectors" hold
// slots 1..4 (Z, then the three attributes) without X: slot c at ilo(c, width of Z, width of one
// attribute), each of its own width.
`include "watkins_assert.svh"

module segment_interpolator #(
  parameter int unsigned FifoDepth      = 4,
  parameter int unsigned XBits          = watkins_pkg::ChannelBits,  // slot words and fractions
  parameter int unsigned XFracBits      = watkins_pkg::FracBits,
  parameter int unsigned ZBits          = watkins_pkg::ChannelBits,
  parameter int unsigned ZFracBits      = watkins_pkg::FracBits,
  parameter int unsigned AttrBits       = watkins_pkg::ChannelBits,
  parameter int unsigned AttrFracBits   = watkins_pkg::FracBits,
  parameter int unsigned DepthBits      = watkins_pkg::DepthBits,     // fragment depth
  parameter int unsigned PolyIdBits     = watkins_pkg::PolyIdBits,
  parameter int unsigned MaterialIdBits = watkins_pkg::MaterialIdBits,
  parameter bit          AttrOut        = 1'b0,  // 1: frag_attr_o carries the attribute words
  localparam int unsigned VectorBits = watkins_pkg::vector_bits(XBits, ZBits, AttrBits)
) (
  input  logic                                   clk_i,
  input  logic                                   rst_ni,
  input  logic [watkins_pkg::LineBits-1:0]       width_i,          // screen width, stable per
                                                                   // frame
  input  logic [VectorBits-1:0]                  seg_e_i,          // left end E
  input  logic [VectorBits-1:0]                  seg_f_i,          // right end F
  input  logic [PolyIdBits-1:0]                  seg_poly_i,       // polygon id
  input  logic [MaterialIdBits-1:0]              seg_material_i,
  input  logic                                   seg_eol_i,        // end-of-line marker, no
                                                                   // segment
  input  logic                                   seg_valid_i,
  output logic                                   seg_ready_o,
  output logic [watkins_pkg::LineBits-1:0]       frag_x_o,
  output logic [DepthBits-1:0]                   frag_depth_o,
  output watkins_pkg::rgb_t                      frag_rgb_o,       // Gouraud shade
  output logic [3*watkins_pkg::NormalInBits-1:0] frag_normal_o,    // {Nz,Ny,Nx}
  output logic [3*AttrBits-1:0]                  frag_attr_o,      // AttrOut: slots {4, 3, 2}
  output logic [PolyIdBits-1:0]                  frag_poly_o,      // its segment's
  output logic [MaterialIdBits-1:0]              frag_material_o,
  output logic                                   frag_eol_o,       // end-of-line marker, no
                                                                   // fragment
  output logic                                   frag_valid_o,
  input  logic                                   frag_ready_i
);
  localparam int unsigned LineBits          = watkins_pkg::LineBits;
  localparam int unsigned RecipBits         = watkins_pkg::RecipBits;
  localparam int unsigned AlphaBits         = watkins_pkg::AlphaBits;
  localparam int unsigned InterpolatedSlots = watkins_pkg::NumChannels - 1;  // slots Z.. (not X)
  localparam int unsigned DxBits            = XBits + 1;                // dx, offset (unsigned)
  localparam int unsigned ExponentBits      = $clog2(DxBits);           // p = floor(log2 dx) <
                                                                        // XBits
  localparam int unsigned AlphaProductBits  = DxBits + RecipBits + 2;   // offset * recip, with
                                                                        // rounding room
  localparam int unsigned XPixelBits        = XBits + 1 - XFracBits;    // signed pixel index of
                                                                        // an X value
  // Pixel indices are compared with the screen width in a width holding both.
  localparam int unsigned PixelCompareBits  = (XPixelBits > LineBits + 1) ? XPixelBits
                                                                          : LineBits + 1;
  localparam int unsigned NormalBits        = watkins_pkg::NormalInBits;
  // The FIFO's copy of the head's attribute words: only with AttrOut (one constant bit without).
  localparam int unsigned HeadAttrBits      = AttrOut ? 3 * AttrBits : 1;

  // Interpolated vectors: slot c (1..4) at ilo(c, zw, aw), Z zw bits wide, each attribute aw.
  function automatic int unsigned ilo(int unsigned c, int unsigned zw, int unsigned aw);
    ilo = (c == 1) ? 0 : zw + (c - 2) * aw;
  endfunction
  // A slot's word and fraction bits, and the widths of its delta (word + 1) and of delta * recip
  // (with room for the rounding constant: the step's shift p + R - XFracBits reaches
  // XBits - 1 + R - XFracBits, so a narrow slot's product still needs X's headroom).
  localparam int unsigned ZDeltaBits          = ZBits + 1;
  localparam int unsigned AttrDeltaBits       = AttrBits + 1;
  localparam int unsigned ZStepProductBits    =
      ((ZBits > XBits - XFracBits) ? ZBits : XBits - XFracBits) + RecipBits + 3;
  localparam int unsigned AttrStepProductBits =
      ((AttrBits > XBits - XFracBits) ? AttrBits : XBits - XFracBits) + RecipBits + 3;
  localparam int unsigned InterpVectorBits    = ZBits + 3 * AttrBits;            // value, step, E
  localparam int unsigned InterpDeltaBits     = ZDeltaBits + 3 * AttrDeltaBits;  // delta
  // The sb shifts: p + RecipBits - AlphaBits (alpha0) and p + RecipBits - XFracBits (the steps),
  // p < DxBits, in shift amounts only as wide as their largest value (for a shift amount as wide
  // as the product yosys builds a shifter stage for every one of its bits).
  localparam int unsigned AlphaShiftMax  = (RecipBits > AlphaBits)
                                               ? DxBits - 1 + RecipBits - AlphaBits : DxBits - 1;
  localparam int unsigned StepShiftMax   = DxBits - 1 + RecipBits - XFracBits;
  localparam int unsigned AlphaShiftBits = $clog2(AlphaShiftMax + 1);
  localparam int unsigned StepShiftBits  = $clog2(StepShiftMax + 1);

  // ---------------------------------------------------------------- s0: range and clipping
  // s0 -> span_reciprocal -> sa: the first centres of X_E and X_F unclamped; sp compares them, sh
  // clamps them and decides whether the span is empty (span_mid_t), so s0 holds only
  // first_centre's add and the offset's mux (the clamps and the empty compares after that add
  // would be s0's longest path), and sa only copies the span out of the reciprocal's payload RAM
  // (after the RAM's output register and its route they would be the sized Gouraud top's longest
  // path).
  typedef struct packed {
    logic                               eol;
    logic [PolyIdBits-1:0]              poly;
    logic [MaterialIdBits-1:0]          material;
    logic signed [PixelCompareBits-1:0] fce;     // first_centre(X_E)
    logic signed [PixelCompareBits-1:0] fcf;     // first_centre(X_F)
    logic [DxBits-1:0]                  offset;  // x_start + 1/2 - X_E >= 0, X units
    logic [InterpVectorBits-1:0]        e;       // E's slots Z..
    logic [InterpDeltaBits-1:0]         delta;   // F - E per slot
  } span_pre_t;
  // sp .. sd: the pixel range; from sh on clamped to the screen (sp: xs clamped, xe the unclamped
  // first_centre(X_F), empty only fcf <= fce; sh applies sp_xe_clip_q and sp_off_q, reading
  // width_i, a frame constant).
  typedef struct packed {
    logic                        eol;
    logic                        empty;   // no pixel centre in [X_E, X_F) on screen
    logic [PolyIdBits-1:0]       poly;
    logic [MaterialIdBits-1:0]   material;
    logic [LineBits-1:0]         xs;      // first pixel
    logic [LineBits-1:0]         xe;      // one past the last pixel
    logic [InterpVectorBits-1:0] e;       // E's slots Z..
    logic [InterpDeltaBits-1:0]  delta;   // F - E per slot
  } span_mid_t;

  // First pixel whose centre is at or right of X: ceil(X - 1/2) =
  // (X + 1/2 - 2^-XFracBits) >> XFracBits, sign-extended to PixelCompareBits bits.
  function automatic logic signed [PixelCompareBits-1:0] first_centre(
      logic signed [XBits-1:0] x);
    // The fraction bits of the sum are what floor() discards.
    /* verilator lint_off UNUSEDSIGNAL */
    logic signed [XBits:0] t;
    /* verilator lint_on UNUSEDSIGNAL */
    t = $signed({x[XBits-1], x}) + $signed((XBits + 1)'((1 << (XFracBits - 1)) - 1));
    first_centre = PixelCompareBits'($signed(t[XBits:XFracBits]));
  endfunction

  logic                 s0_valid_q, s0_ready, s0_load;
  logic                 rc_valid, tail_en;  // the reciprocal's output valid, the tail's stall
  logic                 tail_en_q, tail_en_next;  // tail_en, a flop loaded a clock ahead (below)
  span_pre_t            s0_q;
  logic [DxBits-1:0]    s0_dx_q;
  logic signed [XBits-1:0] xe_e, xe_f;  // X of E and F

  assign xe_e = seg_e_i[0 +: XBits];
  assign xe_f = seg_f_i[0 +: XBits];

  assign seg_ready_o = !s0_valid_q || s0_ready;
  // seg_ready_o && seg_valid_i, one LUT from flops to s0's clock enables: s0_ready is the
  // reciprocal's own enable flop (LookAhead), equal to tail_en || !rc_valid.
  assign s0_load     = seg_valid_i && (!s0_valid_q || s0_ready);

  always_ff @(posedge clk_i) begin
    if (!rst_ni) s0_valid_q <= 1'b0;
    else if (seg_ready_o) s0_valid_q <= seg_valid_i;
  end
  // s0's values are computed inside its registers' enable (a segment arriving), not in an
  // always_comb that only feeds them: the same logic, which a simulator then evaluates only on
  // the clocks a segment arrives, not on every clock.
  always_ff @(posedge clk_i) begin
    if (s0_load) begin : s0_set
      logic signed [PixelCompareBits-1:0] fce;
      // The clipped offset h - X_E: offset < dx when the span is not empty, so its top bits are
      // dropped (the difference is exact modulo 2^(DxBits+2)).
      /* verilator lint_off UNUSEDSIGNAL */
      logic signed [DxBits+1:0]  off_clip;
      /* verilator lint_on UNUSEDSIGNAL */
      logic [XFracBits-1:0]      frac_h, off_frac;
      fce = first_centre(xe_e);
      // offset = x_start + h - X_E (h = 2^(F-1), F = XFracBits), not through x_start's add and
      // clamp: unclipped (fce >= 0, x_start = fce) fce 2^F = X_E + h - 1 - ((X_E + h - 1) mod 2^F),
      // so the offset is 2^F - 1 - ((X_E + h - 1) mod 2^F), the complement of an F-bit sum of
      // X_E's fraction bits; clipped (fce < 0, x_start = 0) it is h - X_E. Both run beside fce's
      // sign. A span whose fce is beyond LineBits bits is empty, so x_start's truncation does not
      // matter here.
      frac_h   = xe_e[XFracBits-1:0] + XFracBits'((1 << (XFracBits - 1)) - 1);
      off_clip = $signed((DxBits + 2)'(1 << (XFracBits - 1)))
               - $signed({{3{xe_e[XBits-1]}}, xe_e});
      off_frac = ~frac_h;
      s0_q.eol      <= seg_eol_i;
      s0_q.fce      <= fce;
      s0_q.fcf      <= first_centre(xe_f);
      s0_q.poly     <= seg_poly_i;
      s0_q.material <= seg_material_i;
      s0_q.offset   <= fce[PixelCompareBits-1] ? DxBits'(off_clip) : DxBits'(off_frac);
      s0_dx_q       <= DxBits'($signed({xe_f[XBits-1], xe_f}) - $signed({xe_e[XBits-1], xe_e}));
    end
  end

  // Per slot: E's value and the delta F - E, one bit wider than the slot's word.
  for (genvar c = 1; c <= InterpolatedSlots; c++) begin : g_s0
    localparam int unsigned SlotBits = watkins_pkg::slot_bits(c, XBits, ZBits, AttrBits);
    localparam int unsigned InputLow = watkins_pkg::slot_lo(c, XBits, ZBits, AttrBits);  // in E, F
    localparam int unsigned SlotLow  = ilo(c, ZBits, AttrBits);                // in e
    localparam int unsigned DeltaLow = ilo(c, ZDeltaBits, AttrDeltaBits);      // in delta
    always_ff @(posedge clk_i) begin
      if (s0_load) begin
        s0_q.e[SlotLow +: SlotBits]          <= seg_e_i[InputLow +: SlotBits];
        s0_q.delta[DeltaLow +: SlotBits + 1] <=
            $signed({seg_f_i[InputLow+SlotBits-1], seg_f_i[InputLow +: SlotBits]})
          - $signed({seg_e_i[InputLow+SlotBits-1], seg_e_i[InputLow +: SlotBits]});
      end
    end
  end

  // ---------------------------------------------------------------- reciprocal
  logic [RecipBits:0]      rc_recip;
  logic [ExponentBits-1:0] rc_p;
  span_pre_t               rc_span;

  // LookAhead: the reciprocal's stall is a flop of its own, loaded from tail_en's next value, not
  // tail_en itself, whose fan-out is the whole setup tail (tail_en_q -> a long route -> s0_ready
  // -> the reciprocal's stage enables would be the sized Gouraud top's longest path, most of it
  // routing).
  /* verilator lint_off UNUSEDSIGNAL */
  logic recip_ready_next_unused;  // s0 is no LookAhead producer
  /* verilator lint_on UNUSEDSIGNAL */
  span_reciprocal #(
    .DxBits     (DxBits),
    .PayloadBits($bits(s0_q)),
    .LookAhead  (1'b1)
  ) u_recip (
    .clk_i, .rst_ni,
    .dx_i     (s0_dx_q),
    .payload_i(s0_q),
    .valid_i  (s0_valid_q),
    .ready_o  (s0_ready),
    .recip_o  (rc_recip),
    .p_o      (rc_p),
    .payload_o(rc_span),
    .valid_o  (rc_valid),
    .ready_i  (tail_en),
    .ready_next_i(tail_en_next),
    .ready_next_o(recip_ready_next_unused)
  );

  // ---------------------------------------------------------------- sa .. sd: alpha0, steps, values
  // sa: offset * recip's and delta * recip's operands, registered in their multiplier blocks
  // (mul18_reg InReg): the reciprocal's quotient register fans out to every one of them, and a
  // route from it across the die that ends at a register has a short setup after it, not the
  // multiplier block's long input setup.
  // sm: their partial products, in the blocks' output registers. sp: offset * recip's sum, and each
  // delta piece's two step partial products added. sh: alpha0's shift, the steps' sums of their
  // pieces. sb: alpha0 = min(round_shift(offset*recip, p + RecipBits - AlphaBits), 2^AlphaBits)
  // (round_shift by 0 is exact), the steps' shifts. sc: delta * alpha0 as partial products, the
  // steps saturated. sv: each delta piece's two value partial products added. sd: the values.
  // Every product wider than a multiplier block is split at bit SplitBits of each operand too
  // wide for one, each partial product registered in its block (mul18_reg) and the partial
  // products summed later (a product and its adder tree in one clock would limit the block):
  // x y = x0 y0 + (x0 y1 + x1 y0) 2^SplitBits + x1 y1 2^(2 SplitBits), the sums taken modulo the
  // product's word. recip and alpha0 are unsigned, so their halves are too. A delta cut into
  // Pieces pieces has 2 Pieces partial products per slot; they are summed over two stages (sp
  // and sh for a step, sv and sd for a value): first each piece's pair, one two-operand add
  // beside its blocks, then the pairs (their sum in one clock, six operands from the blocks'
  // registers, would be the Phong configuration's longest path). The steps wait two stages for
  // the values anyway, so their extra stage costs no cycle; the values' costs one.
  localparam int unsigned SplitBits      = 17;  // a low part fits an 18 x 18 multiplier, signed
                                                // or not
  localparam int unsigned OffsetHighBits = (DxBits > SplitBits) ? DxBits - SplitBits : 1;
  localparam int unsigned RecipHighBits  = RecipBits + 1 - SplitBits;   // recip's high part
  localparam int unsigned AlphaHighBits  = AlphaBits + 1 - SplitBits;   // alpha0's high part
  logic                sa_valid_q, sm_valid_q, sp_valid_q, sh_valid_q, sb_valid_q, sc_valid_q;
  logic                sd_valid_q;
  // sa's and sm's copies of the span leaving the reciprocal (its offset and delta are read in
  // sa, by the multiplier blocks' operand registers).
  /* verilator lint_off UNUSEDSIGNAL */
  span_pre_t           sa_span_q, sm_span_q;
  /* verilator lint_on UNUSEDSIGNAL */
  span_mid_t           sp_span_q, sh_span_q, sb_span_q, sc_span_q;
  logic                sv_valid_q;
  span_mid_t           sv_span_q;
  // sp's compares, applied in sh: x_end clamps to the width; the span is off the screen (fcf <= 0,
  // width <= fce, width == 0). sp_span_q.empty is fcf <= fce alone, sh_span_q.empty the whole test.
  logic                sp_xe_clip_q;
  logic [2:0]          sp_off_q;
  // alpha0's shift p + RecipBits - AlphaBits; the steps' shift p + RecipBits - XFracBits (> 0).
  logic [AlphaShiftBits-1:0]               sa_sha_q, sm_sha_q, sp_sha_q;
  logic [StepShiftBits-1:0]                sa_shs_q, sm_shs_q, sp_shs_q, sh_shs_q;
  logic [2*SplitBits-1:0]                  sm_pa00_q;   // offset * recip: low x low
  logic [SplitBits+RecipHighBits-1:0]      sm_pa01_q;   // low offset x high recip
  logic [OffsetHighBits+SplitBits-1:0]     sm_pa10_q;   // high offset x low recip
  logic [OffsetHighBits+RecipHighBits-1:0] sm_pa11_q;   // high x high (0 for an offset of
                                                        // SplitBits bits)
  logic [AlphaProductBits-1:0]             sp_pa_q;     // offset * recip, unsigned
  logic [AlphaBits:0]                      sb_alpha_q;  // alpha0 in [0, 2^AlphaBits]
  // e and delta are spent by the FIFO; keeping one span type is simpler than a third struct.
  /* verilator lint_off UNUSEDSIGNAL */
  span_mid_t           sd_span_q;
  /* verilator lint_on UNUSEDSIGNAL */
  logic [InterpVectorBits-1:0] sc_step_q, sv_step_q, sd_step_q;
  logic [InterpVectorBits-1:0] sd_value_q;  // E + round_shift(delta * alpha0, AlphaBits) per slot

  logic [SplitBits-1:0]     rc_r0, sb_a0;  // recip's and alpha0's low parts
  logic [RecipHighBits-1:0] rc_r1;
  logic [AlphaHighBits-1:0] sb_a1;
  logic [SplitBits-1:0]     rc_o0;         // offset's low part (its high part in g_pa_hi)
  assign rc_r0 = SplitBits'(rc_recip);
  assign rc_r1 = RecipHighBits'(rc_recip >> SplitBits);
  assign sb_a0 = SplitBits'(sb_alpha_q);
  assign sb_a1 = AlphaHighBits'(sb_alpha_q >> SplitBits);
  assign rc_o0 = SplitBits'(rc_span.offset);

  // alpha0 shifts first and rounds after: round_shift(x, s) = (floor(2x / 2^s) + 1) / 2, so the
  // shifter takes the product straight from its register (u = {x, 0} >> s, also exact for s = 0)
  // and the rounding is one increment of the AlphaBits + 1 bits the clamp keeps. The clamp reads
  // the high bits: ra > 2^AlphaBits exactly when u has a bit above ua's, or ua >= 2^AlphaBits
  // with anything below that bit or the rounding bit set; it does not wait for the increment.
  // The shift has its own stage (sh): shift, increment and clamp in one clock would be the
  // block's longest path.
  logic [AlphaProductBits:0] sh_u_q;

  // Each tail stage loads only for a valid beat: the stall (tail_en) and the valid entering it,
  // as the reciprocal's stages do (stall_pipe's ce_o). A bubble leaves a stage's registers as
  // they were (nobody reads a bubble's values), and a simulator evaluates a stage's products
  // and sums, computed inside its enable, only on the clocks a span passes. Same flops.
  logic sa_ce, sm_ce, sp_ce, sh_ce, sb_ce, sc_ce, sv_ce, sd_ce;
  assign sa_ce = tail_en && rc_valid;
  assign sm_ce = tail_en && sa_valid_q;
  assign sp_ce = tail_en && sm_valid_q;
  assign sh_ce = tail_en && sp_valid_q;
  assign sb_ce = tail_en && sh_valid_q;
  assign sc_ce = tail_en && sb_valid_q;
  assign sv_ce = tail_en && sc_valid_q;
  assign sd_ce = tail_en && sv_valid_q;

  // offset * recip's partial products, each in its multiplier block's own registers (mul18_reg
  // InReg: the MULT18X18D's input registers in sa, its output register in sm, on the ECP5): a
  // product is then the block's setup, not a route into the block, the block and a route out of
  // it in one clock (the sized Phong top's many MULT18 blocks spread far from their fabric
  // registers).
  mul18_reg #(.ABits(SplitBits), .BBits(SplitBits), .InReg(1'b1)) u_pa00 (
    .clk_i, .ce_i({sm_ce, sa_ce}), .a_i(rc_o0), .b_i(rc_r0), .p_o(sm_pa00_q));
  mul18_reg #(.ABits(SplitBits), .BBits(RecipHighBits), .InReg(1'b1)) u_pa01 (
    .clk_i, .ce_i({sm_ce, sa_ce}), .a_i(rc_o0), .b_i(rc_r1), .p_o(sm_pa01_q));
  if (DxBits > SplitBits) begin : g_pa_hi
    logic [OffsetHighBits-1:0] rc_o1;
    assign rc_o1 = OffsetHighBits'(rc_span.offset >> SplitBits);
    mul18_reg #(.ABits(OffsetHighBits), .BBits(SplitBits), .InReg(1'b1)) u_pa10 (
      .clk_i, .ce_i({sm_ce, sa_ce}), .a_i(rc_o1), .b_i(rc_r0), .p_o(sm_pa10_q));
    mul18_reg #(.ABits(OffsetHighBits), .BBits(RecipHighBits), .InReg(1'b1)) u_pa11 (
      .clk_i, .ce_i({sm_ce, sa_ce}), .a_i(rc_o1), .b_i(rc_r1), .p_o(sm_pa11_q));
  end else begin : g_pa_lo
    // The offset fits its low part: no multiplier block for a zero high part.
    assign sm_pa10_q = '0;
    assign sm_pa11_q = '0;
  end

  always_ff @(posedge clk_i) begin
    if (sa_ce) begin : sa_set
      sa_span_q <= rc_span;
      // Both shifts are known from p alone: computed here, beside the products.
      sa_sha_q  <= AlphaShiftBits'(rc_p) + AlphaShiftBits'(RecipBits)
                 - AlphaShiftBits'(AlphaBits);
      sa_shs_q  <= StepShiftBits'(rc_p) + StepShiftBits'(RecipBits) - StepShiftBits'(XFracBits);
    end
    if (sm_ce) begin : sm_set
      sm_span_q <= sa_span_q;
      sm_sha_q  <= sa_sha_q;
      sm_shs_q  <= sa_shs_q;
    end
    if (sp_ce) begin : sp_set
      // sp: the pixel range x_start = max(fce, 0), x_end = min(fcf, width), from sm's copy of
      // the span. The clamped ends keep LineBits bits: beyond them the span is empty. sp
      // registers each compare on its own (its carry chain straight into a flip-flop: the span's
      // copy sits by the reciprocal's RAM, far from here); sh applies them (sp_xe_clip_q,
      // sp_off_q).
      sp_span_q.eol      <= sm_span_q.eol;
      sp_span_q.empty    <= sm_span_q.fcf <= sm_span_q.fce;
      sp_span_q.poly     <= sm_span_q.poly;
      sp_span_q.material <= sm_span_q.material;
      sp_span_q.xs       <= sm_span_q.fce[PixelCompareBits-1] ? '0 : LineBits'(sm_span_q.fce);
      sp_span_q.xe       <= LineBits'(sm_span_q.fcf);
      sp_span_q.e        <= sm_span_q.e;
      sp_span_q.delta    <= sm_span_q.delta;
      sp_xe_clip_q <= sm_span_q.fcf > $signed(PixelCompareBits'(width_i));
      // empty = min(fcf, width) <= max(fce, 0), spread into four compares of the unclamped ends
      // (through the clamps it would be the block's longest path): fcf <= fce above, the rest
      // here.
      sp_off_q <= {sm_span_q.fcf <= 0, $signed(PixelCompareBits'(width_i)) <= sm_span_q.fce,
                   width_i == '0};
      sp_sha_q  <= sm_sha_q;
      sp_shs_q  <= sm_shs_q;
      sp_pa_q   <= AlphaProductBits'({sm_pa11_q, sm_pa00_q})
                 + (AlphaProductBits'(sm_pa01_q) << SplitBits)
                 + (AlphaProductBits'(sm_pa10_q) << SplitBits);
    end
    if (sh_ce) begin
      sh_span_q       <= sp_span_q;
      sh_span_q.empty <= sp_span_q.empty || (|sp_off_q);
      if (sp_xe_clip_q) sh_span_q.xe <= LineBits'(width_i);
      sh_shs_q  <= sp_shs_q;
      sh_u_q    <= {sp_pa_q, 1'b0} >> sp_sha_q;
    end
    if (sb_ce) begin : sb_set
      logic [AlphaBits:0] ua;    // floor(x / 2^s), when it is below 2^(AlphaBits + 1)
      logic               over;  // ra > 2^AlphaBits
      ua   = sh_u_q[AlphaBits+1:1];
      over = |sh_u_q[AlphaProductBits:AlphaBits+2]
          || (ua[AlphaBits] && (|ua[AlphaBits-1:0] || sh_u_q[0]));
      sb_span_q  <= sh_span_q;
      sb_alpha_q <= over ? (AlphaBits + 1)'(1 << AlphaBits) : ua + (AlphaBits + 1)'(sh_u_q[0]);
    end
    if (sc_ce) sc_span_q <= sb_span_q;
    if (sv_ce) begin
      sv_span_q <= sc_span_q;
      sv_step_q <= sc_step_q;
    end
    if (sd_ce) begin
      sd_span_q <= sv_span_q;
      sd_step_q <= sv_step_q;
    end
  end

  // Per slot: step = saturate(round_shift(delta*recip, p + RecipBits - XFracBits), SlotBits) --
  // the shift uses X's fraction bits (the step per pixel is delta * 2^XFracBits / dx), always
  // > 0; delta * alpha0.
  for (genvar c = 1; c <= InterpolatedSlots; c++) begin : g_setup
    localparam int unsigned SlotBits        = watkins_pkg::slot_bits(c, XBits, ZBits, AttrBits);
    localparam int unsigned SlotLow         = ilo(c, ZBits, AttrBits);
    localparam int unsigned DeltaLow        = ilo(c, ZDeltaBits, AttrDeltaBits);
    localparam int unsigned StepProductBits = (c == 1) ? ZStepProductBits : AttrStepProductBits;
    localparam int unsigned ValueSumBits    = SlotBits + AlphaBits;  // the value's sum: SlotBits
                                                                     // bits above AlphaBits
    localparam logic signed [StepProductBits-1:0] StepMax =
        $signed((StepProductBits'(1) << (SlotBits - 1)) - StepProductBits'(1));
    localparam logic signed [StepProductBits-1:0] StepMin =
        -$signed(StepProductBits'(1) << (SlotBits - 1));
    // The delta (signed, SlotBits + 1 bits) times an unsigned low part ({0, x0}: SplitBits + 1
    // bits) and high part: exact products. A delta wider than a multiplier's signed 18 bits is
    // cut into Pieces pieces too, SplitBits unsigned bits each and a signed top, so every partial
    // product is one MULT18 registered straight from it (a 43-bit delta times 18 bits as three
    // multipliers and their LUT adders in one clock would be the Phong configuration's longest
    // path).
    localparam int unsigned Pieces = (SlotBits + 1 <= SplitBits + 1)  // ceil((SlotBits + 1) /
        ? 1 : (SlotBits + SplitBits) / SplitBits;                     //      SplitBits)
    localparam int unsigned PieceBits            = (Pieces == 1) ? SlotBits + 1 : SplitBits + 1;
    localparam int unsigned LowProductBits       = PieceBits + SplitBits + 1;      // piece * low
                                                                                   // part
    localparam int unsigned RecipHighProductBits = PieceBits + RecipHighBits + 1;  // piece *
                                                                                   // recip's high
    localparam int unsigned AlphaHighProductBits = PieceBits + AlphaHighBits + 1;  // piece *
                                                                                   // alpha0's high
    localparam int unsigned TopPieceBits = SlotBits + 1 - SplitBits * (Pieces - 1);
    // A piece's pair x_k r0 + x_k r1 2^SplitBits (steps) or x_k a0 + x_k a1 2^SplitBits
    // (values), exact: one bit above the wider of its two terms.
    localparam int unsigned StepPairBits  = ((LowProductBits > RecipHighProductBits + SplitBits)
        ? LowProductBits : RecipHighProductBits + SplitBits) + 1;
    localparam int unsigned ValuePairBits = ((LowProductBits > AlphaHighProductBits + SplitBits)
        ? LowProductBits : AlphaHighProductBits + SplitBits) + 1;
    // The pairs, piece k at k StepPairBits (k ValuePairBits), each written in its piece's
    // generate block: the second stage of each sum reads these registers, never a vector of the
    // blocks' outputs (one, assembled from every block's product on every clock, would be most
    // of the simulator's cost in this loop).
    logic [Pieces*StepPairBits-1:0]  pps_q;  // in sp
    logic [Pieces*ValuePairBits-1:0] ppv_q;  // in sv
    // Piece k of the delta at bit SplitBits k: SplitBits unsigned bits, the top one TopPieceBits
    // signed bits (the multiplier sign-extends it). sa takes the delta leaving the reciprocal
    // (into the blocks' operand registers; the products are sm's), sc the delta in sb; each
    // partial product is one mul18_reg, registered in its block (see u_pa00), and its pair's add
    // reads the two blocks' outputs straight.
    for (genvar k = 0; k < Pieces; k++) begin : g_piece
      localparam bit          IsTop         = (k == Pieces - 1);
      localparam int unsigned ThisPieceBits = IsTop ? TopPieceBits : SplitBits;
      localparam int unsigned PieceLow      = DeltaLow + SplitBits * k;  // in delta
      logic [LowProductBits-1:0]       ps0, pv0;  // x_k times the low part of recip / alpha0
      logic [RecipHighProductBits-1:0] ps1;       // x_k times recip's high part
      logic [AlphaHighProductBits-1:0] pv1;       // x_k times alpha0's high part
      mul18_reg #(.ABits(ThisPieceBits), .ASigned(IsTop), .BBits(SplitBits),
                  .PBits(LowProductBits), .InReg(1'b1)) u_ps0 (
        .clk_i, .ce_i({sm_ce, sa_ce}), .a_i(rc_span.delta[PieceLow +: ThisPieceBits]),
        .b_i(rc_r0), .p_o(ps0));
      mul18_reg #(.ABits(ThisPieceBits), .ASigned(IsTop), .BBits(RecipHighBits),
                  .PBits(RecipHighProductBits), .InReg(1'b1)) u_ps1 (
        .clk_i, .ce_i({sm_ce, sa_ce}), .a_i(rc_span.delta[PieceLow +: ThisPieceBits]),
        .b_i(rc_r1), .p_o(ps1));
      mul18_reg #(.ABits(ThisPieceBits), .ASigned(IsTop), .BBits(SplitBits),
                  .PBits(LowProductBits)) u_pv0 (
        .clk_i, .ce_i(sc_ce), .a_i(sb_span_q.delta[PieceLow +: ThisPieceBits]), .b_i(sb_a0),
        .p_o(pv0));
      mul18_reg #(.ABits(ThisPieceBits), .ASigned(IsTop), .BBits(AlphaHighBits),
                  .PBits(AlphaHighProductBits)) u_pv1 (
        .clk_i, .ce_i(sc_ce), .a_i(sb_span_q.delta[PieceLow +: ThisPieceBits]), .b_i(sb_a1),
        .p_o(pv1));
      // The pairs' adds inside their stages' enables (see below).
      always_ff @(posedge clk_i) begin
        if (sp_ce)
          pps_q[k*StepPairBits +: StepPairBits] <=
              StepPairBits'($signed(ps0)) + (StepPairBits'($signed(ps1)) << SplitBits);
        if (sv_ce)
          ppv_q[k*ValuePairBits +: ValuePairBits] <=
              ValuePairBits'($signed(pv0)) + (ValuePairBits'($signed(pv1)) << SplitBits);
      end
    end
    logic signed [StepProductBits-1:0] ps_q;  // delta * recip, in sh
    // Shift first, round after, as alpha0: u = {x, 0} >>> s = floor(x / 2^(s-1)) (s > 0), and
    // rs = floor((u + 1) / 2) = (u >>> 1) + u[0]. Saturate from u's high bits: when u >>> 1
    // does not fit SlotBits bits, rs saturates to its sign (below the range, + u[0] reaches at
    // most StepMin); when it fits, only StepMax + 1 leaves the range, so StepMax is picked there.
    // The SlotBits-bit increment (by u[0] alone) runs beside the tests, which pick among it and
    // the bounds: the test for StepMax in the increment's carry-in would be the Phong block's
    // longest path (u_q -> at_max -> the carry chain -> sc_step_q).
    logic signed [StepProductBits:0] u_q;  // in sb
    // Every value below is computed inside its stage's enable (sa_ce .. sd_ce), not in an
    // always_comb or assign that only feeds it: the same logic, evaluated by a simulator only
    // when a span passes.
    always_ff @(posedge clk_i) begin
      if (sh_ce) begin : sh_sum
        // The pieces' pairs at bit SplitBits k, summed modulo the product's word.
        logic signed [StepProductBits-1:0] sum;
        sum = '0;
        for (int k = 0; k < Pieces; k++)
          sum = sum + (StepProductBits'($signed(pps_q[k*StepPairBits +: StepPairBits]))
                       << (SplitBits * k));
        ps_q <= sum;
      end
      if (sb_ce) u_q <= $signed({ps_q, 1'b0}) >>> sh_shs_q;
      if (sc_ce) begin : sc_sat
        logic fits, at_max;
        logic [SlotBits-1:0] inc;
        fits   = &u_q[StepProductBits:SlotBits] || ~|u_q[StepProductBits:SlotBits];
        // at_max: u >>> 1 = StepMax, the increment would leave the range.
        at_max = !u_q[SlotBits] && &u_q[SlotBits-1:1];
        inc    = u_q[SlotBits:1] + SlotBits'(u_q[0]);
        if (!fits)
          sc_step_q[SlotLow +: SlotBits] <= u_q[StepProductBits] ? SlotBits'(StepMin)
                                                                 : SlotBits'(StepMax);
        else if (at_max) sc_step_q[SlotLow +: SlotBits] <= SlotBits'(StepMax);
        else sc_step_q[SlotLow +: SlotBits] <= inc;
      end
      if (sd_ce) begin : sd_sum
        // value = wrap(E + ((pv + 2^(AlphaBits-1)) >> AlphaBits), SlotBits) = bits
        // [AlphaBits +: SlotBits] of pv + (E 2^AlphaBits + 2^(AlphaBits-1)): E and the rounding
        // constant are one operand (their bits do not overlap), added with the pieces' pairs in
        // sd, so the FIFO's input is a register. Sums modulo 2^ValueSumBits keep those bits.
        /* verilator lint_off UNUSEDSIGNAL */
        logic [ValueSumBits-1:0] sum;
        /* verilator lint_on UNUSEDSIGNAL */
        sum = {sv_span_q.e[SlotLow +: SlotBits], 1'b1, (AlphaBits - 1)'(0)};
        for (int k = 0; k < Pieces; k++)
          sum = sum + (ValueSumBits'($signed(ppv_q[k*ValuePairBits +: ValuePairBits]))
                       << (SplitBits * k));
        sd_value_q[SlotLow +: SlotBits] <= SlotBits'(sum >> AlphaBits);
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      sa_valid_q <= 1'b0;
      sm_valid_q <= 1'b0;
      sp_valid_q <= 1'b0;
      sh_valid_q <= 1'b0;
      sb_valid_q <= 1'b0;
      sc_valid_q <= 1'b0;
      sv_valid_q <= 1'b0;
      sd_valid_q <= 1'b0;
    end else if (tail_en) begin
      sa_valid_q <= rc_valid;
      sm_valid_q <= sa_valid_q;
      sp_valid_q <= sm_valid_q;
      sh_valid_q <= sp_valid_q;
      sb_valid_q <= sh_valid_q;
      sc_valid_q <= sb_valid_q;
      sv_valid_q <= sc_valid_q;
      sd_valid_q <= sv_valid_q;
    end
  end

  // ---------------------------------------------------------------- FIFO of ready spans
  // A span's first pixel leaves straight from the FIFO head, so what the stepper would compute
  // from the head (that pixel's readings, the next pixel's value, whether there is one) is
  // computed from sd's registers before the FIFO and stored: the head's read is then followed by
  // a pick only (the distributed RAM's read, a route, the rounding add and the clamp after it
  // would be the block's longest paths, in both shading modes).
  typedef struct packed {
    logic                        eol;
    logic                        more;    // a pixel after xs: xs + 1 != xe
    logic [PolyIdBits-1:0]       poly;
    logic [MaterialIdBits-1:0]   material;
    logic [LineBits-1:0]         xs;
    logic [LineBits-1:0]         xe;
    logic [DepthBits-1:0]        depth;   // pixel xs's readings (g_frag)
    logic [3*8-1:0]              rgb;
    logic [3*NormalBits-1:0]     normal;
    logic [HeadAttrBits-1:0]     attr;    // AttrOut: pixel xs's attribute words
    logic [InterpVectorBits-1:0] value1;  // slots Z.. at pixel xs + 1 (wrapped as the stepper
                                          // wraps)
    logic [InterpVectorBits-1:0] step;    // per-pixel increments
  } span_t;

  span_t          f_in, f_out;
  logic           f_in_valid, f_in_ready, f_out_valid, f_out_ready;
  logic           f_in_ready_next;  // f_in_ready on the next clock
  logic           sd_keep;

  // Empty spans produce nothing and are dropped here; markers always go through.
  assign sd_keep    = sd_span_q.eol || !sd_span_q.empty;
  assign f_in_valid = sd_valid_q && sd_keep;
  // tail_en = !sd_valid_q || !sd_keep || f_in_ready is a flop loaded a clock ahead (a_tail_en):
  // sd's valid and keep on the next clock (sv's when the tail advances), the FIFO's next ready.
  // From a compare it would reach the reciprocal's and s0's clock enables across the block in
  // one clock (`sd_valid_q` -> `tail_en` -> a long route -> `s0_ready` -> `s0_load` -> s0's
  // enables: the sized Gouraud top's critical path, most of it routing).
  // A stall means sd holds a kept beat, which stays: then only the FIFO's ready decides.
  assign tail_en_next = f_in_ready_next
                     || (tail_en && (!sv_valid_q || !(sv_span_q.eol || !sv_span_q.empty)));
  always_ff @(posedge clk_i) begin
    if (!rst_ni) tail_en_q <= 1'b1;  // sd empty
    else tail_en_q <= tail_en_next;
  end
  assign tail_en    = tail_en_q;

  stream_fifo #(
    .DataBits($bits(f_in)),
    .Depth   (FifoDepth)
  ) u_fifo (
    .clk_i, .rst_ni,
    .data_i (f_in),
    .valid_i(f_in_valid),
    .ready_o(f_in_ready),
    .ready_next_o(f_in_ready_next),
    .data_o (f_out),
    .valid_o(f_out_valid),
    .ready_i(f_out_ready)
  );

  // ---------------------------------------------------------------- stepper
  // st_active_q (a span is being stepped from the st_* registers) in copies, one per group of
  // registers it picks for and enables, each with its own fragment enable computed from the same
  // flops: one enable reaching every frag_* and st_* flop (st_active_q -> the FIFO's pop ->
  // emit_frag -> a long route back to st_active_q's clock enable) would be the sized Phong top's
  // critical path. Each copy's next state is computed from the copy itself, so the copies are
  // not identical logic and yosys keeps them apart (opt_merge merges flops and LUTs of equal
  // inputs, a (* keep *) on their wires notwithstanding).
  localparam int unsigned CopyControl  = 0;  // st_active_q's own state, frag_valid_o,
                                             // st_x/xe/poly/material
  localparam int unsigned CopyFragment = 1;  // the frag_* outputs
  localparam int unsigned CopyValue    = 2;  // st_value_q, st_step_q
  localparam int unsigned CopyHead     = 3;  // the FIFO's ready (its pop)
  localparam int unsigned Copies       = 4;
  logic [Copies-1:0]           st_active_q;  // all equal (a_st_copies)
  logic [LineBits-1:0]         st_x_q, st_xe_q;
  logic [PolyIdBits-1:0]       st_poly_q;
  logic [MaterialIdBits-1:0]   st_material_q;
  logic [InterpVectorBits-1:0] st_value_q, st_step_q;

  logic                        out_free, head_frag, head_eol;
  logic [Copies-1:0]           emit_frag;  // per copy: a fragment leaves into frag_*_o
  logic                        emit_eol;   // a marker does
  logic                        st_more;    // a pixel after st_x_q in the stepper's span
  logic [InterpVectorBits-1:0] st_value1, hd_value1;  // the stepper's value + step; sd's, into
                                                      // the FIFO

  assign out_free  = !frag_valid_o || frag_ready_i;
  assign head_frag = f_out_valid && !f_out.eol;  // the head is a span
  assign head_eol  = f_out_valid && f_out.eol;
  for (genvar i = 0; i < Copies; i++) begin : g_cp
    assign emit_frag[i] = out_free && (st_active_q[i] || head_frag);
    always_ff @(posedge clk_i) begin
      if (!rst_ni) st_active_q[i] <= 1'b0;
      else if (emit_frag[i]) st_active_q[i] <= st_active_q[i] ? st_more : f_out.more;
    end
  end
  assign emit_eol    = out_free && !st_active_q[CopyFragment] && head_eol;
  // The head leaves when the stepper is idle and the output free (a span's first pixel, or a
  // marker); a pop needs the FIFO's valid as well, which the FIFO adds.
  assign f_out_ready = out_free && !st_active_q[CopyHead];

  // Per slot: the next pixel's value (wrapping at the slot's word) and the fragment's readings:
  // depth = clamp(round_shift(Z, ZFracBits), 0, 2^DepthBits - 1); shade = clamp(round_shift(v,
  // AttrFracBits), 0, 255); normal = v rescaled to FracBits fraction bits (round_shift when
  // AttrFracBits is larger, a left shift when smaller), saturated to NormalInBits.
  logic [DepthBits-1:0]      depth_d;
  logic [3*8-1:0]            rgb_d;       // {B, G, R} by slot
  logic [3*NormalBits-1:0]   normal_d;    // {Nz, Ny, Nx}
  logic [2*DepthBits-1:0]    depth_src;   // per source: {the span entering the FIFO, stepper}
  logic [2*3*8-1:0]          rgb_src;
  logic [2*3*NormalBits-1:0] normal_src;
  for (genvar c = 1; c <= InterpolatedSlots; c++) begin : g_frag
    localparam int unsigned SlotBits     = watkins_pkg::slot_bits(c, XBits, ZBits, AttrBits);
    localparam int unsigned SlotFracBits = (c == 1) ? ZFracBits : AttrFracBits;
    localparam int unsigned SlotLow      = ilo(c, ZBits, AttrBits);
    localparam int unsigned LevelBits    = (c == 1) ? DepthBits : 8;  // output level width
    // The rounded integer part, and a width that holds it and the level's maximum.
    localparam int unsigned RoundedBits  = SlotBits + 1 - SlotFracBits;
    localparam int unsigned ClampBits    = (RoundedBits > LevelBits + 1) ? RoundedBits
                                                                         : LevelBits + 1;
    assign st_value1[SlotLow +: SlotBits] = st_value_q[SlotLow +: SlotBits]
                                          + st_step_q[SlotLow +: SlotBits];
    assign hd_value1[SlotLow +: SlotBits] = sd_value_q[SlotLow +: SlotBits]
                                          + sd_step_q[SlotLow +: SlotBits];
    // The readings of both sources, the stepper's registers (s = 0) and the span entering the
    // FIFO (s = 1, sd's value: stored, they come out at the head with the span); st_active_q
    // picks among the readings, after the rounding add and the clamp (a pick before them would
    // put its fan-out to every value bit and the FIFO's read in series with that add).
    for (genvar s = 0; s < 2; s++) begin : g_src
      logic signed [SlotBits-1:0]  v;
      /* verilator lint_off UNUSEDSIGNAL */
      logic signed [SlotBits:0]    t;  // fraction bits are rounded away
      /* verilator lint_on UNUSEDSIGNAL */
      logic signed [ClampBits-1:0] r;
      logic [ClampBits-2:0]        mag;  // r without its sign
      logic [LevelBits-1:0]        level;
      assign v = (s == 0) ? st_value_q[SlotLow +: SlotBits] : sd_value_q[SlotLow +: SlotBits];
      if (SlotFracBits > 0) begin : g_round
        assign t = $signed({v[SlotBits-1], v})
                 + $signed((SlotBits + 1)'(1) << (SlotFracBits - 1));
      end else begin : g_exact
        assign t = $signed({v[SlotBits-1], v});
      end
      assign r = ClampBits'($signed(t[SlotBits:SlotFracBits]));
      // clamp(r, 0, 2^LevelBits - 1) from r's bits, not through two compares after the rounding
      // add: below 0 when the sign is set, above the maximum when a bit above the level's is set.
      assign mag   = r[ClampBits-2:0];
      assign level = r[ClampBits-1] ? '0 : (|(mag >> LevelBits)) ? {LevelBits{1'b1}}
                                                                  : LevelBits'(mag);
      if (c == 1) begin : g_depth
        assign depth_src[s*DepthBits +: DepthBits] = level;
      end else begin : g_attr
        assign rgb_src[s*24 + (c - 2)*8 +: 8] = level;
        // Normal: FracBits fraction bits out of SlotFracBits.
        localparam int unsigned NormalFracBits = watkins_pkg::FracBits;
        localparam int unsigned RescaledBits   = (SlotFracBits >= NormalFracBits)  // rescaled width
            ? SlotBits + 1 - (SlotFracBits - NormalFracBits)
            : SlotBits + (NormalFracBits - SlotFracBits);
        localparam int unsigned SaturateBits   = (RescaledBits > NormalBits)       // compare width
            ? RescaledBits : NormalBits;
        logic signed [RescaledBits-1:0]   n;
        logic signed [SaturateBits-1:0]   ns;
        logic [SaturateBits-NormalBits:0] ns_hi;  // all equal: ns fits NormalBits bits
        if (SlotFracBits > NormalFracBits) begin : g_down
          /* verilator lint_off UNUSEDSIGNAL */
          logic signed [SlotBits:0] tn;
          /* verilator lint_on UNUSEDSIGNAL */
          assign tn = $signed({v[SlotBits-1], v})
                    + $signed((SlotBits + 1)'(1) << (SlotFracBits - NormalFracBits - 1));
          assign n  = tn[SlotBits:SlotFracBits-NormalFracBits];
        end else if (SlotFracBits == NormalFracBits) begin : g_same
          assign n = $signed({v[SlotBits-1], v});
        end else begin : g_up
          assign n = $signed({v, (NormalFracBits - SlotFracBits)'(0)});
        end
        assign ns    = SaturateBits'(n);
        assign ns_hi = ns[SaturateBits-1:NormalBits-1];
        // Saturate to NormalBits bits from the bits above them, not through two compares.
        assign normal_src[s*3*NormalBits + (c - 2)*NormalBits +: NormalBits] =
            (&ns_hi || ~|ns_hi) ? NormalBits'(ns)
          : ns[SaturateBits-1]  ? NormalBits'(64'd1 << (NormalBits - 1))
          :                       NormalBits'((64'd1 << (NormalBits - 1)) - 1);
      end
    end
  end
  // The readings of the fragment, picked by the CopyFragment copy after the rounding and the
  // clamp.
  assign st_more  = (st_x_q + 1'b1 != st_xe_q);
  assign depth_d  = st_active_q[CopyFragment] ? depth_src[0 +: DepthBits]      : f_out.depth;
  assign rgb_d    = st_active_q[CopyFragment] ? rgb_src[0 +: 24]               : f_out.rgb;
  assign normal_d = st_active_q[CopyFragment] ? normal_src[0 +: 3*NormalBits] : f_out.normal;

  // The FIFO's input: sd's span with the head's readings and next value computed from it.
  assign f_in.eol      = sd_span_q.eol;
  assign f_in.more     = (sd_span_q.xs + 1'b1 != sd_span_q.xe);
  assign f_in.poly     = sd_span_q.poly;
  assign f_in.material = sd_span_q.material;
  assign f_in.xs       = sd_span_q.xs;
  assign f_in.xe       = sd_span_q.xe;
  assign f_in.depth    = depth_src[DepthBits +: DepthBits];
  assign f_in.rgb      = rgb_src[24 +: 24];
  assign f_in.normal   = normal_src[3*NormalBits +: 3*NormalBits];
  if (AttrOut) begin : g_attr_in
    assign f_in.attr = sd_value_q[ZBits +: 3*AttrBits];
  end else begin : g_no_attr_in
    assign f_in.attr = '0;
  end
  assign f_in.value1   = hd_value1;
  assign f_in.step     = sd_step_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) frag_valid_o <= 1'b0;
    else if (out_free) frag_valid_o <= st_active_q[CopyControl] || f_out_valid;  // a fragment or
                                                                                 // a marker
  end

  // Each group from its own copy: the picks and the enable.
  always_ff @(posedge clk_i) begin
    if (emit_frag[CopyFragment]) begin
      frag_x_o        <= st_active_q[CopyFragment] ? st_x_q : f_out.xs;
      frag_depth_o    <= depth_d;
      frag_rgb_o.r    <= rgb_d[0 +: 8];
      frag_rgb_o.g    <= rgb_d[8 +: 8];
      frag_rgb_o.b    <= rgb_d[16 +: 8];
      frag_normal_o   <= normal_d;
      frag_poly_o     <= st_active_q[CopyFragment] ? st_poly_q : f_out.poly;
      frag_material_o <= st_active_q[CopyFragment] ? st_material_q : f_out.material;
      frag_eol_o      <= 1'b0;
    end else if (emit_eol) begin
      frag_eol_o      <= 1'b1;
    end
    if (emit_frag[CopyControl]) begin
      st_x_q        <= (st_active_q[CopyControl] ? st_x_q : f_out.xs) + 1'b1;
      st_xe_q       <= st_active_q[CopyControl] ? st_xe_q : f_out.xe;
      st_poly_q     <= st_active_q[CopyControl] ? st_poly_q : f_out.poly;
      st_material_q <= st_active_q[CopyControl] ? st_material_q : f_out.material;
    end
    if (emit_frag[CopyValue]) begin
      // The next pixel's value, for each source and picked after the add (a pick before the add
      // would be the Gouraud block's limit).
      st_value_q <= st_active_q[CopyValue] ? st_value1 : f_out.value1;
      st_step_q  <= st_active_q[CopyValue] ? st_step_q : f_out.step;
    end
  end

  `WATKINS_ASSERT_HOLD(a_in_hold, seg_valid_i, seg_ready_o, {seg_e_i, seg_f_i, seg_poly_i, seg_material_i,
    seg_eol_i})
  // The attribute words, as the other readings: the stepper's registers or the head's stored copy.
  if (AttrOut) begin : g_attr_out
    always_ff @(posedge clk_i) begin
      if (emit_frag[CopyFragment])
        frag_attr_o <= st_active_q[CopyFragment] ? st_value_q[ZBits +: 3*AttrBits] : f_out.attr;
    end
  end else begin : g_no_attr_out
    assign frag_attr_o = '0;
    logic unused_attr;
    assign unused_attr = ^f_out.attr;
  end

  `WATKINS_ASSERT_HOLD(a_out_hold, frag_valid_o, frag_ready_i, {frag_x_o, frag_depth_o, frag_rgb_o,
    frag_normal_o, frag_attr_o, frag_poly_o, frag_material_o, frag_eol_o})
  `WATKINS_ASSERT(a_x_on_screen, frag_valid_o && !frag_eol_o |-> frag_x_o < width_i)
  `WATKINS_COVER(c_back_to_back_spans, emit_frag[CopyControl] && !st_active_q[CopyControl]
    && frag_valid_o && !frag_eol_o)
  `WATKINS_ASSERT(a_st_copies, st_active_q == {Copies{st_active_q[CopyControl]}})
  `WATKINS_COVER(c_empty_dropped, sd_valid_q && !sd_keep)
  `WATKINS_ASSERT(a_tail_en, tail_en == (!sd_valid_q || !sd_keep || f_in_ready))
  // The head's stored flag is what the stepper would compare there (the other stored fields
  // are checked by every co-simulation's fragments).
  `WATKINS_ASSERT(a_head_more, f_out_valid && !f_out.eol
    |-> f_out.more == (f_out.xs + 1'b1 != f_out.xe))
endmodule
