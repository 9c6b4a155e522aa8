// line_credit: the board's back-pressure on the pipeline's pixels -- ready_o while the slot of the
// line being written is free, (written - released) < LineSlots; ready_o and the count are
// registers, so ready_o changes the clock after a take or a release (latency 1, every output
// registered).
//
// The difference is a register, in_use_q, stepped +1 by a line's last pixel taken (take_i) and -1
// by a release (release_i). Each clock moves it by -1, 0 or +1, so both next values are chosen
// from three candidates computed from in_use_q alone (one carry chain each, against a constant) by
// take_i and release_i, which only select: the path from the pipeline's output handshake back to
// these registers is one multiplexer, and no adder follows another.
module line_credit #(
  parameter int unsigned CountBits = 12,
  parameter int unsigned LineSlots = 2
) (
  input  logic clk_i,
  input  logic rst_ni,   // synchronous, active low: no line in use
  input  logic take_i,   // a line's last pixel taken this clock
  input  logic release_i,  // a slot released this clock
  output logic ready_o
);
  logic [CountBits-1:0] in_use_q, in_use_down, in_use_up, in_use_d;
  logic                 room_q, room_down, room_same, room_up, room_d;
  assign in_use_down = in_use_q - 1'b1;
  assign in_use_up   = in_use_q + 1'b1;
  assign room_down   = $signed(in_use_q) < $signed(CountBits'(LineSlots + 1));
  assign room_same   = $signed(in_use_q) < $signed(CountBits'(LineSlots));
  assign room_up     = $signed(in_use_q) < $signed(CountBits'(LineSlots - 1));
  assign ready_o     = room_q;

  always_comb begin
    unique case ({take_i, release_i})
      2'b10:   begin in_use_d = in_use_up;   room_d = room_up;   end
      2'b01:   begin in_use_d = in_use_down; room_d = room_down; end
      default: begin in_use_d = in_use_q;    room_d = room_same; end  // neither, or both
    endcase
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      in_use_q <= '0;
      room_q   <= 1'b1;
    end else begin
      in_use_q <= in_use_d;
      room_q   <= room_d;
    end
  end
endmodule
