// segment_interpolator: span setup for each segment E..F, then one fragment per pixel by alpha
// stepping, exactly model/twins/segment_interpolator.cpp (setup(), fragment(), step()).
// Setup pipeline, one segment per clock: s0 (first pixel centres, dx, offset, deltas) ->
// span_reciprocal (26) -> sa (alpha's and the steps' multiplier operands, deltas in 17-bit pieces
// when wider than a MULT18, each registered in its multiplier block) -> sm (those partial
// products, in their blocks' output registers) -> sp (alpha0's sum;
// each delta piece's pair of step partial products added; the pixel range's and the empty test's
// compares) -> sh (alpha0's shift; the steps' sums of their pieces; the clamp to the screen and the
// empty test applied) -> sb (round, clamp
// alpha0; the steps' shifts) -> sc (value partial products, in their blocks' registers too; the
// steps saturated) -> sv (each delta piece's pair of value partial products added) -> sd (the
// pieces' sums with E and the rounding constant: the value E + round(delta*alpha0)) -> FIFO;
// empty spans are dropped before the FIFO. The stepper emits one fragment per clock from a
// registered output, taking a span's first pixel straight from the FIFO head, so consecutive
// spans (even of one pixel) leave no bubble and a span's setup hides behind the previous spans'
// pixels.
// Latency segment -> first fragment: 37 cycles. All stage outputs registered; the setup stages'
// one stall signal (tail_en) is a flop, loaded a clock ahead from the FIFO's next ready. A setup
// stage's registers load only for a valid beat (the stall and the valid entering the stage), and
// their values are computed inside that enable: a simulator evaluates the setup only on the
// clocks a span passes (issue 11), the hardware is the same flops and logic.
// End-of-line markers pass through in order. Each fragment carries its segment's polygon id
// (the scanline_buffer's equal-depth rule) and material id, and both readings of the three
// attribute channels: frag_rgb_o (Gouraud shade levels) and frag_normal_o (Phong normal, the
// channel rescaled to FracBits fraction bits and saturated to NormalInBits); a top uses one
// and synthesis drops the other.
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
  localparam int unsigned VB = watkins_pkg::vector_bits(XBits, ZBits, AttrBits)
) (
  input  logic                                                             clk_i,
  input  logic                                                             rst_ni,
  input  logic [watkins_pkg::LineBits-1:0]                                 width_i,  // screen width, stable per frame
  input  logic [VB-1:0]                                                    seg_e_i, // left end E
  input  logic [VB-1:0]                                                    seg_f_i, // right end F
  input  logic [PolyIdBits-1:0]                                            seg_poly_i, // polygon id
  input  logic [MaterialIdBits-1:0]                                        seg_material_i,
  input  logic                                                             seg_eol_i, // end-of-line marker, no segment
  input  logic                                                             seg_valid_i,
  output logic                                                             seg_ready_o,
  output logic [watkins_pkg::LineBits-1:0]                                 frag_x_o,
  output logic [DepthBits-1:0]                                             frag_depth_o,
  output watkins_pkg::rgb_t                                                frag_rgb_o,  // Gouraud shade
  output logic [3*watkins_pkg::NormalInBits-1:0]                           frag_normal_o, // {Nz,Ny,Nx}
  output logic [PolyIdBits-1:0]                                            frag_poly_o, // its segment's
  output logic [MaterialIdBits-1:0]                                        frag_material_o,
  output logic                                                             frag_eol_o,  // end-of-line marker, no fragment
  output logic                                                             frag_valid_o,
  input  logic                                                             frag_ready_i
);
  localparam int unsigned LB        = watkins_pkg::LineBits;
  localparam int unsigned RecipBits = watkins_pkg::RecipBits;
  localparam int unsigned AlphaBits = watkins_pkg::AlphaBits;
  localparam int unsigned NI        = watkins_pkg::NumChannels - 1;  // interpolated slots Z.. (not X)
  localparam int unsigned FX        = XFracBits;
  localparam int unsigned DxBits    = XBits + 1;                     // dx, offset (unsigned)
  localparam int unsigned ExpBits   = $clog2(DxBits);                // p = floor(log2 dx) < XBits
  localparam int unsigned APBits    = DxBits + RecipBits + 2;        // offset * recip, with rounding room
  localparam int unsigned XCB       = XBits + 1 - FX;                // signed pixel index of an X value
  // Pixel indices are compared with the screen width in a width holding both.
  localparam int unsigned PCB       = (XCB > LB + 1) ? XCB : LB + 1;
  localparam int unsigned NB        = watkins_pkg::NormalInBits;
  localparam int unsigned MIB       = MaterialIdBits;
  localparam int unsigned DepB      = DepthBits;

  // Interpolated vectors: slot c (1..4) at ilo(c, zw, aw), Z zw bits wide, each attribute aw.
  function automatic int unsigned ilo(int unsigned c, int unsigned zw, int unsigned aw);
    ilo = (c == 1) ? 0 : zw + (c - 2) * aw;
  endfunction
  // A slot's word and fraction bits, and the widths of its delta (word + 1) and of delta * recip
  // (with room for the rounding constant: the step's shift p + R - FX reaches XBits - 1 + R - FX,
  // so a narrow slot's product still needs X's headroom).
  localparam int unsigned ZD  = ZBits + 1,    AD  = AttrBits + 1;
  localparam int unsigned ZPS = ((ZBits > XBits - FX) ? ZBits : XBits - FX) + RecipBits + 3;
  localparam int unsigned APS = ((AttrBits > XBits - FX) ? AttrBits : XBits - FX) + RecipBits + 3;
  localparam int unsigned IVB = ZBits + 3 * AttrBits;  // value, step, E
  localparam int unsigned IDB = ZD + 3 * AD;           // delta
  // The sb shifts: p + RecipBits - AlphaBits (alpha0) and p + RecipBits - FX (the steps), p <
  // DxBits, in shift amounts only as wide as their largest value (a shift amount as wide as the
  // product made yosys build a shifter stage for every one of its bits).
  localparam int unsigned ShAMax = (RecipBits > AlphaBits) ? DxBits - 1 + RecipBits - AlphaBits
                                                          : DxBits - 1;
  localparam int unsigned ShSMax = DxBits - 1 + RecipBits - FX;
  localparam int unsigned ShAB   = $clog2(ShAMax + 1);
  localparam int unsigned ShSB   = $clog2(ShSMax + 1);

  // ---------------------------------------------------------------- s0: range and clipping
  // s0 -> span_reciprocal -> sa: the first centres of X_E and X_F unclamped; sp compares them, sh
  // clamps them and decides whether the span is empty (span_mid_t), so s0 holds only first_centre's
  // add and the offset's mux (the clamps and the empty compares after that add were s0's longest
  // path), and sa only copies the span out of the reciprocal's payload RAM (after the RAM's output
  // register and its route they were the sized Gouraud top's longest path, 11.5 ns at 084a177).
  typedef struct packed {
    logic                    eol;
    logic [PolyIdBits-1:0]   poly;
    logic [MIB-1:0]          material;
    logic signed [PCB-1:0]   fce;     // first_centre(X_E)
    logic signed [PCB-1:0]   fcf;     // first_centre(X_F)
    logic [DxBits-1:0]       offset;  // x_start + 1/2 - X_E >= 0, X units
    logic [IVB-1:0]          e;       // E's slots Z..
    logic [IDB-1:0]          delta;   // F - E per slot
  } span_pre_t;
  // sp .. sd: the pixel range; from sh on clamped to the screen (sp: xs clamped, xe the unclamped
  // first_centre(X_F), empty only fcf <= fce; sh applies sp_xe_clip_q and sp_off_q, reading width_i,
  // a frame constant).
  typedef struct packed {
    logic                    eol;
    logic                    empty;   // no pixel centre in [X_E, X_F) on screen
    logic [PolyIdBits-1:0]   poly;
    logic [MIB-1:0]          material;
    logic [LB-1:0]           xs;      // first pixel
    logic [LB-1:0]           xe;      // one past the last pixel
    logic [IVB-1:0]          e;       // E's slots Z..
    logic [IDB-1:0]          delta;   // F - E per slot
  } span_mid_t;

  // First pixel whose centre is at or right of X: ceil(X - 1/2) = (X + 1/2 - 2^-FX) >> FX,
  // sign-extended to PCB bits.
  function automatic logic signed [PCB-1:0] first_centre(logic signed [XBits-1:0] x);
    // The fraction bits of the sum are what floor() discards.
    /* verilator lint_off UNUSEDSIGNAL */
    logic signed [XBits:0] t;
    /* verilator lint_on UNUSEDSIGNAL */
    t = $signed({x[XBits-1], x}) + $signed((XBits + 1)'((1 << (FX - 1)) - 1));
    first_centre = PCB'($signed(t[XBits:FX]));
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
      logic signed [PCB-1:0] fce;
      // The clipped offset h - X_E: offset < dx when the span is not empty, so its top bits are
      // dropped (the difference is exact modulo 2^(DxBits+2)).
      /* verilator lint_off UNUSEDSIGNAL */
      logic signed [DxBits+1:0]  off_clip;
      /* verilator lint_on UNUSEDSIGNAL */
      logic [FX-1:0]             frac_h, off_frac;
      fce = first_centre(xe_e);
      // offset = x_start + h - X_E (h = 2^(FX-1)), not through x_start's add and clamp: unclipped
      // (fce >= 0, x_start = fce) fce 2^FX = X_E + h - 1 - ((X_E + h - 1) mod 2^FX), so the offset
      // is 2^FX - 1 - ((X_E + h - 1) mod 2^FX), the complement of an FX-bit sum of X_E's fraction
      // bits; clipped (fce < 0, x_start = 0) it is h - X_E. Both run beside fce's sign. A span
      // whose fce is beyond LB bits is empty, so x_start's truncation never mattered here.
      frac_h   = xe_e[FX-1:0] + FX'((1 << (FX - 1)) - 1);
      off_clip = $signed((DxBits + 2)'(1 << (FX - 1))) - $signed({{3{xe_e[XBits-1]}}, xe_e});
      off_frac = ~frac_h;
      s0_q.eol      <= seg_eol_i;
      s0_q.fce      <= fce;
      s0_q.fcf      <= first_centre(xe_f);
      s0_q.poly     <= seg_poly_i;
      s0_q.material <= seg_material_i;
      s0_q.offset   <= fce[PCB-1] ? DxBits'(off_clip) : DxBits'(off_frac);
      s0_dx_q       <= DxBits'($signed({xe_f[XBits-1], xe_f}) - $signed({xe_e[XBits-1], xe_e}));
    end
  end

  // Per slot: E's value and the delta F - E, one bit wider than the slot's word.
  for (genvar c = 1; c <= NI; c++) begin : g_s0
    localparam int unsigned W  = watkins_pkg::slot_bits(c, XBits, ZBits, AttrBits);
    localparam int unsigned In = watkins_pkg::slot_lo(c, XBits, ZBits, AttrBits);
    localparam int unsigned Lo = ilo(c, ZBits, AttrBits);
    localparam int unsigned Dl = ilo(c, ZD, AD);
    always_ff @(posedge clk_i) begin
      if (s0_load) begin
        s0_q.e[Lo +: W]         <= seg_e_i[In +: W];
        s0_q.delta[Dl +: W + 1] <= $signed({seg_f_i[In+W-1], seg_f_i[In +: W]})
                                 - $signed({seg_e_i[In+W-1], seg_e_i[In +: W]});
      end
    end
  end

  // ---------------------------------------------------------------- reciprocal
  logic [RecipBits:0] rc_recip;
  logic [ExpBits-1:0] rc_p;
  span_pre_t          rc_span;

  // LookAhead: the reciprocal's stall is a flop of its own, loaded from tail_en's next value, not
  // tail_en itself (whose fan-out is the whole setup tail; tail_en_q -> a 4.5 ns route ->
  // s0_ready -> the reciprocal's stage enables was the sized Gouraud top's path at f67158a,
  // 10.7 ns, 9.7 of it routing).
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
  // (mul18_reg InReg): the reciprocal's quotient register fans out to every one of them, so
  // a route from it across the die ended at a multiplier's input, the block's 3.5 ns setup after
  // up to 6.4 ns of route (the Phong top's path on seed 2 at 6a98e2c); now it ends at a register.
  // sm: their partial products, in the blocks' output registers. sp: offset * recip's sum, and each
  // delta piece's two step partial products added. sh: alpha0's shift, the steps' sums of their
  // pieces. sb: alpha0 = min(round_shift(offset*recip, p + RecipBits - AlphaBits), 2^AlphaBits)
  // (round_shift by 0 is exact), the steps' shifts. sc: delta * alpha0 as partial products, the
  // steps saturated. sv: each delta piece's two value partial products added. sd: the values.
  // Every product wider than a multiplier block is split at bit MSplit of each operand too wide
  // for one, each partial product registered in its block (mul18_reg) and the partial products
  // summed later (a product and its adder tree in one clock limited the block):
  // x y = x0 y0 + (x0 y1 + x1 y0) 2^MSplit + x1 y1 2^(2 MSplit), the sums taken modulo the
  // product's word as before. recip and alpha0 are unsigned, so their halves are too. A delta cut
  // into K pieces has 2K partial products per slot; they are summed over two stages (sp and sh
  // for a step, sv and sd for a value): first each piece's pair, one two-operand add beside its
  // blocks, then the K pairs (their sum in one clock, six operands from the blocks' registers,
  // was the Phong configuration's longest path: 88.1 MHz). The steps wait two stages for the
  // values anyway, so their extra stage costs no cycle; the values' costs one.
  localparam int unsigned MSplit = 17;  // a low part fits an 18 x 18 multiplier, signed or not
  localparam int unsigned OHi = (DxBits > MSplit) ? DxBits - MSplit : 1;  // offset's high part
  localparam int unsigned RHi = RecipBits + 1 - MSplit;                    // recip's high part
  localparam int unsigned AHi = AlphaBits + 1 - MSplit;                    // alpha0's high part
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
  logic [ShAB-1:0]     sa_sha_q, sm_sha_q, sp_sha_q;  // alpha0's shift p + RecipBits - AlphaBits
  logic [ShSB-1:0]     sa_shs_q, sm_shs_q, sp_shs_q, sh_shs_q;  // the steps' shift p + RecipBits - FX (> 0)
  logic [2*MSplit-1:0]   sm_pa00_q;           // offset * recip: low x low
  logic [MSplit+RHi-1:0] sm_pa01_q;           // low offset x high recip
  logic [OHi+MSplit-1:0] sm_pa10_q;           // high offset x low recip
  logic [OHi+RHi-1:0]    sm_pa11_q;           // high x high (0 for an offset of MSplit bits)
  logic [APBits-1:0]   sp_pa_q;             // offset * recip, unsigned
  logic [AlphaBits:0]  sb_alpha_q;          // alpha0 in [0, 2^AlphaBits]
  // e and delta are spent by the FIFO; keeping one span type is simpler than a third struct.
  /* verilator lint_off UNUSEDSIGNAL */
  span_mid_t           sd_span_q;
  /* verilator lint_on UNUSEDSIGNAL */
  logic [IVB-1:0]      sc_step_q, sv_step_q, sd_step_q;
  logic [IVB-1:0]      sd_value_q;          // E + round_shift(delta * alpha0, AlphaBits) per slot

  logic [MSplit-1:0] rc_r0, sb_a0;  // recip's and alpha0's low parts
  logic [RHi-1:0]    rc_r1;
  logic [AHi-1:0]    sb_a1;
  logic [MSplit-1:0] rc_o0;         // offset's low part (its high part in g_pa_hi)
  assign rc_r0 = MSplit'(rc_recip);
  assign rc_r1 = RHi'(rc_recip >> MSplit);
  assign sb_a0 = MSplit'(sb_alpha_q);
  assign sb_a1 = AHi'(sb_alpha_q >> MSplit);
  assign rc_o0 = MSplit'(rc_span.offset);

  // alpha0 shifts first and rounds after: round_shift(x, s) = (floor(2x / 2^s) + 1) / 2, so the
  // shifter takes the product straight from its register (u = {x, 0} >> s, also exact for s = 0)
  // and the rounding is one increment of the AlphaBits + 1 bits the clamp keeps. The clamp reads
  // the high bits: ra > 2^AlphaBits exactly when u has a bit above ua's, or ua >= 2^AlphaBits
  // with anything below that bit or the rounding bit set; it does not wait for the increment.
  // The shift has its own stage (sh): shift, increment and clamp in one clock were the block's
  // longest path.
  logic [APBits:0]    sh_u_q;

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
  // it in one clock (the sized Phong top's 112 MULT18 spread its setup multipliers far from
  // their fabric registers: 18.6 ns at 4d2bd2c).
  mul18_reg #(.ABits(MSplit), .BBits(MSplit), .InReg(1'b1)) u_pa00 (
    .clk_i, .ce_i({sm_ce, sa_ce}), .a_i(rc_o0), .b_i(rc_r0), .p_o(sm_pa00_q));
  mul18_reg #(.ABits(MSplit), .BBits(RHi), .InReg(1'b1)) u_pa01 (
    .clk_i, .ce_i({sm_ce, sa_ce}), .a_i(rc_o0), .b_i(rc_r1), .p_o(sm_pa01_q));
  if (DxBits > MSplit) begin : g_pa_hi
    logic [OHi-1:0] rc_o1;
    assign rc_o1 = OHi'(rc_span.offset >> MSplit);
    mul18_reg #(.ABits(OHi), .BBits(MSplit), .InReg(1'b1)) u_pa10 (
      .clk_i, .ce_i({sm_ce, sa_ce}), .a_i(rc_o1), .b_i(rc_r0), .p_o(sm_pa10_q));
    mul18_reg #(.ABits(OHi), .BBits(RHi), .InReg(1'b1)) u_pa11 (
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
      sa_sha_q  <= ShAB'(rc_p) + ShAB'(RecipBits) - ShAB'(AlphaBits);
      sa_shs_q  <= ShSB'(rc_p) + ShSB'(RecipBits) - ShSB'(FX);
    end
    if (sm_ce) begin : sm_set
      sm_span_q <= sa_span_q;
      sm_sha_q  <= sa_sha_q;
      sm_shs_q  <= sa_shs_q;
    end
    if (sp_ce) begin : sp_set
      // sp: the pixel range x_start = max(fce, 0), x_end = min(fcf, width), from sm's copy of
      // the span. The clamped ends keep LB bits: beyond them the span is empty. sp registers
      // each compare on its own (its carry chain straight into a flip-flop: the span's copy
      // was placed by the reciprocal's RAM, far from here); sh applies them (sp_xe_clip_q, sp_off_q).
      sp_span_q.eol      <= sm_span_q.eol;
      sp_span_q.empty    <= sm_span_q.fcf <= sm_span_q.fce;
      sp_span_q.poly     <= sm_span_q.poly;
      sp_span_q.material <= sm_span_q.material;
      sp_span_q.xs       <= sm_span_q.fce[PCB-1] ? '0 : LB'(sm_span_q.fce);
      sp_span_q.xe       <= LB'(sm_span_q.fcf);
      sp_span_q.e        <= sm_span_q.e;
      sp_span_q.delta    <= sm_span_q.delta;
      sp_xe_clip_q <= sm_span_q.fcf > $signed(PCB'(width_i));
      // empty = min(fcf, width) <= max(fce, 0), spread into four compares of the unclamped ends
      // (through the clamps it was the block's longest path): fcf <= fce above, the rest here.
      sp_off_q <= {sm_span_q.fcf <= 0, $signed(PCB'(width_i)) <= sm_span_q.fce, width_i == '0};
      sp_sha_q  <= sm_sha_q;
      sp_shs_q  <= sm_shs_q;
      sp_pa_q   <= APBits'({sm_pa11_q, sm_pa00_q}) + (APBits'(sm_pa01_q) << MSplit)
                 + (APBits'(sm_pa10_q) << MSplit);
    end
    if (sh_ce) begin
      sh_span_q       <= sp_span_q;
      sh_span_q.empty <= sp_span_q.empty || (|sp_off_q);
      if (sp_xe_clip_q) sh_span_q.xe <= LB'(width_i);
      sh_shs_q  <= sp_shs_q;
      sh_u_q    <= {sp_pa_q, 1'b0} >> sp_sha_q;
    end
    if (sb_ce) begin : sb_set
      logic [AlphaBits:0] ua;    // floor(x / 2^s), when it is below 2^(AlphaBits + 1)
      logic               over;  // ra > 2^AlphaBits
      ua   = sh_u_q[AlphaBits+1:1];
      over = |sh_u_q[APBits:AlphaBits+2] || (ua[AlphaBits] && (|ua[AlphaBits-1:0] || sh_u_q[0]));
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

  // Per slot: step = saturate(round_shift(delta*recip, p + RecipBits - FX), W) -- the shift uses
  // X's fraction bits (the step per pixel is delta * 2^FX / dx), always > 0; delta * alpha0.
  for (genvar c = 1; c <= NI; c++) begin : g_setup
    localparam int unsigned W  = watkins_pkg::slot_bits(c, XBits, ZBits, AttrBits);
    localparam int unsigned Lo = ilo(c, ZBits, AttrBits);
    localparam int unsigned Dl = ilo(c, ZD, AD);
    localparam int unsigned PS = (c == 1) ? ZPS : APS;
    localparam int unsigned VS = W + AlphaBits;  // the value's sum: W bits above AlphaBits
    localparam logic signed [PS-1:0] StepMax = $signed((PS'(1) << (W - 1)) - PS'(1));
    localparam logic signed [PS-1:0] StepMin = -$signed(PS'(1) << (W - 1));
    // The delta (signed, W + 1 bits) times an unsigned low part ({0, x0}: MSplit + 1 bits) and
    // high part: exact products. A delta wider than a multiplier's signed 18 bits is cut into K
    // pieces too, MSplit unsigned bits each and a signed top, so every partial product is one
    // MULT18 registered straight from it (a 43-bit delta times 18 bits was three multipliers and
    // their LUT adders in one clock, the Phong configuration's longest path).
    localparam int unsigned K   = (W + 1 <= MSplit + 1) ? 1 : (W + MSplit) / MSplit;  // ceil((W+1)/MSplit)
    localparam int unsigned DB  = (K == 1) ? W + 1 : MSplit + 1;  // a piece, signed
    localparam int unsigned Q0B = DB + MSplit + 1;                // piece * low part
    localparam int unsigned Q1B = DB + RHi + 1;                   // piece * recip's high part
    localparam int unsigned QV1B = DB + AHi + 1;                  // piece * alpha0's high part
    localparam int unsigned TW  = W + 1 - MSplit * (K - 1);       // the top piece's bits
    // A piece's pair x_k r0 + x_k r1 2^MSplit (steps) or x_k a0 + x_k a1 2^MSplit (values),
    // exact: one bit above the wider of its two terms.
    localparam int unsigned PSB = ((Q0B > Q1B + MSplit) ? Q0B : Q1B + MSplit) + 1;
    localparam int unsigned PVB = ((Q0B > QV1B + MSplit) ? Q0B : QV1B + MSplit) + 1;
    // The pairs, piece k at k PSB (k PVB), each written in its piece's generate block: the
    // second stage of each sum reads these registers, never a vector of the blocks' outputs
    // (one, assembled from every block's product on every clock, was most of Verilator's cost
    // in this loop).
    logic [K*PSB-1:0]      pps_q;       // in sp
    logic [K*PVB-1:0]      ppv_q;       // in sv
    // Piece k of the delta at bit MSplit k: MSplit unsigned bits, the top one TW signed bits (the
    // multiplier sign-extends it). sa takes the delta leaving the reciprocal (into
    // the blocks' operand registers; the products are sm's), sc the delta in sb; each partial
    // product is one mul18_reg, registered in its block (see u_pa00), and its pair's
    // add reads the two blocks' outputs straight.
    for (genvar k = 0; k < K; k++) begin : g_piece
      localparam bit          Top = (k == K - 1);
      localparam int unsigned PB  = Top ? TW : MSplit;
      logic [Q0B-1:0]  ps0, pv0;  // x_k times the low part of recip / alpha0
      logic [Q1B-1:0]  ps1;       // x_k times recip's high part
      logic [QV1B-1:0] pv1;       // x_k times alpha0's high part
      mul18_reg #(.ABits(PB), .ASigned(Top), .BBits(MSplit), .PBits(Q0B), .InReg(1'b1)) u_ps0 (
        .clk_i, .ce_i({sm_ce, sa_ce}), .a_i(rc_span.delta[Dl + MSplit*k +: PB]), .b_i(rc_r0),
        .p_o(ps0));
      mul18_reg #(.ABits(PB), .ASigned(Top), .BBits(RHi), .PBits(Q1B), .InReg(1'b1)) u_ps1 (
        .clk_i, .ce_i({sm_ce, sa_ce}), .a_i(rc_span.delta[Dl + MSplit*k +: PB]), .b_i(rc_r1),
        .p_o(ps1));
      mul18_reg #(.ABits(PB), .ASigned(Top), .BBits(MSplit), .PBits(Q0B)) u_pv0 (
        .clk_i, .ce_i(sc_ce), .a_i(sb_span_q.delta[Dl + MSplit*k +: PB]), .b_i(sb_a0), .p_o(pv0));
      mul18_reg #(.ABits(PB), .ASigned(Top), .BBits(AHi), .PBits(QV1B)) u_pv1 (
        .clk_i, .ce_i(sc_ce), .a_i(sb_span_q.delta[Dl + MSplit*k +: PB]), .b_i(sb_a1), .p_o(pv1));
      // The pairs' adds inside their stages' enables (see below).
      always_ff @(posedge clk_i) begin
        if (sp_ce) pps_q[k*PSB +: PSB] <= PSB'($signed(ps0)) + (PSB'($signed(ps1)) << MSplit);
        if (sv_ce) ppv_q[k*PVB +: PVB] <= PVB'($signed(pv0)) + (PVB'($signed(pv1)) << MSplit);
      end
    end
    logic signed [PS-1:0]  ps_q;        // delta * recip, in sh
    // Shift first, round after, as alpha0: u = {x, 0} >>> s = floor(x / 2^(s-1)) (s > 0), and
    // rs = floor((u + 1) / 2) = (u >>> 1) + u[0]. Saturate from u's high bits: when u >>> 1
    // does not fit W bits, rs saturates to its sign (below the range, + u[0] reaches at most
    // StepMin); when it fits, only StepMax + 1 leaves the range, so StepMax is picked there. The
    // W-bit increment (by u[0] alone) runs beside the tests, which pick among it and the bounds:
    // the test for StepMax in the increment's carry-in was the Phong block's longest path
    // (u_q -> at_max -> the carry chain -> sc_step_q, 10.3 ns).
    logic signed [PS:0] u_q;            // in sb
    // Every value below is computed inside its stage's enable (sa_ce .. sd_ce), not in an
    // always_comb or assign that only feeds it: the same logic, evaluated by a simulator only
    // when a span passes.
    always_ff @(posedge clk_i) begin
      if (sh_ce) begin : sh_sum
        // The pieces' pairs at bit MSplit k, summed modulo the product's word as before.
        logic signed [PS-1:0] sum;
        sum = '0;
        for (int k = 0; k < K; k++) sum = sum + (PS'($signed(pps_q[k*PSB +: PSB])) << (MSplit * k));
        ps_q <= sum;
      end
      if (sb_ce) u_q <= $signed({ps_q, 1'b0}) >>> sh_shs_q;
      if (sc_ce) begin : sc_sat
        logic fits, at_max;
        logic [W-1:0] inc;
        fits   = &u_q[PS:W] || ~|u_q[PS:W];
        at_max = !u_q[W] && &u_q[W-1:1];  // u >>> 1 = StepMax: the increment would leave the range
        inc    = u_q[W:1] + W'(u_q[0]);
        if (!fits) sc_step_q[Lo +: W] <= u_q[PS] ? W'(StepMin) : W'(StepMax);
        else if (at_max) sc_step_q[Lo +: W] <= W'(StepMax);
        else sc_step_q[Lo +: W] <= inc;
      end
      if (sd_ce) begin : sd_sum
        // value = wrap(E + ((pv + 2^(AlphaBits-1)) >> AlphaBits), W) = bits [AlphaBits +: W] of
        // pv + (E 2^AlphaBits + 2^(AlphaBits-1)): E and the rounding constant are one operand
        // (their bits do not overlap), added with the pieces' pairs in sd, so the FIFO's input
        // is a register. Sums modulo 2^VS keep those bits.
        /* verilator lint_off UNUSEDSIGNAL */
        logic [VS-1:0] sum;
        /* verilator lint_on UNUSEDSIGNAL */
        sum = {sv_span_q.e[Lo +: W], 1'b1, (AlphaBits - 1)'(0)};
        for (int k = 0; k < K; k++) sum = sum + (VS'($signed(ppv_q[k*PVB +: PVB])) << (MSplit * k));
        sd_value_q[Lo +: W] <= W'(sum >> AlphaBits);
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
  // were the block's longest paths, 10.4 ns at Phong, 9.5 ns at Gouraud).
  typedef struct packed {
    logic                  eol;
    logic                  more;    // a pixel after xs: xs + 1 != xe
    logic [PolyIdBits-1:0] poly;
    logic [MIB-1:0]        material;
    logic [LB-1:0]         xs;
    logic [LB-1:0]         xe;
    logic [DepB-1:0]       depth;   // pixel xs's readings (g_frag)
    logic [3*8-1:0]        rgb;
    logic [3*NB-1:0]       normal;
    logic [IVB-1:0]        value1;  // slots Z.. at pixel xs + 1 (wrapped as the stepper wraps)
    logic [IVB-1:0]        step;    // per-pixel increments
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
  // From its compare it reached the reciprocal's and s0's clock enables across the block (the
  // sized Gouraud top's critical path at 0129076: `sd_valid_q` -> `tail_en` -> 4.5 ns route ->
  // `s0_ready` -> `s0_load` -> s0's enables, 12.0 ns, 10.6 of it routing).
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
  // flops: one enable reaching every frag_* and st_* flop was the sized Phong top's critical path
  // on nextpnr seed 2 at 14f3c10 (st_active_q -> the FIFO's pop -> emit_frag -> a 4.6 ns route
  // back to st_active_q's clock enable, 12.2 ns). Each copy's next state is computed from the
  // copy itself, so the copies are not identical logic and yosys keeps them apart (opt_merge
  // merges flops and LUTs of equal inputs, a (* keep *) on their wires notwithstanding).
  localparam int unsigned CpCtl  = 0;  // st_active_q's own state, frag_valid_o, st_x/xe/poly/material
  localparam int unsigned CpFrag = 1;  // the frag_* outputs
  localparam int unsigned CpVal  = 2;  // st_value_q, st_step_q
  localparam int unsigned CpHead = 3;  // the FIFO's ready (its pop)
  localparam int unsigned NumCp  = 4;
  logic [NumCp-1:0]      st_active_q;  // all equal (a_st_copies)
  logic [LB-1:0]         st_x_q, st_xe_q;
  logic [PolyIdBits-1:0] st_poly_q;
  logic [MIB-1:0]        st_material_q;
  logic [IVB-1:0]        st_value_q, st_step_q;

  logic                  out_free, head_frag, head_eol;
  logic [NumCp-1:0]      emit_frag;    // per copy: a fragment leaves into frag_*_o
  logic                  emit_eol;     // a marker does
  logic                  st_more;      // a pixel after st_x_q in the stepper's span
  logic [IVB-1:0]        st_value1, hd_value1;  // the stepper's value + step; sd's, into the FIFO

  assign out_free  = !frag_valid_o || frag_ready_i;
  assign head_frag = f_out_valid && !f_out.eol;  // the head is a span
  assign head_eol  = f_out_valid && f_out.eol;
  for (genvar i = 0; i < NumCp; i++) begin : g_cp
    assign emit_frag[i] = out_free && (st_active_q[i] || head_frag);
    always_ff @(posedge clk_i) begin
      if (!rst_ni) st_active_q[i] <= 1'b0;
      else if (emit_frag[i]) st_active_q[i] <= st_active_q[i] ? st_more : f_out.more;
    end
  end
  assign emit_eol    = out_free && !st_active_q[CpFrag] && head_eol;
  // The head leaves when the stepper is idle and the output free (a span's first pixel, or a
  // marker); a pop needs the FIFO's valid as well, which the FIFO adds.
  assign f_out_ready = out_free && !st_active_q[CpHead];

  // Per slot: the next pixel's value (wrapping at the slot's word) and the fragment's readings:
  // depth = clamp(round_shift(Z, ZFracBits), 0, 2^DepthBits - 1); shade = clamp(round_shift(v,
  // AttrFracBits), 0, 255); normal = v rescaled to FracBits fraction bits (round_shift when
  // AttrFracBits is larger, a left shift when smaller), saturated to NormalInBits.
  logic [DepB-1:0]   depth_d;
  logic [3*8-1:0]    rgb_d;      // {B, G, R} by slot
  logic [3*NB-1:0]   normal_d;   // {Nz, Ny, Nx}
  logic [2*DepB-1:0] depth_src;  // per source: {the span entering the FIFO, stepper}
  logic [2*3*8-1:0]  rgb_src;
  logic [2*3*NB-1:0] normal_src;
  for (genvar c = 1; c <= NI; c++) begin : g_frag
    localparam int unsigned W  = watkins_pkg::slot_bits(c, XBits, ZBits, AttrBits);
    localparam int unsigned F  = (c == 1) ? ZFracBits : AttrFracBits;
    localparam int unsigned Lo = ilo(c, ZBits, AttrBits);
    localparam int unsigned HiBits = (c == 1) ? DepB : 8;   // output level width
    // The rounded integer part, and a width that holds it and the level's maximum.
    localparam int unsigned RB = W + 1 - F;
    localparam int unsigned CW = (RB > HiBits + 1) ? RB : HiBits + 1;
    assign st_value1[Lo +: W] = st_value_q[Lo +: W] + st_step_q[Lo +: W];
    assign hd_value1[Lo +: W] = sd_value_q[Lo +: W] + sd_step_q[Lo +: W];
    // The readings of both sources, the stepper's registers (s = 0) and the span entering the
    // FIFO (s = 1, sd's value: stored, they come out at the head with the span); st_active_q
    // picks among the readings, after the rounding add and the clamp (before them, its fan-out
    // to every value bit and the FIFO's read were in series with that add).
    for (genvar s = 0; s < 2; s++) begin : g_src
      logic signed [W-1:0] v;
      /* verilator lint_off UNUSEDSIGNAL */
      logic signed [W:0]   t;  // fraction bits are rounded away
      /* verilator lint_on UNUSEDSIGNAL */
      logic signed [CW-1:0] r;
      logic [CW-2:0]       mag;  // r without its sign
      logic [HiBits-1:0]   level;
      assign v = (s == 0) ? st_value_q[Lo +: W] : sd_value_q[Lo +: W];
      if (F > 0) begin : g_round
        assign t = $signed({v[W-1], v}) + $signed((W + 1)'(1) << (F - 1));
      end else begin : g_exact
        assign t = $signed({v[W-1], v});
      end
      assign r = CW'($signed(t[W:F]));
      // clamp(r, 0, 2^HiBits - 1) from r's bits, not through two compares after the rounding add:
      // below 0 when the sign is set, above the maximum when a bit above the level's is set.
      assign mag   = r[CW-2:0];
      assign level = r[CW-1] ? '0 : (|(mag >> HiBits)) ? {HiBits{1'b1}} : HiBits'(mag);
      if (c == 1) begin : g_depth
        assign depth_src[s*DepB +: DepB] = level;
      end else begin : g_attr
        assign rgb_src[s*24 + (c - 2)*8 +: 8] = level;
        // Normal: FracBits fraction bits out of F.
        localparam int unsigned FB = watkins_pkg::FracBits;
        localparam int unsigned NW = (F >= FB) ? W + 1 - (F - FB) : W + (FB - F);  // rescaled width
        localparam int unsigned SW = (NW > NB) ? NW : NB;                           // compare width
        logic signed [NW-1:0] n;
        logic signed [SW-1:0] ns;
        logic [SW-NB:0]       ns_hi;  // all equal: ns fits NB bits
        if (F > FB) begin : g_down
          /* verilator lint_off UNUSEDSIGNAL */
          logic signed [W:0] tn;
          /* verilator lint_on UNUSEDSIGNAL */
          assign tn = $signed({v[W-1], v}) + $signed((W + 1)'(1) << (F - FB - 1));
          assign n  = tn[W:F-FB];
        end else if (F == FB) begin : g_same
          assign n = $signed({v[W-1], v});
        end else begin : g_up
          assign n = $signed({v, (FB - F)'(0)});
        end
        assign ns    = SW'(n);
        assign ns_hi = ns[SW-1:NB-1];
        // Saturate to NB bits from the bits above them, not through two compares.
        assign normal_src[s*3*NB + (c - 2)*NB +: NB] =
            (&ns_hi || ~|ns_hi) ? NB'(ns)
          : ns[SW-1]            ? NB'(64'd1 << (NB - 1))
          :                       NB'((64'd1 << (NB - 1)) - 1);
      end
    end
  end
  // The readings of the fragment, picked by the CpFrag copy after the rounding and the clamp.
  assign st_more  = (st_x_q + 1'b1 != st_xe_q);
  assign depth_d  = st_active_q[CpFrag] ? depth_src[0 +: DepB]  : f_out.depth;
  assign rgb_d    = st_active_q[CpFrag] ? rgb_src[0 +: 24]      : f_out.rgb;
  assign normal_d = st_active_q[CpFrag] ? normal_src[0 +: 3*NB] : f_out.normal;

  // The FIFO's input: sd's span with the head's readings and next value computed from it.
  assign f_in.eol      = sd_span_q.eol;
  assign f_in.more     = (sd_span_q.xs + 1'b1 != sd_span_q.xe);
  assign f_in.poly     = sd_span_q.poly;
  assign f_in.material = sd_span_q.material;
  assign f_in.xs       = sd_span_q.xs;
  assign f_in.xe       = sd_span_q.xe;
  assign f_in.depth    = depth_src[DepB +: DepB];
  assign f_in.rgb      = rgb_src[24 +: 24];
  assign f_in.normal   = normal_src[3*NB +: 3*NB];
  assign f_in.value1   = hd_value1;
  assign f_in.step     = sd_step_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) frag_valid_o <= 1'b0;
    else if (out_free) frag_valid_o <= st_active_q[CpCtl] || f_out_valid;  // a fragment or a marker
  end

  // Each group from its own copy: the picks and the enable.
  always_ff @(posedge clk_i) begin
    if (emit_frag[CpFrag]) begin
      frag_x_o        <= st_active_q[CpFrag] ? st_x_q : f_out.xs;
      frag_depth_o    <= depth_d;
      frag_rgb_o.r    <= rgb_d[0 +: 8];
      frag_rgb_o.g    <= rgb_d[8 +: 8];
      frag_rgb_o.b    <= rgb_d[16 +: 8];
      frag_normal_o   <= normal_d;
      frag_poly_o     <= st_active_q[CpFrag] ? st_poly_q : f_out.poly;
      frag_material_o <= st_active_q[CpFrag] ? st_material_q : f_out.material;
      frag_eol_o      <= 1'b0;
    end else if (emit_eol) begin
      frag_eol_o      <= 1'b1;
    end
    if (emit_frag[CpCtl]) begin
      st_x_q        <= (st_active_q[CpCtl] ? st_x_q : f_out.xs) + 1'b1;
      st_xe_q       <= st_active_q[CpCtl] ? st_xe_q : f_out.xe;
      st_poly_q     <= st_active_q[CpCtl] ? st_poly_q : f_out.poly;
      st_material_q <= st_active_q[CpCtl] ? st_material_q : f_out.material;
    end
    if (emit_frag[CpVal]) begin
      // The next pixel's value, for each source and picked after the add (the pick before the
      // add was the Gouraud block's limit).
      st_value_q <= st_active_q[CpVal] ? st_value1 : f_out.value1;
      st_step_q  <= st_active_q[CpVal] ? st_step_q : f_out.step;
    end
  end

  `WATKINS_ASSERT_HOLD(a_in_hold, seg_valid_i, seg_ready_o, {seg_e_i, seg_f_i, seg_poly_i, seg_material_i,
    seg_eol_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, frag_valid_o, frag_ready_i, {frag_x_o, frag_depth_o, frag_rgb_o,
    frag_normal_o, frag_poly_o, frag_material_o, frag_eol_o})
  `WATKINS_ASSERT(a_x_on_screen, frag_valid_o && !frag_eol_o |-> frag_x_o < width_i)
  `WATKINS_COVER(c_back_to_back_spans, emit_frag[CpCtl] && !st_active_q[CpCtl] && frag_valid_o
    && !frag_eol_o)
  `WATKINS_ASSERT(a_st_copies, st_active_q == {NumCp{st_active_q[CpCtl]}})
  `WATKINS_COVER(c_empty_dropped, sd_valid_q && !sd_keep)
  `WATKINS_ASSERT(a_tail_en, tail_en == (!sd_valid_q || !sd_keep || f_in_ready))
  // The head's stored flag is what the stepper would compare there (the other stored fields
  // are checked by every co-simulation's fragments).
  `WATKINS_ASSERT(a_head_more, f_out_valid && !f_out.eol
    |-> f_out.more == (f_out.xs + 1'b1 != f_out.xe))
endmodule
