// stall_pipe_checker: the induction invariants of one rtl/stall_pipe.sv instance whose beats carry
// sequence numbers (formal harnesses only; yosys `read_verilog -formal`). Its inputs are the
// instance's internals, which the harness reads through hierconn wires. A ghost tag per stage
// shifts on the instance's en as its valid bits do: the n_in its slot entered with, bubble or
// beat. Each slot's tag is the next older slot's plus that slot's valid bit, the oldest slot's is
// n_out, the youngest slot's plus its valid bit n_in; per slot, the beats that entered after it
// are at most the slots at and below it; each valid stage's payload (or each RAM word of a beat
// in flight, and out_q) is its tag. Every invariant relates a stage to its neighbour or a word to
// the counters, so the SAT problem has no chain across the stages (invariants that tie each
// valid stage's tag to the nearest valid stage above and below build a mux chain as deep as the
// pipe, and checking each valid stage's RAM word takes Stages x Depth checks: the shader's proof
// then does not close in practical time). With them `sat -tempinduct` closes at length 1
// whatever the stall pattern; without them a stall long enough hides any corrupt state.
module stall_pipe_checker #(
  parameter int unsigned Stages      = 2,
  parameter int unsigned PayloadBits = 4,     // the tag width, >= PointerBits
  parameter bit          PayloadRam  = 1'b0,
  localparam int unsigned PointerBits = $clog2(Stages + 1),  // as stall_pipe's g_ram
  localparam int unsigned Depth       = 2 ** PointerBits
) (
  input logic                           clk_i,
  input logic                           rst_ni,
  input logic                           en_i,          // the instance's en_o
  input logic [PayloadBits-1:0]         n_in_i,        // tag of the next beat in
  input logic [PayloadBits-1:0]         n_out_i,       // tag of the next beat out
  input logic [Stages-1:0]              valid_q_i,     // valid_q
  input logic [Stages*PayloadBits-1:0]  shift_q_i,     // g_shift.payload_q[s] at s*PayloadBits
  input logic [PointerBits-1:0]         wr_q_i,        // g_ram.wr_q
  input logic [PointerBits-1:0]         rd_q_i,        // g_ram.rd_q
  input logic [Depth*PayloadBits-1:0]   mem_i,         // g_ram.mem[k] at k*PayloadBits
  input logic [PayloadBits-1:0]         out_q_i        // g_ram.out_q
);
  // The ghost tag of each stage: n_in when the stage's slot entered, for a bubble as for a beat
  // (reset with the counters, so the invariants hold from the reset on).
  logic [PayloadBits-1:0] tag_q [Stages];
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      for (int unsigned s = 0; s < Stages; s++) tag_q[s] <= '0;
    end else if (en_i) begin
      tag_q[0] <= n_in_i;
      for (int unsigned s = 1; s < Stages; s++) tag_q[s] <= tag_q[s-1];
    end
  end

  // The tag at or after n_out whose low PointerBits are w: the beat word w holds if it is in
  // flight.
  logic [PayloadBits-1:0] word_tag [Depth];
  always_comb
    for (int unsigned w = 0; w < Depth; w++)
      word_tag[w] = n_out_i + PayloadBits'(PointerBits'(PointerBits'(w) - PointerBits'(n_out_i)));

  always_comb begin
    if (rst_ni) begin
      // Each slot's tag is the next older slot's plus that slot's valid bit (a beat took a
      // number, a bubble none); the youngest slot's plus its valid bit is n_in, the oldest
      // slot's tag is n_out (every beat before it has left).
      assert (n_in_i == tag_q[0] + PayloadBits'(valid_q_i[0]));
      for (int unsigned s = 0; s + 1 < Stages; s++)
        assert (tag_q[s] == tag_q[s+1] + PayloadBits'(valid_q_i[s+1]));
      assert (n_out_i == tag_q[Stages-1]);
      // Beats that entered after slot s's: at most s + 1 (the slots at and below it), at least
      // one if slot s holds a beat. (Each follows from the sums above; stated per slot, every
      // invariant is local, and beats in flight = n_in - tag_q[Stages-1] <= Stages.)
      for (int unsigned s = 0; s < Stages; s++) begin
        assert (PayloadBits'(n_in_i - tag_q[s]) <= PayloadBits'(s + 1));
        if (valid_q_i[s]) assert (n_in_i != tag_q[s]);
        if (!PayloadRam && valid_q_i[s]) assert (shift_q_i[s*PayloadBits +: PayloadBits] == tag_q[s]);
      end
      if (PayloadRam) begin
        // Each word of a beat in flight holds its tag (Depth > Stages: a word is rewritten only
        // once its beat left). Word w's beat, if any, is the tag at or after n_out whose low
        // PointerBits are w; it is in flight if it comes before n_in.
        for (int unsigned w = 0; w < Depth; w++) begin
          if (PayloadBits'(word_tag[w] - n_out_i) < PayloadBits'(n_in_i - n_out_i))
            assert (mem_i[w*PayloadBits +: PayloadBits] == word_tag[w]);
        end
        // The pointers count beats in and out as the tags do.
        assert (wr_q_i == PointerBits'(n_in_i) && rd_q_i == PointerBits'(n_out_i));
        // The beat in the last stage: out_q was loaded with it as it left the stage before (its
        // word written at least a clock earlier), and is not reloaded but with the same word while
        // it waits. (out_q is read only while a beat is in the last stage but one: a beat further
        // back is not in it yet.)
        if (valid_q_i[Stages-1]) assert (out_q_i == n_out_i);
      end
    end
  end
endmodule
