// compact_schedule: the control of a compact block that works in a fixed schedule of 5-clock
// periods (compact_normalizer, compact_phong_shader): the clock within the period, the period
// count that names each item's RAM slot, one valid bit per period an item spends inside, and the
// output register's valid. Cycle twin: model/twins/compact_schedule_timing.hpp.
// An item is taken in a period's last clock (ready_o = ph_o == 4, a flop); it moves to its next
// period at each period's end (tick_o) and is loaded into the parent's output register (load_o)
// in phase LoadPhase of its last period. Every register of the parent moves on en_o, low only in
// a clock whose load finds the output holding an item not taken: then everything waits a clock.
// Latency 0: the control of the parent's registers, which take their enables from it.
// Registered: ph_o, pc_o, ready_o, valid_o.
module compact_schedule #(
  parameter int Periods   = 7,  // periods an item spends inside, >= 2
  parameter int LoadPhase = 1,  // the clock of the last period that loads the output, 0..3
  parameter int SlotBits  = 3   // pc_o's width: 2^SlotBits >= Periods
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                valid_i,       // an item is offered
  output logic                ready_o,       // it is taken this clock
  output logic                ready_next_o,  // ready_o on the next clock
  output logic                valid_o,       // the output register holds an item
  input  logic                ready_i,       // the consumer takes it
  output logic [2:0]          ph_o,          // the clock within the period, 0..4
  output logic [SlotBits-1:0] pc_o,          // the period count: an item in its k-th period has
                                             // slot pc_o - k
  output logic                en_o,          // every register of the parent moves
  output logic                tick_o,        // en_o in a period's last clock
  output logic                load_o         // the output register loads (en_o included)
);
  localparam int Period = 5;
  logic [2:0]          ph_q;
  logic [SlotBits-1:0] pc_q;
  logic [Periods-1:0]  v_q;      // [k]: the item in its k-th period is valid
  logic                valid_q;
  logic                out_load; // the last period's item reaches the output this clock

  assign out_load     = ph_q == 3'(LoadPhase) && v_q[Periods-1];
  assign en_o         = !(out_load && valid_q && !ready_i);
  assign tick_o       = en_o && ph_q == 3'(Period - 1);
  assign load_o       = en_o && out_load;
  assign ready_o      = ph_q == 3'(Period - 1);  // en_o is high in a period's last clock
  assign ready_next_o = ph_q == 3'(Period - 2) && en_o;
  assign valid_o      = valid_q;
  assign ph_o         = ph_q;
  assign pc_o         = pc_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      ph_q    <= '0;
      pc_q    <= '0;
      v_q     <= '0;
      valid_q <= 1'b0;
    end else begin
      if (en_o) begin
        ph_q <= tick_o ? '0 : ph_q + 3'd1;
        if (tick_o) begin
          pc_q <= pc_q + 1'b1;
          v_q  <= {v_q[Periods-2:0], valid_i};
        end
      end
      if (load_o) valid_q <= 1'b1;
      else if (ready_i) valid_q <= 1'b0;
    end
  end
endmodule
