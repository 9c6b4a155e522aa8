// segment_interpolator: span setup for each segment E..F, then one fragment per pixel by alpha
// stepping, exactly model/twins/segment_interpolator.cpp (setup(), fragment(), step()).
// Setup pipeline, one segment per clock: s0 (pixel range, clipping, dx, offset, deltas) ->
// span_reciprocal (26) -> sa (alpha and step products) -> sb (round, clamp alpha0, saturate
// steps) -> sc (value products) -> FIFO (value = E + round(delta*alpha0)); empty spans are
// dropped before the FIFO. The stepper emits one fragment per clock from a registered output,
// taking a span's first pixel straight from the FIFO head, so consecutive spans (even of one
// pixel) leave no bubble and a span's setup hides behind the previous spans' pixels.
// Latency segment -> first fragment: 32 cycles. All stage outputs registered; ready is
// combinational through the setup stages (one stall signal), registered at the FIFO.
// End-of-line markers pass through in order. Each fragment carries both readings of the three
// attribute channels: frag_rgb_o (Gouraud shade levels) and frag_normal_o (Phong normal, the
// channel saturated to NormalInBits); a top uses one and synthesis drops the other.
`include "watkins_assert.svh"

module segment_interpolator #(
  parameter int unsigned FifoDepth = 4
) (
  input  logic                                                             clk_i,
  input  logic                                                             rst_ni,
  input  logic [watkins_pkg::LineBits-1:0]                                 width_i,  // screen width, stable per frame
  input  logic [watkins_pkg::NumChannels*watkins_pkg::ChannelBits-1:0]   seg_e_i, // left end E
  input  logic [watkins_pkg::NumChannels*watkins_pkg::ChannelBits-1:0]   seg_f_i, // right end F
  input  logic [watkins_pkg::MaterialIdBits-1:0]                          seg_material_i,
  input  logic                                                             seg_eol_i, // end-of-line marker, no segment
  input  logic                                                             seg_valid_i,
  output logic                                                             seg_ready_o,
  output logic [watkins_pkg::LineBits-1:0]                                 frag_x_o,
  output logic [watkins_pkg::DepthBits-1:0]                                frag_depth_o,
  output watkins_pkg::rgb_t                                                frag_rgb_o,  // Gouraud shade
  output logic [3*watkins_pkg::NormalInBits-1:0]                           frag_normal_o, // {Nz,Ny,Nx}
  output logic [watkins_pkg::MaterialIdBits-1:0]                          frag_material_o,
  output logic                                                             frag_eol_o,  // end-of-line marker, no fragment
  output logic                                                             frag_valid_o,
  input  logic                                                             frag_ready_i
);
  localparam int unsigned CB        = watkins_pkg::ChannelBits;
  localparam int unsigned FB        = watkins_pkg::FracBits;
  localparam int unsigned LB        = watkins_pkg::LineBits;
  localparam int unsigned RecipBits = watkins_pkg::RecipBits;
  localparam int unsigned AlphaBits = watkins_pkg::AlphaBits;
  localparam int unsigned NI        = watkins_pkg::NumChannels - 1;  // interpolated channels Z.. (not X)
  localparam int unsigned DeltaBits = CB + 1;                        // dx, offset, delta widths
  localparam int unsigned ExpBits   = $clog2(DeltaBits);             // p = floor(log2 dx)
  localparam int unsigned ProdBits  = DeltaBits + RecipBits + 2;     // products with recip, with guard
  localparam int unsigned XCB       = CB + 1 - FB;                   // signed width of a pixel index
  localparam int unsigned DepB      = watkins_pkg::DepthBits;
  localparam int unsigned XLo       = watkins_pkg::ChanX * CB;
  localparam int unsigned NB        = watkins_pkg::NormalInBits;
  localparam int unsigned MIB       = watkins_pkg::MaterialIdBits;

  typedef logic signed [CB-1:0] chan_t;
  typedef logic signed [ProdBits-1:0] prod_t;
  // saturate_signed(., CB)
  localparam logic signed [ProdBits-1:0] StepMax = $signed((ProdBits'(1) << (CB - 1)) - ProdBits'(1));
  localparam logic signed [ProdBits-1:0] StepMin = -$signed(ProdBits'(1) << (CB - 1));

  // ---------------------------------------------------------------- s0: range and clipping
  typedef struct packed {
    logic                    eol;
    logic                    empty;   // no pixel centre in [X_E, X_F) on screen
    logic [MIB-1:0]          material;
    logic [LB-1:0]           xs;      // first pixel
    logic [LB-1:0]           xe;      // one past the last pixel
    logic [DeltaBits-1:0]    offset;  // x_start + 1/2 - X_E >= 0, X units
    logic [NI*CB-1:0]        e;       // E's channels Z..
    logic [NI*DeltaBits-1:0] delta;   // F - E per channel
  } span_pre_t;

  // First pixel whose centre is at or right of X: ceil(X - 1/2) = (X + 1/2 - 2^-FB) >> FB.
  function automatic logic signed [XCB-1:0] first_centre(chan_t x);
    // The fraction bits of the sum are what floor() discards.
    /* verilator lint_off UNUSEDSIGNAL */
    logic signed [CB:0] t;
    /* verilator lint_on UNUSEDSIGNAL */
    t = $signed({x[CB-1], x}) + $signed((CB + 1)'((1 << (FB - 1)) - 1));
    first_centre = t[CB:FB];
  endfunction

  logic                 s0_valid_q, s0_ready;
  span_pre_t            s0_q;
  logic [DeltaBits-1:0] s0_dx_q;
  span_pre_t            s0_d;
  logic [DeltaBits-1:0] s0_dx_d;

  always_comb begin
    logic signed [XCB-1:0] fce, fcf, xs_full, xe_full;
    // offset < dx when the span is not empty, so its top bits are dropped.
    /* verilator lint_off UNUSEDSIGNAL */
    logic signed [DeltaBits+1:0]  off;
    /* verilator lint_on UNUSEDSIGNAL */
    fce     = first_centre(seg_e_i[XLo +: CB]);
    fcf     = first_centre(seg_f_i[XLo +: CB]);
    xs_full = (fce < 0) ? '0 : fce;
    xe_full = (fcf > $signed(XCB'(width_i))) ? $signed(XCB'(width_i)) : fcf;
    s0_d.eol   = seg_eol_i;
    s0_d.empty = (xe_full <= xs_full);
    s0_d.material = seg_material_i;
    s0_d.xs    = LB'(xs_full);
    s0_d.xe    = LB'(xe_full);
    off        = $signed((DeltaBits + 2)'({s0_d.xs, 1'b1, (FB - 1)'(0)}))
               - $signed({{3{seg_e_i[XLo+CB-1]}}, seg_e_i[XLo +: CB]});
    s0_d.offset = DeltaBits'(off);
    s0_dx_d     = DeltaBits'($signed({seg_f_i[XLo+CB-1], seg_f_i[XLo +: CB]})
                    - $signed({seg_e_i[XLo+CB-1], seg_e_i[XLo +: CB]}));
    for (int c = 0; c < NI; c++) begin
      s0_d.e[c*CB +: CB]     = seg_e_i[(c+1)*CB +: CB];
      s0_d.delta[c*DeltaBits +: DeltaBits] =
          DeltaBits'($signed({seg_f_i[(c+2)*CB-1], seg_f_i[(c+1)*CB +: CB]})
                     - $signed({seg_e_i[(c+2)*CB-1], seg_e_i[(c+1)*CB +: CB]}));
    end
  end

  assign seg_ready_o = !s0_valid_q || s0_ready;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) s0_valid_q <= 1'b0;
    else if (seg_ready_o) s0_valid_q <= seg_valid_i;
  end
  always_ff @(posedge clk_i) begin
    if (seg_ready_o && seg_valid_i) begin
      s0_q    <= s0_d;
      s0_dx_q <= s0_dx_d;
    end
  end

  // ---------------------------------------------------------------- reciprocal
  logic               rc_valid, tail_en;
  logic [RecipBits:0] rc_recip;
  logic [ExpBits-1:0] rc_p;
  span_pre_t          rc_span;

  span_reciprocal #(
    .DxBits     (DeltaBits),
    .PayloadBits($bits(s0_q))
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
    .ready_i  (tail_en)
  );

  // ---------------------------------------------------------------- sa: products with recip
  logic                sa_valid_q;
  span_pre_t           sa_span_q;
  logic [ExpBits-1:0]  sa_p_q;
  logic [ProdBits-1:0] sa_pa_q;       // offset * recip, unsigned
  prod_t               sa_ps_q [NI];  // delta * recip
  always_ff @(posedge clk_i) begin
    if (tail_en) begin
      sa_span_q <= rc_span;
      sa_p_q    <= rc_p;
      sa_pa_q   <= ProdBits'(rc_span.offset) * ProdBits'(rc_recip);
      for (int c = 0; c < NI; c++)
        sa_ps_q[c] <= $signed(rc_span.delta[c*DeltaBits +: DeltaBits]) * $signed({1'b0, rc_recip});
    end
  end

  // ---------------------------------------------------------------- sb: alpha0 and steps
  logic               sb_valid_q;
  span_pre_t          sb_span_q;
  logic [AlphaBits:0] sb_alpha_q;  // alpha0 in [0, 2^AlphaBits]
  chan_t              sb_step_q [NI];
  always_ff @(posedge clk_i) begin
    if (tail_en) begin
      logic [ProdBits-1:0] ra;
      logic [ProdBits-1:0] sh;
      prod_t         rs;
      sb_span_q <= sa_span_q;
      // alpha0 = min(round_shift(offset*recip, p + RecipBits - AlphaBits), 2^AlphaBits); round_shift
      // by 0 is exact.
      sh = ProdBits'(sa_p_q) + ProdBits'(RecipBits) - ProdBits'(AlphaBits);
      ra = (sh == '0) ? sa_pa_q : ((sa_pa_q + (ProdBits'(1) << (sh - 1))) >> sh);
      sb_alpha_q <= (ra > ProdBits'(1 << AlphaBits)) ? (AlphaBits + 1)'(1 << AlphaBits)
                                                     : (AlphaBits + 1)'(ra);
      // step = saturate(round_shift(delta*recip, p + RecipBits - FB)), shift always > 0.
      for (int c = 0; c < NI; c++) begin
        logic [ProdBits-1:0] s2;
        s2 = ProdBits'(sa_p_q) + ProdBits'(RecipBits) - ProdBits'(FB);
        rs = (sa_ps_q[c] + $signed(ProdBits'(1) << (s2 - 1))) >>> s2;
        if (rs > StepMax) sb_step_q[c] <= CB'(StepMax);
        else if (rs < StepMin) sb_step_q[c] <= CB'(StepMin);
        else sb_step_q[c] <= CB'(rs);
      end
    end
  end

  // ---------------------------------------------------------------- sc: value products
  logic                  sc_valid_q;
  // offset and delta are spent by now; keeping one span type is simpler than a third struct.
  /* verilator lint_off UNUSEDSIGNAL */
  span_pre_t             sc_span_q;
  /* verilator lint_on UNUSEDSIGNAL */
  chan_t                 sc_step_q [NI];
  prod_t                 sc_pv_q   [NI];   // delta * alpha0
  always_ff @(posedge clk_i) begin
    if (tail_en) begin
      sc_span_q <= sb_span_q;
      for (int c = 0; c < NI; c++) begin
        sc_step_q[c] <= sb_step_q[c];
        sc_pv_q[c]   <= $signed(sb_span_q.delta[c*DeltaBits +: DeltaBits]) * $signed({1'b0, sb_alpha_q});
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      sa_valid_q <= 1'b0;
      sb_valid_q <= 1'b0;
      sc_valid_q <= 1'b0;
    end else if (tail_en) begin
      sa_valid_q <= rc_valid;
      sb_valid_q <= sa_valid_q;
      sc_valid_q <= sb_valid_q;
    end
  end

  // ---------------------------------------------------------------- FIFO of ready spans
  typedef struct packed {
    logic                  eol;
    logic [MIB-1:0]        material;
    logic [LB-1:0]         xs;
    logic [LB-1:0]         xe;
    logic [NI*CB-1:0]      value;  // channels at pixel xs
    logic [NI*CB-1:0]      step;   // per-pixel increments
  } span_t;

  span_t f_in, f_out;
  logic  f_in_valid, f_in_ready, f_out_valid, f_out_ready;
  logic  sc_keep;

  always_comb begin
    f_in.eol = sc_span_q.eol;
    f_in.material = sc_span_q.material;
    f_in.xs  = sc_span_q.xs;
    f_in.xe  = sc_span_q.xe;
    for (int c = 0; c < NI; c++) begin
      // The wrap to CB bits drops the quotient's top bits.
      /* verilator lint_off UNUSEDSIGNAL */
      prod_t r;
      /* verilator lint_on UNUSEDSIGNAL */
      // value = wrap(E + round_shift(delta*alpha0, AlphaBits)): only the low CB bits survive.
      r = (sc_pv_q[c] + $signed(ProdBits'(1) << (AlphaBits - 1))) >>> AlphaBits;
      f_in.value[c*CB +: CB] = sc_span_q.e[c*CB +: CB] + CB'(r);
      f_in.step[c*CB +: CB]  = sc_step_q[c];
    end
  end

  // Empty spans produce nothing and are dropped here; markers always go through.
  assign sc_keep    = sc_span_q.eol || !sc_span_q.empty;
  assign f_in_valid = sc_valid_q && sc_keep;
  assign tail_en    = !sc_valid_q || !sc_keep || f_in_ready;

  stream_fifo #(
    .DataBits($bits(f_in)),
    .Depth   (FifoDepth)
  ) u_fifo (
    .clk_i, .rst_ni,
    .data_i (f_in),
    .valid_i(f_in_valid),
    .ready_o(f_in_ready),
    .data_o (f_out),
    .valid_o(f_out_valid),
    .ready_i(f_out_ready)
  );

  // ---------------------------------------------------------------- stepper
  logic                  st_active_q;  // a span is being stepped from the registers below
  logic [LB-1:0]         st_x_q, st_xe_q;
  logic [MIB-1:0]        st_material_q;
  logic [NI*CB-1:0]      st_value_q, st_step_q;

  logic                  out_free, from_head, emit_frag, emit_eol;
  logic [LB-1:0]         cur_x, cur_xe;
  logic [MIB-1:0]        cur_material;
  logic [NI*CB-1:0]      cur_value, cur_step;

  assign out_free  = !frag_valid_o || frag_ready_i;
  assign from_head = !st_active_q && f_out_valid && !f_out.eol;
  assign emit_frag = out_free && (st_active_q || from_head);
  assign emit_eol  = out_free && !st_active_q && f_out_valid && f_out.eol;
  assign f_out_ready = emit_eol || (emit_frag && from_head);

  assign cur_x     = st_active_q ? st_x_q     : f_out.xs;
  assign cur_xe    = st_active_q ? st_xe_q    : f_out.xe;
  assign cur_material = st_active_q ? st_material_q : f_out.material;
  assign cur_value = st_active_q ? st_value_q : f_out.value;
  assign cur_step  = st_active_q ? st_step_q  : f_out.step;

  // clamp(round_shift(v, FB), 0, hi) of a channel value.
  function automatic logic [DepB-1:0] level(logic [CB-1:0] v, logic [DepB-1:0] hi);
    /* verilator lint_off UNUSEDSIGNAL */
    logic signed [CB:0] t;  // fraction bits are rounded away
    /* verilator lint_on UNUSEDSIGNAL */
    logic signed [CB-FB:0] r;
    t = $signed({v[CB-1], v}) + $signed((CB + 1)'(1 << (FB - 1)));
    r = t[CB:FB];
    if (r < 0) level = '0;
    else if (r > $signed((CB - FB + 1)'(hi))) level = hi;
    else level = DepB'(r);
  endfunction

  // saturate_signed(v, NormalInBits) of a channel value: the normal keeps its FracBits fraction.
  function automatic logic [NB-1:0] normal_word(logic signed [CB-1:0] v);
    if (v > $signed(CB'((64'd1 << (NB - 1)) - 1))) normal_word = NB'((64'd1 << (NB - 1)) - 1);
    else if (v < -$signed(CB'(64'd1 << (NB - 1)))) normal_word = NB'(64'd1 << (NB - 1));
    else normal_word = NB'(v);
  endfunction

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      st_active_q  <= 1'b0;
      frag_valid_o <= 1'b0;
    end else begin
      if (out_free) frag_valid_o <= emit_frag || emit_eol;
      if (emit_frag) st_active_q <= (cur_x + 1'b1 != cur_xe);
    end
  end

  always_ff @(posedge clk_i) begin
    if (emit_frag) begin
      frag_x_o     <= cur_x;
      frag_depth_o <= level(cur_value[(watkins_pkg::ChanZ - 1)*CB +: CB], DepB'((64'd1 << DepB) - 1));
      frag_rgb_o.r <= 8'(level(cur_value[(watkins_pkg::ChanR - 1)*CB +: CB], DepB'(255)));
      frag_rgb_o.g <= 8'(level(cur_value[(watkins_pkg::ChanG - 1)*CB +: CB], DepB'(255)));
      frag_rgb_o.b <= 8'(level(cur_value[(watkins_pkg::ChanB - 1)*CB +: CB], DepB'(255)));
      for (int c = 0; c < 3; c++)
        frag_normal_o[c*NB +: NB] <= normal_word(cur_value[(watkins_pkg::ChanNx - 1 + c)*CB +: CB]);
      frag_material_o <= cur_material;
      frag_eol_o   <= 1'b0;
      st_x_q       <= cur_x + 1'b1;
      st_material_q <= cur_material;
      st_xe_q      <= cur_xe;
      st_step_q    <= cur_step;
      for (int c = 0; c < NI; c++)
        st_value_q[c*CB +: CB] <= cur_value[c*CB +: CB] + cur_step[c*CB +: CB];
    end else if (emit_eol) begin
      frag_eol_o   <= 1'b1;
    end
  end

  `WATKINS_ASSERT_HOLD(a_in_hold, seg_valid_i, seg_ready_o, {seg_e_i, seg_f_i, seg_material_i, seg_eol_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, frag_valid_o, frag_ready_i, {frag_x_o, frag_depth_o, frag_rgb_o,
    frag_normal_o, frag_material_o, frag_eol_o})
  `WATKINS_ASSERT(a_x_on_screen, frag_valid_o && !frag_eol_o |-> frag_x_o < width_i)
  `WATKINS_COVER(c_back_to_back_spans, emit_frag && from_head && frag_valid_o && !frag_eol_o)
  `WATKINS_COVER(c_empty_dropped, sc_valid_q && !sc_keep)
endmodule
