// The Phong per-pixel path (WatkinsTop's fast path) against the stage-by-stage formulas, kept here
// as its specification: the same bits for every input. rsqrt: every mantissa (W = 20 bits). power:
// every n and a dense set of bases. The normalizer and the shader: the fast forms are exact
// identities (the comments in normalizer.hpp and phong_shader.hpp argue each); here dense random
// and boundary inputs check them, and every mantissa checks the bound that makes the normalizer's
// saturation idle.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>

#include "normalizer.hpp"
#include "phong_shader.hpp"
#include "rsqrt_unit.hpp"

namespace watkins {
namespace {

// ---- the stage-by-stage formulas: the specification the fast path must match bit for bit ----
std::uint32_t ref_rsqrt_mant(std::uint32_t mant) {
  using R = RsqrtUnit;
  const std::uint64_t mc = (static_cast<std::uint64_t>(mant) << 1) | 1u;
  const std::uint64_t y0 = R::seed_row(static_cast<int>(mant >> (R::W - R::P)));
  const std::uint64_t y0sq = y0 * y0;
  const i64 t = round_shift64(static_cast<i64>(mc * y0sq), (R::W + 1) + 2 * R::T - R::G);
  const i64 u = (i64{3} << R::G) - t;
  return static_cast<std::uint32_t>(round_shift64(static_cast<i64>(y0) * u, R::T + R::G + 1 - R::F));
}

std::array<i64, 3> ref_normalize(i64 nx, i64 ny, i64 nz) {
  const RsqrtUnit::Mantissa mm = RsqrtUnit::normalize_mantissa(Normalizer::sum_of_squares(nx, ny, nz));
  const std::uint32_t y = ref_rsqrt_mant(mm.mant);
  const i64 hi = (i64{1} << (fmt::UnitBits - 1)) - 1;
  auto scale = [&](i64 n) {
    return std::clamp<i64>(round_shift64(n * static_cast<i64>(y), Normalizer::F + 4 - mm.j), -hi - 1, hi);
  };
  return {scale(nx), scale(ny), scale(nz)};
}

i64 ref_power(i64 base, int n) {
  constexpr int P = PhongShader::P;
  i64 acc = PhongShader::One;
  for (int k = 0; k < PhongShader::NBits && (n >> k) != 0; ++k) {
    if ((n >> k) & 1) acc = (acc * base + (i64{1} << (P - 1))) >> P;
    base = (base * base + (i64{1} << (P - 1))) >> P;
  }
  return acc;
}

std::array<int, 3> ref_shade(const PhongShader::Pixel& px, const PhongShader::Vec& light,
                             const PhongShader::Vec& eye) {
  using PS = PhongShader;
  constexpr int D = PS::D, P = PS::P, MF = PS::MF;
  const i64 le = PS::round_dot(PS::dot(light, eye), true);
  const i64 cos_i = PS::round_dot(PS::dot(px.n, light), false);
  const i64 ne = PS::round_dot(PS::dot(px.n, eye), true);
  const i64 cs = std::clamp<i64>(round_shift64(2 * cos_i * ne - le * (i64{1} << D), 2 * D - P), 0, PS::One);
  const bool spec = cos_i > 0 && cs > 0;
  const i64 d = px.d > (1 << MF) ? (1 << MF) : px.d;
  const i64 f = cos_i * ((1 << MF) - d) + (d << D);
  const i64 pw = spec ? ref_power(cs, px.shininess) : 0;
  const i64 sp = 255 * px.w * pw * (i64{1} << (D - P));
  std::array<int, 3> out{};
  for (int c = 0; c < 3; ++c)
    out[c] = static_cast<int>(std::clamp<i64>(round_shift64(px.cp[c] * f + sp, PS::OutFrac), 0, fmt::ShadeMax));
  return out;
}

TEST(PhongFastPath, RsqrtEveryMantissaAndTheSaturationBound) {
  using R = RsqrtUnit;
  ASSERT_EQ(R::rsqrt_mant(0), 0u);
  ASSERT_EQ(ref_rsqrt_mant(0), 0u);
  // The bound normalize() relies on to skip stage 7's saturation: (mant + 1) 2^-W (y 2^-F)^2 < 3,
  // so |unit| < sqrt(3) 2^UF + 1/2 <= 2^(UnitBits-1) - 1.
  static_assert(1.7320508075688772 * (1 << fmt::UnitFracBits) + 0.5 <= (1 << (fmt::UnitBits - 1)) - 1,
                "sqrt(3) 2^UF fits the unit register");
  unsigned __int128 worst_num = 0;  // max (mant + 1) y^2, against 3 2^(W + 2F)
  for (std::uint32_t mant = R::MantLo; mant < static_cast<std::uint32_t>(R::MantHi); ++mant) {
    const std::uint32_t y = R::rsqrt_mant(mant);
    if (y != ref_rsqrt_mant(mant)) FAIL() << "rsqrt_mant(" << mant << ") = " << y << ", expected " << ref_rsqrt_mant(mant);
    worst_num = std::max(worst_num, static_cast<unsigned __int128>(mant + 1) * y * y);
  }
  EXPECT_LT(worst_num, static_cast<unsigned __int128>(3) << (R::W + 2 * R::F));
  // And it is a real bound, not a vacuous one: 1/sqrt(m') times sqrt(m') is about 1.
  EXPECT_GT(worst_num, static_cast<unsigned __int128>(1) << (R::W + 2 * R::F));
}

TEST(PhongFastPath, NormalizerDenseRandomAndBoundaries) {
  const i64 lim = (i64{1} << (fmt::NormalInBits - 1)) - 1;  // NormalInBits signed
  auto check = [&](i64 x, i64 y, i64 z) {
    const Normalizer::Unit u = Normalizer::normalize(x, y, z);
    const std::array<i64, 3> want = ref_normalize(x, y, z);
    if (u.n != want)
      ADD_FAILURE() << "normalize(" << x << ", " << y << ", " << z << ") = (" << u.n[0] << ", " << u.n[1] << ", "
                    << u.n[2] << "), expected (" << want[0] << ", " << want[1] << ", " << want[2] << ")";
    return u.n == want;
  };
  // Boundaries: the null vector, the axes and diagonals at every power of two (every j), the
  // largest components of either sign.
  for (i64 a : {i64{0}, i64{1}, i64{2}, i64{3}, lim, -lim - 1, lim - 1, -lim})
    for (i64 b : {i64{0}, i64{1}, -i64{1}, lim, -lim - 1})
      for (i64 c : {i64{0}, i64{1}, -i64{1}, lim, -lim - 1}) ASSERT_TRUE(check(a, b, c));
  for (int k = 0; k < fmt::NormalInBits - 1; ++k) {
    const i64 p = i64{1} << k;
    for (i64 d : {-1, 0, 1})
      for (i64 s : {i64{1}, -i64{1}}) {
        ASSERT_TRUE(check(s * (p + d), 0, 0));
        ASSERT_TRUE(check(p + d, s * (p + d), -(p + d)));
        ASSERT_TRUE(check(s * (p + d), p / 2, -(p / 3)));
      }
  }
  // Dense random: full-range and short vectors (every magnitude class, so every j).
  std::mt19937_64 rng(11);
  for (int i = 0; i < 2000000; ++i) {
    const int bits = 1 + static_cast<int>(rng() % (fmt::NormalInBits - 1));
    const i64 r = (i64{1} << bits) - 1;
    std::uniform_int_distribution<i64> dist(std::max(-r - 1, -lim - 1), std::min(r, lim));
    if (!check(dist(rng), dist(rng), dist(rng))) break;
  }
}

TEST(PhongFastPath, PowerEveryExponent) {
  constexpr i64 One = PhongShader::One;
  std::vector<i64> bases;
  for (i64 b = 0; b <= 4096; ++b) bases.push_back(b);  // small bases flush to 0 at some stage
  for (i64 b = 4097; b < One; b += 61) bases.push_back(b);
  for (i64 b = One - 4096; b <= One; ++b) bases.push_back(b);  // near 1.0, long chains of roundings
  for (int n = 0; n < (1 << PhongShader::NBits); ++n)
    for (const i64 b : bases) {
      const i64 want = ref_power(b, n);
      if (PhongShader::power(b, n) != want || PowerTable[static_cast<std::size_t>(n)](b) != want)
        FAIL() << "power(" << b << ", " << n << ") = " << PhongShader::power(b, n) << " / "
               << PowerTable[static_cast<std::size_t>(n)](b) << ", expected " << want;
    }
  // n is the RTL's NBits-bit register: bits above it do not count.
  for (const i64 b : {i64{0}, i64{1}, One / 3, One - 1, One})
    for (int n : {256, 257, 300, 511, -1, -255})
      EXPECT_EQ(PhongShader::power(b, n), ref_power(b, n & 255)) << b << " " << n;
}

TEST(PhongFastPath, ShadeDenseRandomAndBoundaries) {
  using PS = PhongShader;
  std::mt19937_64 rng(12);
  const i64 unit_lim = (i64{1} << (fmt::UnitBits - 1)) - 1;
  std::uniform_int_distribution<i64> comp(-unit_lim - 1, unit_lim);
  std::uniform_int_distribution<i64> normal_in(-(i64{1} << (fmt::NormalInBits - 1)), (i64{1} << (fmt::NormalInBits - 1)) - 1);
  std::uniform_int_distribution<int> level(0, 255), coef(0, (1 << fmt::MaterialBits) - 1), shin(0, 255);
  auto unit = [&] {  // a normalizer output: what the pipeline feeds the shader
    const Normalizer::Unit u = Normalizer::normalize(normal_in(rng), normal_in(rng), normal_in(rng));
    return u.n;
  };
  int mismatches = 0;
  auto check = [&](const PS::Vec& n, const std::array<int, 3>& cp, int d, int w, int sh, const PS::Vec& l,
                   const PS::Vec& e) {
    const PS::Pixel px{n, cp, d, w, sh};
    const std::array<int, 3> want = ref_shade(px, l, e);
    const std::array<int, 3> fast = PS::shade(n, PS::material_terms(cp, d, w, sh), l, e, PS::frame_le(l, e));
    const std::array<int, 3> twin = PS::shade(px, l, e);
    if ((fast != want || twin != want) && ++mismatches <= 5)
      ADD_FAILURE() << "shade differs: n (" << n[0] << ", " << n[1] << ", " << n[2] << ") cp " << cp[0] << " d " << d
                    << " w " << w << " n " << sh << ": fast " << fast[0] << "," << fast[1] << "," << fast[2]
                    << " twin " << twin[0] << "," << twin[1] << "," << twin[2] << " want " << want[0] << ","
                    << want[1] << "," << want[2];
  };
  const PS::Vec z{0, 0, 1 << fmt::UnitFracBits}, x{1 << fmt::UnitFracBits, 0, 0};
  // Boundaries: the null normal, the light at the eye and opposite it, grazing and backlit
  // normals, full-range (non-unit) vectors, d at and past 1.0, W at its top, n = 0, 1, 255.
  const std::array<PS::Vec, 8> vecs = {PS::Vec{0, 0, 0}, z, x, PS::Vec{0, 0, -(1 << fmt::UnitFracBits)},
                                       PS::Vec{unit_lim, unit_lim, unit_lim}, PS::Vec{-unit_lim - 1, -unit_lim - 1, -unit_lim - 1},
                                       PS::Vec{11585, 0, 11585}, PS::Vec{-11585, 0, 11585}};
  for (const PS::Vec& n : vecs)
    for (const PS::Vec& l : vecs)
      for (const PS::Vec& e : {z, x, vecs[6]})
        for (int d : {0, 128, 256, 300, (1 << fmt::MaterialBits) - 1})
          for (int w : {0, 256, (1 << fmt::MaterialBits) - 1})
            for (int sh : {0, 1, 2, 255}) check(n, {255, 0, 128}, d, w, sh, l, e);
  // Dense random: normalizer outputs against unit-ish lights, and raw full-range words.
  for (int i = 0; i < 1000000; ++i) {
    const bool raw = i % 4 == 0;
    const PS::Vec n = raw ? PS::Vec{comp(rng), comp(rng), comp(rng)} : unit();
    const PS::Vec l = raw ? PS::Vec{comp(rng), comp(rng), comp(rng)} : unit();
    const PS::Vec e = i % 3 == 0 ? z : (raw ? PS::Vec{comp(rng), comp(rng), comp(rng)} : unit());
    check(n, {level(rng), level(rng), level(rng)}, coef(rng), coef(rng), shin(rng), l, e);
  }
  EXPECT_EQ(mismatches, 0);
}

}  // namespace
}  // namespace watkins
