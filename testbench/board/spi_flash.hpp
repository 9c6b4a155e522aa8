// A pin-level model of the iCEBreaker's SPI flash (a W25Q128JV) as flash_loader uses it: SPI mode
// 0, the select low for a command, bits in on the clock's rising edges and out on its falling
// ones, most significant first. Release Power-down (0xAB) is taken and does nothing here; Read
// Data (0x03, a 24-bit address) puts out the bytes from the address on, one bit per falling edge
// from the falling edge after the address's last bit, 0xFF outside `bytes`. Any other command is
// counted in bad_commands and answered with nothing. The bench calls pins() with the pins after
// every clock edge of the FPGA and drives miso() into the FPGA before its next rising edge.
#pragma once

#include <cstdint>
#include <vector>

namespace watkins::board_tb {

class SpiFlash {
 public:
  // `bytes` at flash addresses base .. base + size - 1.
  SpiFlash(std::vector<std::uint8_t> bytes, long long base) : bytes_(std::move(bytes)), base_(base) {}

  void pins(bool ss_n, bool sck, bool mosi) {
    if (ss_n) {
      if (in_bits_ >= 8 && command() != 0x03 && command() != 0xAB) ++bad_commands_;
      in_bits_ = 0;
      head_ = 0;
      sck_ = sck;
      return;
    }
    if (sck && !sck_) {  // rising: a bit in
      if (in_bits_ < 32) head_ = (head_ << 1) | (mosi ? 1u : 0u);
      ++in_bits_;
    } else if (!sck && sck_ && in_bits_ >= 32 && command() == 0x03) {  // falling: a bit out
      const long long bit = in_bits_ - 32;  // the data bits already put out before this one
      const long long at = static_cast<long long>(head_ & 0xFFFFFFu) + bit / 8 - base_;
      const std::uint8_t byte = at >= 0 && at < static_cast<long long>(bytes_.size()) ? bytes_[std::size_t(at)] : 0xFF;
      miso_ = (byte >> (7 - bit % 8)) & 1;
      ++reads_;
    }
    sck_ = sck;
  }
  bool miso() const { return miso_; }
  long long bits_read() const { return reads_; }
  long long bad_commands() const { return bad_commands_; }

 private:
  std::uint32_t command() const { return in_bits_ >= 32 ? head_ >> 24 : head_ >> (in_bits_ - 8); }

  std::vector<std::uint8_t> bytes_;
  long long base_;
  bool sck_ = false, miso_ = false;
  long long in_bits_ = 0;  // bits taken since the select fell
  std::uint32_t head_ = 0;  // the first 32 of them
  long long reads_ = 0, bad_commands_ = 0;
};

}  // namespace watkins::board_tb
