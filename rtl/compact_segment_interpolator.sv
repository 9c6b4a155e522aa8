// compact_segment_interpolator: segment_interpolator's span setup and alpha stepping with one
// iterative reciprocal, one multiplier stepped through the channels and one adder per channel,
// for small parts: the same fragments, value for value and in the same order (model/twins/
// segment_interpolator.cpp setup(), fragment(), step()); only the clocks differ. Every output and
// every arithmetic stage is registered; seg_ready_o comes from flops. Cycle model:
// model/twins/compact_segment_interpolator_timing.hpp. Units, each holding one item:
// - Offer (pk_*): the offered item is classified on its first clock (a marker, an empty span, a
//   span that needs 1/dx); the offer holds while valid and not ready, so the divider and the
//   take read it on the port.
// - Divider (d_*): 1/dx of the offered span before it is taken: latches dx and its leading one
//   on the offer's first clock, normalizes (shifts) on the next, then Iterations =
//   ceil((RecipBits + 1) / QuotientBitsPerClock) clocks of restoring steps; the quotient is
//   then held (d_done_q) until the take.
// - Setup (m_*): takes the offered item when it is idle and its head is empty, a span only with
//   its reciprocal done (seg_ready_o). An empty span is dropped at the take; a marker goes
//   straight to the head. A span loads its operands and its head's range, ids and E, then
//   issues nine multiplications in order -- alpha0's offset * recip, the four steps delta * recip,
//   the four values delta * alpha0 -- one DigitBits-bit digit of the unsigned operand per clock
//   (the sign handled apart), IssueClocks = OffsetDigits + 2 (ZDigits + 3 AttrDigits) clocks,
//   through stages o (operands), p (the digit's product, DigitBits x (RecipBits + 1)), x (the
//   digit sums), s (the rounding shift) and w (round, clamp, write the head).
// - Stepper (st_*): loads the head when idle (one clock, no fragment), or on the clock it emits
//   its span's last beat (no bubble between spans); one beat per clock while frag_ready_i
//   allows. A marker leaves from the head when the stepper is idle.
// Lanes: a beat carries up to Lanes fragments of one span. At 2 a span's beats are its pixels in
// pairs from x_start, lane 0 at x (the frag_* ports), lane 1 at x + 1 (frag_pair_o, frag_depth1_o,
// frag_rgb1_o; poly and material lane 0's); a span of an odd pixel count ends with a beat of lane
// 0 alone, and a marker's beat has frag_pair_o = 0. Lane 1's value is the stepper's value plus
// one step, read through its own copy of the rounding and clamping; the stepper advances by two
// steps in one add of the step shifted left by one (both wrap like the slot's register).
// At 1 frag_pair_o, frag_depth1_o and frag_rgb1_o are constant 0 and no lane-1 logic exists.
// Latency: with every unit idle, a span offered at clock t is taken at t + 2 + Iterations and
// its first fragment is on frag_*_o at the take + IssueClocks + 7 (t + 32 at the sized default
// configuration: Iterations 13, IssueClocks 10); a marker at t + 3.
// Throughput: one span per max(IssueClocks + 6, Iterations + 3) clocks (16 at the sized default
// configuration) while spans are shorter, one beat (Lanes fragments) per clock while they are
// longer; an empty span or a marker takes 2 clocks of the setup.
// FifoDepth is accepted for the drop-in and unused: the head is the one span queued.
`include "watkins_assert.svh"

module compact_segment_interpolator #(
  /* verilator lint_off UNUSEDPARAM */
  parameter int unsigned FifoDepth      = 4,  // segment_interpolator's; no FIFO here
  /* verilator lint_on UNUSEDPARAM */
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
  parameter int unsigned Lanes          = 1,  // fragments per beat: 1, or 2 (then AttrOut = 0)
  parameter int unsigned QuotientBitsPerClock = 2,  // restoring steps per divider clock
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
  output logic                                   frag_pair_o,      // lane 1 holds the fragment
                                                                   // at frag_x_o + 1
  output logic [DepthBits-1:0]                   frag_depth1_o,    // lane 1's depth
  output watkins_pkg::rgb_t                      frag_rgb1_o,      // lane 1's Gouraud shade
  output logic                                   frag_valid_o,
  input  logic                                   frag_ready_i
);
  localparam int unsigned LineBits          = watkins_pkg::LineBits;
  localparam int unsigned RecipBits         = watkins_pkg::RecipBits;
  localparam int unsigned AlphaBits         = watkins_pkg::AlphaBits;
  localparam int unsigned InterpolatedSlots = watkins_pkg::NumChannels - 1;  // slots Z.. (not X)
  localparam int unsigned DxBits            = XBits + 1;                // dx, offset (unsigned)
  localparam int unsigned ExponentBits      = $clog2(DxBits);           // p = floor(log2 dx)
  localparam int unsigned XPixelBits        = XBits + 1 - XFracBits;    // signed pixel index
  localparam int unsigned PixelCompareBits  = (XPixelBits > LineBits + 1) ? XPixelBits
                                                                          : LineBits + 1;
  localparam int unsigned NormalBits        = watkins_pkg::NormalInBits;
  localparam int unsigned InterpVectorBits  = ZBits + 3 * AttrBits;     // slots Z..
  localparam int unsigned MagVectorBits     = ZBits + 1 + 3 * (AttrBits + 1);  // |delta| per slot

  // Interpolated vectors: slot c (1..4) at ilo(c, zw, aw), Z zw bits wide, each attribute aw.
  function automatic int unsigned ilo(int unsigned c, int unsigned zw, int unsigned aw);
    ilo = (c == 1) ? 0 : zw + (c - 2) * aw;
  endfunction
  function automatic int unsigned max2(int unsigned a, int unsigned b);
    max2 = (a > b) ? a : b;
  endfunction

  // ---------------------------------------------------------------- the offered segment
  // First pixel whose centre is at or right of X: ceil(X - 1/2), as segment_interpolator.
  function automatic logic signed [PixelCompareBits-1:0] first_centre(
      logic signed [XBits-1:0] x);
    /* verilator lint_off UNUSEDSIGNAL */
    logic signed [XBits:0] t;
    /* verilator lint_on UNUSEDSIGNAL */
    t = $signed({x[XBits-1], x}) + $signed((XBits + 1)'((1 << (XFracBits - 1)) - 1));
    first_centre = PixelCompareBits'($signed(t[XBits:XFracBits]));
  endfunction

  logic signed [XBits-1:0]            in_xe, in_xf;  // X of E and F
  logic signed [PixelCompareBits-1:0] in_fce, in_fcf;
  logic                               in_empty;      // no pixel centre on screen
  logic                               in_recip;      // a span that needs 1/dx

  assign in_xe    = seg_e_i[0 +: XBits];
  assign in_xf    = seg_f_i[0 +: XBits];
  assign in_fce   = first_centre(in_xe);
  assign in_fcf   = first_centre(in_xf);
  // min(fcf, width) <= max(fce, 0), in compares of the unclamped ends.
  assign in_empty = (in_fcf <= in_fce) || (in_fcf <= 0)
                 || ($signed(PixelCompareBits'(width_i)) <= in_fce) || (width_i == '0);
  assign in_recip = !seg_eol_i && !in_empty;

  // ---------------------------------------------------------------- divider
  // recip = floor(2^(2R-1) / m), p = floor(log2 dx), m = dx normalized to R bits (span_
  // reciprocal's mantissa): long division from the partial remainder 2^(R-2) that the dividend
  // leaves before quotient bit R, one restoring step per quotient bit, Iterations * Q steps in
  // all; the ExtraBits steps past bit 0 extend the quotient below it, and floor(floor(x 2^e) /
  // 2^e) = floor(x) drops them exactly.
  localparam int unsigned Q              = QuotientBitsPerClock;
  localparam int unsigned Iterations     = (RecipBits + 1 + Q - 1) / Q;
  localparam int unsigned QuotientBits   = Iterations * Q;
  localparam int unsigned ExtraBits      = QuotientBits - (RecipBits + 1);
  localparam int unsigned IterBits       = $clog2(Iterations + 1);
  localparam int unsigned NormalizedBits = (DxBits > RecipBits) ? DxBits : RecipBits;
  localparam int unsigned ShiftBits      = $clog2(NormalizedBits);

  logic                    d_run_q, d_done_q;  // a reciprocal under way; its quotient ready
  logic [IterBits-1:0]     d_iter_q;                     // restoring clocks left
  logic [DxBits-1:0]       d_dx_q;
  // d_dx_q's leading one: p and the normalizing shift, latched with it, so the normalize clock
  // only shifts (the leading-one search and the shift in one clock are the UP5K's longest path).
  logic [ExponentBits-1:0] d_lead_p_q;
  logic [ShiftBits-1:0]    d_lead_sh_q;
  logic [RecipBits-1:0]    d_m_q;
  logic [RecipBits:0]      d_rem_q;  // partial remainder in [-m, m), signed
  logic [QuotientBits-1:0] d_quo_q;
  logic [ExponentBits-1:0] d_p_q;
  logic [RecipBits:0]      d_recip;
  logic                    take;  // the setup takes the offered item
  logic                    pk_seen_q, pk_recip_q;  // the offer classified; it needs 1/dx

  function automatic logic [ExponentBits+ShiftBits-1:0] lead_of(logic [DxBits-1:0] dx);
    logic [ExponentBits-1:0] lead;
    logic [ShiftBits-1:0]    lead_sh;
    lead    = '0;
    lead_sh = ShiftBits'(NormalizedBits - 1);
    for (int i = 0; i < DxBits; i++) begin
      if (dx[i]) begin
        lead    = ExponentBits'(i);
        lead_sh = ShiftBits'(NormalizedBits - 1 - i);
      end
    end
    lead_of = {lead, lead_sh};
  endfunction

  // The divider normalizes on the clock after the offer's first (its classification in flops),
  // from dx latched on that first clock: the offer's compares do not reach its enables.
  logic d_norm;
  assign d_norm = !d_run_q && pk_seen_q && pk_recip_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni || take) begin
      d_run_q  <= 1'b0;
      d_done_q <= 1'b0;
    end else if (d_norm) begin
      d_run_q  <= 1'b1;
    end else if (d_run_q && !d_done_q && d_iter_q == IterBits'(1)) begin
      d_done_q <= 1'b1;
    end
  end
  always_ff @(posedge clk_i) begin
    if (!d_run_q) begin : d_latch
      logic [DxBits-1:0] dx;
      dx = DxBits'($signed({in_xf[XBits-1], in_xf}) - $signed({in_xe[XBits-1], in_xe}));
      d_dx_q                    <= dx;
      {d_lead_p_q, d_lead_sh_q} <= lead_of(dx);
    end
    if (d_norm) begin : d_normalize
      d_p_q    <= d_lead_p_q;
      d_m_q    <= RecipBits'((NormalizedBits'(d_dx_q) << d_lead_sh_q)
                             >> (NormalizedBits - RecipBits));
      d_rem_q  <= (RecipBits + 1)'(1) << (RecipBits - 2);
      d_quo_q  <= '0;
      d_iter_q <= IterBits'(Iterations);
    end else if (d_run_q && !d_done_q) begin : d_steps
      // Non-restoring steps: r = 2 r - m when r >= 0, 2 r + m when r < 0, quotient bit r >= 0.
      // The bits are the restoring divider's (its remainder is r, or r + m when r < 0), and a
      // step is one add whose operand the previous sign inverts: no compare and pick after it.
      // The sum modulo 2^(RecipBits+1): the new r lies in [-m, m).
      logic [RecipBits:0]      r;
      logic [QuotientBits-1:0] quo;
      r   = d_rem_q;
      quo = d_quo_q;
      for (int i = 0; i < Q; i++) begin
        r   = {r[RecipBits-1:0], 1'b0} + ({1'b0, d_m_q} ^ {(RecipBits + 1){!r[RecipBits]}})
            + (RecipBits + 1)'(!r[RecipBits]);
        quo = {quo[QuotientBits-2:0], !r[RecipBits]};
      end
      d_rem_q  <= r;
      d_quo_q  <= quo;
      d_iter_q <= d_iter_q - 1'b1;
    end
  end
  assign d_recip = d_quo_q[ExtraBits +: RecipBits + 1];

  // ---------------------------------------------------------------- setup
  // Multiplications one DigitBits-bit digit of the unsigned operand per clock, least significant
  // first: p = digit * B (B = recip or alpha0, unsigned), x = the running sum, its low digit
  // shifted out into x_lo_q. A negative delta multiplies ~delta = |delta| - 1 with the sum
  // started at B - 1, so x holds |delta| B - 1 = Q, and the product -|delta| B is ~Q: the s stage
  // shifts {Q, 1} and inverts (floor(-2P / 2^s) = ~floor((2P - 1) / 2^s)), the value adds ~Q.
  localparam int unsigned DigitBits    = 16;  // an SB_MAC16's operand
  localparam int unsigned BBits        = max2(RecipBits, AlphaBits) + 1;
  localparam int unsigned ProductBits  = DigitBits + BBits;
  localparam int unsigned SumBits      = ProductBits + 2;  // signed running sum
  localparam int unsigned OffsetDigits = (DxBits + DigitBits - 1) / DigitBits;
  localparam int unsigned ZDigits      = (ZBits + 1 + DigitBits - 1) / DigitBits;
  localparam int unsigned AttrDigits   = (AttrBits + 1 + DigitBits - 1) / DigitBits;
  localparam int unsigned MaxDigits    = max2(OffsetDigits, max2(ZDigits, AttrDigits));
  localparam int unsigned OperandBits  = MaxDigits * DigitBits;
  localparam int unsigned LoBits       = DigitBits * ((MaxDigits > 1) ? MaxDigits - 1 : 1);
  localparam int unsigned DigitIdxBits = (MaxDigits > 1) ? $clog2(MaxDigits) : 1;
  // The signed product (or Q): any operand below 2^max(DxBits, ZBits, AttrBits) times B.
  localparam int unsigned QBits        = max2(DxBits, max2(ZBits, AttrBits)) + BBits + 1;
  // The s stage's window: the bits of u the w stage reads -- alpha0's AlphaBits + 2 (u and its
  // rounding bit), a step's SlotBits + 1 -- and two above it that keep u's sign and whether
  // every bit of u above the window equals it, which is all a saturation test asks of them.
  localparam int unsigned MaxSlotBits  = max2(ZBits, AttrBits);
  localparam int unsigned WindowBits   = max2(AlphaBits + 2, MaxSlotBits + 1);
  localparam int unsigned UBits        = WindowBits + 2;
  // The shifter's operand, sign-extended so that every level's slice lies inside it.
  localparam int unsigned ShiftInBits  = max2(QBits + 2, WindowBits + (1 << ExponentBits) - 1);
  // The s stage's constant shifts: alpha0 by p + RecipBits - AlphaBits, a step by
  // p + RecipBits - XFracBits; p is the shifter's amount.
  localparam int unsigned AlphaShift   = RecipBits - AlphaBits;
  localparam int unsigned StepShift    = RecipBits - XFracBits;
  localparam int unsigned Ops          = 9;  // alpha0, steps of slots 1..4, values of slots 1..4
  localparam int unsigned OpBits       = 4;

  logic                       m_busy_q;    // issuing or finishing a span's operations
  logic [OpBits-1:0]          m_op_q;      // the operation issued next (Ops: all issued)
  logic [DigitIdxBits-1:0]    m_dig_q;     // its digit
  logic [DxBits-1:0]          m_offset_q;  // x_start + 1/2 - X_E >= 0, X units
  // per slot (ilo(c, ZBits + 1, AttrBits + 1)): F - E, or ~(F - E) = |F - E| - 1 when negative
  logic [MagVectorBits-1:0]   m_mag_q;
  logic [InterpolatedSlots:1] m_neg_q;     // F - E < 0 per slot
  logic [RecipBits:0]         m_recip_q;
  logic [ExponentBits-1:0]    m_p_q;
  logic [AlphaBits:0]         m_alpha_q;   // alpha0 in [0, 2^AlphaBits], written by op 0

  // The head: the span the stepper loads next (range, ids, value at x_start, steps), or a marker.
  logic                        h_valid_q, h_eol_q;
  logic [LineBits-1:0]         h_xs_q, h_xe_q;
  logic [PolyIdBits-1:0]       h_poly_q;
  logic [MaterialIdBits-1:0]   h_material_q;
  logic [InterpVectorBits-1:0] h_value_q, h_step_q;
  logic                        h_pop;  // the stepper takes the head

  // The offered item is classified on its first clock (pk_seen_q, pk_recip_q), so seg_ready_o
  // and the take are functions of flops: from the offer's compares they would run into every
  // clock enable of the take (the block's longest path).
  always_ff @(posedge clk_i) begin
    if (!rst_ni || take) pk_seen_q <= 1'b0;
    else if (seg_valid_i) pk_seen_q <= 1'b1;
    if (!pk_seen_q) pk_recip_q <= in_recip;
  end
  assign seg_ready_o = pk_seen_q && !m_busy_q && !h_valid_q && (d_done_q || !pk_recip_q);
  assign take        = seg_valid_i && seg_ready_o;

  // Per operation: its digits, and whether its operand is negative.
  function automatic logic [DigitIdxBits-1:0] last_digit(logic [OpBits-1:0] op);
    if (op == 0) last_digit = DigitIdxBits'(OffsetDigits - 1);
    else if (op == 1 || op == 5) last_digit = DigitIdxBits'(ZDigits - 1);
    else last_digit = DigitIdxBits'(AttrDigits - 1);
  endfunction
  function automatic logic [2:0] op_slot(logic [OpBits-1:0] op);  // 0: the offset
    op_slot = (op > 4) ? 3'(op - 4'd4) : 3'(op);
  endfunction

  // o: the operation's digit and B, registered beside the multiplier; p: the product.
  logic                    o_valid_q, o_first_q, o_last_q, o_neg_q;
  logic [OpBits-1:0]       o_op_q;
  logic [DigitBits-1:0]    o_a_q;
  logic [BBits-1:0]        o_b_q;
  logic                    p_valid_q, p_first_q, p_last_q, p_neg_q;
  logic [OpBits-1:0]       p_op_q;
  logic [ProductBits-1:0]  p_prod_q;
  logic signed [BBits:0]   p_init_q;
  // x: the running sum, its digits shifted out, and the finished Q.
  logic signed [SumBits-1:0] x_hi_q;
  logic [LoBits-1:0]         x_lo_q;
  logic                      x_valid_q, x_neg_q;
  logic [OpBits-1:0]         x_op_q;
  logic signed [QBits-1:0]   x_q_q;
  // s: the shifted product (alpha0, steps) or Q (values), inverted for a negative delta.
  logic                      s_valid_q;
  logic [OpBits-1:0]         s_op_q;
  logic signed [UBits-1:0]   s_u_q;

  logic issue;
  assign issue = m_busy_q && m_op_q != OpBits'(Ops);

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      m_busy_q  <= 1'b0;
      o_valid_q <= 1'b0;
      p_valid_q <= 1'b0;
      x_valid_q <= 1'b0;
      s_valid_q <= 1'b0;
    end else begin
      if (take && pk_recip_q) m_busy_q <= 1'b1;
      else if (s_valid_q && s_op_q == OpBits'(Ops - 1)) m_busy_q <= 1'b0;
      o_valid_q <= issue;
      p_valid_q <= o_valid_q;
      x_valid_q <= p_valid_q && p_last_q;
      s_valid_q <= x_valid_q;
    end
  end

  // The take: operands, the head's range, ids and E (the values' sums start from E).
  always_ff @(posedge clk_i) begin
    if (take) begin : m_take
      logic [XFracBits-1:0]     frac_h, off_frac;
      /* verilator lint_off UNUSEDSIGNAL */
      logic signed [DxBits+1:0] off_clip;
      /* verilator lint_on UNUSEDSIGNAL */
      // offset = x_start + h - X_E (h = 2^(XFracBits-1)), as segment_interpolator's s0: the
      // complement of an XFracBits-bit sum when unclipped, h - X_E when clipped at 0.
      frac_h   = in_xe[XFracBits-1:0] + XFracBits'((1 << (XFracBits - 1)) - 1);
      off_clip = $signed((DxBits + 2)'(1 << (XFracBits - 1)))
               - $signed({{3{in_xe[XBits-1]}}, in_xe});
      off_frac = ~frac_h;
      m_offset_q   <= in_fce[PixelCompareBits-1] ? DxBits'(off_clip) : DxBits'(off_frac);
      m_recip_q    <= d_recip;
      m_p_q        <= d_p_q;
      m_op_q       <= '0;
      m_dig_q      <= '0;
      h_eol_q      <= seg_eol_i;
      h_xs_q       <= in_fce[PixelCompareBits-1] ? '0 : LineBits'(in_fce);
      h_xe_q       <= (in_fcf > $signed(PixelCompareBits'(width_i))) ? width_i
                                                                     : LineBits'(in_fcf);
      h_poly_q     <= seg_poly_i;
      h_material_q <= seg_material_i;
    end else if (issue) begin
      if (m_dig_q == last_digit(m_op_q)) begin
        m_op_q  <= m_op_q + 1'b1;
        m_dig_q <= '0;
      end else begin
        m_dig_q <= m_dig_q + 1'b1;
      end
    end
  end

  // Per slot at the take: E into the head's value, |F - E| and its sign.
  for (genvar c = 1; c <= InterpolatedSlots; c++) begin : g_take
    localparam int unsigned SlotBits = watkins_pkg::slot_bits(c, XBits, ZBits, AttrBits);
    localparam int unsigned InputLow = watkins_pkg::slot_lo(c, XBits, ZBits, AttrBits);
    localparam int unsigned MagLow   = ilo(c, ZBits + 1, AttrBits + 1);
    logic signed [SlotBits:0] fe;  // F - E
    assign fe = $signed({seg_f_i[InputLow+SlotBits-1], seg_f_i[InputLow +: SlotBits]})
              - $signed({seg_e_i[InputLow+SlotBits-1], seg_e_i[InputLow +: SlotBits]});
    always_ff @(posedge clk_i) begin
      if (take) begin
        m_mag_q[MagLow +: SlotBits + 1] <= fe ^ {(SlotBits + 1){fe[SlotBits]}};
        m_neg_q[c]                      <= fe[SlotBits];
      end
    end
  end

  // o: digit m_dig_q of the operation's unsigned operand, and B. Each slot's |delta| (less one
  // when negative) widened to the operand's digits (slot 0: the offset).
  logic [(InterpolatedSlots+1)*OperandBits-1:0] m_operand;  // slot s at s OperandBits
  logic [InterpolatedSlots:0]                    m_neg_ext;
  assign m_operand[0 +: OperandBits] = OperandBits'(m_offset_q);
  assign m_neg_ext    = {m_neg_q, 1'b0};
  for (genvar c = 1; c <= InterpolatedSlots; c++) begin : g_operand
    localparam int unsigned MagBits = watkins_pkg::slot_bits(c, XBits, ZBits, AttrBits) + 1;
    assign m_operand[c*OperandBits +: OperandBits] =
        OperandBits'(m_mag_q[ilo(c, ZBits + 1, AttrBits + 1) +: MagBits]);
  end
  always_ff @(posedge clk_i) begin
    if (issue) begin : o_set
      logic [OperandBits-1:0] a;
      logic [2:0]             slot;
      slot = op_slot(m_op_q);
      a    = m_operand[slot * OperandBits +: OperandBits];
      o_a_q     <= a[m_dig_q * DigitBits +: DigitBits];
      o_b_q     <= (m_op_q > 4) ? BBits'(m_alpha_q) : BBits'(m_recip_q);
      o_op_q    <= m_op_q;
      o_first_q <= m_dig_q == '0;
      o_last_q  <= m_dig_q == last_digit(m_op_q);
      o_neg_q   <= m_neg_ext[slot];
    end
  end

  logic signed [BBits:0] o_b_less;  // B - 1: -1 when alpha0 is 0
  assign o_b_less = $signed({1'b0, o_b_q} - (BBits + 1)'(1));
  // p: the digit's product, and the sum's start (B - 1 for a negative operand, else 0). x: the
  // running sum; on the last digit the whole of Q, its digits placed by the operation's digit
  // count.
  always_ff @(posedge clk_i) begin
    if (o_valid_q) begin
      p_prod_q  <= ProductBits'(o_a_q) * ProductBits'(o_b_q);
      p_init_q  <= o_neg_q ? o_b_less : '0;
      p_op_q    <= o_op_q;
      p_first_q <= o_first_q;
      p_last_q  <= o_last_q;
      p_neg_q   <= o_neg_q;
    end
  end

  logic signed [SumBits-1:0] x_sum;
  logic signed [QBits-1:0]   x_q_offset, x_q_z, x_q_attr;  // Q for each digit count
  assign x_sum = (p_first_q ? $signed({{(SumBits - BBits - 1){p_init_q[BBits]}}, p_init_q})
                            : x_hi_q)
               + $signed({2'b00, p_prod_q});
  function automatic logic signed [QBits-1:0] assemble(logic signed [SumBits-1:0] hi,
                                                       logic [LoBits-1:0] lo, int unsigned n);
    // Q's top bits beyond QBits are its sign.
    /* verilator lint_off UNUSEDSIGNAL */
    logic signed [SumBits+LoBits-1:0] all;
    /* verilator lint_on UNUSEDSIGNAL */
    all = $signed({hi, lo})
      >>> (DigitBits * (MaxDigits - n) + LoBits - DigitBits * (MaxDigits - 1));
    assemble = (n == 1) ? QBits'(hi) : QBits'(all);
  endfunction
  assign x_q_offset = assemble(x_sum, x_lo_q, OffsetDigits);
  assign x_q_z      = assemble(x_sum, x_lo_q, ZDigits);
  assign x_q_attr   = assemble(x_sum, x_lo_q, AttrDigits);

  // The digit leaving the sum enters x_lo_q at the top.
  logic [LoBits-1:0] x_lo_next;
  if (LoBits > DigitBits) begin : g_lo_shift
    assign x_lo_next = {x_sum[DigitBits-1:0], x_lo_q[LoBits-1:DigitBits]};
  end else begin : g_lo_one
    assign x_lo_next = x_sum[DigitBits-1:0];
  end
  always_ff @(posedge clk_i) begin
    if (p_valid_q) begin
      if (p_last_q) begin
        x_q_q   <= (p_op_q == 0) ? x_q_offset
                 : (p_op_q == 1 || p_op_q == 5) ? x_q_z : x_q_attr;
        x_op_q  <= p_op_q;
        x_neg_q <= p_neg_q;
      end else begin
        x_hi_q <= x_sum >>> DigitBits;
        x_lo_q <= x_lo_next;
      end
    end
  end

  // s: alpha0's and the steps' u = floor(2 x / 2^s) (round_shift(x, s) = floor((u + 1) / 2)),
  // the constant part of the shift wired, p through one shifter; a value's u = floor(Q /
  // 2^(AlphaBits-1)), wired. Both inverted for a negative delta. Only u's window is kept: the
  // shifter's levels go from the largest, each keeping the bits that a smaller shift can still
  // bring into the window and testing the bits it drops against the sign.
  localparam int unsigned ValueShift = AlphaBits - 1;
  logic signed [QBits:0]                    s_alpha_in, s_step_in;
  logic                                     s_sign;  // u's sign before the inversion: Q's
  /* verilator lint_off UNUSEDSIGNAL */
  // level k's word at k ShiftInBits (split: each level reads the one above it)
  logic [(ExponentBits+1)*ShiftInBits-1:0] s_level /* verilator split_var */;
  logic [ShiftInBits-1:0]                  s_value_in;
  /* verilator lint_on UNUSEDSIGNAL */
  logic [ExponentBits-1:0]                  s_level_eq;  // the bits level k drops equal the sign
  logic [UBits-1:0]                         s_u;
  assign s_sign     = x_q_q[QBits-1];
  assign s_alpha_in = $signed({x_q_q, 1'b0}) >>> AlphaShift;
  assign s_step_in  = $signed({x_q_q, x_neg_q}) >>> StepShift;
  assign s_level[ExponentBits*ShiftInBits +: ShiftInBits] =
      {{(ShiftInBits - QBits - 1){s_sign}}, (x_op_q == 0) ? s_alpha_in : s_step_in};
  for (genvar k = 0; k < ExponentBits; k++) begin : g_shift
    localparam int unsigned Step    = 1 << k;
    localparam int unsigned OutBits = WindowBits + Step - 1;  // what shifts below k can use
    localparam int unsigned InBits  = (k == ExponentBits - 1) ? ShiftInBits
                                                              : WindowBits + 2 * Step - 1;
    logic [InBits-1:0] in;
    logic              drop_eq, drop_shifted_eq;
    assign in = s_level[(k + 1)*ShiftInBits +: InBits];
    assign s_level[k*ShiftInBits +: OutBits] = m_p_q[k] ? in[Step +: OutBits] : in[0 +: OutBits];
    assign s_level[k*ShiftInBits + OutBits +: ShiftInBits - OutBits] = '0;
    assign drop_eq = in[InBits-1:OutBits] == {(InBits - OutBits){s_sign}};
    if (InBits > Step + OutBits) begin : g_drop_shifted
      assign drop_shifted_eq = in[InBits-1:Step+OutBits] == {(InBits - Step - OutBits){s_sign}};
    end else begin : g_drop_none
      assign drop_shifted_eq = 1'b1;
    end
    assign s_level_eq[k] = m_p_q[k] ? drop_shifted_eq : drop_eq;
  end
  assign s_value_in = $signed({{(ShiftInBits - QBits){s_sign}}, x_q_q}) >>> ValueShift;
  assign s_u = (x_op_q > 4) ? {s_sign, s_sign, s_value_in[WindowBits-1:0]}
             : {s_sign, s_sign ^ !(&s_level_eq), s_level[0 +: WindowBits]};
  always_ff @(posedge clk_i) begin
    if (x_valid_q) begin
      s_u_q  <= x_neg_q ? ~s_u : s_u;
      s_op_q <= x_op_q;
    end
  end

  // w: alpha0 rounded and clamped to 2^AlphaBits; a step rounded and saturated to its slot; a
  // value E + round_shift(delta alpha0, AlphaBits) wrapped to its slot. One rounding adder
  // serves all three: floor((u + 1) / 2) = u[.. 1] + u[0].
  logic [WindowBits-2:0] w_round;
  assign w_round = s_u_q[WindowBits-1:1] + (WindowBits - 1)'(s_u_q[0]);
  always_ff @(posedge clk_i) begin
    if (s_valid_q && s_op_q == 0) begin : w_alpha
      logic [AlphaBits:0] ua;
      logic               over;
      ua   = s_u_q[AlphaBits+1:1];
      over = |s_u_q[UBits-1:AlphaBits+2] || (ua[AlphaBits] && (|ua[AlphaBits-1:0] || s_u_q[0]));
      m_alpha_q <= over ? (AlphaBits + 1)'(1 << AlphaBits) : w_round[AlphaBits:0];
    end
  end
  for (genvar c = 1; c <= InterpolatedSlots; c++) begin : g_w
    localparam int unsigned SlotBits     = watkins_pkg::slot_bits(c, XBits, ZBits, AttrBits);
    localparam int unsigned SlotLow      = ilo(c, ZBits, AttrBits);
    localparam logic signed [SlotBits-1:0] StepMax = {1'b0, {(SlotBits - 1){1'b1}}};
    localparam logic signed [SlotBits-1:0] StepMin = {1'b1, {(SlotBits - 1){1'b0}}};
    always_ff @(posedge clk_i) begin
      if (s_valid_q && s_op_q == OpBits'(c)) begin : w_step
        logic fits, at_max;
        fits   = &s_u_q[UBits-1:SlotBits] || ~|s_u_q[UBits-1:SlotBits];
        at_max = !s_u_q[SlotBits] && &s_u_q[SlotBits-1:1];
        if (!fits) h_step_q[SlotLow +: SlotBits] <= s_u_q[UBits-1] ? StepMin : StepMax;
        else if (at_max) h_step_q[SlotLow +: SlotBits] <= StepMax;
        else h_step_q[SlotLow +: SlotBits] <= w_round[SlotBits-1:0];
      end
      if (take) begin
        h_value_q[SlotLow +: SlotBits] <=
            seg_e_i[watkins_pkg::slot_lo(c, XBits, ZBits, AttrBits) +: SlotBits];
      end else if (s_valid_q && s_op_q == OpBits'(c + 4)) begin
        // E + round_shift(X, AlphaBits) with u = floor(X / 2^(AlphaBits-1)): only the slot's
        // bits of the rounded u are added.
        h_value_q[SlotLow +: SlotBits] <= h_value_q[SlotLow +: SlotBits]
                                        + w_round[SlotBits-1:0];
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) h_valid_q <= 1'b0;
    else if (take && seg_eol_i) h_valid_q <= 1'b1;
    else if (s_valid_q && s_op_q == OpBits'(Ops - 1)) h_valid_q <= 1'b1;
    else if (h_pop) h_valid_q <= 1'b0;
  end

  // ---------------------------------------------------------------- stepper
  logic                        st_active_q;  // st_* hold the next beat to emit
  logic [LineBits-1:0]         st_x_q, st_xe_q;
  logic [PolyIdBits-1:0]       st_poly_q;
  logic [MaterialIdBits-1:0]   st_material_q;
  logic [InterpVectorBits-1:0] st_value_q, st_step_q;
  logic [InterpVectorBits-1:0] st_value1;      // the value one step on: lane 1's
  logic [InterpVectorBits-1:0] st_value_next;  // the value Lanes steps on: the next beat's
  logic                        out_free, emit_frag, emit_eol, st_last, load;

  assign out_free  = !frag_valid_o || frag_ready_i;
  assign emit_frag = out_free && st_active_q;
  assign load      = h_valid_q && !h_eol_q && (!st_active_q || (emit_frag && st_last));
  assign emit_eol  = out_free && !st_active_q && h_valid_q && h_eol_q;
  assign h_pop     = load || emit_eol;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      st_active_q  <= 1'b0;
      frag_valid_o <= 1'b0;
    end else begin
      if (load) st_active_q <= 1'b1;
      else if (emit_frag && st_last) st_active_q <= 1'b0;
      if (out_free) frag_valid_o <= emit_frag || emit_eol;
    end
  end

  // Per slot: the next beat's value and each lane's readings (segment_interpolator's g_frag):
  // depth = clamp(round_shift(Z, ZFracBits), 0, 2^DepthBits - 1); shade = clamp(round_shift(v,
  // AttrFracBits), 0, 255); normal (lane 0) = v rescaled to FracBits fraction bits, saturated to
  // NormalInBits.
  logic [Lanes*DepthBits-1:0] depth_d;   // lane l at l DepthBits
  logic [Lanes*3*8-1:0]       rgb_d;     // lane l's {B, G, R} by slot at l 24
  logic [3*NormalBits-1:0]    normal_d;  // {Nz, Ny, Nx}
  for (genvar c = 1; c <= InterpolatedSlots; c++) begin : g_frag
    localparam int unsigned SlotBits     = watkins_pkg::slot_bits(c, XBits, ZBits, AttrBits);
    localparam int unsigned SlotFracBits = (c == 1) ? ZFracBits : AttrFracBits;
    localparam int unsigned SlotLow      = ilo(c, ZBits, AttrBits);
    localparam int unsigned LevelBits    = (c == 1) ? DepthBits : 8;
    localparam int unsigned RoundedBits  = SlotBits + 1 - SlotFracBits;
    localparam int unsigned ClampBits    = (RoundedBits > LevelBits + 1) ? RoundedBits
                                                                         : LevelBits + 1;
    logic signed [SlotBits-1:0] v;  // lane 0's
    assign v = st_value_q[SlotLow +: SlotBits];
    assign st_value1[SlotLow +: SlotBits] = v + st_step_q[SlotLow +: SlotBits];
    if (Lanes == 2) begin : g_two_steps
      // Two steps wrapped to the slot: the step doubled in the slot's width, one add.
      assign st_value_next[SlotLow +: SlotBits] =
          v + {st_step_q[SlotLow +: SlotBits - 1], 1'b0};
    end else begin : g_one_step
      assign st_value_next[SlotLow +: SlotBits] = st_value1[SlotLow +: SlotBits];
    end
    for (genvar l = 0; l < Lanes; l++) begin : g_lane
      logic signed [SlotBits-1:0]  lv;  // the lane's value
      /* verilator lint_off UNUSEDSIGNAL */
      logic signed [SlotBits:0]    t;   // fraction bits are rounded away
      /* verilator lint_on UNUSEDSIGNAL */
      logic signed [ClampBits-1:0] r;
      logic [ClampBits-2:0]        mag;
      logic [LevelBits-1:0]        level;
      assign lv = (l == 0) ? v : st_value1[SlotLow +: SlotBits];
      if (SlotFracBits > 0) begin : g_round
        assign t = $signed({lv[SlotBits-1], lv})
                 + $signed((SlotBits + 1)'(1) << (SlotFracBits - 1));
      end else begin : g_exact
        assign t = $signed({lv[SlotBits-1], lv});
      end
      assign r     = ClampBits'($signed(t[SlotBits:SlotFracBits]));
      assign mag   = r[ClampBits-2:0];
      assign level = r[ClampBits-1] ? '0 : (|(mag >> LevelBits)) ? {LevelBits{1'b1}}
                                                                  : LevelBits'(mag);
      if (c == 1) begin : g_depth
        assign depth_d[l*DepthBits +: DepthBits] = level;
      end else begin : g_shade
        assign rgb_d[l*3*8 + (c - 2)*8 +: 8] = level;
      end
    end
    if (c != 1) begin : g_normal
      localparam int unsigned NormalFracBits = watkins_pkg::FracBits;
      localparam int unsigned RescaledBits   = (SlotFracBits >= NormalFracBits)
          ? SlotBits + 1 - (SlotFracBits - NormalFracBits)
          : SlotBits + (NormalFracBits - SlotFracBits);
      localparam int unsigned SaturateBits   = (RescaledBits > NormalBits) ? RescaledBits
                                                                           : NormalBits;
      logic signed [RescaledBits-1:0]   n;
      logic signed [SaturateBits-1:0]   ns;
      logic [SaturateBits-NormalBits:0] ns_hi;
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
      assign normal_d[(c - 2)*NormalBits +: NormalBits] =
          (&ns_hi || ~|ns_hi) ? NormalBits'(ns)
        : ns[SaturateBits-1]  ? NormalBits'(64'd1 << (NormalBits - 1))
        :                       NormalBits'((64'd1 << (NormalBits - 1)) - 1);
    end
  end

  always_ff @(posedge clk_i) begin
    if (emit_frag) begin
      frag_x_o        <= st_x_q;
      frag_depth_o    <= depth_d[0 +: DepthBits];
      frag_rgb_o.r    <= rgb_d[0 +: 8];
      frag_rgb_o.g    <= rgb_d[8 +: 8];
      frag_rgb_o.b    <= rgb_d[16 +: 8];
      frag_normal_o   <= normal_d;
      frag_poly_o     <= st_poly_q;
      frag_material_o <= st_material_q;
      frag_eol_o      <= 1'b0;
    end else if (emit_eol) begin
      frag_eol_o      <= 1'b1;
    end
    if (load) begin
      st_x_q        <= h_xs_q;
      st_xe_q       <= h_xe_q;
      st_poly_q     <= h_poly_q;
      st_material_q <= h_material_q;
      st_value_q    <= h_value_q;
      st_step_q     <= h_step_q;
    end else if (emit_frag) begin
      st_x_q     <= st_x_q + LineBits'(Lanes);
      st_value_q <= st_value_next;
    end
  end

  // The span's last beat: one pixel left, or (Lanes = 2) two. A span ends below 2^LineBits, so
  // x + 1 never wraps, and x + 2 wraps only where x + 1 is the end already.
  if (Lanes == 2) begin : g_lane1
    logic one_left;  // the beat is the span's last pixel alone
    assign one_left = (st_x_q + 1'b1 == st_xe_q);
    assign st_last  = one_left || (st_x_q + LineBits'(2) == st_xe_q);
    always_ff @(posedge clk_i) begin
      if (emit_frag) begin
        frag_pair_o     <= !one_left;
        frag_depth1_o   <= depth_d[DepthBits +: DepthBits];
        frag_rgb1_o.r   <= rgb_d[3*8 +: 8];
        frag_rgb1_o.g   <= rgb_d[4*8 +: 8];
        frag_rgb1_o.b   <= rgb_d[5*8 +: 8];
      end else if (emit_eol) begin
        frag_pair_o     <= 1'b0;
      end
    end
  end else begin : g_lane0_only
    assign st_last       = (st_x_q + 1'b1 == st_xe_q);
    assign frag_pair_o   = 1'b0;
    assign frag_depth1_o = '0;
    assign frag_rgb1_o   = '0;
  end

  if (AttrOut) begin : g_attr_out
    always_ff @(posedge clk_i) begin
      if (emit_frag) frag_attr_o <= st_value_q[ZBits +: 3*AttrBits];
    end
  end else begin : g_no_attr_out
    assign frag_attr_o = '0;
  end

  `WATKINS_ASSERT_HOLD(a_in_hold, seg_valid_i, seg_ready_o, {seg_e_i, seg_f_i, seg_poly_i,
    seg_material_i, seg_eol_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, frag_valid_o, frag_ready_i, {frag_x_o, frag_depth_o,
    frag_rgb_o, frag_normal_o, frag_attr_o, frag_poly_o, frag_material_o, frag_eol_o, frag_pair_o,
    frag_depth1_o, frag_rgb1_o})
  `WATKINS_ASSERT(a_x_on_screen, frag_valid_o && !frag_eol_o |-> frag_x_o < width_i)
  `WATKINS_ASSERT(a_pair_on_screen, frag_valid_o && frag_pair_o
    |-> !frag_eol_o && (LineBits + 1)'(frag_x_o) + 1'b1 < (LineBits + 1)'(width_i))
  // The values need alpha0 when their first digit is issued: op 0 has been written by then.
  `WATKINS_ASSERT(a_alpha_ready, issue && m_op_q == OpBits'(5) && m_dig_q == '0
    |-> !(o_valid_q && o_op_q == 0) && !(p_valid_q && p_op_q == 0)
        && !(x_valid_q && x_op_q == 0) && !(s_valid_q && s_op_q == 0))
  `WATKINS_COVER(c_back_to_back_spans, load && st_active_q)
  `WATKINS_COVER(c_take_empty, take && !seg_eol_i && in_empty)
  `WATKINS_ASSERT(a_pk_recip, pk_seen_q && seg_valid_i |-> pk_recip_q == in_recip)

  if (Lanes != 1 && Lanes != 2) begin : g_check_lanes
    $error("compact_segment_interpolator: Lanes must be 1 or 2");
  end
  if (Lanes == 2 && AttrOut) begin : g_check_lanes_attr
    $error("compact_segment_interpolator: Lanes = 2 needs AttrOut = 0 (lane 1 has no attribute words)");
  end
endmodule
