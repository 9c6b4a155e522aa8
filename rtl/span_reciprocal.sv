// span_reciprocal: 1/dx for a span width dx > 0, as a mantissa and an exponent.
// recip = floor(2^(2R-1) / m) and p = floor(log2 dx), m = dx normalized to exactly
// R = RecipBits bits (low bits truncated), exactly model/twins/span_reciprocal.hpp:
// 1/dx ~= recip * 2^-(p+R).
// Pipelined, one input per clock: a stage of leading-one detection, a stage of normalization,
// then a restoring divider whose first stage takes quotient bits R and R-1 (both decided by m
// alone) and whose R-1 further stages take one bit each.
// Latency 26 cycles (RecipBits + 2; RecipBits is watkins_pkg::RecipBits unless given: the
// shade divider takes 1/depth from this block with its own mantissa width). Every stage is registered; one global stall (ready_o =
// ready_i || !valid_o, stall_pipe) holds the whole pipe (with LookAhead that stall is a flop of
// its own, loaded a clock ahead from ready_next_i), and a stage's registers load only for a
// valid beat (stall_pipe's ce_o). payload_i travels alongside, so the caller keeps its span data
// in step with the quotient: kept in a RAM (stall_pipe PayloadRam), only the quotient's own
// registers are per stage.
// Stages: g_lead (leading one) -> g_norm (normalize) -> g_top (quotient bits R and R-1) ->
// g_bit (stages 3 .. R+1, one quotient bit each).
`include "watkins_assert.svh"

module span_reciprocal #(
  parameter int unsigned DxBits      = watkins_pkg::ChannelBits + 1,  // unsigned width of dx
  parameter int unsigned PayloadBits = 1,
  parameter bit          LookAhead   = 1'b0,  // stall_pipe's: the stall from a flop of its own
  parameter int unsigned RecipBits   = watkins_pkg::RecipBits,  // R below
  localparam int unsigned ExponentBits = $clog2(DxBits)         // width of p
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic [DxBits-1:0]      dx_i,       // span width, X channel units; result unused for 0
  input  logic [PayloadBits-1:0] payload_i,
  input  logic                   valid_i,
  output logic                   ready_o,
  output logic [RecipBits:0]     recip_o,    // in (2^(R-1), 2^R]
  output logic [ExponentBits-1:0] p_o,        // floor(log2 dx)
  output logic [PayloadBits-1:0] payload_o,
  output logic                   valid_o,
  input  logic                   ready_i,
  input  logic                   ready_next_i,  // LookAhead: ready_i on the next clock
  output logic                   ready_next_o   // ready_o on the next clock (from ready_next_i)
);
  localparam int unsigned Stages = RecipBits + 2;  // detect, normalize, R quotient stages (R+1 bits)

  // ce[k]: stage k loads, the pipe advances (en) and the beat entering stage k is valid. A
  // bubble leaves a stage's registers as they were: nobody reads a bubble's quotient, and a
  // simulator then evaluates a stage's divider step only for the few clocks a span passes
  // (most clocks the pipe holds bubbles). Same flops; only their clock enables differ.
  logic [Stages-1:0] ce;

  // Valid, payload and the stall of every stage; the registers below advance on their ce.
  // The payload (a whole span's setup in segment_interpolator) is written once, not shifted
  // through 26 stages of registers.
  /* verilator lint_off UNUSEDSIGNAL */
  logic [Stages-1:0] v_unused;
  logic              en;  // the pipe advances: read by tests/formal's probes, not here
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
    .en_next_o   (ready_next_o),
    .en_o     (en),
    .valid_q_o(v_unused),
    .ce_o     (ce)
  );

  // Leading-one detection (stage 0), then normalization (stage 1): dx << (NormalizedBits-1-p)
  // puts the leading one on top; its top R bits are the model's m whether dx is shifted left or
  // right.
  // A narrow dx (a configuration with few X bits) is widened to R bits first. The detection and
  // the shift are a clock apart: together they would be the block's longest path.
  localparam int unsigned NormalizedBits = (DxBits > RecipBits) ? DxBits : RecipBits;
  localparam int unsigned ShiftBits      = $clog2(NormalizedBits);
  // The shift NormalizedBits - 1 - p comes out of the encoder beside p, not from a subtract
  // after it. A function called inside stage 0's enable, not an always_comb: a simulator
  // evaluates it only when a span enters (the same encoder).
  function automatic logic [ExponentBits+ShiftBits-1:0] lead_of(  // {p, shift}
      logic [DxBits-1:0] dx);
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
  // One restoring step: {quotient bit, next partial remainder} from a remainder < m.
  function automatic logic [RecipBits:0] div_step(logic [RecipBits-1:0] rem,
                                                  logic [RecipBits-1:0] m);
    logic [RecipBits:0] twice;
    twice    = {rem, 1'b0};
    div_step = (twice >= {1'b0, m}) ? {1'b1, RecipBits'(twice - {1'b0, m})}
                                    : {1'b0, RecipBits'(twice)};
  endfunction

  // Quotient bit R-k+1 in stage k >= 3, bits R and R-1 in stage 2: the numerator 2^(2R-1) has
  // contributed 2^(R-2) to the partial remainder before bit R (smaller than m, so every higher
  // quotient bit is zero). With m in [2^(R-1), 2^R), the restoring steps for bits R and R-1 are
  // fixed: bit R = (2^(R-1) >= m), i.e. m = 2^(R-1), leaving 0 or 2^(R-1); bit R-1 is then
  // its complement (0 >= m never, 2^R >= m always), leaving 0 or 2^R - m.
  // Each stage's registers are their own variables in a generate block, not elements of
  // per-stage arrays: a simulator (Verilator) keeps a pending-write flag and value per written
  // array element and clears them on every evaluation; plain variables need neither. Same flops.
  for (genvar k = 0; k < Stages; k++) begin : g_stage
    // The last stage's divisor and remainder (and every quotient's top bit but the last) are
    // not read: synthesis drops those flops.
    /* verilator lint_off UNUSEDSIGNAL */
    logic [RecipBits-1:0] m_q;    // normalized divisor in [2^(R-1), 2^R)
    logic [RecipBits-1:0] rem_q;  // partial remainder, < m
    logic [RecipBits:0]   quo_q;  // quotient bits so far
    logic [DxBits-1:0]    dx_q;   // stage 0 only: dx
    logic [ShiftBits-1:0] sh_q;   // stage 0 only: NormalizedBits - 1 - p
    /* verilator lint_on UNUSEDSIGNAL */
    logic [ExponentBits-1:0] p_q;
    if (k == 0) begin : g_lead
      always_ff @(posedge clk_i) begin
        if (ce[0]) begin
          dx_q         <= dx_i;
          {p_q, sh_q}  <= lead_of(dx_i);
        end
      end
    end else if (k == 1) begin : g_norm
      // Only the top R bits of the normalized width matter (the model truncates the rest).
      always_ff @(posedge clk_i) begin
        if (ce[1]) begin
          m_q <= RecipBits'((NormalizedBits'(g_stage[0].dx_q) << g_stage[0].sh_q)
                            >> (NormalizedBits - RecipBits));
          p_q <= g_stage[0].p_q;
        end
      end
    end else if (k == 2) begin : g_top
      // Quotient bit R is m = 2^(R-1): m's low bits all clear.
      always_ff @(posedge clk_i) begin
        if (ce[2]) begin
          rem_q <= (|g_stage[1].m_q[RecipBits-2:0]) ? RecipBits'(-g_stage[1].m_q) : '0;
          quo_q <= {(RecipBits - 1)'(0), ~|g_stage[1].m_q[RecipBits-2:0], |g_stage[1].m_q[RecipBits-2:0]};
          m_q   <= g_stage[1].m_q;
          p_q   <= g_stage[1].p_q;
        end
      end
    end else begin : g_bit
      always_ff @(posedge clk_i) begin
        if (ce[k]) begin
          {quo_q, rem_q} <= {g_stage[k-1].quo_q[RecipBits-1:0],
                             div_step(g_stage[k-1].rem_q, g_stage[k-1].m_q)};
          m_q   <= g_stage[k-1].m_q;
          p_q   <= g_stage[k-1].p_q;
        end
      end
    end
  end

  assign recip_o = g_stage[Stages-1].quo_q;
  assign p_o     = g_stage[Stages-1].p_q;

  // The payload's hold is checked once, by u_pipe (stall_pipe's a_in_hold and a_out_hold: the
  // same valid and ready): a simulator keeps a sampled copy of every signal an assertion reads,
  // and the payload is a whole span's setup.
  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, dx_i)
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, {recip_o, p_o})
  `WATKINS_COVER(c_stall, valid_o && !ready_i)
endmodule
