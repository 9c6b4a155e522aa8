// Twin of rtl/segment_interpolator.sv. Span setup for one segment E..F, then one fragment per
// pixel by α stepping: each channel's per-pixel step ΔS/Δx comes from the span reciprocal, and
// the first pixel centre right of X_E gets its value by direct interpolation with
// α0 = (x_c − X_E)/(X_F − X_E) (the sub-pixel prestep, which also absorbs clipping at x = 0).
// Pixels covered: centres x + 1/2 in [X_E, X_F), clipped to [0, width).
//
// Widths and shifts from the configuration (config.hpp, ChannelFormats f; slot c = X, Z, R|Nx,
// G|Ny, B|Nz; Fx = f.frac[ChanX]), as rtl/segment_interpolator.sv sizes them:
//   s0  first_centre(X): half = 2^(Fx-1), floor by >> Fx; pixel index X >> Fx
//       offset = (x_start << Fx) + 2^(Fx-1) - X_E: width bits[ChanX] + 1
//       dx = X_F - X_E: DxBits = bits[ChanX] + 1 (span_reciprocal's DxBits)
//       delta[c] = F[c] - E[c]: bits[c] + 1 per channel
//   sa  offset * recip: (bits[ChanX] + 1) + (RecipBits + 1) + 2 rounding guard;
//       delta[c] * recip: max(bits[c], bits[ChanX] - Fx) + RecipBits + 3 (the rounding constant
//       2^(p+R-Fx-1) of a narrow slot needs X's headroom)
//   sb  alpha0 shift p + RecipBits - AlphaBits;
//       step[c] = saturate(round_shift(delta[c]*recip, p + RecipBits - Fx), bits[c]) -- the shift
//       uses X's fraction bits (ΔS per pixel = Δ·2^Fx/dx), the saturation the channel's word
//   sc  delta[c] * alpha0: bits[c] + AlphaBits + 3
//   FIFO and stepper value[c], step[c]: bits[c] each (span_t from their sum)
//   value[c] = wrap(E[c] + round_shift(delta[c]*alpha0, AlphaBits), bits[c]); step adds wrap at bits[c]
//   fragment depth  clamp(round_shift(Z, f.frac[ChanZ]), 0, 2^f.depth_bits - 1): DepthBits output
//   fragment rgb    clamp(round_shift(v, f.frac[ChanR+c]), 0, 255)
//   fragment normal saturate(v scaled from f.frac[ChanNx+c] to FracBits fraction bits, NormalInBits):
//                   v << (FracBits - fn) when fn < FracBits, round_shift(v, fn - FracBits) when
//                   larger (the normalizer's input format does not change with the configuration)
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>

#include "config.hpp"
#include "segment_former.hpp"
#include "span_reciprocal.hpp"

namespace watkins {

// A fragment leaving the interpolator: one pixel of one segment.
// Both readings of the attribute channels are produced; each pipeline uses one of them.
struct Fragment {
  int x = 0;
  std::uint32_t depth = 0;  // DepthBits, smaller is nearer
  std::uint8_t rgb[3] = {0, 0, 0};  // Gouraud: clamp(round(channel), 0, 255)
  std::array<i64, 3> normal{};      // Phong: saturate(channel, NormalInBits), FracBits fraction
  int poly = 0;
  int material = 0;
};

struct SpanSetup {
  int x_start = 0, x_end = 0;  // pixels [x_start, x_end); empty when x_end <= x_start
  int poly = 0;
  int material = 0;
  ChannelVector value{};       // channel values at pixel x_start (X unused)
  ChannelVector step{};        // per-pixel increments (X unused)
  ChannelFormats formats = default_formats();  // of the channel slots
  // Config{}.channels(ShadingMode::Gouraud) as constants: every slot ChannelBits wide with
  // FracBits fraction bits (a span is set up per segment; its formats are overwritten).
  static constexpr ChannelFormats default_formats() {
    ChannelFormats f{};
    for (int c = 0; c < fmt::NumChannels; ++c) f.bits[c] = fmt::ChannelBits, f.frac[c] = fmt::FracBits;
    return f;
  }
};

struct SegmentInterpolator {
  // The span's pixels [x_start, x_end), clipped to [0, width), x_end == x_start when empty; X
  // has x_frac_bits fraction bits. What setup() covers, without its reciprocal and values.
  static std::pair<int, int> pixels(const Segment& s, int width, int x_frac_bits);
  static SpanSetup setup(const Segment& s, int width, const ChannelFormats& formats);
  // The same into `span`, whose formats the caller has set to `formats` (a loop over a line's
  // segments sets them once): every other field is written; an empty span's value and step
  // keep what they held.
  static void setup(const Segment& s, int width, const ChannelFormats& formats, SpanSetup& span);
  static SpanSetup setup(const Segment& s, int width) {  // the default configuration
    return setup(s, width, Config{}.channels(ShadingMode::Gouraud));
  }
  // Which readings of the attribute slots a fragment carries: a pipeline uses one (Gouraud the
  // shade, Phong the normal), a bench comparing the interpolator's ports needs both. The other
  // stays zero.
  enum class Readings { Both, Shade, Normal };
  // Fragment at pixel x_start + k of a span whose values have been stepped k times (both
  // readings).
  static Fragment fragment(const SpanSetup& span, int x, const ChannelVector& value);
  // One α step: value += step in every interpolated channel.
  static void step(const SpanSetup& span, ChannelVector& value);
};

// The per-pixel path (fragment() and step()) with the configuration's shifts, masks and limits
// worked out once: what a frame's inner loop uses. All in 64 bits: a channel word is at most
// Config::MaxWordBits (62) bits, so a value plus a step, or plus half an ulp, cannot overflow.
// InRange (a template parameter of head, fill and step): the caller knows, from in_range(), that
// the span's values stay inside their words and inside the readings' ranges, so a step needs no
// wrap and a reading no clamp; the values are the same as the general path's.
class PixelPath {
 public:
  using Readings = SegmentInterpolator::Readings;
  explicit PixelPath(const ChannelFormats& f) {
    for (int c = fmt::ChanZ; c < fmt::NumChannels; ++c) {
      sign_[c] = i64{1} << (f.bits[c] - 1);
      lo_[c] = -sign_[c];  // the word's range; readings narrow it below
      hi_[c] = sign_[c] - 1;
    }
    z_shift_ = f.frac[fmt::ChanZ];
    z_half_ = half(z_shift_);
    depth_max_ = (i64{1} << f.depth_bits) - 1;
    narrow(lo_[fmt::ChanZ], hi_[fmt::ChanZ], z_half_, static_cast<i128>(depth_max_ + 1) << z_shift_);
    shade_lo_ = lo_;
    shade_hi_ = hi_;
    for (int c = 0; c < 3; ++c) {
      shade_shift_[c] = f.frac[fmt::ChanR + c];
      shade_half_[c] = half(shade_shift_[c]);
      normal_shift_[c] = f.frac[fmt::ChanNx + c] - fmt::FracBits;
      narrow(shade_lo_[fmt::ChanR + c], shade_hi_[fmt::ChanR + c], shade_half_[c],
             static_cast<i128>(fmt::ShadeMax + 1) << shade_shift_[c]);
    }
  }

  // Whether the span keeps every slot inside its word and (for the readings R) inside the range
  // its reading needs no clamp for: the values are linear in x, so the first and the last pixel
  // decide. In 64 bits: an overflow of last's product or sum answers false (the general path).
  template <Readings R>
  bool in_range(const SpanSetup& span) const {
    if (R == Readings::Both) return false;  // a bench's fragments take the general path
    const i64 last_k = span.x_end - span.x_start - 1;
    bool ok = true;
    for (int c = fmt::ChanZ; c < fmt::NumChannels; ++c) {
      const i64 first = span.value[c];
      i64 run = 0, last = 0;
      if (__builtin_mul_overflow(last_k, span.step[c], &run) || __builtin_add_overflow(first, run, &last)) return false;
      const i64 lo = R == Readings::Shade ? shade_lo_[c] : lo_[c];
      const i64 hi = R == Readings::Shade ? shade_hi_[c] : hi_[c];
      // lo <= v <= hi as one unsigned comparison of v - lo (modulo 2^64) with hi - lo.
      const std::uint64_t width = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
      ok &= (lo <= hi) & (static_cast<std::uint64_t>(first) - static_cast<std::uint64_t>(lo) <= width) &
            (static_cast<std::uint64_t>(last) - static_cast<std::uint64_t>(lo) <= width);
    }
    return ok;
  }

  // Slot c's values whose shade-reading path (in_range<Readings::Shade>) needs no wrap or clamp.
  i64 shade_lo(int c) const { return shade_lo_[static_cast<std::size_t>(c)]; }
  i64 shade_hi(int c) const { return shade_hi_[static_cast<std::size_t>(c)]; }

  // The fragment's position, ids and depth: what the depth test needs.
  template <bool InRange = false>
  Fragment head(const SpanSetup& span, int x, const ChannelVector& value) const {
    Fragment f;
    f.x = x;
    f.poly = span.poly;
    f.material = span.material;
    f.depth = static_cast<std::uint32_t>(InRange ? (value[fmt::ChanZ] + z_half_) >> z_shift_
                                                 : round_clamp(value[fmt::ChanZ], z_shift_, z_half_, depth_max_));
    return f;
  }
  // The attribute readings R, for a fragment that needs them (one that won its pixel, or one a
  // bench observes). A template parameter: a frame's loop knows which it needs.
  template <Readings R, bool InRange = false>
  void fill(Fragment& f, const ChannelVector& value) const {
    if (R != Readings::Normal)
      for (int c = 0; c < fmt::ShadeChannels; ++c)
        f.rgb[c] = static_cast<std::uint8_t>(
            InRange && R == Readings::Shade
                ? (value[fmt::ChanR + c] + shade_half_[c]) >> shade_shift_[c]
                : round_clamp(value[fmt::ChanR + c], shade_shift_[c], shade_half_[c], fmt::ShadeMax));
    if (R != Readings::Shade)
      for (int c = 0; c < 3; ++c) f.normal[c] = normal(value[fmt::ChanNx + c], normal_shift_[c]);
  }
  Fragment fragment(const SpanSetup& span, int x, const ChannelVector& value) const {
    Fragment f = head(span, x, value);
    fill<Readings::Both>(f, value);
    return f;
  }

  // value += step per slot, wrapping like a register of the slot's width.
  template <bool InRange = false>
  void step(const ChannelVector& step, ChannelVector& value) const {
    for (int c = fmt::ChanZ; c < fmt::NumChannels; ++c)
      value[c] = InRange ? value[c] + step[c] : wrap_to_sign(value[c] + step[c], sign_[c]);
  }
  void step(const SpanSetup& span, ChannelVector& value) const { step(span.step, value); }

 private:
  // Half an ulp of a value with s fraction bits (none for s = 0): round_shift64's constant.
  static i64 half(int s) { return s == 0 ? 0 : i64{1} << (s - 1); }
  // clamp(round_shift64(v, s), 0, hi), with h = half(s): a negative sum rounds to a negative
  // value, which clamps to 0, so only a non-negative sum is shifted.
  static i64 round_clamp(i64 v, int s, i64 h, i64 hi) {
    const i64 t = v + h;
    if (t < 0) return 0;
    const i64 r = t >> s;
    return r > hi ? hi : r;
  }
  // Values v whose round_clamp(v, s, h, hi) needs no clamp: 0 <= v + h < (hi + 1) << s = top.
  // Within a word's range, so each bound fits 64 bits.
  static void narrow(i64& lo, i64& hi, i64 h, i128 top) {
    lo = std::max(lo, -h);
    hi = static_cast<i64>(std::min<i128>(hi, top - h - 1));
  }
  // The normalizer reads FracBits fraction bits whatever the normal's channel format: round away
  // extra bits, or scale up, saturating to NormalInBits (compared before the shift, so nothing
  // overflows; FracBits < NormalInBits - 1, so a shift never passes the word).
  static i64 normal(i64 v, int shift) {
    constexpr i64 hi = (i64{1} << (fmt::NormalInBits - 1)) - 1;
    if (shift >= 0) return std::clamp<i64>(round_shift64(v, shift), -hi - 1, hi);
    const int up = -shift;
    return v > (hi >> up) ? hi : v < ~(hi >> up) ? -hi - 1 : v * (i64{1} << up);
  }
  static_assert(fmt::FracBits < fmt::NormalInBits - 1, "normal scaling stays within the word");

  std::array<i64, fmt::NumChannels> sign_{};  // per slot: 2^(bits-1), wrap_to_sign's word
  // Per slot, the values for which InRange gives the general path's result: lo_/hi_ the word
  // (and, for Z, an unclamped depth); shade_lo_/shade_hi_ also an unclamped shade in slots 2..4.
  std::array<i64, fmt::NumChannels> lo_{}, hi_{}, shade_lo_{}, shade_hi_{};
  int z_shift_ = 0;
  i64 z_half_ = 0, depth_max_ = 0;
  int shade_shift_[3] = {0, 0, 0}, normal_shift_[3] = {0, 0, 0};
  i64 shade_half_[3] = {0, 0, 0};
};

inline Fragment SegmentInterpolator::fragment(const SpanSetup& span, int x, const ChannelVector& value) {
  return PixelPath(span.formats).fragment(span, x, value);
}

inline void SegmentInterpolator::step(const SpanSetup& span, ChannelVector& value) {
  PixelPath(span.formats).step(span, value);
}

}  // namespace watkins
