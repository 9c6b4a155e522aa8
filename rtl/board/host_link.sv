// host_link: frames from the host over the serial line into the scene bank the frame player is
// not reading (docs/reference/board.md, "Host link"): uart_rx (the line through two flip-flops,
// 8N1 at Baud) feeding scene_loader (packets to bank words, the CRC, the swap at begin_i).
// Latency: a word is written 2 clocks after its last byte's stop-bit sample (uart_rx's output
// register, then the write register). Registered: every output.

module host_link #(
  parameter int unsigned ClockHz     = 78_750_000,
  parameter int unsigned Baud        = 3_000_000,
  parameter int unsigned BankWords   = 512,
  parameter int unsigned WordBits    = 64,
  parameter int unsigned TimeoutBits = 20,
  localparam int unsigned AddrBits = $clog2(BankWords)
) (
  input  logic                clk_i,
  input  logic                rst_ni,         // active-low synchronous reset
  input  logic                rx_i,           // the serial line, asynchronous (idle high)
  input  logic                begin_i,        // one clock: the frame player starts a frame
  output logic                bank_active_o,  // the bank the frame player reads
  output logic                wr_en_o,
  output logic                wr_bank_o,
  output logic [AddrBits-1:0] wr_addr_o,
  output logic [WordBits-1:0] wr_data_o,
  output logic [15:0]         frame_count_o,  // good packets (wraps)
  output logic [15:0]         error_count_o   // dropped packets (saturates)
);
  logic [7:0] rx_data;
  logic       rx_valid, rx_error;

  // crossing: the asynchronous serial line, two flip-flops inside uart_rx.
  uart_rx #(.ClockHz(ClockHz), .Baud(Baud)) u_uart_rx (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .rx_i   (rx_i),
    .data_o (rx_data),
    .valid_o(rx_valid),
    .error_o(rx_error)
  );

  scene_loader #(.BankWords(BankWords), .WordBits(WordBits), .TimeoutBits(TimeoutBits)) u_scene_loader (
    .clk_i        (clk_i),
    .rst_ni       (rst_ni),
    .byte_i       (rx_data),
    .byte_valid_i (rx_valid),
    .byte_error_i (rx_error),
    .begin_i      (begin_i),
    .bank_active_o(bank_active_o),
    .wr_en_o      (wr_en_o),
    .wr_bank_o    (wr_bank_o),
    .wr_addr_o    (wr_addr_o),
    .wr_data_o    (wr_data_o),
    .frame_count_o(frame_count_o),
    .error_count_o(error_count_o)
  );
endmodule
