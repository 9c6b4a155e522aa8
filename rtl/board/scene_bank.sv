// scene_bank: the scene in block RAM, Banks (2, or 1 on a board without a host link) banks of
// Words words of Bits bits (docs/reference/board.md, "Scene banks"). Bank 0 starts with the words
// of File ($readmemh, one hexadecimal word a line, at most Words lines); bank 1 starts empty; with
// one bank rd_bank_i and wr_bank_i are ignored. One read port: rd_data_o
// is a register loaded with word rd_addr_i of bank rd_bank_i on a clock with rd_en_i (latency 1;
// it holds otherwise). One write port (the host link's): word wr_addr_i of bank wr_bank_i on a
// clock with wr_en_i. Both ports on clk_i. In simulation, +watkins_bank=FILE replaces File.

module scene_bank #(
  parameter int unsigned Words = 512,  // per bank, a power of two
  parameter int unsigned Bits  = 64,
  parameter int unsigned Banks = 2,    // 1 or 2
  parameter              File  = "",   // bank 0's $readmemh file; "" leaves it empty
  localparam int unsigned AddrBits = $clog2(Words),
  localparam int unsigned BankBits = Banks > 1 ? 1 : 0
) (
  input  logic                clk_i,
  input  logic                rd_en_i,
  input  logic                rd_bank_i,
  input  logic [AddrBits-1:0] rd_addr_i,
  output logic [Bits-1:0]     rd_data_o,
  input  logic                wr_en_i,
  input  logic                wr_bank_i,
  input  logic [AddrBits-1:0] wr_addr_i,
  input  logic [Bits-1:0]     wr_data_i
);
  logic [Bits-1:0] mem_q [Banks * Words];
  logic [Bits-1:0] rd_data_q;
  logic [AddrBits+BankBits-1:0] rd_word, wr_word;  // {bank, address}, or the address alone

  if (Banks > 1) begin : g_two_banks
    assign rd_word = {rd_bank_i, rd_addr_i};
    assign wr_word = {wr_bank_i, wr_addr_i};
  end else begin : g_one_bank
    /* verilator lint_off UNUSEDSIGNAL */
    logic unused_banks;
    /* verilator lint_on UNUSEDSIGNAL */
    assign unused_banks = rd_bank_i ^ wr_bank_i;
    assign rd_word = rd_addr_i;
    assign wr_word = wr_addr_i;
  end

  // Bank 0 is the lower half, so the file's word k is word k of bank 0.
`ifdef SYNTHESIS
  initial begin
    for (int i = 0; i < Banks * Words; i++) mem_q[i] = '0;
    if (File != "") $readmemh(File, mem_q);
  end
`else
  // In simulation a bench may start bank 0 from another file without a rebuild:
  // +watkins_bank=FILE on the simulator's command line replaces File.
  string bank_file;
  initial begin
    for (int i = 0; i < Banks * Words; i++) mem_q[i] = '0;
    bank_file = File;
    if ($value$plusargs("watkins_bank=%s", bank_file)) ;
    if (bank_file != "") $readmemh(bank_file, mem_q);
  end
`endif

  always_ff @(posedge clk_i) begin
    if (wr_en_i) mem_q[wr_word] <= wr_data_i;
    if (rd_en_i) rd_data_q <= mem_q[rd_word];
  end

  assign rd_data_o = rd_data_q;

  if (Banks != 1 && Banks != 2) begin : g_check_banks
    $error("scene_bank: Banks must be 1 or 2");
  end
endmodule
