// Error figures of the Phong shader model (model/twins/phong_shader.hpp) against double precision on
// the same quantized inputs (N, L, E in Q2.14, Cp, d, W, n as given): random unit normals from
// the normalizer model, random and grazing light (N.L within a few degrees of 0), n = 0..255
// (and every n = 1..128 in its own class), random Cp, d, W. The reference evaluates eq. 3 in
// double with Phong's reflected vector R = 2(N.L)N - L (cos(s) = R.E, the other form of the
// model's 2(N.L)(N.E) - L.E), cos(s) clamped to [0, 1] and cos(i) to >= 0 as documented; the front-facing decision is
// the model's (cos(i) rounded to PhongDotBits > 0), so the figure measures arithmetic error.
// Error = |output level - exact level| (includes the final rounding's 1/2 level).
// `--narrow` measures the narrow set (PhongFormat::Narrow), its normals from the narrow normalizer.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "normalizer.hpp"
#include "phong_shader.hpp"

using namespace watkins;
using Vec = PhongShader::Vec;

namespace {

PhongFormat format = PhongFormat::Model;
std::mt19937_64 rng(20250512);
std::uniform_real_distribution<double> U(-1.0, 1.0);

Vec quant_unit(const double v[3]) {  // a unit vector in Q2.14 through the normalizer model
  i64 in[3];
  for (int c = 0; c < 3; ++c) in[c] = std::llround(std::ldexp(v[c], fmt::FracBits - 1));
  const auto u = Normalizer::normalize(in[0], in[1], in[2], format);
  return {u.n[0], u.n[1], u.n[2]};
}
Vec random_unit() {
  double v[3], l;
  do {
    v[0] = U(rng), v[1] = U(rng), v[2] = U(rng);
    l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  } while (l < 0.1 || l > 1);
  for (double& c : v) c /= l;
  return quant_unit(v);
}
// A unit normal at angle (90 deg + delta) from L, delta in [-spread, spread] degrees.
Vec grazing(const Vec& L, double spread) {
  const double l[3] = {std::ldexp(double(L[0]), -14), std::ldexp(double(L[1]), -14), std::ldexp(double(L[2]), -14)};
  double p[3], t;
  do {  // a random direction perpendicular to L
    const double r[3] = {U(rng), U(rng), U(rng)};
    const double dl = r[0] * l[0] + r[1] * l[1] + r[2] * l[2];
    for (int c = 0; c < 3; ++c) p[c] = r[c] - dl * l[c];
    t = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  } while (t < 1e-3);
  const double a = U(rng) * spread * M_PI / 180;
  double v[3];
  for (int c = 0; c < 3; ++c) v[c] = std::cos(a) * p[c] / t - std::sin(a) * l[c];
  return quant_unit(v);
}

double dotd(const Vec& a, const Vec& b) {
  return std::ldexp(double(a[0]) * b[0] + double(a[1]) * b[1] + double(a[2]) * b[2], -28);
}

struct Stats {
  double max_err = 0, sum = 0;
  std::uint64_t n = 0, off_by_one = 0;
  PhongShader::Pixel worst{};
  void add(const PhongShader::Pixel& px, const Vec& L, const Vec& E) {
    const i64 le = PhongShader::frame_le(L, E, format);
    const auto out = PhongShader::shade(px, L, E, le, format);
    const auto t = format == PhongFormat::Narrow ? PhongShader::terms_narrow(px, L, E, le) : PhongShader::terms(px, L, E);
    // Reference: eq. 3 in double, Phong's reflected vector.
    const double ci = std::max(0.0, dotd(px.n, L));
    double R[3];
    const double nl = dotd(px.n, L);
    for (int c = 0; c < 3; ++c) R[c] = 2 * nl * std::ldexp(double(px.n[c]), -14) - std::ldexp(double(L[c]), -14);
    // cos(s) = R.E with Phong's reflected vector, clamped to [0, 1] as the model does.
    const double cs = std::min(1.0, std::max(0.0, R[0] * std::ldexp(double(E[0]), -14) +
                                                      R[1] * std::ldexp(double(E[1]), -14) +
                                                      R[2] * std::ldexp(double(E[2]), -14)));
    const double d = std::min(1.0, px.d / 256.0), w = px.w / 256.0;
    const double spec = (t.front && cs > 0) ? w * std::pow(cs, px.shininess) : 0.0;
    const double f = (t.front ? ci : 0.0) * (1 - d) + d;  // N.L unclamped above, as the model
    for (int c = 0; c < 3; ++c) {
      const double exact = std::min(255.0, std::max(0.0, px.cp[c] * f + 255 * spec));
      const double e = std::fabs(out[c] - exact);
      sum += e;
      if (out[c] != static_cast<int>(std::floor(exact + 0.5))) ++off_by_one;
      if (e > max_err) max_err = e, worst = px;
    }
    ++n;
  }
};

PhongShader::Pixel random_pixel(const Vec& n, int shininess) {
  PhongShader::Pixel px;
  px.n = n;
  for (int& c : px.cp) c = static_cast<int>(rng() % 256);
  px.d = static_cast<int>(rng() % 257);
  px.w = static_cast<int>(rng() % 257);
  px.shininess = shininess;
  return px;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--narrow") format = PhongFormat::Narrow, --argc, ++argv;
  const std::uint64_t N = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 2000000ull;
  // Check first that R.E and 2(N.L)(N.E) - L.E agree (they are the same polynomial).
  double max_identity = 0;
  for (int k = 0; k < 100000; ++k) {
    const Vec n = random_unit(), L = random_unit(), E = random_unit();
    const double nl = dotd(n, L);
    double re = 0;
    for (int c = 0; c < 3; ++c)
      re += (2 * nl * std::ldexp(double(n[c]), -14) - std::ldexp(double(L[c]), -14)) * std::ldexp(double(E[c]), -14);
    max_identity = std::max(max_identity, std::fabs(re - (2 * nl * dotd(n, E) - dotd(L, E))));
  }
  std::printf("R.E vs 2(N.L)(N.E) - L.E in double: max difference %.3g (rounding only)\n", max_identity);

  Stats rnd, graze, per_n, big_n;
  for (std::uint64_t k = 0; k < N; ++k) {
    const Vec L = random_unit(), E = random_unit();
    // Half the normals near the highlight (N between L and E), half anywhere.
    Vec n;
    if (k & 1) {
      n = random_unit();
    } else {
      double h[3];
      for (int c = 0; c < 3; ++c) h[c] = std::ldexp(double(L[c] + E[c]), -14) + 0.05 * U(rng);
      const double l = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
      if (l < 1e-3) continue;
      for (double& c : h) c /= l;
      n = quant_unit(h);
    }
    rnd.add(random_pixel(n, static_cast<int>(rng() % 256)), L, E);
    graze.add(random_pixel(grazing(L, 3.0), static_cast<int>(rng() % 256)), L, E);
  }
  for (int s = 1; s <= 128; ++s)
    for (int k = 0; k < 20000; ++k) {
      const Vec L = random_unit(), E = random_unit();
      double h[3];
      for (int c = 0; c < 3; ++c) h[c] = std::ldexp(double(L[c] + E[c]), -14) + 0.3 * U(rng) / std::sqrt(double(s));
      const double l = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
      if (l < 1e-3) continue;
      for (double& c : h) c /= l;
      (s <= 128 ? per_n : big_n).add(random_pixel(quant_unit(h), s), L, E);
    }
  auto show = [](const char* name, const Stats& s) {
    std::printf("  %-44s %9llu pixels  max %.4f levels  mean %.4f  != round(exact): %llu\n", name,
                static_cast<unsigned long long>(s.n), s.max_err, s.sum / std::max<double>(1, 3.0 * s.n),
                static_cast<unsigned long long>(s.off_by_one));
  };
  std::printf("phong shader vs double (8-bit levels, seed 20250512):\n");
  show("random N (half near the highlight), n 0..255", rnd);
  show("grazing light, |i - 90 deg| <= 3 deg, n 0..255", graze);
  show("every n = 1..128, N near the highlight", per_n);
  const Stats* all[] = {&rnd, &graze, &per_n};
  // The narrow set's bound: cos(s) from N.E at 14 fraction bits (2^-14 in cos(s) near the
  // highlight, 255 n 2^-14 W levels for large n) and the tabled power.
  const bool narrow_set = format == PhongFormat::Narrow;
  const double bound = narrow_set ? 6.0 : 0.6;
  bool ok = true;
  for (const Stats* s : all) ok &= s->max_err < bound;
  const PhongShader::Pixel& w = rnd.max_err >= per_n.max_err ? rnd.worst : per_n.worst;
  std::printf("  worst pixel: n %d, d %d, W %d, Cp (%d, %d, %d)\n", w.shininess, w.d, w.w, w.cp[0], w.cp[1], w.cp[2]);
  std::printf("shader_error (%s set): %s (< %.1f levels)\n", narrow_set ? "narrow" : "model",
              ok ? "within bounds" : "BOUND EXCEEDED", bound);
  return ok ? 0 : 1;
}
