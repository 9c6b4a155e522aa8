// stream_skid_formal: proves rtl/stream_skid.sv holds valid and data until ready and passes every
// beat once, in order, unchanged: each input beat carries its sequence number, the output must
// carry the next one expected, and beats in minus beats out is the skid slot's fill (0 or 1).
// ready_o is the empty slot; a full slot offers its beat. Induction invariants tie the slot's
// flag and word to the beat in flight. The DUT's internals are read through yosys hierconn wires
// (flatten connects `\u_dut.x` to the instance's x), so rtl/ carries no formal code.
`include "formal_stream.svh"

module stream_skid_formal #(
  parameter int unsigned DataBits = 3  // >= 2: the tags of the beats around the slot differ
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic [DataBits-1:0] data_i,
  input  logic                valid_i,
  input  logic                ready_i
);
  logic                ready_o, valid_o;
  logic [DataBits-1:0] data_o;
  stream_skid #(.DataBits(DataBits)) u_dut (.*);

  `FORMAL_PAST
  `FORMAL_COUNT(n_in_q, DataBits, valid_i, ready_o)
  `FORMAL_COUNT(n_out_q, DataBits, valid_o, ready_i)
  `FORMAL_ASSUME_HOLD(in, valid_i, ready_o, data_i)
  `FORMAL_ASSERT_HOLD(out, valid_o, ready_i, data_o)

  (* hierconn *) logic                \u_dut.full_q ;
  (* hierconn *) logic [DataBits-1:0] \u_dut.skid_q ;

  logic [DataBits-1:0] occupancy;
  assign occupancy = n_in_q - n_out_q;

  always_comb begin
    // The input tags beats in order: data is the sequence number of the beat.
    if (valid_i) assume (data_i == n_in_q);
    if (rst_ni) begin
      // No drop, no duplicate, in order: the output beat is the next one expected.
      if (valid_o) assert (data_o == n_out_q);
      // At most one beat inside, the one in the slot; the slot's flag is the registered ready.
      assert (occupancy == DataBits'(\u_dut.full_q ));
      assert (ready_o == !\u_dut.full_q );
      // A full slot offers its beat (induction: the word in the slot is the beat expected next).
      if (\u_dut.full_q ) assert (valid_o && \u_dut.skid_q == n_out_q);
      // Latency 0: an empty slot passes the input straight through.
      if (!\u_dut.full_q ) assert (valid_o == valid_i && (!valid_i || data_o == data_i));
    end
  end
endmodule
