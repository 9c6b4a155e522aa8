// stall_pipe_checker: the induction invariants of one rtl/stall_pipe.sv instance whose beats carry
// sequence numbers (formal harnesses only; yosys `read_verilog -formal`). Its inputs are the
// instance's internals, which the harness reads through hierconn wires. A ghost tag per stage
// shifts on the instance's en as its valid bits do. The valid stages hold consecutive tags: each
// one more than the nearest valid stage above (n_out - 1 above the top one) and one less than the
// nearest valid stage below (n_in below the bottom one); each stage's payload (or the RAM word of
// each beat in flight, and out_q) is its tag. Every invariant is local to a stage or a word: a
// population count of the valid bits against n_in - n_out says the same, but the SAT solver
// takes minutes on it at 26 stages (and explicit per-stage bounds on the beats ahead and behind
// made it three times slower at 15). With them `sat -tempinduct` closes in two steps whatever the stall pattern;
// without them a stall long enough hides any corrupt state.
module stall_pipe_checker #(
  parameter int unsigned Stages      = 2,
  parameter int unsigned PayloadBits = 4,     // the tag width, >= PtrBits
  parameter bit          PayloadRam  = 1'b0,
  localparam int unsigned PtrBits = $clog2(Stages + 1),  // as stall_pipe's g_ram
  localparam int unsigned Depth   = 2 ** PtrBits
) (
  input logic                           clk_i,
  input logic                           rst_ni,
  input logic                           en_i,          // the instance's en_o
  input logic [PayloadBits-1:0]         n_in_i,        // tag of the next beat in
  input logic [PayloadBits-1:0]         n_out_i,       // tag of the next beat out
  input logic [Stages-1:0]              valid_q_i,     // valid_q
  input logic [Stages*PayloadBits-1:0]  shift_q_i,     // g_shift.payload_q[s] at s*PayloadBits
  input logic [PtrBits-1:0]             wr_q_i,        // g_ram.wr_q
  input logic [PtrBits-1:0]             rd_q_i,        // g_ram.rd_q
  input logic [Depth*PayloadBits-1:0]   mem_i,         // g_ram.mem[k] at k*PayloadBits
  input logic [PayloadBits-1:0]         out_q_i        // g_ram.out_q
);
  logic [PayloadBits-1:0] tag_q [Stages];  // the tag of the beat in each stage (when valid)
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      tag_q[0] <= n_in_i;
      for (int unsigned s = 1; s < Stages; s++) tag_q[s] <= tag_q[s-1];
    end
  end

  // The tag of the nearest valid stage above s (n_out - 1 if none), and below s (n_in if none).
  logic [PayloadBits-1:0] above [Stages];
  logic [PayloadBits-1:0] below [Stages];
  always_comb begin
    above[Stages-1] = n_out_i - 1'b1;
    for (int s = Stages - 2; s >= 0; s--) above[s] = valid_q_i[s+1] ? tag_q[s+1] : above[s+1];
    below[0] = n_in_i;
    for (int s = 1; s < Stages; s++) below[s] = valid_q_i[s-1] ? tag_q[s-1] : below[s-1];
  end

  always_comb begin
    if (rst_ni) begin
      // No beat in flight: as many in as out.
      if (valid_q_i == '0) assert (n_in_i == n_out_i);
      for (int unsigned s = 0; s < Stages; s++) begin
        if (valid_q_i[s]) begin
          assert (tag_q[s] == above[s] + 1'b1 && tag_q[s] == below[s] - 1'b1);
          if (!PayloadRam) assert (shift_q_i[s*PayloadBits +: PayloadBits] == tag_q[s]);
          // Its RAM word holds it (Depth > Stages: a word is rewritten only once its beat left).
          if (PayloadRam)
            for (int unsigned w = 0; w < Depth; w++)
              if (PtrBits'(tag_q[s]) == PtrBits'(w))
                assert (mem_i[w*PayloadBits +: PayloadBits] == tag_q[s]);
        end
      end
      if (PayloadRam) begin
        // The pointers count beats in and out as the tags do.
        assert (wr_q_i == PtrBits'(n_in_i) && rd_q_i == PtrBits'(n_out_i));
        // The beat in the last stage: out_q was loaded with it as it left the stage before (its
        // word written at least a clock earlier), and is not reloaded but with the same word while
        // it waits. (out_q is read only while a beat is in the last stage but one: a beat further
        // back is not in it yet.)
        if (valid_q_i[Stages-1]) assert (out_q_i == n_out_i);
      end
    end
  end
endmodule
