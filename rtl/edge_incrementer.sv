// edge_incrementer: steps one active edge to the next scan line.
// value += slope in every channel slot (each wrapping at its own word, as
// model/twins/edge_incrementer.hpp does) and remaining -= 1. Channel vectors are laid out as
// watkins_pkg::slot_lo/slot_bits say.
// EdgeOrder 3 (curved edges, Whitted 1978, by forward differences): slope is {d3, d2, d1} and
// one line steps value += d1, d1 += d2, d2 += d3, all from this line's values: three adders per
// slot instead of one, no multiplier, still one edge per clock.
// Latency 1 cycle: valid and data are registered; ready_o = ready_i || !valid_o is
// combinational.
`include "watkins_assert.svh"

module edge_incrementer #(
  parameter int unsigned XBits       = watkins_pkg::ChannelBits,  // slot word widths: X,
  parameter int unsigned ZBits       = watkins_pkg::ChannelBits,  // depth,
  parameter int unsigned AttrBits    = watkins_pkg::ChannelBits,  // R G B or Nx Ny Nz
  parameter int unsigned PayloadBits = 1,  // carried unchanged (polygon id, edge id, ...)
  parameter int unsigned EdgeOrder   = 1,  // forward differences per edge: 1 (slope) or 3 (cubic)
  localparam int unsigned VectorBits = watkins_pkg::vector_bits(XBits, ZBits, AttrBits),
  localparam int unsigned SlopeBits  = EdgeOrder * VectorBits  // {d3, d2, d1}, d1 at the bottom
) (
  input  logic                              clk_i,
  input  logic                              rst_ni,
  input  logic [VectorBits-1:0]             value_i,      // on this line
  input  logic [SlopeBits-1:0]              slope_i,      // per line (order 3: {d3, d2, d1})
  input  logic [watkins_pkg::LineBits-1:0]  remaining_i,  // lines left incl. this
  input  logic [PayloadBits-1:0]            payload_i,
  input  logic                              valid_i,
  output logic                              ready_o,
  output logic [VectorBits-1:0]             value_o,      // on the next line
  output logic [SlopeBits-1:0]              slope_o,      // order 3: {d3, d2 + d3, d1 + d2}
  output logic [watkins_pkg::LineBits-1:0]  remaining_o,  // remaining_i - 1
  output logic                              retire_o,     // remaining_i <= 1: edge ends
  output logic [PayloadBits-1:0]            payload_o,
  output logic                              valid_o,
  input  logic                              ready_i
);
  logic load;
  assign ready_o = ready_i || !valid_o;
  assign load    = valid_i && ready_o;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) valid_o <= 1'b0;
    else if (ready_o) valid_o <= valid_i;
  end

  // One adder per slot, as wide as its word: a SlotBits-bit sum keeps the low SlotBits bits,
  // the model's wrap_signed(value + slope, bits[c]); no carry crosses into the next slot.
  for (genvar c = 0; c < watkins_pkg::NumChannels; c++) begin : g_slot
    localparam int unsigned SlotLow  = watkins_pkg::slot_lo(c, XBits, ZBits, AttrBits);
    localparam int unsigned SlotBits = watkins_pkg::slot_bits(c, XBits, ZBits, AttrBits);
    always_ff @(posedge clk_i) begin
      if (load) begin
        value_o[SlotLow +: SlotBits] <= value_i[SlotLow +: SlotBits]
                                      + slope_i[SlotLow +: SlotBits];
      end
    end
    if (EdgeOrder == 3) begin : g_cubic
      // The differences step with the value, each in its slot's word: modulo 2^SlotBits the sums
      // are the exact ones, so the value is right whenever it fits (scene preparation checks it
      // on every line). d3 is constant.
      localparam int unsigned D1Low = SlotLow;                   // this slot's d1,
      localparam int unsigned D2Low = VectorBits + SlotLow;      // d2
      localparam int unsigned D3Low = 2 * VectorBits + SlotLow;  // and d3
      always_ff @(posedge clk_i) begin
        if (load) begin
          slope_o[D1Low +: SlotBits] <= slope_i[D1Low +: SlotBits] + slope_i[D2Low +: SlotBits];
          slope_o[D2Low +: SlotBits] <= slope_i[D2Low +: SlotBits] + slope_i[D3Low +: SlotBits];
          slope_o[D3Low +: SlotBits] <= slope_i[D3Low +: SlotBits];
        end
      end
    end else begin : g_linear
      always_ff @(posedge clk_i) begin
        if (load) slope_o[SlotLow +: SlotBits] <= slope_i[SlotLow +: SlotBits];
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (load) begin
      remaining_o <= remaining_i - 1'b1;
      // The model retires when the decremented count is <= 0; n = 0 (malformed) retires too.
      retire_o    <= (remaining_i <= watkins_pkg::LineBits'(1));
      payload_o   <= payload_i;
    end
  end

  `WATKINS_ASSERT_HOLD(a_in_hold, valid_i, ready_o, {value_i, slope_i, remaining_i, payload_i})
  `WATKINS_ASSERT_HOLD(a_out_hold, valid_o, ready_i, {value_o, slope_o, remaining_o, retire_o, payload_o})
  `WATKINS_COVER(c_retire, valid_o && retire_o)
endmodule
