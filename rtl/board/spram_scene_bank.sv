// spram_scene_bank: the iCEBreaker's scene bank in the UP5K's four SPRAMs (SB_SPRAM256KA, 16,384
// words of 16 bits each) side by side: 16,384 words of 64 bits, SPRAM n holding bits 16 n + 15 ..
// 16 n of every word (docs/reference/board.md, "iCEBreaker"). Both ports on clk_i, one access a
// clock: with wr_en_i, wr_data_i goes to lane wr_lane_i (bits 16 wr_lane_i + 15 .. 16 wr_lane_i) of
// word wr_addr_i, the other lanes untouched; else with rd_en_i word rd_addr_i is read into
// rd_data_o (latency 1), which holds in every clock without a read (the SPRAMs' output registers).
// Registered: rd_data_o (inside the SPRAMs); the SPRAMs' ports are a multiplexer from the inputs.

module spram_scene_bank #(
  localparam int unsigned AddrBits = 14
) (
  input  logic                clk_i,
  input  logic                rd_en_i,
  input  logic [AddrBits-1:0] rd_addr_i,
  output logic [63:0]         rd_data_o,
  input  logic                wr_en_i,
  input  logic [1:0]          wr_lane_i,
  input  logic [AddrBits-1:0] wr_addr_i,
  input  logic [15:0]         wr_data_i
);
  logic [AddrBits-1:0] addr;
  assign addr = wr_en_i ? wr_addr_i : rd_addr_i;

  for (genvar n = 0; n < 4; n++) begin : g_lane
    SB_SPRAM256KA u_spram (
      .ADDRESS   (addr),
      .DATAIN    (wr_data_i),
      .MASKWREN  (4'b1111),
      .WREN      (wr_en_i),
      .CHIPSELECT(wr_en_i ? wr_lane_i == 2'(n) : rd_en_i),
      .CLOCK     (clk_i),
      .STANDBY   (1'b0),
      .SLEEP     (1'b0),
      .POWEROFF  (1'b1),
      .DATAOUT   (rd_data_o[16*n +: 16])
    );
  end
endmodule
