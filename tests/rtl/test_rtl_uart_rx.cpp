// rtl/board/uart_rx.sv at 78.75 MHz and 3 Mbaud (26.25 clocks a bit), driven by the bit-level
// line model (testbench/board/uart_line.hpp) sampled at each rising edge at a random phase:
// random bytes back to back and with random idle gaps are received exactly, in order, with the
// sender's rate off by 0, +-2 % and +-4.5 % (the receiver's stated tolerance is 4.8 %); a byte
// whose stop bit is low is flagged and the bytes after the line goes high again are received; a
// low pulse shorter than half a bit starts nothing.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "Vuart_rx.h"
#include "board/uart_line.hpp"
#include "rtl_harness.hpp"

using namespace watkins::rtl;
using watkins::board_tb::UartLine;

namespace {

constexpr double ClockHz = 78.75e6, Baud = 3e6;

struct Received {
  std::vector<std::uint8_t> bytes;
  std::vector<std::size_t> errors;  // indices of bytes flagged with a framing error
};

// Clocks the receiver until the line is idle past its last byte; rising edge n samples the line
// at phase + n / ClockHz.
Received run(Harness<Vuart_rx>& h, const UartLine& line, double phase) {
  Received r;
  h.dut.rx_i = 1;
  h.reset();
  const auto clocks = static_cast<std::uint64_t>((line.end_s() + 20 * line.bit_s()) * ClockHz) + 1;
  for (std::uint64_t n = 0; n < clocks; ++n) {
    h.dut.rx_i = line.level(phase + static_cast<double>(n) / ClockHz);
    h.tick();
    if (h.dut.valid_o) {
      if (h.dut.error_o) r.errors.push_back(r.bytes.size());
      r.bytes.push_back(static_cast<std::uint8_t>(h.dut.data_o));
    }
  }
  return r;
}

void expect_received(double rate_error, double gap_bits, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint8_t> bytes(3000);
  for (auto& b : bytes) b = static_cast<std::uint8_t>(rng());
  UartLine line(Baud * (1 + rate_error));
  const double t0 = 3e-6;
  if (gap_bits == 0) {
    line.send(bytes, t0);
  } else {
    std::uniform_real_distribution<double> gap(0, gap_bits);
    double t = t0;
    for (std::uint8_t b : bytes) t = line.send({b}, t) + gap(rng) * line.bit_s();
  }
  Harness<Vuart_rx> h;
  const double phase = std::uniform_real_distribution<double>(0, 1 / ClockHz)(rng);
  const Received r = run(h, line, phase);
  EXPECT_TRUE(r.errors.empty()) << "rate error " << rate_error << ": framing errors, first at byte " << r.errors.front();
  ASSERT_EQ(r.bytes.size(), bytes.size()) << "rate error " << rate_error;
  std::size_t bad = 0;
  for (std::size_t i = 0; i < bytes.size(); ++i)
    if (r.bytes[i] != bytes[i] && ++bad <= 3)
      ADD_FAILURE() << "rate error " << rate_error << ": byte " << i << " received " << int(r.bytes[i]) << ", sent "
                    << int(bytes[i]);
  EXPECT_EQ(bad, 0u);
}

TEST(RtlUartRx, BackToBackBytesAtRateErrors) {
  std::uint64_t seed = 1;
  for (double e : {0.0, 0.02, -0.02, 0.045, -0.045}) expect_received(e, 0, seed++);
}

TEST(RtlUartRx, BytesWithIdleGaps) {
  std::uint64_t seed = 11;
  for (double e : {0.0, 0.02, -0.02}) expect_received(e, 3.7, seed++);
}

TEST(RtlUartRx, LowStopBitIsFlaggedAndTheLineRecovers) {
  UartLine line(Baud);
  line.send({0x12, 0x34}, 1e-6);
  line.break_last_stop_bit();  // 0x34's stop bit low
  const double t = line.end_s() + 2 * line.bit_s();  // the line high again for two bits
  line.send({0x56, 0xa5}, t);
  Harness<Vuart_rx> h;
  const Received r = run(h, line, 0.3 / ClockHz);
  ASSERT_EQ(r.bytes.size(), 4u);
  EXPECT_EQ(r.bytes[0], 0x12);
  EXPECT_EQ(r.bytes[1], 0x34);
  EXPECT_EQ(r.bytes[2], 0x56);
  EXPECT_EQ(r.bytes[3], 0xa5);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0], 1u);
}

TEST(RtlUartRx, ShortLowPulseIsNoByte) {
  Harness<Vuart_rx> h;
  h.dut.rx_i = 1;
  h.reset();
  int bytes = 0;
  for (int n = 0; n < 2000; ++n) {
    h.dut.rx_i = !(n >= 100 && n < 112);  // 12 clocks low: less than half a bit (13.1)
    h.tick();
    bytes += h.dut.valid_o;
  }
  EXPECT_EQ(bytes, 0);
}

}  // namespace
