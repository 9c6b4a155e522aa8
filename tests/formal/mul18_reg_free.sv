// mul18_reg (formal abstraction): rtl/mul18_reg.sv's parameters and ports, its product register
// loading a free value ($anyseq: a fresh unconstrained value on every clock in yosys 0.23's `sat`)
// when ce_i is high and holding otherwise. Every behaviour of the real block (the register loads
// a_i * b_i under the same enable) is one of this module's, so a property proved with it holds for
// rtl/mul18_reg.sv. For the stream proofs of the pipelined units (normalizer, phong_shader), whose
// hold, tag and capacity properties do not depend on product values: the SAT problem then carries
// no multiplier (76 of them in the shader). scripts/formal reads it for a proof whose module list
// names `formal:mul18_reg_free`; docs/reference/formal.md says why it is sound.
module mul18_reg #(
  parameter int ABits   = 18,
  parameter int BBits   = 18,
  parameter bit ASigned = 1'b0,
  parameter bit BSigned = 1'b0,
  parameter int PBits   = ABits + BBits,
  parameter bit InReg   = 1'b0
) (
  input  logic             clk_i,
  input  logic [InReg:0]   ce_i,   // [InReg]: the product register loads ([0] with InReg: unread)
  input  logic [ABits-1:0] a_i,    // unread: the product is free
  input  logic [BBits-1:0] b_i,
  output logic [PBits-1:0] p_o     // any value, loaded under ce_i like the real product register
);
  logic [PBits-1:0] free;
  logic [PBits-1:0] p_q;
  assign free = $anyseq;
  always_ff @(posedge clk_i) if (ce_i[InReg]) p_q <= free;
  assign p_o = p_q;
endmodule
