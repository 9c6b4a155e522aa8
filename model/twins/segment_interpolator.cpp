#include "segment_interpolator.hpp"

#include <algorithm>
#include <tuple>

namespace watkins {
namespace {

// First pixel whose centre x + 1/2 is at or right of X: ceil(X − 1/2), X with fx fraction bits.
i64 first_centre_at_or_after(i64 x, int fx) {
  return static_cast<i64>(floor_shift(x - (i64{1} << (fx - 1)) + (i64{1} << fx) - 1, fx));
}

}  // namespace

std::pair<int, int> SegmentInterpolator::pixels(const Segment& s, int width, int x_frac_bits) {
  const i64 x_start = std::max<i64>(first_centre_at_or_after(s.e[fmt::ChanX], x_frac_bits), 0);
  const i64 x_end = std::min<i64>(first_centre_at_or_after(s.f[fmt::ChanX], x_frac_bits), width);
  return {static_cast<int>(x_start), static_cast<int>(std::max(x_end, x_start))};
}

SpanSetup SegmentInterpolator::setup(const Segment& s, int width, const ChannelFormats& formats) {
  SpanSetup span;
  span.formats = formats;
  span.poly = s.poly;
  span.material = s.material;
  const int fx = formats.x_frac();
  const i64 xe = s.e[fmt::ChanX], xf = s.f[fmt::ChanX];
  std::tie(span.x_start, span.x_end) = pixels(s, width, fx);
  if (span.x_end == span.x_start) return span;  // empty span: no reciprocal needed
  const i64 dx = xf - xe;  // > 0: a pixel centre lies in [X_E, X_F)
  const SpanReciprocal r = SpanReciprocal::of(dx);
  const i64 offset = static_cast<i64>(span.x_start) * (i64{1} << fx) + (i64{1} << (fx - 1)) - xe;  // >= 0
  // α0 in 2^-AlphaBits units; α0 <= 1 up to the reciprocal's error, so clamp at one.
  const i64 alpha0 = static_cast<i64>(std::min<i128>(
      round_shift(static_cast<i128>(offset) * r.recip, r.p + fmt::RecipBits - fmt::AlphaBits),
      i128{1} << fmt::AlphaBits));
  for (int c = fmt::ChanZ; c < fmt::NumChannels; ++c) {
    const i128 delta = static_cast<i128>(s.f[c]) - s.e[c];
    // ΔS per pixel = Δ·2^Fx/dx = Δ·recip·2^-(p+R-Fx). Saturation only matters when dx < 1 pixel,
    // where the span holds at most one pixel and the step is never used.
    span.step[c] = saturate_signed(round_shift(delta * r.recip, r.p + fmt::RecipBits - fx), formats.bits[c]);
    span.value[c] = wrap_signed(s.e[c] + round_shift(delta * alpha0, fmt::AlphaBits), formats.bits[c]);
  }
  return span;
}

}  // namespace watkins
