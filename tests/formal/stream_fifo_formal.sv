// stream_fifo_formal: proves rtl/stream_fifo.sv (Depth <= 4) holds valid and data until ready,
// and passes every beat once, in order, unchanged: each input beat carries its sequence number,
// the output must carry the next one expected, and beats in minus beats out is the FIFO's count
// (never above Depth). Induction invariants tie the pointers and every occupied slot to the
// beats in flight. The DUT's internals are read through yosys hierconn wires (flatten connects
// `\u_dut.x` to the instance's x), so rtl/ carries no formal code.
`include "formal_stream.svh"

module stream_fifo_formal #(
  parameter int unsigned DataBits = 4,  // > log2(Depth + 1): tags of the beats in flight differ
  parameter int unsigned Depth    = 3   // 1..4 (the slots probed below)
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic [DataBits-1:0] data_i,
  input  logic                valid_i,
  input  logic                ready_i
);
  localparam int unsigned PointerBits = (Depth > 1) ? $clog2(Depth) : 1;
  localparam int unsigned CountBits = $clog2(Depth + 1);

  logic                ready_o, valid_o, ready_next_o;
  logic [DataBits-1:0] data_o;
  stream_fifo #(.DataBits(DataBits), .Depth(Depth)) u_dut (.*);

  `FORMAL_PAST
  `FORMAL_COUNT(n_in_q, DataBits, valid_i, ready_o)
  `FORMAL_COUNT(n_out_q, DataBits, valid_o, ready_i)
  `FORMAL_ASSUME_HOLD(in, valid_i, ready_o, data_i)
  `FORMAL_ASSERT_HOLD(out, valid_o, ready_i, data_o)
  // ready_next_o is the next clock's ready_o (unless a reset comes between).
  logic ready_next_q;
  always_ff @(posedge clk_i) ready_next_q <= rst_ni ? ready_next_o : 1'b1;
  always_comb if (past_q && rst_ni) assert (ready_o == ready_next_q);

  (* hierconn *) logic [CountBits-1:0]  \u_dut.cnt_q ;
  (* hierconn *) logic                \u_dut.room_q ;
  (* hierconn *) logic [PointerBits-1:0]  \u_dut.rd_q ;
  (* hierconn *) logic [PointerBits-1:0]  \u_dut.wr_q ;
  (* hierconn *) logic [DataBits-1:0] \u_dut.head_q ;
  (* hierconn *) logic [DataBits-1:0] \u_dut.mem_q[0] ;
  (* hierconn *) logic [DataBits-1:0] \u_dut.mem_q[1] ;
  (* hierconn *) logic [DataBits-1:0] \u_dut.mem_q[2] ;
  (* hierconn *) logic [DataBits-1:0] \u_dut.mem_q[3] ;
  logic [DataBits-1:0] slot [4];
  assign slot[0] = \u_dut.mem_q[0] ;
  assign slot[1] = \u_dut.mem_q[1] ;
  assign slot[2] = \u_dut.mem_q[2] ;
  assign slot[3] = \u_dut.mem_q[3] ;

  logic [DataBits-1:0] occupancy;
  assign occupancy = n_in_q - n_out_q;

  // (p + k) mod Depth for p, k < Depth, without a divider (which would swamp the SAT problem).
  function automatic int unsigned wrap(int unsigned p, int unsigned k);
    wrap = (p + k >= Depth) ? p + k - Depth : p + k;
  endfunction

  always_comb begin
    // The input tags beats in order: data is the sequence number of the beat.
    if (valid_i) assume (data_i == n_in_q);
    if (rst_ni) begin
      // No drop, no duplicate, in order: the head beat is the next one expected.
      if (valid_o) assert (data_o == n_out_q);
      // Beats in flight are those the FIFO counts, at most Depth; it offers one whenever it
      // holds one, and takes one whenever it has room.
      assert (occupancy == DataBits'(\u_dut.cnt_q ));
      assert (occupancy <= DataBits'(Depth));
      assert (valid_o == (occupancy != '0));
      assert (ready_o == (occupancy != DataBits'(Depth)));
      // Induction invariants: pointers in range, the write pointer cnt slots after the read
      // pointer, and the k-th occupied slot holds beat n_out + k.
      assert (\u_dut.room_q == (\u_dut.cnt_q != CountBits'(Depth)));
      assert (32'(\u_dut.rd_q ) < Depth);
      assert (32'(\u_dut.wr_q ) < Depth);
      assert (wrap(32'(\u_dut.rd_q ), 32'(\u_dut.cnt_q )) == 32'(\u_dut.wr_q ));
      for (int k = 0; k < Depth; k++)
        if (k < 32'(\u_dut.cnt_q ))
          assert (slot[wrap(32'(\u_dut.rd_q ), k)] == n_out_q + DataBits'(k));
      // The head register holds the head slot's word.
      if (\u_dut.cnt_q != '0) assert (\u_dut.head_q == n_out_q);
    end
  end
endmodule
