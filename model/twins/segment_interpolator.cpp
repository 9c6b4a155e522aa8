#include "segment_interpolator.hpp"

#include <algorithm>
#include <tuple>

namespace watkins {
namespace {

// First pixel whose centre x + 1/2 is at or right of X: ceil(X − 1/2), X with fx fraction bits.
// In 64 bits: X is a word of at most 62 bits, so adding under one pixel cannot overflow.
i64 first_centre_at_or_after(i64 x, int fx) {
  return floor_shift64(x - (i64{1} << (fx - 1)) + (i64{1} << fx) - 1, fx);
}

}  // namespace

std::pair<int, int> SegmentInterpolator::pixels(const Segment& s, int width, int x_frac_bits) {
  const i64 x_start = std::max<i64>(first_centre_at_or_after(s.e[fmt::ChanX], x_frac_bits), 0);
  const i64 x_end = std::min<i64>(first_centre_at_or_after(s.f[fmt::ChanX], x_frac_bits), width);
  return {static_cast<int>(x_start), static_cast<int>(std::max(x_end, x_start))};
}

namespace {

// The setup's products in the narrowest machine word that holds them: 64 bits for sized
// configurations, 128 for the widest words. Same formulas, same rounding, so the same values.
i64 round_in(i64 v, int s) { return round_shift64(v, s); }
i128 round_in(i128 v, int s) { return round_shift(v, s); }
i64 wrap_in(i64 v, int bits) { return wrap_signed64(v, bits); }
i64 wrap_in(i128 v, int bits) { return wrap_signed(v, bits); }

// α0 in 2^-AlphaBits units; α0 <= 1 up to the reciprocal's error, so clamp at one.
template <class W>
i64 alpha0_in(const SpanReciprocal& r, i64 offset) {
  return static_cast<i64>(std::min<W>(round_in(static_cast<W>(offset) * r.recip, r.p + fmt::RecipBits - fmt::AlphaBits),
                                      W{1} << fmt::AlphaBits));
}

// The products of a slot's setup rounded: in 64 bits the caller has checked |delta| < 2^37, and
// recip and alpha0 are at most 2^24, so a product is below 2^61 and its shift (p + R - Fx >= 1,
// AlphaBits) in [1, 61]: round_shift62, round_shift64's value without its sign branch.
i64 round_product(i64 v, int s) { return round_shift62(v, s); }
i128 round_product(i128 v, int s) { return round_shift(v, s); }

// Slot c's per-pixel step and its value at the first pixel.
template <class W>
void setup_slot(const Segment& s, int c, const ChannelFormats& formats, const SpanReciprocal& r, i64 alpha0,
                SpanSetup& span) {
  const W delta = static_cast<W>(s.f[c]) - s.e[c];
  // ΔS per pixel = Δ·2^Fx/dx = Δ·recip·2^-(p+R-Fx). Saturation only matters when dx < 1 pixel,
  // where the span holds at most one pixel and the step is never used.
  const W hi = (W{1} << (formats.bits[c] - 1)) - 1;
  span.step[c] = static_cast<i64>(
      std::clamp<W>(round_product(delta * r.recip, r.p + fmt::RecipBits - formats.x_frac()), -hi - 1, hi));
  span.value[c] = wrap_in(s.e[c] + round_product(delta * alpha0, fmt::AlphaBits), formats.bits[c]);
}

// The 128-bit slot, out of the common path's way.
__attribute__((noinline, cold)) void setup_wide(const Segment& s, int c, const ChannelFormats& formats,
                                                const SpanReciprocal& r, i64 alpha0, SpanSetup& span) {
  setup_slot<i128>(s, c, formats, r, alpha0, span);
}

}  // namespace

SpanSetup SegmentInterpolator::setup(const Segment& s, int width, const ChannelFormats& formats) {
  SpanSetup span;
  span.formats = formats;
  setup(s, width, formats, span);
  return span;
}

void SegmentInterpolator::setup(const Segment& s, int width, const ChannelFormats& formats, SpanSetup& span) {
  span.poly = s.poly;
  span.material = s.material;
  const int fx = formats.x_frac();
  const i64 xe = s.e[fmt::ChanX], xf = s.f[fmt::ChanX];
  std::tie(span.x_start, span.x_end) = pixels(s, width, fx);
  if (span.x_end == span.x_start) return;  // empty span: no reciprocal needed
  const i64 dx = xf - xe;  // > 0: a pixel centre lies in [X_E, X_F)
  const SpanReciprocal r = SpanReciprocal::of(dx);
  const i64 offset = static_cast<i64>(span.x_start) * (i64{1} << fx) + (i64{1} << (fx - 1)) - xe;  // >= 0
  // 64 bits hold a product and its rounding constant when the operands are small enough, which
  // they usually are whatever the words: the offset is under a pixel except where the span is
  // clipped, a delta is what the slot changes across the span (|F - E|, small even where E and F
  // are large, as depth usually is). Checked on the values, per product;
  // otherwise 128 bits. Same formulas and rounding either way, so the same values.
  constexpr int Small = 62 - std::max(fmt::RecipBits, fmt::AlphaBits) - 1;  // operand bits
  constexpr i64 Limit = i64{1} << Small;
  const i64 alpha0 = offset < Limit ? alpha0_in<i64>(r, offset) : alpha0_in<i128>(r, offset);
  const bool small_shift = r.p + fmt::RecipBits - fx <= 61;  // the step's rounding constant
  for (int c = fmt::ChanZ; c < fmt::NumChannels; ++c) {
    i64 delta = 0;
    const bool overflow = __builtin_sub_overflow(s.f[c], s.e[c], &delta);  // not for words of 62 bits
    if (__builtin_expect(small_shift && !overflow && delta > -Limit && delta < Limit, 1))
      setup_slot<i64>(s, c, formats, r, alpha0, span);
    else
      setup_wide(s, c, formats, r, alpha0, span);
  }
}

}  // namespace watkins
