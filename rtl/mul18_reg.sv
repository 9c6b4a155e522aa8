// mul18_reg: p = a * b in one 18 x 18 multiplier block, the product registered.
// Operands up to 18 bits each, signed or unsigned each (ASigned, BSigned); the product's low
// PBits bits are kept. No handshake: the parent gives each register its stage's clock enable
// (ce[k:k-1] of a stall_pipe).
// Latency: 1 cycle, or 2 with InReg. InReg = 0: ce_i[0] loads the product register. InReg = 1:
// ce_i[0] loads the operand registers, ce_i[1] the product register.
// Stages: operands (a_q, b_q; InReg only) -> product (p_q).
// Why a module: on the ECP5 (WATKINS_ECP5, defined by `watkins synth` for that target only) the
// product register is the MULT18X18D's own output register (REG_OUTPUT_CLK), which yosys 0.23
// does not infer; the multiplier is then the product's setup inside the block, not a block
// between two fabric flip-flops with a route on each side. Everywhere else (Verilator, the formal
// proofs, lint, iCE40) the same register is in RTL.
// InReg: the operands are also registered in the block (REG_INPUTA/B), so a route from the
// fabric ends at a register with a small setup instead of at the multiplier's input, whose setup
// is long on the ECP5 (in the Phong top the MULT18 blocks spread across the die, so those routes
// are long too).
module mul18_reg #(
  parameter int ABits   = 18,             // <= 18
  parameter int BBits   = 18,             // <= 18
  parameter bit ASigned = 1'b0,           // a is two's complement
  parameter bit BSigned = 1'b0,           // b is two's complement
  parameter int PBits   = ABits + BBits,  // <= 36: the product's low bits
  parameter bit InReg   = 1'b0            // the operands registered in the block: latency 2
) (
  input  logic             clk_i,
  input  logic [InReg:0]   ce_i,   // [InReg]: the product register loads; [0] with InReg: the operands
  input  logic [ABits-1:0] a_i,
  input  logic [BBits-1:0] b_i,
  output logic [PBits-1:0] p_o     // a * b, registered
);
`ifdef WATKINS_ECP5
  logic [17:0] a18, b18;  // the operands extended to the block's 18 bits
  /* verilator lint_off UNUSEDSIGNAL */
  logic [35:0] p36;       // bits above PBits are not kept
  /* verilator lint_on UNUSEDSIGNAL */
  if (ASigned) begin : g_as
    assign a18 = 18'(signed'(a_i));
  end else begin : g_au
    assign a18 = 18'(a_i);
  end
  if (BSigned) begin : g_bs
    assign b18 = 18'(signed'(b_i));
  end else begin : g_bu
    assign b18 = 18'(b_i);
  end
  MULT18X18D #(
    .REG_INPUTA_CLK(InReg ? "CLK0" : "NONE"), .REG_INPUTA_CE("CE1"), .REG_INPUTA_RST("RST0"),
    .REG_INPUTB_CLK(InReg ? "CLK0" : "NONE"), .REG_INPUTB_CE("CE1"), .REG_INPUTB_RST("RST0"),
    .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0"),
    .GSR("DISABLED"), .RESETMODE("SYNC")
  ) u_mult (
      .A0(a18[0]), .A1(a18[1]), .A2(a18[2]), .A3(a18[3]), .A4(a18[4]), .A5(a18[5]), .A6(a18[6]),
      .A7(a18[7]), .A8(a18[8]), .A9(a18[9]), .A10(a18[10]), .A11(a18[11]), .A12(a18[12]),
      .A13(a18[13]), .A14(a18[14]), .A15(a18[15]), .A16(a18[16]), .A17(a18[17]),
      .B0(b18[0]), .B1(b18[1]), .B2(b18[2]), .B3(b18[3]), .B4(b18[4]), .B5(b18[5]), .B6(b18[6]),
      .B7(b18[7]), .B8(b18[8]), .B9(b18[9]), .B10(b18[10]), .B11(b18[11]), .B12(b18[12]),
      .B13(b18[13]), .B14(b18[14]), .B15(b18[15]), .B16(b18[16]), .B17(b18[17]),
      .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0),
      .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0),
      .C16(1'b0), .C17(1'b0),
      .SIGNEDA(ASigned), .SIGNEDB(BSigned), .SOURCEA(1'b0), .SOURCEB(1'b0),
      .CLK0(clk_i), .CLK1(1'b0), .CLK2(1'b0), .CLK3(1'b0),
      .CE0(ce_i[InReg]), .CE1(InReg ? ce_i[0] : 1'b0), .CE2(1'b0), .CE3(1'b0),
      .RST0(1'b0), .RST1(1'b0), .RST2(1'b0), .RST3(1'b0),
      .P0(p36[0]), .P1(p36[1]), .P2(p36[2]), .P3(p36[3]), .P4(p36[4]), .P5(p36[5]), .P6(p36[6]),
      .P7(p36[7]), .P8(p36[8]), .P9(p36[9]), .P10(p36[10]), .P11(p36[11]), .P12(p36[12]),
      .P13(p36[13]), .P14(p36[14]), .P15(p36[15]), .P16(p36[16]), .P17(p36[17]), .P18(p36[18]),
      .P19(p36[19]), .P20(p36[20]), .P21(p36[21]), .P22(p36[22]), .P23(p36[23]), .P24(p36[24]),
      .P25(p36[25]), .P26(p36[26]), .P27(p36[27]), .P28(p36[28]), .P29(p36[29]), .P30(p36[30]),
      .P31(p36[31]), .P32(p36[32]), .P33(p36[33]), .P34(p36[34]), .P35(p36[35])
  );
  assign p_o = p36[PBits-1:0];
`else
  logic [ABits-1:0] a;  // the operands the product reads: a_i / b_i, or their registers (InReg)
  logic [BBits-1:0] b;
  if (InReg) begin : g_in
    logic [ABits-1:0] a_q;
    logic [BBits-1:0] b_q;
    always_ff @(posedge clk_i) if (ce_i[0]) begin
      a_q <= a_i;
      b_q <= b_i;
    end
    assign a = a_q;
    assign b = b_q;
  end else begin : g_direct
    assign a = a_i;
    assign b = b_i;
  end
  logic [PBits-1:0] p_q;
  if (!ASigned && !BSigned) begin : g_u
    always_ff @(posedge clk_i) if (ce_i[InReg]) p_q <= PBits'(a) * PBits'(b);
  end else begin : g_s
    // Each operand one bit wider, its sign bit a copy of its top bit or 0, multiplied signed;
    // extended inside the enable, not by continuous assigns, which Verilator evaluates on every
    // clock (the tops hold dozens of these, as the interpolator's products use it).
    always_ff @(posedge clk_i)
      if (ce_i[InReg]) p_q <= PBits'($signed({ASigned & a[ABits-1], a})
                                     * $signed({BSigned & b[BBits-1], b}));
  end
  assign p_o = p_q;
`endif
endmodule
