// mac16_phased: one 16 x 16 multiplier of a compact block's fixed schedule of 5-clock periods
// (compact_schedule): in phase k of the period (ph_i) the operands a_i[k], b_i[k] enter its
// operand registers, and their product is on p_o from the next clock to the one after that.
// Latency 2 (operands in, product out); registered: the operands and the product, each loading
// on en_i (on the iCE40 the SB_MAC16's own input and output registers).
module mac16_phased #(
  parameter bit Signed = 1'b0  // both operands two's complement (else both unsigned)
) (
  input  logic        clk_i,
  input  logic        en_i,   // the schedule moves (compact_schedule's en_o)
  input  logic [2:0]  ph_i,   // the clock within the period, 0..4
  input  logic [79:0] a_i,    // {a[4], .., a[0]}: a[k] is taken in phase k
  input  logic [79:0] b_i,    // {b[4], .., b[0]}
  output logic [31:0] p_o     // a b of the operands taken a clock before
);
  logic [15:0] a_q, b_q;
  logic [31:0] p_q;
  always_ff @(posedge clk_i) if (en_i) begin
    case (ph_i)
      3'd0:    begin a_q <= a_i[0 +: 16];  b_q <= b_i[0 +: 16]; end
      3'd1:    begin a_q <= a_i[16 +: 16]; b_q <= b_i[16 +: 16]; end
      3'd2:    begin a_q <= a_i[32 +: 16]; b_q <= b_i[32 +: 16]; end
      3'd3:    begin a_q <= a_i[48 +: 16]; b_q <= b_i[48 +: 16]; end
      default: begin a_q <= a_i[64 +: 16]; b_q <= b_i[64 +: 16]; end
    endcase
  end
  if (Signed) begin : g_signed
    always_ff @(posedge clk_i) if (en_i) p_q <= 32'($signed(a_q) * $signed(b_q));
  end else begin : g_unsigned
    always_ff @(posedge clk_i) if (en_i) p_q <= a_q * b_q;
  end
  assign p_o = p_q;
endmodule
