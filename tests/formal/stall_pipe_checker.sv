// stall_pipe_checker: the induction invariants of one rtl/stall_pipe.sv instance whose beats carry
// sequence numbers (formal harnesses only; yosys `read_verilog -formal`). Its inputs are the
// instance's internals, which the harness reads through hierconn wires: the beats in flight are
// the valid stages, and the beat in stage s (or the k-th oldest entry of the payload RAM) is
// n_out + (the number of beats ahead of it). With them `sat -tempinduct` closes in a few steps
// whatever the stall pattern; without them a stall long enough hides any corrupt state.
module stall_pipe_checker #(
  parameter int unsigned Stages      = 2,
  parameter int unsigned PayloadBits = 4,     // the tag width
  parameter bit          PayloadRam  = 1'b0,
  localparam int unsigned PtrBits = $clog2(Stages + 1),  // as stall_pipe's g_ram
  localparam int unsigned Depth   = 2 ** PtrBits
) (
  input logic                           rst_ni,
  input logic [PayloadBits-1:0]         occupancy_i,   // beats in minus beats out
  input logic [PayloadBits-1:0]         n_out_i,       // tag of the next beat out
  input logic [Stages-1:0]              valid_q_i,     // u_pipe.valid_q
  input logic [Stages*PayloadBits-1:0]  shift_q_i,     // g_shift.payload_q[s] at s*PayloadBits
  input logic [PtrBits-1:0]             wr_q_i,        // g_ram.wr_q
  input logic [PtrBits-1:0]             rd_q_i,        // g_ram.rd_q
  input logic [Depth*PayloadBits-1:0]   mem_i,         // g_ram.mem[k] at k*PayloadBits
  input logic [PayloadBits-1:0]         out_q_i        // g_ram.out_q
);
  // Beats in stages above s: they leave before the beat in stage s.
  function automatic logic [PayloadBits-1:0] ahead(logic [Stages-1:0] v, int unsigned s);
    ahead = '0;
    for (int unsigned t = s + 1; t < Stages; t++) ahead = ahead + PayloadBits'(v[t]);
  endfunction

  logic [PtrBits-1:0] in_ram;  // entries written and not yet read (wraps at Depth, as the pointers)
  assign in_ram = wr_q_i - rd_q_i;

  always_comb begin
    if (rst_ni) begin
      assert (occupancy_i == ahead(valid_q_i, 0) + PayloadBits'(valid_q_i[0]));
      if (!PayloadRam) begin
        for (int unsigned s = 0; s < Stages; s++)
          if (valid_q_i[s]) assert (shift_q_i[s*PayloadBits +: PayloadBits] == n_out_i + ahead(valid_q_i, s));
      end else begin
        assert (PayloadBits'(in_ram) == occupancy_i);
        for (int unsigned k = 0; k < Depth; k++)
          if (PayloadBits'(k) < occupancy_i)
            assert (mem_i[PtrBits'(rd_q_i + PtrBits'(k))*PayloadBits +: PayloadBits] == n_out_i + PayloadBits'(k));
        // The oldest beat past stage 0 was written at least a clock before out_q was loaded.
        if ((valid_q_i >> 1) != '0) assert (out_q_i == n_out_i);
      end
    end
  end
endmodule
