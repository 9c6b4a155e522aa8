#include "segment_interpolator.hpp"

#include <algorithm>

namespace watkins {
namespace {

constexpr i64 kOne = i64{1} << fmt::FracBits;  // one pixel in X channel units
constexpr i64 kHalf = kOne / 2;

// First pixel whose centre x + 1/2 is at or right of X: ceil(X − 1/2).
i64 first_centre_at_or_after(i64 x) { return static_cast<i64>(floor_shift(x - kHalf + kOne - 1, fmt::FracBits)); }

}  // namespace

SpanSetup SegmentInterpolator::setup(const Segment& s, int width) {
  SpanSetup span;
  span.poly = s.poly;
  span.material = s.material;
  const i64 xe = s.e[fmt::ChanX], xf = s.f[fmt::ChanX];
  span.x_start = static_cast<int>(std::max<i64>(first_centre_at_or_after(xe), 0));
  span.x_end = static_cast<int>(std::min<i64>(first_centre_at_or_after(xf), width));
  if (span.x_end <= span.x_start) {
    span.x_end = span.x_start;  // empty span: no reciprocal needed
    return span;
  }
  const i64 dx = xf - xe;  // > 0: a pixel centre lies in [X_E, X_F)
  const SpanReciprocal r = SpanReciprocal::of(dx);
  const i64 offset = (static_cast<i64>(span.x_start) << fmt::FracBits) + kHalf - xe;  // >= 0
  // α0 in 2^-AlphaBits units; α0 <= 1 up to the reciprocal's error, so clamp at one.
  const i64 alpha0 = static_cast<i64>(std::min<i128>(
      round_shift(static_cast<i128>(offset) * r.recip, r.p + fmt::RecipBits - fmt::AlphaBits),
      i128{1} << fmt::AlphaBits));
  for (int c = fmt::ChanZ; c < fmt::NumChannels; ++c) {
    const i128 delta = static_cast<i128>(s.f[c]) - s.e[c];
    // ΔS per pixel = Δ·2^F/dx = Δ·recip·2^-(p+R-F). Saturation only matters when dx < 1 pixel,
    // where the span holds at most one pixel and the step is never used.
    span.step[c] = saturate_signed(round_shift(delta * r.recip, r.p + fmt::RecipBits - fmt::FracBits),
                                   fmt::ChannelBits);
    span.value[c] = wrap_signed(s.e[c] + round_shift(delta * alpha0, fmt::AlphaBits), fmt::ChannelBits);
  }
  return span;
}

Fragment SegmentInterpolator::fragment(const SpanSetup& span, int x, const ChannelVector& value) {
  Fragment f;
  f.x = x;
  f.poly = span.poly;
  f.material = span.material;
  f.depth = static_cast<std::uint32_t>(
      clamp_i(round_shift(value[fmt::ChanZ], fmt::FracBits), 0, fmt::DepthMax));
  for (int c = 0; c < fmt::ShadeChannels; ++c)
    f.rgb[c] = static_cast<std::uint8_t>(
        clamp_i(round_shift(value[fmt::ChanR + c], fmt::FracBits), 0, fmt::ShadeMax));
  for (int c = 0; c < 3; ++c)
    f.normal[c] = saturate_signed(value[fmt::ChanNx + c], fmt::NormalInBits);
  return f;
}

void SegmentInterpolator::step(const SpanSetup& span, ChannelVector& value) {
  for (int c = fmt::ChanZ; c < fmt::NumChannels; ++c)
    value[c] = wrap_signed(static_cast<i128>(value[c]) + span.step[c], fmt::ChannelBits);
}

}  // namespace watkins
