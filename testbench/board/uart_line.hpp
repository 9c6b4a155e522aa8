// A bit-level model of an 8N1 serial line (the FT231X's transmit line, the board's ftdi_txd):
// bytes queued at a bit rate, each a start bit (low), eight data bits LSB first and a stop bit
// (high); the line is high between bytes. level(t) is the line at time t (seconds), so a bench
// samples it on its own clock, at any phase and at a rate that is not the receiver's.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace watkins::board_tb {

class UartLine {
 public:
  explicit UartLine(double baud) : bit_s_(1.0 / baud) {}

  // Queues `bytes` back to back, the first starting at `at_s` or when the line is free, whichever
  // is later; gap_bits of idle line after each byte. Returns the time the last stop bit ends.
  double send(const std::vector<std::uint8_t>& bytes, double at_s = 0, double gap_bits = 0) {
    double t = std::max(at_s, end_s_);
    for (std::uint8_t b : bytes) {
      bytes_.push_back({t, static_cast<std::uint16_t>((1u << 9) | (unsigned(b) << 1))});
      t += (10 + gap_bits) * bit_s_;
    }
    end_s_ = t;
    return t;
  }
  // The stop bit of the last byte queued low (a framing error).
  void break_last_stop_bit() {
    if (!bytes_.empty()) bytes_.back().bits &= 0x1ff;
  }
  // The line at t; calls with t not decreasing are constant time.
  bool level(double t) const {
    if (bytes_.empty() || t < bytes_.front().start) return true;
    if (bytes_[cursor_].start > t) {
      const auto it = std::upper_bound(bytes_.begin(), bytes_.end(), t,
                                       [](double v, const Byte& b) { return v < b.start; });
      cursor_ = static_cast<std::size_t>(it - bytes_.begin()) - 1;
    }
    while (cursor_ + 1 < bytes_.size() && bytes_[cursor_ + 1].start <= t) ++cursor_;
    const double bit = (t - bytes_[cursor_].start) / bit_s_;
    if (bit >= 10) return true;
    return (bytes_[cursor_].bits >> static_cast<int>(bit)) & 1u;
  }
  double end_s() const { return end_s_; }
  double bit_s() const { return bit_s_; }

 private:
  struct Byte {
    double start;
    std::uint16_t bits;  // bit k is the line in the k-th bit time: 0 start, 1..8 data, 9 stop
  };
  double bit_s_;
  double end_s_ = 0;
  std::vector<Byte> bytes_;
  mutable std::size_t cursor_ = 0;
};

}  // namespace watkins::board_tb
