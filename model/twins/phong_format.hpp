// The Phong blocks' internal formats, a configuration field (Config::phong, the config file's
// "phong": {"formats": ...}; docs/reference/compact-phong.md, "Narrow formats"):
//   Model   the formats of formats.hpp: PhongDotBits 24, PhongPowBits 20, the normalizer's seed
//           and Newton-Raphson step, cos(s)^n by square-and-multiply (every Phong top)
//   Narrow  every product of the normalizer and the shader one 16 x 16 product (one SB_MAC16),
//           1/sqrt(m') and cos(s)^n from 256-row block-RAM tables with linear interpolation
//           (the compact Phong blocks only)
// The constants below are the narrow set's; the model set's are formats.hpp's.
#pragma once

namespace watkins {

enum class PhongFormat { Model, Narrow };

namespace narrow {
constexpr int InBits = 16;        // normalizer input n_c: signed, InFracBits fraction bits
constexpr int InFracBits = 15;    // |n_c| < 1: one signed 16-bit multiplier operand
constexpr int TableBits = 8;      // every table: 256 rows of 16 bits (one 256 x 16 block RAM)
constexpr int RsqrtFracBits = 16; // y' = 1/sqrt(m') - 1 in [0, 1), 16 fraction bits
constexpr int RsqrtDeltaBits = 16;  // m' bits below the rsqrt table's index
constexpr int CosIBits = 15;      // fraction bits of cos(i) in [0, 2): one unsigned 16-bit operand
constexpr int NeBits = 14;        // fraction bits of N.E in (-2, 2): one signed 16-bit operand
constexpr int LeBits = 16;        // fraction bits of L.E (a frame constant, never an operand): 18 bits
constexpr int CosBits = 16;       // fraction bits of cos(s) in [0, 1]
constexpr int LogFracBits = 16;   // fraction bits of -log2 cos(s) and of n (-log2 cos(s))
constexpr int PowBits = 16;       // fraction bits of cos(s)^n in [0, 1 - 2^-16]
constexpr int DiffuseBits = 15;   // fraction bits of f = cos(i)(1 - d) + d, rounded for Cp f
constexpr int LevelFracBits = 24; // fraction bits of the summed level: Cp fr 2^9 + 255 W pow
}  // namespace narrow

}  // namespace watkins
