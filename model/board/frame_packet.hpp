// The host link's packet (docs/reference/board.md, "Host link"; rtl/board/scene_loader.sv): one
// frame's bank words as the board's serial receiver takes them. A packet is the magic "WKFR",
// B (one byte: ceil(word_bits / 8), the word's bytes), W (two bytes, little-endian: the words),
// the W words of B bytes each, little-endian, and the CRC-32/ISO-HDLC of everything after the
// magic (four bytes, little-endian). The board drops a packet whose B is not its own, whose W is
// not in 8 .. BankWords, or whose CRC fails.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "board_image.hpp"

namespace watkins::board {

struct PacketFormat {
  static constexpr std::array<std::uint8_t, 4> Magic{'W', 'K', 'F', 'R'};
  static constexpr int HeaderBytes = 7;  // the magic, B, W
  static constexpr int CrcBytes = 4;
  static constexpr int MaxWords = 65535;  // W is two bytes
};

// CRC-32/ISO-HDLC (reflected, polynomial 0x04C11DB7, initial and final XOR all ones; "123456789"
// gives 0xCBF43926), continued from `crc` (0 to start): crc32(b, crc32(a)) is the CRC of a then b.
std::uint32_t crc32(const std::uint8_t* data, std::size_t size, std::uint32_t crc = 0);

// The bytes of one bank word: ceil(word_bits / 8).
int word_bytes(int word_bits);

// The packet of `bank` (bank_image). Throws std::invalid_argument when it has more than MaxWords
// words.
std::vector<std::uint8_t> frame_packet(const BankImage& bank);

// The seconds a packet of `bytes` takes on an 8N1 line at `baud` (ten bits a byte).
double packet_seconds(std::size_t bytes, double baud);

}  // namespace watkins::board
