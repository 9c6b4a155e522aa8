// edge_incrementer_formal: proves rtl/edge_incrementer.sv (slot words of 3, 4 and 5 bits) holds
// valid and its whole output until ready, and passes every beat once, in order: each input beat
// carries its sequence number as payload and as remaining count, slot c holds the tag as value
// and c + 1 as slope, so the output beat must carry the next tag expected, value tag + c + 1 in
// each slot (wrapped at its own word), slope c + 1, remaining tag - 1 and retire = tag <= 1.
// Beats in minus beats out is valid_o (one register stage).
`include "formal_stream.svh"

module edge_incrementer_formal #(
  parameter int unsigned XBits       = 3,
  parameter int unsigned ZBits       = 4,
  parameter int unsigned AttrBits    = 5,
  parameter int unsigned PayloadBits = 3,  // the tag; <= every slot width
  localparam int unsigned VectorBits = watkins_pkg::vector_bits(XBits, ZBits, AttrBits),
  localparam int unsigned LineBits   = watkins_pkg::LineBits
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic [VectorBits-1:0]  value_i,
  input  logic [VectorBits-1:0]  slope_i,
  input  logic [LineBits-1:0]    remaining_i,
  input  logic [PayloadBits-1:0] payload_i,
  input  logic                   valid_i,
  input  logic                   ready_i
);
  logic                   ready_o, valid_o, retire_o;
  logic [VectorBits-1:0]  value_o, slope_o;
  logic [LineBits-1:0]    remaining_o;
  logic [PayloadBits-1:0] payload_o;
  edge_incrementer #(
    .XBits(XBits), .ZBits(ZBits), .AttrBits(AttrBits), .PayloadBits(PayloadBits)
  ) u_dut (.*);

  `FORMAL_PAST
  `FORMAL_COUNT(n_in_q, PayloadBits, valid_i, ready_o)
  `FORMAL_COUNT(n_out_q, PayloadBits, valid_o, ready_i)
  `FORMAL_ASSUME_HOLD(in, valid_i, ready_o, {value_i, slope_i, remaining_i, payload_i})
  `FORMAL_ASSERT_HOLD(out, valid_o, ready_i, {value_o, slope_o, remaining_o, retire_o, payload_o})

  // The input beat tagged t and the output beat it must become.
  logic [VectorBits-1:0] value_in, slope_in, value_out;
  always_comb begin
    for (int unsigned c = 0; c < watkins_pkg::NumChannels; c++) begin
      for (int unsigned b = 0; b < watkins_pkg::slot_bits(c, XBits, ZBits, AttrBits); b++) begin
        value_in[watkins_pkg::slot_lo(c, XBits, ZBits, AttrBits) + b]  = 32'(n_in_q) >> b & 1;
        slope_in[watkins_pkg::slot_lo(c, XBits, ZBits, AttrBits) + b]  = (c + 1) >> b & 1;
        value_out[watkins_pkg::slot_lo(c, XBits, ZBits, AttrBits) + b] = (32'(n_out_q) + c + 1) >> b & 1;
      end
    end
  end

  always_comb begin
    if (valid_i)
      assume (payload_i == n_in_q && remaining_i == LineBits'(n_in_q) && value_i == value_in
              && slope_i == slope_in);
    if (rst_ni) begin
      assert (ready_o == (ready_i || !valid_o));
      assert (PayloadBits'(n_in_q - n_out_q) == PayloadBits'(valid_o));
      if (valid_o) begin
        assert (payload_o == n_out_q);
        assert (remaining_o == LineBits'(n_out_q) - 1'b1);
        assert (retire_o == (n_out_q <= PayloadBits'(1)));
        assert (value_o == value_out);
        // The slope passes unchanged (slope_in is the same for every tag).
        assert (slope_o == slope_in);
      end
    end
  end
endmodule
