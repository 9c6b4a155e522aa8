// Error figures of the normalizer model (model/twins/normalizer.hpp) against double precision:
//  (a) the inverse square root over every mantissa m' at RsqrtMantBits (exhaustive), relative
//      error of y against 1/sqrt(m'c) and against 1/sqrt of every m' the mantissa stands for;
//  (b) the full normalizer over every exponent class (component magnitudes 2^e, e = 0..17),
//      near-null vectors, interpolated antipodal normals, and 10^7 random inputs (fixed seed):
//      max error in ulps of the Q2.14 output (2^-14) and max length error ||unit| - 1|.
// `--narrow` measures the narrow set (PhongFormat::Narrow) instead: (a) its table's 1/sqrt over
// every M at 2^-25 steps of m', (b) the block against double on its own 16-bit input (stage 0's
// rounding of the 18-bit input is the configuration's quantization, as the model set's input is).
// Exits non-zero if a bound is exceeded, so ctest runs it; scripts/lib/normalizer_ulp.sh prints it.
#include <cmath>
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <random>
#include <string>

#include "normalizer.hpp"

using namespace watkins;

namespace {

PhongFormat format = PhongFormat::Model;

struct Stats {
  double max_ulp = 0, max_len = 0, sum_ulp = 0;
  std::uint64_t n = 0, nulls = 0, bad_null = 0;
  i64 worst[3] = {0, 0, 0};
  void add(i64 x, i64 y, i64 z) {
    const Normalizer::Unit u = Normalizer::normalize(x, y, z, format);
    if (format == PhongFormat::Narrow)  // the block's own input
      x = Normalizer::narrow_input(x), y = Normalizer::narrow_input(y), z = Normalizer::narrow_input(z);
    ++n;
    if (x == 0 && y == 0 && z == 0) {
      ++nulls;
      if (!u.null || u.n[0] || u.n[1] || u.n[2]) ++bad_null;
      return;
    }
    if (u.null) ++bad_null;
    const double len = std::sqrt(double(x) * x + double(y) * y + double(z) * z);
    const i64 in[3] = {x, y, z};
    double l2 = 0;
    for (int c = 0; c < 3; ++c) {
      const double exact = std::ldexp(double(in[c]) / len, fmt::UnitFracBits);
      const double e = std::fabs(double(u.n[c]) - exact);
      sum_ulp += e;
      if (e > max_ulp) {
        max_ulp = e;
        worst[0] = x, worst[1] = y, worst[2] = z;
      }
      const double v = std::ldexp(double(u.n[c]), -fmt::UnitFracBits);
      l2 += v * v;
    }
    max_len = std::max(max_len, std::fabs(std::sqrt(l2) - 1.0));
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--narrow") format = PhongFormat::Narrow, --argc, ++argv;
  const bool narrow_set = format == PhongFormat::Narrow;
  const std::uint64_t randoms = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 10000000ull;
  bool ok = true;

  if (narrow_set) {
    // (a) the narrow 1/sqrt: every row and 2^-25 steps of m' (M's bits below the 16 of d are
    // truncated), y = 1 + y' 2^-16 against 1/sqrt(M 2^-32).
    double rel = 0;
    for (std::uint64_t big_m = std::uint64_t{1} << 30; big_m < (std::uint64_t{1} << 32); big_m += 128) {
      const double y = 1 + std::ldexp(double(RsqrtUnit::rsqrt_narrow(static_cast<std::uint32_t>(big_m))), -16);
      rel = std::max(rel, std::fabs(y * std::sqrt(std::ldexp(double(big_m), -32)) - 1));
    }
    std::printf("narrow inverse sqrt, m' in [1/4, 1) at 2^-25 steps (256-row table, linear interpolation):\n");
    std::printf("  max rel error vs 1/sqrt(m')  %.3g = 2^%.2f\n", rel, std::log2(rel));
    ok &= rel < std::ldexp(1.0, -15.9);
  } else {
    // (a) inverse square root, every mantissa.
    double rel_c = 0, rel_any = 0;
    std::uint64_t mants = 0;
    for (std::uint32_t mant = RsqrtUnit::MantLo; mant < RsqrtUnit::MantHi; ++mant, ++mants) {
      const double y = std::ldexp(double(RsqrtUnit::rsqrt_mant(mant)), -Normalizer::F);
      const double lo = std::ldexp(double(mant), -RsqrtUnit::W);       // m' range of this mantissa
      const double hi = std::ldexp(double(mant) + 1, -RsqrtUnit::W);
      const double c = std::ldexp(2.0 * mant + 1, -(RsqrtUnit::W + 1));
      rel_c = std::max(rel_c, std::fabs(y * std::sqrt(c) - 1));
      rel_any = std::max({rel_any, std::fabs(y * std::sqrt(lo) - 1), std::fabs(y * std::sqrt(hi) - 1)});
    }
    std::printf("inverse sqrt, %llu mantissas (every m' in [1/4,1) at %d bits; y depends on m' only):\n",
                static_cast<unsigned long long>(mants), RsqrtUnit::W);
    std::printf("  max rel error vs 1/sqrt(m'c) (table + Newton-Raphson)  %.3g = 2^%.2f\n", rel_c,
                std::log2(rel_c));
    std::printf("  max rel error vs 1/sqrt(m') over the truncated bits   %.3g = 2^%.2f\n", rel_any,
                std::log2(rel_any));
    ok &= rel_any < std::ldexp(1.0, -18);
  }

  // (b) the full normalizer.
  Stats classes, random, nearnull, antipodal;
  std::mt19937_64 rng(20250511);
  const i64 hi = (i64{1} << (fmt::NormalInBits - 1));
  for (int e = 0; e < fmt::NormalInBits; ++e) {  // every exponent class: |component| < 2^e
    const i64 lim = i64{1} << e;
    for (int k = 0; k < 100000; ++k) {
      auto r = [&] { return static_cast<i64>(rng() % (2 * lim + 1)) - lim; };
      i64 x = r(), y = r(), z = r();
      if (x < -hi) x = -hi;
      if (x >= hi) x = hi - 1;
      if (y >= hi) y = hi - 1;
      if (z >= hi) z = hi - 1;
      if (y < -hi) y = -hi;
      if (z < -hi) z = -hi;
      classes.add(x, y, z);
    }
    for (i64 s : {lim - 1, lim, -lim}) {  // axis vectors and the edges of the input range
      const i64 v = std::max(-hi, std::min(hi - 1, s));
      classes.add(v, 0, 0), classes.add(0, v, 0), classes.add(0, 0, v), classes.add(v, v, v);
    }
  }
  for (i64 x = -4; x <= 4; ++x)
    for (i64 y = -4; y <= 4; ++y)
      for (i64 z = -4; z <= 4; ++z) nearnull.add(x, y, z);
  // Interpolating two nearly antipodal unit normals: (1-a) A + a B passes near the origin.
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int k = 0; k < 200000; ++k) {
    double a[3] = {U(rng), U(rng), U(rng)};
    const double la = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    const double t = 0.5 + U(rng) * 1e-3;
    const double jit = 1e-4;
    i64 v[3];
    for (int c = 0; c < 3; ++c) {
      const double A = a[c] / la, B = -A + jit * U(rng);
      v[c] = std::llround(std::ldexp((1 - t) * A + t * B, fmt::FracBits));
    }
    antipodal.add(v[0], v[1], v[2]);
  }
  for (std::uint64_t k = 0; k < randoms; ++k) {
    const int e = static_cast<int>(rng() % fmt::NormalInBits) + 1;  // magnitude class 2^(e-1)
    auto r = [&] { return wrap_signed(static_cast<i128>(rng()), e); };
    random.add(r(), r(), r());
  }
  auto show = [](const char* name, const Stats& s) {
    std::printf("  %-34s %9llu inputs  max %.4f ulp  mean %.4f ulp  max ||u|-1| %.3g = %.3f ulp\n", name,
                static_cast<unsigned long long>(s.n), s.max_ulp,
                s.sum_ulp / std::max<double>(1, 3.0 * double(s.n - s.nulls)), s.max_len,
                std::ldexp(s.max_len, fmt::UnitFracBits));
  };
  std::printf("normalizer vs double (ulp = 2^-%d of the Q2.14 output):\n", fmt::UnitFracBits);
  show("every exponent class 2^0..2^17", classes);
  show("near-null, |components| <= 4", nearnull);
  show("interpolated antipodal normals", antipodal);
  show("random (seed 20250511)", random);
  std::printf("  worst input (random): (%lld, %lld, %lld)\n", static_cast<long long>(random.worst[0]),
              static_cast<long long>(random.worst[1]), static_cast<long long>(random.worst[2]));
  std::printf("  null vector (0,0,0): %llu seen, %llu not mapped to (0,0,0)+null\n",
              static_cast<unsigned long long>(classes.nulls + nearnull.nulls + random.nulls + antipodal.nulls),
              static_cast<unsigned long long>(classes.bad_null + nearnull.bad_null + random.bad_null +
                                              antipodal.bad_null));
  // The narrow set's bounds: its 1/sqrt is within 2^-16 (the 16-bit y' and its interpolation),
  // a quarter ulp more than the model set's.
  const double ulp_bound = narrow_set ? 0.8 : 0.55, len_bound = narrow_set ? 1.1 : 1.0;
  for (const Stats* s : {&classes, &nearnull, &antipodal, &random}) {
    ok &= s->max_ulp < ulp_bound && s->bad_null == 0;
    ok &= s->max_len < std::ldexp(len_bound, -fmt::UnitFracBits);
  }
  std::printf("normalizer_error (%s set): %s (< %.2f ulp, ||u|-1| < %.1f 2^-14)\n", narrow_set ? "narrow" : "model",
              ok ? "within bounds" : "BOUND EXCEEDED", ulp_bound, len_bound);
  return ok ? 0 : 1;
}
