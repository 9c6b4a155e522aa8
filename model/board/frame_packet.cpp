// The host link's packet (frame_packet.hpp).
#include "frame_packet.hpp"

#include <stdexcept>
#include <string>

namespace watkins::board {

std::uint32_t crc32(const std::uint8_t* data, std::size_t size, std::uint32_t crc) {
  std::uint32_t c = ~crc;
  for (std::size_t i = 0; i < size; ++i) {
    c ^= data[i];
    for (int b = 0; b < 8; ++b) c = (c & 1u) ? (c >> 1) ^ 0xedb88320u : c >> 1;
  }
  return ~c;
}

int word_bytes(int word_bits) { return (word_bits + 7) / 8; }

std::vector<std::uint8_t> frame_packet(const BankImage& bank) {
  const std::size_t words = bank.words.size();
  if (words > static_cast<std::size_t>(PacketFormat::MaxWords))
    throw std::invalid_argument("frame packet: " + std::to_string(words) + " words, more than the packet's " +
                                std::to_string(PacketFormat::MaxWords));
  const int b = word_bytes(bank.word_bits);
  std::vector<std::uint8_t> p(PacketFormat::Magic.begin(), PacketFormat::Magic.end());
  p.reserve(PacketFormat::HeaderBytes + words * b + PacketFormat::CrcBytes);
  p.push_back(static_cast<std::uint8_t>(b));
  p.push_back(static_cast<std::uint8_t>(words & 0xff));
  p.push_back(static_cast<std::uint8_t>(words >> 8));
  for (const tb::EdgeWords& w : bank.words)
    for (int j = 0; j < b; ++j) p.push_back(static_cast<std::uint8_t>(w[j / 4] >> (8 * (j % 4))));
  const std::size_t after_magic = PacketFormat::Magic.size();
  const std::uint32_t crc = crc32(p.data() + after_magic, p.size() - after_magic);
  for (int j = 0; j < PacketFormat::CrcBytes; ++j) p.push_back(static_cast<std::uint8_t>(crc >> (8 * j)));
  return p;
}

double packet_seconds(std::size_t bytes, double baud) { return 10.0 * static_cast<double>(bytes) / baud; }

}  // namespace watkins::board
