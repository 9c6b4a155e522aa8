// The board's scene bank (docs/reference/board.md, "Scene banks"; rtl/board/scene_bank.sv): the
// words of a prepared frame as the frame player reads them, at the configuration the board top is
// built for, and the $readmemh file that initializes bank 0. Every word is EdgeBits wide (the
// top's edge record, Config::edge_record_bits), each field in its low bits:
//   0 N (edge records), 1 width, 2 height, 3 background {R, G, B}, 4 flags (bit 0
//   tie_submission_i, bit 1 eq2_i, bits 8.. smooth_w_i), 5 light, 6 eye ({z, y, x} Q2.14), 7 M
//   (materials), 8.. the materials {n, w, d, cp} (cp lowest), then the edge records packed as
//   edge_i (pack_edge). A Gouraud frame carries no materials and zero light and eye, as the
//   benches drive watkins_top.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "config.hpp"
#include "edge_packing.hpp"
#include "frame.hpp"
#include "image.hpp"

namespace watkins::board {

// Where each field sits (bit offsets inside its word).
struct BankLayout {
  static constexpr int HeaderWords = 8;
  static constexpr int FlagTieBit = 0, FlagEq2Bit = 1, FlagSmoothLsb = 8;
  static constexpr int MaterialDLsb = 24, MaterialWLsb = 33, MaterialNLsb = 42;  // cp at 0
  static constexpr int MinWordBits = 64;  // the header's widest field (light, eye: 48 bits)
};

struct BankImage {
  int word_bits = 0;                 // EdgeBits of the top
  std::vector<tb::EdgeWords> words;  // each word's bits, little-endian 32-bit words
  int edges = 0, materials = 0;
};

// The bank of `frame` for the board top built for `config` (the frame must be prepared for it).
// Throws std::invalid_argument, naming the field, when a value does not fit its word, the record
// is narrower than MinWordBits, or the bank would hold more than bank_words words (0: no limit).
BankImage bank_image(const Frame& frame, const Config& config, int bank_words = 0);

// `image` as the iCEBreaker's 12-bit DVI Pmod shows it: each 8-bit level's top four bits (the
// board top drives rgb[7:4] of each channel onto the Pmod's pins).
Image pmod_levels(Image image);

// One word a line, ceil(word_bits / 4) hexadecimal digits, most significant first: $readmemh.
void write_readmemh(std::ostream& out, const BankImage& bank);
// The same into `path`; throws std::runtime_error naming the file when it cannot be written.
void write_readmemh_file(const std::string& path, const BankImage& bank);

}  // namespace watkins::board
