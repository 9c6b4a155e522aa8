// edge_incrementer: steps one active edge to the next scan line, value += slope in every
// channel (wrapping at ChannelBits, as model/twins/edge_incrementer.hpp) and remaining -= 1.
// Latency 1: valid and data registered; ready_o = ready_i || !valid_o (combinational).
`include "watkins_assert.svh"

module edge_incrementer #(
  parameter int unsigned NumChannels = watkins_pkg::NumChannels,
  parameter int unsigned PayloadBits = 1  // carried unchanged (polygon id, edge id, ...)
) (
  input  logic                                                    clk_i,
  input  logic                                                    rst_ni,
  input  logic [NumChannels*watkins_pkg::ChannelBits-1:0] value_i,      // on this line
  input  logic [NumChannels*watkins_pkg::ChannelBits-1:0] slope_i,      // per line
  input  logic [watkins_pkg::LineBits-1:0]                        remaining_i,  // lines left incl. this
  input  logic [PayloadBits-1:0]                                  payload_i,
  input  logic                                                    valid_i,
  output logic                                                    ready_o,
  output logic [NumChannels*watkins_pkg::ChannelBits-1:0] value_o,      // on the next line
  output logic [NumChannels*watkins_pkg::ChannelBits-1:0] slope_o,
  output logic [watkins_pkg::LineBits-1:0]                        remaining_o,  // remaining_i - 1
  output logic                                                    retire_o,     // remaining_i <= 1: edge ends
  output logic [PayloadBits-1:0]                                  payload_o,
  output logic                                                    valid_o,
  input  logic                                                    ready_i
);
  localparam int unsigned CB = watkins_pkg::ChannelBits;

  logic load;
  assign ready_o = ready_i || !valid_o;
  assign load    = valid_i && ready_o;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) valid_o <= 1'b0;
    else if (ready_o) valid_o <= valid_i;
  end

  always_ff @(posedge clk_i) begin
    if (load) begin
      // A CB-bit sum keeps the low CB bits: the model's wrap_signed(value + slope, ChannelBits).
      for (int c = 0; c < NumChannels; c++)
        value_o[c*CB +: CB] <= value_i[c*CB +: CB] + slope_i[c*CB +: CB];
      slope_o     <= slope_i;
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
