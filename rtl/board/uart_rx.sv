// uart_rx: an 8N1 serial receiver on a clock that is not a multiple of the bit rate.
// The line (asynchronous) crosses into clk_i through two flip-flops; a falling edge of the
// synchronized line starts a byte, and a fractional accumulator (Baud added each clock, modulo
// ClockHz, both divided by their greatest common divisor) marks the middle of each bit: the start
// bit (high there: a glitch, ignored), eight data bits LSB first, the stop bit. valid_o is high for
// one clock, the clock after the stop bit's sample, with data_o (registered); error_o with it when
// the stop bit is low (a framing error: the byte is not to be trusted, and the receiver waits for
// the line to go high before the next start). Sampling error: each sample falls within one clock
// either side of the bit's middle (the edge is seen up to a clock late, the accumulator starts a
// clock ahead), so at 78.75 MHz and 3 Mbaud (26.25 clocks a bit) within +-3.8 % of a bit; a
// sender whose rate is off by e drifts 9.5 e bits by the stop bit, so bytes are received while
// 9.5 |e| + 0.038 < 0.5, |e| up to 4.8 %. Registered: every output.

module uart_rx #(
  parameter int unsigned ClockHz = 78_750_000,  // clk_i
  parameter int unsigned Baud    = 3_000_000
) (
  input  logic       clk_i,
  input  logic       rst_ni,   // active-low synchronous reset
  input  logic       rx_i,     // the line, asynchronous to clk_i (idle high)
  output logic [7:0] data_o,   // the byte, LSB received first
  output logic       valid_o,  // one clock: a byte's stop bit was sampled
  output logic       error_o   // with valid_o: the stop bit was low
);
  function automatic int unsigned gcd(int unsigned a, int unsigned b);
    int unsigned x, y, t;
    x = a;
    y = b;
    for (int i = 0; i < 64; i++) begin
      if (y != 0) begin
        t = x % y;
        x = y;
        y = t;
      end
    end
    gcd = x;
  endfunction

  localparam int unsigned Divisor  = gcd(ClockHz, Baud);
  localparam int unsigned Modulus  = ClockHz / Divisor;  // one bit, in accumulator units
  localparam int unsigned Step     = Baud / Divisor;     // one clock, in accumulator units
  localparam int unsigned AccBits  = $clog2(Modulus + Step + 1);
  // Half a bit and one clock: the first sample (the start bit's middle) comes half a bit after
  // the edge, less the clock the edge may have been seen late.
  localparam int unsigned StartAcc = Modulus / 2 + Step;

  (* async_reg = "true" *) logic meta_q;
  (* async_reg = "true" *) logic sync_q;
  logic               last_q;     // sync_q a clock ago: a falling edge starts a byte
  logic               busy_q;     // receiving a byte
  logic [3:0]         bit_q;      // 0 start, 1..8 data, 9 stop
  logic [AccBits-1:0] acc_q;
  logic [AccBits-1:0] acc_next;
  logic               sample;     // this clock is the middle of bit bit_q
  logic [7:0]         data_q;
  logic               valid_q, error_q;

  assign acc_next = acc_q + AccBits'(Step);
  assign sample   = busy_q && acc_next >= AccBits'(Modulus);

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      meta_q  <= 1'b1;
      sync_q  <= 1'b1;
      last_q  <= 1'b1;
      busy_q  <= 1'b0;
      valid_q <= 1'b0;
      error_q <= 1'b0;
    end else begin
      meta_q  <= rx_i;  // crossing: asynchronous line, first of two flip-flops
      sync_q  <= meta_q;
      last_q  <= sync_q;
      valid_q <= 1'b0;
      error_q <= 1'b0;
      if (!busy_q) begin
        if (last_q && !sync_q) busy_q <= 1'b1;
      end else if (sample) begin
        if (bit_q == 4'd0 && sync_q) busy_q <= 1'b0;  // no start bit at its middle: a glitch
        if (bit_q == 4'd9) begin
          busy_q  <= 1'b0;
          valid_q <= 1'b1;
          error_q <= !sync_q;
        end
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!busy_q) begin
      acc_q <= AccBits'(StartAcc);
      bit_q <= 4'd0;
    end else if (sample) begin
      acc_q <= acc_next - AccBits'(Modulus);
      bit_q <= bit_q + 4'd1;
      if (bit_q >= 4'd1 && bit_q <= 4'd8) data_q <= {sync_q, data_q[7:1]};
    end else begin
      acc_q <= acc_next;
    end
  end

  assign data_o  = data_q;
  assign valid_o = valid_q;
  assign error_o = error_q;

  if (ClockHz < 8 * Baud) begin : g_check_rate
    $error("uart_rx: ClockHz must be at least 8 x Baud (a sample within one clock of a bit's middle)");
  end
endmodule
