// Twin of rtl/shade_divider.sv: Gouraud's eq. (2) per pixel. In an eq2 frame (Frame::eq2) the
// shade slots carry the numerator N = S·Z of each vertex (Z the depth as a fraction of 1) and the
// depth slot Z itself; the interpolator interpolates both linearly, and each pixel's shade is
// S = N / Z, one division per pixel as the eq. (2) in Gouraud's paper asks: 1/Z from the span
// reciprocal's block (span_reciprocal.hpp, R = eq2_recip_bits), then one multiply per channel.
//
// Per fragment, from its depth d (the interpolator's rounded, clamped depth word, depth_bits bits:
// Z = d·2^-depth_bits) and the three shade slots' words v (Fs = the shade group's frac_bits):
//   in   n  = clamp(v, 0, 2^NumBits − 1), NumBits = ShadeBits + Fs: N ≥ 256 gives S ≥ 256 whatever
//            Z < 1 is, so the saturated numerator changes no output; a negative N gives 0.
//        dz = max(d, 1): a zero depth divides by one unit of the depth word.
//   span_reciprocal (R + 2 stages)  recip = floor(2^(2R−1) / m), p = floor(log2 dz): 1/dz ≈ recip·2^−(p+R)
//   sm   prod = n·recip (NumBits + R + 1 bits, unsigned); s = p + R + Fs − depth_bits
//   sr   S = n·2^−Fs / (dz·2^−depth_bits) ≈ prod·2^−s:
//          s ≤ 0: 255 when n ≠ 0 (prod·2^−s ≥ 2^(R−1) > 255, R ≥ 9), else 0;
//          s ≥ 1: min(round_shift(prod, s), 255), the rounding as ((prod >> (s − 1)) + 1) >> 1.
// Error against the exact N/Z: the reciprocal's relative 2^−(R−1) (255·2^−15 = 0.008 levels at
// the default R = 16) and half a level of rounding.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "config.hpp"
#include "span_reciprocal.hpp"

namespace watkins {

class ShadeDivider {
 public:
  // The values of one fragment's stages, as the RTL's registers hold them (the unit bench's
  // hand-worked checks read them).
  struct Trace {
    i64 dz = 0;                      // the divisor, max(depth, 1)
    SpanReciprocal r;                // 1/dz
    std::array<i64, 3> n{};          // saturated numerators
    std::array<unsigned __int128, 3> prod{};  // sm: n·recip
    int s = 0;                       // sm: the shift p + R + Fs − depth_bits
    std::array<std::uint8_t, 3> rgb{};  // sr
  };

  explicit ShadeDivider(const ChannelFormats& f)
      : depth_bits_(f.depth_bits), frac_(f.frac[fmt::ChanR]), recip_bits_(f.eq2_recip_bits) {}

  // Bits of the saturated numerator (unsigned): 8 integer bits and the shade's fraction bits.
  int num_bits() const { return fmt::ShadeBits + frac_; }
  // The shift's constant part, R + Fs − depth_bits.
  int shift_offset() const { return recip_bits_ + frac_ - depth_bits_; }

  Trace trace(std::uint32_t depth, const std::array<i64, 3>& v) const {
    Trace t;
    t.dz = std::max<i64>(depth, 1);
    t.r = SpanReciprocal::of(t.dz, recip_bits_);
    t.s = t.r.p + shift_offset();
    const i64 n_max = (i64{1} << num_bits()) - 1;
    for (int c = 0; c < 3; ++c) {
      t.n[c] = std::clamp<i64>(v[c], 0, n_max);
      t.prod[c] = static_cast<unsigned __int128>(t.n[c]) * static_cast<unsigned __int128>(t.r.recip);
      if (t.s <= 0) {
        t.rgb[c] = t.n[c] != 0 ? fmt::ShadeMax : 0;
      } else {
        const unsigned __int128 q = ((t.prod[c] >> (t.s - 1)) + 1) >> 1;
        t.rgb[c] = static_cast<std::uint8_t>(q > fmt::ShadeMax ? fmt::ShadeMax : static_cast<int>(q));
      }
    }
    return t;
  }
  std::array<std::uint8_t, 3> shade(std::uint32_t depth, const std::array<i64, 3>& v) const {
    return trace(depth, v).rgb;
  }

 private:
  int depth_bits_, frac_, recip_bits_;
};

}  // namespace watkins
