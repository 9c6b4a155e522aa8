// The iCEBreaker's scene bank in its SPI flash and its SPRAMs (docs/reference/board.md,
// "iCEBreaker"; rtl/board/flash_loader.sv, spram_scene_bank.sv, spram_frame_player.sv). A bank word
// (board_image.hpp) of word_bits takes Parts = ceil(word_bits / 64) SPRAM words of 64 bits, its
// low 64 bits first; in the flash, bank word k is the 8 Parts bytes at FlashAddress + 8 Parts k,
// little-endian, so the loader's 16-bit pairs go to the SPRAM words' lanes in order. `watkins
// board build` writes the bitstream, 0xFF up to FlashAddress and the bank's bytes as one .bin:
// one iceprog run programs both.
#pragma once

#include <cstdint>
#include <vector>

#include "board_image.hpp"

namespace watkins::board {

struct SpramBank {
  static constexpr int ReadBits = 64;               // spram_scene_bank's word
  static constexpr int MaxWords = 16384;            // SPRAM words of 64 bits
  static constexpr long long FlashAddress = 0x20000;  // icebreaker_top's FlashAddress (128 KiB)
  static constexpr int GapClocks = 128;             // flash_loader's GapClocks
};

// SPRAM words a bank word of `word_bits` takes: ceil(word_bits / 64).
int spram_parts(int word_bits);

// The flash bytes of `bank` from FlashAddress on: bank_words words of 8 Parts bytes (the words
// past the frame zero). Throws std::invalid_argument when the frame has more words than
// bank_words or bank_words Parts passes MaxWords.
std::vector<std::uint8_t> flash_image(const BankImage& bank, int bank_words);

// `bitstream`, 0xFF up to FlashAddress, then `image`: the .bin the iCEBreaker's flash holds.
// Throws std::invalid_argument when the bitstream reaches FlashAddress.
std::vector<std::uint8_t> flash_with_scene(const std::vector<std::uint8_t>& bitstream,
                                           const std::vector<std::uint8_t>& image);

// flash_loader's LoadClocks for a bank of bank_words words of `parts` SPRAM words: 80 + GapClocks
// + 128 words (a 16-bit pair every 32 clocks, four to a word).
long long flash_load_clocks(int bank_words, int parts);

// The clock edge that samples the iCEBreaker's first video state (BoardTiming::video_start): the
// loader's reset leaves its two flip-flops for edge 2, the load takes flash_load_clocks, and the
// register of the rest's reset one more.
int icebreaker_video_start(int bank_words, int parts);

}  // namespace watkins::board
