// smoother: Herman & Liu's image-space smoothing of the raster-order frame, 3x3 weighted means.
// Twin: model/twins/smoother.hpp. Every covered pixel becomes the 3x3 weighted mean
// (G1 + W·Σ edges + W²·Σ corners) / (1 + W·n_edge + W²·n_corner) per channel, neighbours counted
// only when on the screen and covered (f_i); uncovered pixels keep their shade.
// W = w_i / 2^SmoothWFracBits; w_i = 0 is the identity.
// Latency: pixel (x, y) leaves 14 clocks after the input beat at (x+1, y+1) (raster index +
// width + 1) was taken; the last width + 1 pixels of a frame come from flush steps, one per clock
// after its last input beat (ready_o low meanwhile). One pixel per clock; every stage
// registered, stalled together: ready_o = (ready_i || !valid_o) && !flushing (combinational).
// Stages: column (cx_q) -> line read (rd_q, p1_q) -> window (win_q) -> pairs (p_edge_q) -> sums
// (s_edge_q) -> products (pe_q, pc_q) -> dividend (rem_q[0]) -> division (g_div, one stage per
// quotient bit: ShadeBits of them).
// Storage: the two previous lines side by side in one RAM of MaxWidth words of 2 x 25 bits
// ({covered, rgb} of lines y-1 and y-2 at x), synchronous read (block RAM), read when a column
// enters and rewritten the clock after; the word written that clock is forwarded when the next
// read hits the same x (width 1). The division: a pipelined restoring divider, 8 quotient bits
// per channel (the mean is <= 255), exact: round half up of the exact quotient.
`include "watkins_assert.svh"

module smoother #(
  parameter int unsigned MaxWidth = watkins_pkg::DefaultMaxWidth  // line-buffer depth in pixels
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  input  logic [watkins_pkg::LineBits-1:0]      width_i,    // 1..MaxWidth, stable per frame
  input  logic [watkins_pkg::LineBits-1:0]      height_i,   // lines per frame, stable per frame
  input  logic [watkins_pkg::SmoothWBits-1:0]   w_i,        // W, SmoothWFracBits fraction bits;
                                                            // stable per frame
  input  watkins_pkg::rgb_t                     rgb_i,      // every pixel of the frame, raster order
  input  logic                                  covered_i,  // some polygon won the pixel (f = 1)
  input  logic                                  last_i,     // the frame's last pixel
  input  logic                                  valid_i,
  output logic                                  ready_o,
  output watkins_pkg::rgb_t                     rgb_o,      // smoothed, raster order
  output logic                                  covered_o,
  output logic [watkins_pkg::LineBits-1:0]      x_o,
  output logic [watkins_pkg::LineBits-1:0]      y_o,
  output logic                                  last_o,     // the frame's last pixel
  output logic                                  valid_o,
  input  logic                                  ready_i
);
  // The comments write the weight's formats as F (WeightFracBits), B (WeightBits) and
  // M (WeightMaxBits).
  localparam int unsigned LineBits           = watkins_pkg::LineBits;
  localparam int unsigned ShadeBits          = watkins_pkg::ShadeBits;
  localparam int unsigned WeightFracBits     = watkins_pkg::SmoothWFracBits;  // F
  localparam int unsigned WeightBits         = watkins_pkg::SmoothWBits;      // B
  localparam int unsigned PixelBits          = watkins_pkg::RgbBits + 1;      // {covered, rgb}
  localparam int unsigned AddressBits        = (MaxWidth > 1) ? $clog2(MaxWidth) : 1;
  localparam int unsigned SumBits            = ShadeBits + 2;                 // four levels
  localparam int unsigned NeighbourCountBits = 3;                             // 0..4 neighbours
  localparam int unsigned WeightMaxBits      = (WeightBits > WeightFracBits)  // M
                                                   ? WeightBits : WeightFracBits;
  // d = 2^2F + 2^F·w·n_edge + w²·n_corner with n_edge, n_corner <= 4 and F < B (W < 2:
  // formats.hpp asserts it) is below 2^2F + 4·2^(F+B) + 4·2^2B <= 6.25·2^2M, so the divisor
  // 2d fits 2M + 4 bits; the dividend 2n + d < 2^8 · 2d (n <= 255·d).
  localparam int unsigned DivisorBits  = 2 * WeightMaxBits + 4;   // holds 2d
  localparam int unsigned DividendBits = DivisorBits + ShadeBits;  // holds 2n + d
  localparam int unsigned DivStages    = ShadeBits;                // one quotient bit each
  localparam int unsigned PayloadBits  = 1 + 2 * LineBits + 1;     // {covered, x, y, last}

  // ------------------------------------------------------------ stage 0: a column enters
  logic                   en, adv, in_fire, emit0, flush_q, ox_end, oy_end;
  logic [AddressBits-1:0] cx_q;        // x of the entering column
  logic [LineBits:0]      lead_q;      // columns entered, up to width + 1 (then each one emits)
  logic [LineBits-1:0]    ox_q, oy_q;  // the pixel the next emitting column completes

  assign en      = !valid_o || ready_i;
  assign ready_o = en && !flush_q;
  assign in_fire = valid_i && ready_o;
  // Flush steps enter uncovered columns after the frame's last input (the lines below the last).
  assign adv     = en && (flush_q || valid_i);
  assign emit0   = lead_q == {1'b0, width_i} + 1'b1;
  assign ox_end  = ox_q == width_i - 1'b1;
  assign oy_end  = oy_q == height_i - 1'b1;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      cx_q    <= '0;
      lead_q  <= '0;
      ox_q    <= '0;
      oy_q    <= '0;
      flush_q <= 1'b0;
    end else if (adv) begin
      cx_q <= (LineBits'(cx_q) == width_i - 1'b1) ? '0 : cx_q + 1'b1;
      if (!emit0) lead_q <= lead_q + 1'b1;
      if (emit0) begin
        ox_q <= ox_end ? '0 : ox_q + 1'b1;
        if (ox_end) oy_q <= oy_q + 1'b1;
      end
      if (in_fire && last_i) flush_q <= 1'b1;
      if (emit0 && ox_end && oy_end) begin  // the frame's last pixel: ready for the next frame
        cx_q    <= '0;
        lead_q  <= '0;
        ox_q    <= '0;
        oy_q    <= '0;
        flush_q <= 1'b0;
      end
    end
  end

  // ------------------------------------------------------------ stage 1: line-buffer read
  logic [2*PixelBits-1:0] line_mem [MaxWidth];  // {line y-1, line y-2} at x
  logic [2*PixelBits-1:0] rd_q, fw_q, word1;
  logic                   v1_q, e1_q, fwd1_q, last1_q;
  logic [3:0]             m1_q;  // on the screen: {left, right, up, down}
  logic [LineBits-1:0]    ox1_q, oy1_q;
  logic [AddressBits-1:0] a1_q;
  logic [PixelBits-1:0]   p1_q, mid1, up1;

  assign word1      = fwd1_q ? fw_q : rd_q;
  assign {mid1, up1} = word1;

  always_ff @(posedge clk_i) begin
    if (adv) rd_q <= line_mem[cx_q];
  end
  always_ff @(posedge clk_i) begin
    if (en && v1_q) line_mem[a1_q] <= {p1_q, mid1};
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      v1_q <= 1'b0;
    end else if (en) begin
      v1_q <= adv;
    end
  end
  always_ff @(posedge clk_i) begin
    if (adv) begin
      p1_q    <= in_fire ? {covered_i, rgb_i} : '0;
      a1_q    <= cx_q;
      // The RAM read misses the word written this same clock: forward it.
      fwd1_q  <= v1_q && a1_q == cx_q;
      fw_q    <= {p1_q, mid1};
      e1_q    <= emit0;
      m1_q    <= {ox_q != '0, !ox_end, oy_q != '0, !oy_end};
      ox1_q   <= ox_q;
      oy1_q   <= oy_q;
      last1_q <= ox_end && oy_end;
    end
  end

  // ------------------------------------------------------------ stage 2: the 3x3 window
  // Column c = {line y-2, y-1, y} (top, middle, bottom); column 1's middle is the centre.
  logic [3*PixelBits-1:0] win_q [3];  // (separate registers: yosys maps a shifted array to flops)
  logic                   v2_q, last2_q;
  logic [3:0]             m2_q;
  logic [LineBits-1:0]    ox2_q, oy2_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      v2_q <= 1'b0;
    end else if (en) begin
      v2_q <= v1_q && e1_q;
    end
  end
  always_ff @(posedge clk_i) begin
    if (en && v1_q) begin
      win_q[0] <= win_q[1];
      win_q[1] <= win_q[2];
      win_q[2] <= {up1, mid1, p1_q};
      m2_q     <= m1_q;
      ox2_q    <= ox1_q;
      oy2_q    <= oy1_q;
      last2_q  <= last1_q;
    end
  end

  // ------------------------------------------------------------ stage 3: f_i and pair sums
  // Stages 3..14 compute inside their registers' enables (functions called under `if`), each
  // stage's registers loading only a valid pixel: the same gates, clock-enabled, and a
  // simulator does no work for an empty stage (a frame with W = 0 leaves all of them empty).
  // Stage 3 adds the masked neighbours two by two, stage 4 the two pairs (the mask and a
  // four-input sum in one clock would limit the smoother on the ECP5).
  localparam int unsigned PairBits  = ShadeBits + 1;
  // {edge pairs, corner pairs, n_edge, n_corner}
  localparam int unsigned PairsBits = 2 * 3 * 2 * PairBits + 2 * NeighbourCountBits;
  // Edges: up, left, right, down; corners: up-left, up-right, down-left, down-right. Pair j of a
  // kind is its neighbours 2j and 2j + 1; channel c's pairs at (2c + j)·PairBits.
  function automatic logic [PairsBits-1:0] window_pairs(
      logic [3*PixelBits-1:0] w0, logic [3*PixelBits-1:0] w1, logic [3*PixelBits-1:0] w2,
      logic [3:0] m);
    logic [PixelBits-1:0]          centre;
    logic [8*PixelBits-1:0]        nb;
    logic [7:0]                    f;
    logic [6*PairBits-1:0]         p_edge, p_corner;
    logic [NeighbourCountBits-1:0] n_edge, n_corner;
    logic                          m_left, m_right, m_up, m_down;
    {m_left, m_right, m_up, m_down} = m;
    centre = w1[PixelBits +: PixelBits];
    nb = {w2[0 +: PixelBits], w0[0 +: PixelBits],
          w2[2*PixelBits +: PixelBits], w0[2*PixelBits +: PixelBits],
          w1[0 +: PixelBits], w2[PixelBits +: PixelBits],
          w0[PixelBits +: PixelBits], w1[2*PixelBits +: PixelBits]};
    // An uncovered centre keeps its shade: no neighbour counts (d = 2^2F, n = 2^2F·G1).
    f[0] = m_up;
    f[1] = m_left;
    f[2] = m_right;
    f[3] = m_down;
    f[4] = m_up && m_left;
    f[5] = m_up && m_right;
    f[6] = m_down && m_left;
    f[7] = m_down && m_right;
    for (int i = 0; i < 8; i++)
      f[i] = f[i] && nb[i*PixelBits + PixelBits-1] && centre[PixelBits-1];
    for (int c = 0; c < 3; c++) begin
      for (int j = 0; j < 2; j++) begin
        p_edge[(2*c + j)*PairBits +: PairBits] =
            (f[2*j]     ? PairBits'(nb[(2*j)*PixelBits + c*ShadeBits +: ShadeBits])     : '0)
          + (f[2*j + 1] ? PairBits'(nb[(2*j + 1)*PixelBits + c*ShadeBits +: ShadeBits]) : '0);
        p_corner[(2*c + j)*PairBits +: PairBits] =
            (f[4 + 2*j] ? PairBits'(nb[(4 + 2*j)*PixelBits + c*ShadeBits +: ShadeBits]) : '0)
          + (f[4 + 2*j + 1] ? PairBits'(nb[(4 + 2*j + 1)*PixelBits + c*ShadeBits +: ShadeBits])
                            : '0);
      end
    end
    n_edge   = '0;
    n_corner = '0;
    for (int i = 0; i < 4; i++) begin
      n_edge   = n_edge + NeighbourCountBits'(f[i]);
      n_corner = n_corner + NeighbourCountBits'(f[i + 4]);
    end
    window_pairs = {p_edge, p_corner, n_edge, n_corner};
  endfunction
  // Per channel, the sum of its two pairs.
  function automatic logic [3*SumBits-1:0] pair_sums(logic [6*PairBits-1:0] p);
    for (int c = 0; c < 3; c++)
      pair_sums[c*SumBits +: SumBits] = SumBits'(p[(2*c)*PairBits +: PairBits])
                                      + SumBits'(p[(2*c + 1)*PairBits +: PairBits]);
  endfunction

  logic [PixelBits-1:0]          centre;
  logic                          vp_q, v3_q;
  logic [6*PairBits-1:0]         p_edge_q, p_corner_q;
  logic [3*SumBits-1:0]          s_edge_q, s_corner_q;
  logic [3*ShadeBits-1:0]        g1p_q, g1_q;
  logic [NeighbourCountBits-1:0] np_edge_q, np_corner_q, n_edge_q, n_corner_q;
  logic [PayloadBits-1:0]        payp_q, pay3_q;

  assign centre = win_q[1][PixelBits +: PixelBits];
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      vp_q <= 1'b0;
      v3_q <= 1'b0;
    end else if (en) begin
      vp_q <= v2_q;
      v3_q <= vp_q;
    end
  end
  always_ff @(posedge clk_i) begin
    if (en && v2_q) begin
      {p_edge_q, p_corner_q, np_edge_q, np_corner_q} <=
          window_pairs(win_q[0], win_q[1], win_q[2], m2_q);
      g1p_q  <= centre[3*ShadeBits-1:0];
      payp_q <= {centre[PixelBits-1], ox2_q, oy2_q, last2_q};
    end
  end

  // ------------------------------------------------------------ stage 4: the sums
  always_ff @(posedge clk_i) begin
    if (en && vp_q) begin
      s_edge_q   <= pair_sums(p_edge_q);
      s_corner_q <= pair_sums(p_corner_q);
      n_edge_q   <= np_edge_q;
      n_corner_q <= np_corner_q;
      g1_q       <= g1p_q;
      pay3_q     <= payp_q;
    end
  end

  // ------------------------------------------------------------ stage 5: the products
  // The products by n in 0..4 by shifts and adds: multiplier blocks (the UP5K has 8) go to the
  // six products by the sums. Stage 5 registers the products, stage 6 their sums (one product
  // and a four-input sum in one clock would limit the whole Gouraud top).
  function automatic logic [DivisorBits-1:0] times_count(logic [DivisorBits-1:0] v,
                                                         logic [NeighbourCountBits-1:0] n);
    case (n)
      3'd0:    times_count = '0;
      3'd1:    times_count = v;
      3'd2:    times_count = v << 1;
      3'd3:    times_count = v + (v << 1);
      default: times_count = v << 2;  // 4, the most neighbours of a kind
    endcase
  endfunction

  // W², a frame constant, from a three-clock adder tree of the partial products of w_i (never
  // one clock: that path would limit the top). w_i is stable for the frame, and a frame's first
  // pixel reaches stage 5 width + 6 clocks after the frame's first input beat, so w2_q is
  // settled by then.
  // (WeightBits is a multiple of 4: pairs, then quads, then their sum.)
  localparam int unsigned WeightSquareBits = 2 * WeightBits;
  logic [WeightSquareBits-1:0] w2_pair_q [WeightBits/2];  // two partial products each
  logic [WeightSquareBits-1:0] w2_quad_q [WeightBits/4];  // four
  logic [WeightSquareBits-1:0] w2_q;
  always_ff @(posedge clk_i) begin
    logic [WeightSquareBits-1:0] sum;
    for (int i = 0; i < WeightBits / 2; i++)
      w2_pair_q[i] <= (w_i[2*i]   ? (WeightSquareBits'(w_i) << (2*i))     : '0)
                    + (w_i[2*i+1] ? (WeightSquareBits'(w_i) << (2*i + 1)) : '0);
    for (int i = 0; i < WeightBits / 4; i++) w2_quad_q[i] <= w2_pair_q[2*i] + w2_pair_q[2*i+1];
    sum = '0;
    for (int i = 0; i < WeightBits / 4; i++) sum = sum + w2_quad_q[i];
    w2_q <= sum;
  end

  localparam int unsigned EdgeProductBits   = WeightBits + SumBits;      // w·S_edge
  localparam int unsigned CornerProductBits = 2 * WeightBits + SumBits;  // w²·S_corner
  logic                           v4_q;
  logic [3*EdgeProductBits-1:0]   pe_q;
  logic [3*CornerProductBits-1:0] pc_q;
  logic [3*ShadeBits-1:0]         g1_4_q;
  logic [DivisorBits-1:0]         de_q, dc_q;  // w·n_edge, w²·n_corner
  logic [PayloadBits-1:0]         pay4_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      v4_q <= 1'b0;
    end else if (en) begin
      v4_q <= v3_q;
    end
  end
  always_ff @(posedge clk_i) begin
    if (en && v3_q) begin
      for (int c = 0; c < 3; c++) begin
        pe_q[c*EdgeProductBits +: EdgeProductBits] <=
            EdgeProductBits'(w_i) * EdgeProductBits'(s_edge_q[c*SumBits +: SumBits]);
        pc_q[c*CornerProductBits +: CornerProductBits] <=
            CornerProductBits'(w2_q) * CornerProductBits'(s_corner_q[c*SumBits +: SumBits]);
      end
      de_q   <= times_count(DivisorBits'(w_i), n_edge_q);
      dc_q   <= times_count(DivisorBits'(w2_q), n_corner_q);
      g1_4_q <= g1_q;
      pay4_q <= pay3_q;
    end
  end

  // ------------------------------------------------------------ stage 6: dividend and divisor
  // d = 2^2F + 2^F·w·n_edge + w²·n_corner.
  function automatic logic [DivisorBits-1:0] divisor(logic [DivisorBits-1:0] de,
                                                     logic [DivisorBits-1:0] dc);
    divisor = (DivisorBits'(1) << (2*WeightFracBits)) + (de << WeightFracBits) + dc;
  endfunction
  // 2n + d per channel, n = 2^2F·G1 + 2^F·w·S_edge + w²·S_corner.
  function automatic logic [3*DividendBits-1:0] dividend(
      logic [3*ShadeBits-1:0] g1, logic [3*EdgeProductBits-1:0] pe,
      logic [3*CornerProductBits-1:0] pc, logic [DivisorBits-1:0] d);
    for (int c = 0; c < 3; c++) begin
      dividend[c*DividendBits +: DividendBits] =
          ((DividendBits'(g1[c*ShadeBits +: ShadeBits]) << (2*WeightFracBits))
           + (DividendBits'(pe[c*EdgeProductBits +: EdgeProductBits]) << WeightFracBits)
           + DividendBits'(pc[c*CornerProductBits +: CornerProductBits])) * DividendBits'(2)
          + DividendBits'(d);
    end
  endfunction

  // ------------------------------------------------------------ stages 7..14: restoring division
  // Stage k takes quotient bit ShadeBits-1-k: the remainder is below 2d·2^(ShadeBits-k) before
  // it.
  logic [DivStages:0]        dv_q;
  logic [3*DividendBits-1:0] rem_q [DivStages+1];
  logic [3*ShadeBits-1:0]    quo_q [DivStages+1];
  logic [DivisorBits-1:0]    dsr_q [DivStages+1];
  logic [PayloadBits-1:0]    pay_q [DivStages+1];

  // One restoring step of the three channels against t = 2d·2^shift: the remainders and the
  // quotients with bit `shift` set where t fitted.
  function automatic logic [3*DividendBits-1:0] div_rem(logic [3*DividendBits-1:0] rem,
                                                        logic [DividendBits-1:0] t);
    logic [DividendBits-1:0] r;
    for (int c = 0; c < 3; c++) begin
      r = rem[c*DividendBits +: DividendBits];
      div_rem[c*DividendBits +: DividendBits] = (r >= t) ? r - t : r;
    end
  endfunction
  function automatic logic [3*ShadeBits-1:0] div_quo(
      logic [3*DividendBits-1:0] rem, logic [3*ShadeBits-1:0] quo, logic [DividendBits-1:0] t,
      int unsigned shift);
    for (int c = 0; c < 3; c++)
      div_quo[c*ShadeBits +: ShadeBits] =
          quo[c*ShadeBits +: ShadeBits]
        | (ShadeBits'(rem[c*DividendBits +: DividendBits] >= t) << shift);
  endfunction

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      dv_q[0] <= 1'b0;
    end else if (en) begin
      dv_q[0] <= v4_q;
    end
  end
  always_ff @(posedge clk_i) begin
    if (en && v4_q) begin
      rem_q[0] <= dividend(g1_4_q, pe_q, pc_q, divisor(de_q, dc_q));
      quo_q[0] <= '0;
      dsr_q[0] <= divisor(de_q, dc_q) << 1;
      pay_q[0] <= pay4_q;
    end
  end

  for (genvar k = 0; k < DivStages; k++) begin : g_div
    localparam int unsigned Shift = DivStages - 1 - k;
    always_ff @(posedge clk_i) begin
      if (!rst_ni) begin
        dv_q[k+1] <= 1'b0;
      end else if (en) begin
        dv_q[k+1] <= dv_q[k];
      end
    end
    always_ff @(posedge clk_i) begin
      if (en && dv_q[k]) begin
        rem_q[k+1] <= div_rem(rem_q[k], DividendBits'(dsr_q[k]) << Shift);
        quo_q[k+1] <= div_quo(rem_q[k], quo_q[k], DividendBits'(dsr_q[k]) << Shift, Shift);
        dsr_q[k+1] <= dsr_q[k];
        pay_q[k+1] <= pay_q[k];
      end
    end
  end

  assign valid_o = dv_q[DivStages];
  assign rgb_o   = quo_q[DivStages];
  assign {covered_o, x_o, y_o, last_o} = pay_q[DivStages];

  // The remainder left over is below the divisor; only the quotient leaves.
  logic unused_rem;
  assign unused_rem = ^rem_q[DivStages];

  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, {rgb_i, covered_i, last_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, {rgb_o, covered_o, x_o, y_o, last_o})
  `WATKINS_ASSERT(a_last_ends_line, in_fire && last_i |-> LineBits'(cx_q) == width_i - 1'b1)
  `WATKINS_ASSERT(a_width, valid_i |-> width_i != '0 && width_i <= LineBits'(MaxWidth))
  `WATKINS_COVER(c_flush, adv && flush_q)
  `WATKINS_COVER(c_forwarded, v1_q && fwd1_q)
  `WATKINS_COVER(c_stall, valid_o && !ready_i)
endmodule
