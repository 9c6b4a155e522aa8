// edge_incrementer: steps one active edge to the next scan line, value += slope in every
// channel slot (each wrapping at its own word, as model/twins/edge_incrementer.hpp) and
// remaining -= 1. Channel vectors as watkins_pkg::slot_lo/slot_bits lay them out.
// EdgeOrder 3 (curved edges, Whitted 1978, by forward differences): slope is {d3, d2, d1} and
// one line steps value += d1, d1 += d2, d2 += d3, all from this line's values: three adders per
// slot instead of one, no multiplier, still one edge per clock.
// Latency 1: valid and data registered; ready_o = ready_i || !valid_o (combinational).
`include "watkins_assert.svh"

module edge_incrementer #(
  parameter int unsigned XBits       = watkins_pkg::ChannelBits,  // slot word widths: X,
  parameter int unsigned ZBits       = watkins_pkg::ChannelBits,  // depth,
  parameter int unsigned AttrBits    = watkins_pkg::ChannelBits,  // R G B or Nx Ny Nz
  parameter int unsigned PayloadBits = 1,  // carried unchanged (polygon id, edge id, ...)
  parameter int unsigned EdgeOrder   = 1,  // forward differences per edge: 1 (slope) or 3 (cubic)
  localparam int unsigned VB = watkins_pkg::vector_bits(XBits, ZBits, AttrBits),
  localparam int unsigned DB = EdgeOrder * VB  // {d3, d2, d1}, d1 at the bottom
) (
  input  logic                              clk_i,
  input  logic                              rst_ni,
  input  logic [VB-1:0]                     value_i,      // on this line
  input  logic [DB-1:0]                     slope_i,      // per line (order 3: {d3, d2, d1})
  input  logic [watkins_pkg::LineBits-1:0]  remaining_i,  // lines left incl. this
  input  logic [PayloadBits-1:0]            payload_i,
  input  logic                              valid_i,
  output logic                              ready_o,
  output logic [VB-1:0]                     value_o,      // on the next line
  output logic [DB-1:0]                     slope_o,      // order 3: {d3, d2 + d3, d1 + d2}
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

  // One adder per slot, as wide as its word: a W-bit sum keeps the low W bits, the model's
  // wrap_signed(value + slope, bits[c]); no carry crosses into the next slot.
  for (genvar c = 0; c < watkins_pkg::NumChannels; c++) begin : g_slot
    localparam int unsigned Lo = watkins_pkg::slot_lo(c, XBits, ZBits, AttrBits);
    localparam int unsigned W  = watkins_pkg::slot_bits(c, XBits, ZBits, AttrBits);
    always_ff @(posedge clk_i) begin
      if (load) value_o[Lo +: W] <= value_i[Lo +: W] + slope_i[Lo +: W];
    end
    if (EdgeOrder == 3) begin : g_cubic
      // The differences step with the value, each in its slot's word: modulo 2^W the sums are
      // the exact ones, so the value is right whenever it fits (scene preparation checks it on
      // every line). d3 is constant.
      always_ff @(posedge clk_i) begin
        if (load) begin
          slope_o[Lo +: W]          <= slope_i[Lo +: W] + slope_i[VB + Lo +: W];
          slope_o[VB + Lo +: W]     <= slope_i[VB + Lo +: W] + slope_i[2 * VB + Lo +: W];
          slope_o[2 * VB + Lo +: W] <= slope_i[2 * VB + Lo +: W];
        end
      end
    end else begin : g_linear
      always_ff @(posedge clk_i) begin
        if (load) slope_o[Lo +: W] <= slope_i[Lo +: W];
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
