// line_buffer: the board's dual-clock line buffer, Slots lines of MaxWidth 24-bit pixels in
// block RAM. Write port on clk_wr_i (the pipeline's clock): one pixel per clock at (slot, x).
// Read port on clk_rd_i (the pixel clock): rd_data_o is a register loaded with (slot, x) of the
// clock before (latency 1). The data crosses clock domains only through the RAM; neither port's
// address leaves its domain (the line counts that free and fill slots cross by gray_sync).
// Each slot holds 2^ceil(log2(MaxWidth)) words so that the address is {slot, x}.

module line_buffer #(
  parameter int unsigned Slots    = 2,    // a power of two, at least 2
  parameter int unsigned MaxWidth = 320,  // pixels per line
  parameter int unsigned DataBits = 24,
  localparam int unsigned SlotBits = $clog2(Slots),
  localparam int unsigned XBits    = $clog2(MaxWidth)
) (
  input  logic                clk_wr_i,
  input  logic                wr_en_i,
  input  logic [SlotBits-1:0] wr_slot_i,
  input  logic [XBits-1:0]    wr_x_i,
  input  logic [DataBits-1:0] wr_data_i,
  input  logic                clk_rd_i,
  input  logic [SlotBits-1:0] rd_slot_i,
  input  logic [XBits-1:0]    rd_x_i,
  output logic [DataBits-1:0] rd_data_o  // (rd_slot_i, rd_x_i) of the previous clk_rd_i edge
);
  logic [DataBits-1:0] mem_q [Slots << XBits];
  logic [DataBits-1:0] rd_data_q;

  always_ff @(posedge clk_wr_i) begin
    if (wr_en_i) mem_q[{wr_slot_i, wr_x_i}] <= wr_data_i;
  end

  // crossing: dual-clock block RAM (data written on clk_wr_i, read on clk_rd_i)
  always_ff @(posedge clk_rd_i) begin
    rd_data_q <= mem_q[{rd_slot_i, rd_x_i}];
  end

  assign rd_data_o = rd_data_q;
endmodule
