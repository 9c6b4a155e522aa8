// Fitting forward-difference edge records to Whitted's curved edges (curved_edges.hpp).
#include "curved_edges.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "prepare.hpp"
#include "scene_error.hpp"
#include "signed_bits.hpp"

namespace watkins {
namespace {

constexpr int Order = 3;
// Runs this short interpolate their crossings with integer differences: always exact.
constexpr int ExactRun = Order + 1;

double binomial(int k, int j) {
  double b = 1;
  for (int i = 0; i < j; ++i) b = b * (k - i) / (i + 1);
  return b;
}

// Least squares: the coefficient of column `top` when r is fitted by columns 0..top of the
// binomial basis C(k, j), k = 0..L-1. Modified Gram-Schmidt on columns scaled to [0, 1], so the
// run's length does not spoil the conditioning.
double ls_top_coefficient(const std::vector<double>& r, int top) {
  const int n = static_cast<int>(r.size());
  const int m = top + 1;
  std::vector<std::vector<double>> q(m, std::vector<double>(n));
  std::vector<double> scale(m);
  for (int j = 0; j < m; ++j) {
    scale[j] = binomial(n - 1, j);
    for (int k = 0; k < n; ++k) q[j][k] = binomial(k, j) / scale[j];
  }
  // R (upper triangular) and Q^T r.
  std::vector<std::vector<double>> rr(m, std::vector<double>(m, 0.0));
  std::vector<double> qtr(m);
  std::vector<double> rhs = r;
  for (int j = 0; j < m; ++j) {
    for (int i = 0; i < j; ++i) {
      double dot = 0;
      for (int k = 0; k < n; ++k) dot += q[i][k] * q[j][k];
      rr[i][j] = dot;
      for (int k = 0; k < n; ++k) q[j][k] -= dot * q[i][k];
    }
    double norm = 0;
    for (int k = 0; k < n; ++k) norm += q[j][k] * q[j][k];
    norm = std::sqrt(norm);
    rr[j][j] = norm;
    for (int k = 0; k < n; ++k) q[j][k] /= norm;
    double dot = 0;
    for (int k = 0; k < n; ++k) dot += q[j][k] * rhs[k];
    qtr[j] = dot;
    for (int k = 0; k < n; ++k) rhs[k] -= dot * q[j][k];
  }
  // Back substitution; only the top coefficient is needed, which is the last row.
  return qtr[top] / rr[top][top] / scale[top];
}

struct RunFit {
  std::array<std::array<i128, Order + 1>, fmt::NumChannels> d{};  // v0, d1, d2, d3 per channel
  std::array<i64, fmt::NumChannels> max_error{};
  std::array<int, fmt::NumChannels> value_bits{};
};

// The integer accumulation of the incrementer, exactly (no wrap): the value on each line.
template <class Visit>
void accumulate(const std::array<i128, Order + 1>& d, int lines, Visit visit) {
  i128 v = d[0], d1 = d[1], d2 = d[2];
  const i128 d3 = d[3];
  for (int k = 0; k < lines; ++k) {
    visit(k, v);
    v += d1;
    d1 += d2;
    d2 += d3;
  }
}

// The differences of one channel over q[s .. s+lines).
std::array<i128, Order + 1> fit_channel(const std::vector<ChannelVector>& q, int s, int lines, int c) {
  std::array<i128, Order + 1> d{};
  if (lines <= ExactRun) {
    // Newton's forward differences of the quantized crossings themselves.
    std::array<i128, ExactRun> t{};
    for (int k = 0; k < lines; ++k) t[k] = q[s + k][c];
    for (int j = 0; j < lines; ++j) {
      d[j] = t[0];
      for (int k = 0; k + 1 < lines - j; ++k) t[k] = t[k + 1] - t[k];
    }
    return d;
  }
  // Relative to the first crossing, so the doubles stay small and exact.
  const i64 base = q[s][c];
  std::vector<double> r(lines);
  for (int k = 0; k < lines; ++k) r[k] = static_cast<double>(q[s + k][c] - base);
  for (int j = Order; j >= 1; --j) {
    const double coef = ls_top_coefficient(r, j);
    d[j] = static_cast<i128>(std::llround(coef));
    for (int k = 0; k < lines; ++k) r[k] -= static_cast<double>(d[j]) * binomial(k, j);
  }
  double mean = 0;
  for (double x : r) mean += x;
  d[0] = base + static_cast<i128>(std::llround(mean / lines));
  // Centre the error: the constant term moves it without changing its spread.
  i128 lo = 0, hi = 0;
  accumulate(d, lines, [&](int k, i128 v) {
    const i128 e = v - q[s + k][c];
    lo = k ? std::min(lo, e) : e;
    hi = k ? std::max(hi, e) : e;
  });
  d[0] -= static_cast<i128>(std::floor(static_cast<double>(lo + hi) / 2));
  return d;
}

// The fit of q[s .. s+lines) when every line is within `bound` in every channel.
std::optional<RunFit> fit_run(const std::vector<ChannelVector>& q, int s, int lines,
                              const std::array<i64, fmt::NumChannels>& bound) {
  RunFit f;
  for (int c = 0; c < fmt::NumChannels; ++c) {
    f.d[c] = fit_channel(q, s, lines, c);
    i128 worst = 0;
    int bits = 1;
    accumulate(f.d[c], lines, [&](int k, i128 v) {
      const i128 e = v - q[s + k][c];
      worst = std::max(worst, e < 0 ? -e : e);
      bits = std::max(bits, signed_bits(v));
    });
    if (worst > bound[c]) return std::nullopt;
    f.max_error[c] = static_cast<i64>(worst);
    f.value_bits[c] = bits;
  }
  return f;
}

}  // namespace

std::array<i64, fmt::NumChannels> CurveFitBounds::lsb(const ChannelFormats& f, ShadingMode shading) const {
  const double attr = shading == ShadingMode::Phong ? normal : shade;
  // Depth is held in 2^-depth_bits units of its range.
  const double unit[fmt::NumChannels] = {x, std::ldexp(depth, f.depth_bits), attr, attr, attr};
  std::array<i64, fmt::NumChannels> b{};
  for (int c = 0; c < fmt::NumChannels; ++c)
    b[c] = static_cast<i64>(std::floor(std::ldexp(std::max(0.0, unit[c]), f.frac[c])));
  return b;
}

ChannelVector quantize_crossing(const ScreenVertex& v, int line, ShadingMode shading, const Config& config) {
  ScreenVertex at = v;
  at.y = line + 0.5;  // the scan line's centre: what the crossing is of
  ChannelVector ch = quantize_vertex(at, shading, config).ch;
  // X at the word's own fraction bits (a vertex has 1/16 pixel; a crossing is no vertex).
  ch[fmt::ChanX] = std::llround(std::ldexp(v.x, config.x.frac_bits));
  return ch;
}

i64 forward_difference_value(const EdgeRecord& e, int c, int k, int bits) {
  const i128 d[Order + 1] = {e.value[c], e.slope[c], e.d2[c], e.d3[c]};
  i128 v = 0;
  for (int j = 0; j <= Order; ++j) v += d[j] * static_cast<i128>(std::llround(binomial(k, j)));
  return wrap_signed(v, bits);
}

CurveEdges fit_curve(const ScreenCurve& curve, int height, ShadingMode shading, const Config& config,
                     const CurveFitBounds& bounds) {
  if (curve.y0 < 0) throw SceneError("curve starts on scan line " + std::to_string(curve.y0) + " (expected >= 0)");
  CurveEdges out;
  out.first_line = curve.y0;
  out.value_bits.fill(1);
  const int lines = std::max(0, std::min(static_cast<int>(curve.lines.size()), height - curve.y0));
  for (int k = 0; k < lines; ++k) {
    try {
      out.quantized.push_back(quantize_crossing(curve.lines[k], curve.y0 + k, shading, config));
    } catch (const SceneError& e) {
      throw SceneError("crossing of scan line " + std::to_string(curve.y0 + k) + ": " + e.what());
    }
  }
  const ChannelFormats formats = config.channels(shading);
  const std::array<i64, fmt::NumChannels> bound = bounds.lsb(formats, shading);
  const std::vector<ChannelVector>& q = out.quantized;
  for (int s = 0; s < lines;) {
    // The longest run from s that fits: double while it does, then bisect to the first failure.
    int good = std::min(ExactRun, lines - s);
    std::optional<RunFit> best = fit_run(q, s, good, bound);
    int bad = 0;
    for (int len = 2 * good; good < lines - s; len *= 2) {
      len = std::min(len, lines - s);
      std::optional<RunFit> f = fit_run(q, s, len, bound);
      if (!f) {
        bad = len;
        break;
      }
      good = len;
      best = std::move(f);
    }
    while (bad && bad - good > 1) {
      const int mid = good + (bad - good) / 2;
      if (std::optional<RunFit> f = fit_run(q, s, mid, bound)) {
        good = mid;
        best = std::move(f);
      } else {
        bad = mid;
      }
    }
    EdgeRecord r;
    r.y0 = curve.y0 + s;
    r.n = good;
    for (int c = 0; c < fmt::NumChannels; ++c) {
      r.value[c] = wrap_signed(best->d[c][0], formats.bits[c]);
      r.slope[c] = wrap_signed(best->d[c][1], formats.bits[c]);
      r.d2[c] = wrap_signed(best->d[c][2], formats.bits[c]);
      r.d3[c] = wrap_signed(best->d[c][3], formats.bits[c]);
      out.max_error[c] = std::max(out.max_error[c], best->max_error[c]);
      out.value_bits[c] = std::max(out.value_bits[c], best->value_bits[c]);
    }
    out.records.push_back(r);
    s += good;
  }
  return out;
}

}  // namespace watkins
