// SB_SPRAM256KA: simulation stand-in for the iCE40 UltraPlus single-port RAM, 16,384 words of 16
// bits (the synthesis flow uses the device's own). On a rising CLOCK edge with CHIPSELECT high:
// WREN high writes DATAIN into the nibbles MASKWREN selects; WREN low loads word ADDRESS into
// DATAOUT (latency 1). With CHIPSELECT low DATAOUT holds, as the device's does. STANDBY, SLEEP and
// POWEROFF are accepted at their running values (0, 0, 1) and otherwise ignored; the words start
// at 0 (the device's are undefined until written).

/* verilator lint_off UNUSEDSIGNAL */
module SB_SPRAM256KA (
  input  logic [13:0] ADDRESS,
  input  logic [15:0] DATAIN,
  input  logic [3:0]  MASKWREN,
  input  logic        WREN,
  input  logic        CHIPSELECT,
  input  logic        CLOCK,
  input  logic        STANDBY,
  input  logic        SLEEP,
  input  logic        POWEROFF,
  output logic [15:0] DATAOUT
);
  logic [15:0] mem_q [16384];
  logic [15:0] out_q = '0;

  initial for (int i = 0; i < 16384; i++) mem_q[i] = '0;

  always_ff @(posedge CLOCK) begin
    if (CHIPSELECT && WREN) begin
      for (int n = 0; n < 4; n++)
        if (MASKWREN[n]) mem_q[ADDRESS][4*n +: 4] <= DATAIN[4*n +: 4];
    end
    if (CHIPSELECT && !WREN) out_q <= mem_q[ADDRESS];
  end
  assign DATAOUT = out_q;
endmodule
/* verilator lint_on UNUSEDSIGNAL */
