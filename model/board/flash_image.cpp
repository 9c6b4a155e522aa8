#include "flash_image.hpp"

#include <stdexcept>
#include <string>

namespace watkins::board {

int spram_parts(int word_bits) { return (word_bits + SpramBank::ReadBits - 1) / SpramBank::ReadBits; }

std::vector<std::uint8_t> flash_image(const BankImage& bank, int bank_words) {
  const int parts = spram_parts(bank.word_bits);
  if (static_cast<long long>(bank.words.size()) > bank_words)
    throw std::invalid_argument("flash image: " + std::to_string(bank.words.size()) + " words in a bank of " +
                                std::to_string(bank_words));
  if (static_cast<long long>(bank_words) * parts > SpramBank::MaxWords)
    throw std::invalid_argument("flash image: " + std::to_string(bank_words) + " bank words of " +
                                std::to_string(parts) + " SPRAM words each pass the SPRAMs' " +
                                std::to_string(SpramBank::MaxWords));
  const std::size_t word_bytes = static_cast<std::size_t>(parts) * SpramBank::ReadBits / 8;
  std::vector<std::uint8_t> out(static_cast<std::size_t>(bank_words) * word_bytes, 0);
  for (std::size_t k = 0; k < bank.words.size(); ++k)
    for (std::size_t b = 0; b < word_bytes && b / 4 < bank.words[k].size(); ++b)
      out[k * word_bytes + b] = static_cast<std::uint8_t>(bank.words[k][b / 4] >> (8 * (b % 4)));
  return out;
}

std::vector<std::uint8_t> flash_with_scene(const std::vector<std::uint8_t>& bitstream,
                                           const std::vector<std::uint8_t>& image) {
  if (static_cast<long long>(bitstream.size()) > SpramBank::FlashAddress)
    throw std::invalid_argument("flash image: the bitstream's " + std::to_string(bitstream.size()) +
                                " bytes reach the scene's address " + std::to_string(SpramBank::FlashAddress));
  std::vector<std::uint8_t> out = bitstream;
  out.resize(static_cast<std::size_t>(SpramBank::FlashAddress), 0xFF);
  out.insert(out.end(), image.begin(), image.end());
  return out;
}

long long flash_load_clocks(int bank_words, int parts) {
  return 80 + SpramBank::GapClocks + 128LL * bank_words * parts;
}

int icebreaker_video_start(int bank_words, int parts) {
  return static_cast<int>(2 + flash_load_clocks(bank_words, parts) + 1);
}

}  // namespace watkins::board
