// Twin of rtl/phong_shader.sv: Phong's shading rule (Phong 1975 eq. 3)
//   S = Cp [cos(i) (1 - d) + d] + W cos(s)^n
// per pixel from a unit normal N (Q2.14, the normalizer's output), with the light L and the eye
// E at infinity (unit, Q2.14, constants of the frame). cos(i) = N.L. cos(s) = R.E with Phong's
// reflected vector R = 2 (N.L) N - L (eqs. 4-8: in the light's frame Zr = 2 Zn^2 - 1,
// Xr = 2 Zn Xn, Yr = 2 Zn Yn), so
//   cos(s) = R.E = 2 (N.L)(N.E) - L.E,
// the same number for any N (expand R.E), computed with two dot products and one multiply per
// pixel; L.E is computed once per frame by frame_le().
//
// Stages (all in integers; rounding is round_shift, ties toward +inf):
//   1  ndl = N.L, nde = N.E exact (2*UnitFracBits = 28 fraction bits)
//   2  cos_i = max(round(ndl, D bits), 0); ne = round(nde, D bits) (both kept below 2.0);
//      front = cos_i > 0 (Phong p. 313: "only incident angles <= 90 degrees are considered")
//   3  cs = clamp(round(2 cos_i ne - le, P bits), 0, 1); spec = front && cs > 0;
//      f = cos_i (1 - d) + d, exact (D + 8 fraction bits)
//   4..11  cs^n by square-and-multiply over the 8 bits of n, LSB first: acc *= base if bit k,
//      base *= base, each product rounded to P bits (monotone, >= 0; tiny powers flush to 0)
//   12, 13  level = saturate(round(Cp f + 255 W pow), 0..255) per channel (specular is white)
// cos(i) <= 0 (light behind the surface, and the null normal (0,0,0)): diffuse = Cp d,
// specular 0. cos(s) <= 0: specular 0 (also for n = 0, where cos(s)^0 would be 1).
// d is clamped to 1.0 (256); W may exceed 1.0 (up to 511/256), the output saturates.
// cos(i) is not clamped at 1.0 (see round_dot); f = cos(i)(1-d) + d may then exceed 1 by a few
// 2^-14, and the level saturates at 255.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "fixed_point.hpp"
#include "formats.hpp"

namespace watkins {

struct PhongShader {
  static constexpr int UF = fmt::UnitFracBits;       // 14
  static constexpr int D = fmt::PhongDotBits;        // 24: cos(i), N.E, L.E
  static constexpr int P = fmt::PhongPowBits;        // 20: cos(s), cos(s)^n
  static constexpr int MF = fmt::MaterialFracBits;   // 8: d, W
  static constexpr int NBits = fmt::ShininessBits;   // 8: n in 0..255
  static constexpr i64 One = i64{1} << P;            // 1.0 in the power stages
  static constexpr int OutFrac = D + MF;             // fraction bits of the summed level

  using Vec = std::array<i64, 3>;  // Q2.14, UnitBits signed

  struct Pixel {
    Vec n{};                        // unit normal (normalizer output)
    std::array<int, 3> cp{};        // Cp: R, G, B reflectance, 8-bit levels (255 = 1.0)
    int d = 0;                      // environmental diffuse coefficient, MaterialBits, 1.0 = 256
    int w = 0;                      // specular coefficient W, MaterialBits, 1.0 = 256
    int shininess = 1;              // n, 0..255
  };

  struct Terms {  // intermediate values, for tests and the docs
    i64 cos_i = 0, ne = 0, cs = 0, f = 0, pow = 0;
    bool front = false, spec = false;
  };

  static i64 dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  // round(v, D fraction bits) clamped to the (D+2)-bit register: [0 or -2, 2 - 2^-D]. No clamp
  // at 1.0: a normal a rounding step longer than 1 gives N.L slightly above 1, which keeps
  // cos(s) = R.E exact (a clamp there would move highlights of large n); the output saturates.
  static i64 round_dot(i64 v, bool neg_ok) {
    const i64 hi = (i64{1} << (D + 1)) - 1;
    // |v| <= 3 * 2^(2 UF): 64 bits hold it and its rounding constant.
    return std::clamp<i64>(round_shift64(v, 2 * UF - D), neg_ok ? -hi - 1 : 0, hi);
  }
  // L.E once per frame: D fraction bits.
  static i64 frame_le(const Vec& light, const Vec& eye) {
    return round_dot(dot(light, eye), true);
  }
  static i64 power(i64 base, int n);  // base^n, P fraction bits, base in [0, 1]
  // The pixel's terms and levels; `le` = frame_le(light, eye), which a frame works out once.
  static Terms terms(const Pixel& px, const Vec& light, const Vec& eye, i64 le);
  static std::array<int, 3> shade(const Pixel& px, const Vec& light, const Vec& eye, i64 le);
  static Terms terms(const Pixel& px, const Vec& light, const Vec& eye) {
    return terms(px, light, eye, frame_le(light, eye));
  }
  static std::array<int, 3> shade(const Pixel& px, const Vec& light, const Vec& eye) {
    return shade(px, light, eye, frame_le(light, eye));
  }
};

}  // namespace watkins
