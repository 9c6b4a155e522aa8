#include "watkins_top.hpp"

#include <algorithm>
#include <cstring>
#if defined(__x86_64__)
#include <immintrin.h>
#endif
#include <exception>
#include <thread>
#include <type_traits>

#include "normalizer.hpp"
#include "phong_shader.hpp"
#include "scan_lines.hpp"
#include "shade_divider.hpp"
#include "smoother.hpp"
#include "span_reciprocal.hpp"

namespace watkins {
namespace {

// The Phong blocks' frame constants: light, eye, L.E (PhongShader::frame_le) and each material's
// terms (PhongShader::material_terms), worked out once per frame instead of per pixel. The narrow
// formats (Config::phong) shade each pixel through Normalizer::normalize_narrow and
// PhongShader::shade_narrow, from the materials as given (phong_narrow_materials).
struct PhongFrame {
  PhongShader::Vec light{}, eye{};
  PhongFormat format = PhongFormat::Model;
  i64 le = 0;
  std::vector<PhongShader::MaterialTerms> materials;  // by material id, as frame.materials
  std::vector<PhongShader::Pixel> phong_narrow_materials;   // Cp, d, W, n by material id (the narrow set)
  // The material terms by field (by material id), for a line kernel's gathers: Cp per channel,
  // 1 - d, the d term, the specular scale and n's NBits bits.
  std::vector<i64> cp[3], one_minus_d, d_term, spec_scale, shininess;
  // Whether the light and the eye fit 32-bit lanes (a line kernel's products of them with a unit
  // normal are 32 x 32 bits); a Q2.14 vector always does.
  bool narrow_vectors = true;
  PhongFrame(const Frame& frame, PhongFormat phong_format)
      : light(frame.light), eye(frame.eye), format(phong_format),
        le(PhongShader::frame_le(frame.light, frame.eye, phong_format)) {
    if (frame.shading != ShadingMode::Phong) return;
    materials.reserve(frame.materials.size());
    for (const QuantizedMaterial& m : frame.materials) {
      const PhongShader::MaterialTerms t = PhongShader::material_terms(m.cp, m.d, m.w, m.shininess);
      materials.push_back(t);
      for (int c = 0; c < 3; ++c) cp[c].push_back(t.cp[static_cast<std::size_t>(c)]);
      one_minus_d.push_back(t.one_minus_d), d_term.push_back(t.d_term), spec_scale.push_back(t.spec_scale);
      shininess.push_back(static_cast<unsigned>(t.shininess) & ((1u << PhongShader::NBits) - 1));
      PhongShader::Pixel px;
      for (int c = 0; c < 3; ++c) px.cp[static_cast<std::size_t>(c)] = m.cp[static_cast<std::size_t>(c)];
      px.d = m.d, px.w = m.w, px.shininess = m.shininess;
      phong_narrow_materials.push_back(px);
    }
    for (int c = 0; c < 3; ++c)
      narrow_vectors &= light[static_cast<std::size_t>(c)] == static_cast<std::int32_t>(light[static_cast<std::size_t>(c)]) &&
                        eye[static_cast<std::size_t>(c)] == static_cast<std::int32_t>(eye[static_cast<std::size_t>(c)]);
  }
  // Whether the line kernels may shade: they compute the model's formats.
  bool kernel_formats() const { return format == PhongFormat::Model && narrow_vectors; }
  // normalizer → phong_shader on one normal of material `id` (checked by the caller).
  std::array<int, 3> shade(const std::array<i64, 3>& normal, int id) const {
    if (format == PhongFormat::Narrow) {
      PhongShader::Pixel px = phong_narrow_materials[static_cast<std::size_t>(id)];
      px.n = Normalizer::normalize_narrow(normal[0], normal[1], normal[2]).n;
      return PhongShader::shade_narrow(px, light, eye, le);
    }
    const Normalizer::Unit u = Normalizer::normalize(normal[0], normal[1], normal[2]);
    return PhongShader::shade(u.n, materials[static_cast<std::size_t>(id)], light, eye, le);
  }
  // The same on a fragment: its rgb becomes the shade of its material (std::out_of_range for an id
  // past the table, as the material table's read).
  void shade(Fragment& f) const {
    const std::array<int, 3> rgb = shade(f.normal, check(f.material));
    for (int c = 0; c < 3; ++c) f.rgb[c] = static_cast<std::uint8_t>(rgb[c]);
  }
  bool valid(int id) const { return id >= 0 && static_cast<std::size_t>(id) < materials.size(); }
  int check(int id) const {
    (void)materials.at(static_cast<std::size_t>(id));
    return id;
  }
};

// The line buffer of the frame loop: scanline_buffer.hpp's depth test (the same keys, the same
// rule) on a plain array, storing each winner straight into its row of the image (the image
// keeps a pixel's last winner, as the buffer's read-out would). The pixels a line's spans cover
// are one range [lo, hi), emptied by range at the end of the line.
class FrameLine {
 public:
  static constexpr std::uint64_t Empty = ~std::uint64_t{0};
  FrameLine(int width, DepthTie tie)
      : width_(width), poly_key_mask_(tie == DepthTie::Submission ? 0xffffffffu : 0u),
        key_(static_cast<std::size_t>(width), Empty), lo_(width) {}
  // Line y of img (its row already background, uncovered): the line's stores go to it.
  void start(Image& img, int y) {
    const std::size_t row = std::size_t(y) * static_cast<std::size_t>(width_);
    out_.rgb = img.rgb.data() + 3 * row;
    out_.covered = img.covered.data() + row;
    out_.owner = img.owner.data() + row;
    out_.keys = key_.data();
    lo_ = width_, hi_ = 0;
  }
  // Pixels [x0, x1) may be written (a span's).
  void touch(int x0, int x1) { lo_ = std::min(lo_, x0), hi_ = std::max(hi_, x1); }
  std::uint64_t tie_bits(int poly) const { return static_cast<std::uint32_t>(poly) & poly_key_mask_; }
  std::uint32_t tie_mask() const { return poly_key_mask_; }  // tie_bits(poly) = poly & tie_mask()
  static std::uint64_t key(std::uint32_t depth, std::uint64_t tie_bits) { return (std::uint64_t{depth} << 32) | tie_bits; }
  bool wins_key(int x, std::uint64_t key) const { return key < key_[static_cast<std::size_t>(x)]; }
  // A winner: its key, shade, coverage and polygon (the shade alone when Phong shades later).
  void store(const Fragment& f, std::uint64_t key) {
    const auto x = static_cast<std::size_t>(f.x);
    key_[x] = key;
    out_.rgb[3 * x] = f.rgb[0], out_.rgb[3 * x + 1] = f.rgb[1], out_.rgb[3 * x + 2] = f.rgb[2];
    out_.covered[x] = 1;
    out_.owner[x] = f.poly;
  }
  // Every covered pixel of the line, in x order, with its rgb in the image row.
  template <class F>
  void each_covered(F&& visit) const {
    for (int x = lo_; x < hi_; ++x)
      if (key_[static_cast<std::size_t>(x)] != Empty) visit(x, out_.rgb + 3 * x);
  }
  int lo() const { return lo_; }
  int hi() const { return hi_; }
  // Where a span kernel stores: the keys and the image row.
  struct Row {
    std::uint64_t* keys = nullptr;
    std::uint8_t* rgb = nullptr;
    std::uint8_t* covered = nullptr;
    int* owner = nullptr;
  };
  const Row& row() const { return out_; }

 private:
  int width_;
  std::uint32_t poly_key_mask_;
  std::vector<std::uint64_t> key_;
  Row out_;
  int lo_, hi_ = 0;
};

// A Gouraud span whose values stay in range (PixelPath::in_range<Shade>), for the span kernel:
// slots Z, R, G, B at x0 and their per-pixel steps as words modulo 2^64, and the readings' shifts.
struct GouraudSpan {
  int x0 = 0, x1 = 0;
  std::uint64_t tie = 0;
  int poly = 0;
  std::uint64_t value[4] = {}, step[4] = {};
  std::uint64_t half[4] = {};
  int shift[4] = {};
};

// The span kernels: PixelPath's in-range fragment (depth, rgb) and FrameLine's depth test and
// store, several pixels at a time. Lane k holds value + k·step modulo 2^64: the span's values stay
// inside their words, so that is the exact value the scalar loop reaches by k additions, and
// (v + half) >> shift (a logical shift: v + half >= 0 in range) is its reading. A lane past x1
// stores nothing. Each returns the fragments that won their pixel. Beside each, the end of a
// line: keys [lo, hi) emptied. Built for AVX2 and AVX-512 beside the baseline x86-64 build
// (whose spans take the scalar loop), chosen at run time (span_kernels).
// What a fused span setup needs of the frame's formats: the X slot's fraction bits, the width,
// and per slot Z, R, G, B its word (64 - bits: the wrap's shift; the step's saturation) and the
// values whose readings need no clamp (PixelPath::in_range with the shade readings).
struct GouraudSetupConsts {
  int width = 0, fx = 0;
  std::uint64_t wrap_shift[4] = {};
  i64 step_hi[4] = {};
  i64 read_lo[4] = {}, read_hi[4] = {};
};
// A span setup's outcome: the span drawn by the kernel, an empty span (no pixel centre), or the
// general path (SegmentInterpolator::setup and PixelPath), which the values fall to whenever
// they leave the fused setup's 64-bit bounds.
enum class FusedSetup { Span, Empty, General };

// PixelPath's normal readings (Normalizer input, FracBits fraction bits) of slots Nx, Ny, Nz, when
// each rounds away extra fraction bits (shift >= 0): round_shift64 by shift (half = 2^(shift-1),
// 0 for shift 0), saturated to NormalInBits.
struct NormalReading {
  std::uint64_t half[3] = {};
  int shift[3] = {};
};

// What a run of spans drawn by SpanKernels::draw_run adds to its line: fragments, winners, and
// the pixels [lo, hi) its spans cover (FrameLine::touch).
struct SpanRun {
  long long fragments = 0, visible = 0;
  int lo = 0, hi = 0;
};

struct SpanKernels {
  long long (*draw)(const GouraudSpan&, const FrameLine::Row&) = nullptr;  // nullptr: the scalar loop
  void (*empty)(std::uint64_t* keys, int lo, int hi) = nullptr;
  // SegmentInterpolator::setup, PixelPath::in_range<Shade> and FrameSetup::gouraud_span in one,
  // the four slots side by side, for a line's n segments at once (independent setups overlap in
  // the processor): span k's x0, x1, poly, value and step and its outcome. nullptr: none.
  void (*setup)(const Segment*, std::size_t n, const GouraudSetupConsts&, GouraudSpan*, FusedSetup*) = nullptr;
  // Spans i .. of a line after the fused setup, in order, while it drew them (Span: draw's
  // arithmetic and stores, the frame's readings held across the spans) or found no pixel
  // (Empty); returns the index of the first General span (or n), and adds the drawn spans'
  // fragments, winners and pixels to `run`. nullptr: each span through draw.
  std::size_t (*draw_run)(const GouraudSpan* spans, const FusedSetup* got, std::size_t i, std::size_t n,
                          const GouraudSpan& readings, std::uint32_t tie_mask, const FrameLine::Row& out,
                          SpanRun& run) = nullptr;
  // A deferred Phong line's read-out: each covered pixel of keys [lo, hi) (key not Empty) gets
  // the shade of normal[x] and material[x] in rgb[3x..3x+2], as PhongFrame::shade gives it.
  // nullptr: the scalar loop.
  void (*phong_line)(const PhongFrame&, const std::array<i64, 3>* normal, const int* material, const std::uint64_t* keys,
                     int lo, int hi, std::uint8_t* rgb) = nullptr;
  // A deferred Phong span in range (slots Z, Nx, Ny, Nz of the GouraudSpan; its tie and poly):
  // the depth test, and for each winner its key, coverage and polygon in the line and its normal
  // reading and material (valid, checked by the caller) in normal[x] and material[x], as the
  // scalar loop stores them (the winner's rgb is the read-out's). Returns the winners. nullptr:
  // the scalar loop.
  long long (*phong_span)(const GouraudSpan&, const NormalReading&, int material, const FrameLine::Row&,
                          std::array<i64, 3>* normal, int* materials) = nullptr;
};

void empty_keys(std::uint64_t* keys, int lo, int hi) {
  if (hi > lo) std::fill(keys + lo, keys + hi, FrameLine::Empty);
}

#if defined(__x86_64__) && defined(__GNUC__)
#define WATKINS_SPAN_KERNELS 1
// GCC 12's AVX-512 headers start vectors from an undefined value (_mm512_undefined_*), which
// -Wall reports as uninitialized.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#ifndef __clang__
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#define WATKINS_AVX512 "avx512f,avx512vl,avx512dq,avx512bw,avx512vbmi,bmi2"
// Bytes 8k, 8k+1, 8k+2 of eight 64-bit lanes (r | g << 8 | b << 16) packed as 24 rgb bytes.
alignas(64) constexpr std::uint8_t RgbPackIndex[64] = {0,  1,  2,  8,  9,  10, 16, 17, 18, 24, 25, 26,
                                                       32, 33, 34, 40, 41, 42, 48, 49, 50, 56, 57, 58};
// A span's pixels eight at a time from v (the lanes' values, stepped by stride): the depth test,
// and each winner's key, rgb, covered flag and owner stored into the row. Gives the winners.
__attribute__((target(WATKINS_AVX512), always_inline)) inline long long gouraud_lanes_avx512(
    const GouraudSpan& s, __m512i* v, const __m512i* stride, const __m512i* half, const __m128i* shift, __m512i tie,
    __m256i poly, __m512i pack, __m128i one, const FrameLine::Row& out) {
  long long won = 0;
  for (int x = s.x0; x < s.x1; x += 8) {
    const int left = s.x1 - x;
    const __mmask8 valid = left >= 8 ? __mmask8(0xff) : static_cast<__mmask8>((1u << left) - 1);
    const __m512i depth = _mm512_srl_epi64(_mm512_add_epi64(v[0], half[0]), shift[0]);
    const __m512i key = _mm512_or_si512(_mm512_slli_epi64(depth, 32), tie);
    const __m512i old = _mm512_maskz_loadu_epi64(valid, out.keys + x);
    const __mmask8 win = _mm512_mask_cmplt_epu64_mask(valid, key, old);
    if (win) {
      _mm512_mask_storeu_epi64(out.keys + x, win, key);
      const __m512i r = _mm512_srl_epi64(_mm512_add_epi64(v[1], half[1]), shift[1]);
      const __m512i g = _mm512_srl_epi64(_mm512_add_epi64(v[2], half[2]), shift[2]);
      const __m512i b = _mm512_srl_epi64(_mm512_add_epi64(v[3], half[3]), shift[3]);
      const __m512i rgb = _mm512_or_si512(r, _mm512_or_si512(_mm512_slli_epi64(g, 8), _mm512_slli_epi64(b, 16)));
      // Three byte-mask bits per winning pixel.
      const std::uint32_t bit = _pdep_u32(win, 0x249249u);
      const __mmask32 bytes = bit | (bit << 1) | (bit << 2);
      _mm256_mask_storeu_epi8(out.rgb + 3 * x, bytes, _mm512_castsi512_si256(_mm512_permutexvar_epi8(pack, rgb)));
      _mm_mask_storeu_epi8(out.covered + x, win, one);
      _mm256_mask_storeu_epi32(out.owner + x, win, poly);
      won += __builtin_popcount(win);
    }
    for (int c = 0; c < 4; ++c) v[c] = _mm512_add_epi64(v[c], stride[c]);
  }
  return won;
}
__attribute__((target(WATKINS_AVX512))) long long gouraud_span_avx512(const GouraudSpan& s,
                                                                      const FrameLine::Row& out) {
  const __m512i lane = _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7);
  __m512i v[4], stride[4], half[4];
  __m128i shift[4];
  for (int c = 0; c < 4; ++c) {
    const __m512i step = _mm512_set1_epi64(static_cast<long long>(s.step[c]));
    v[c] = _mm512_add_epi64(_mm512_set1_epi64(static_cast<long long>(s.value[c])), _mm512_mullo_epi64(lane, step));
    stride[c] = _mm512_slli_epi64(step, 3);
    half[c] = _mm512_set1_epi64(static_cast<long long>(s.half[c]));
    shift[c] = _mm_cvtsi32_si128(s.shift[c]);
  }
  const __m512i tie = _mm512_set1_epi64(static_cast<long long>(s.tie));
  const __m256i poly = _mm256_set1_epi32(s.poly);
  const __m128i one = _mm_set1_epi8(1);
  // Bytes 8k, 8k+1, 8k+2 of the eight lanes (r | g << 8 | b << 16) packed as 24 rgb bytes.
  const __m512i pack = _mm512_load_si512(RgbPackIndex);
  return gouraud_lanes_avx512(s, v, stride, half, shift, tie, poly, pack, one, out);
}

// gouraud_span_avx512 over a run of a line's spans (SpanKernels::draw_run): the same lanes and
// stores, with the readings' halves and shifts held across the spans. Lane k's k·step is summed
// from step, 2·step and 4·step by lane bits: the same word modulo 2^64 as the product.
__attribute__((target(WATKINS_AVX512))) std::size_t gouraud_run_avx512(const GouraudSpan* spans, const FusedSetup* got,
                                                                        std::size_t i, std::size_t n,
                                                                        const GouraudSpan& readings,
                                                                        std::uint32_t tie_mask,
                                                                        const FrameLine::Row& out, SpanRun& run) {
  __m512i half[4];
  __m128i shift[4];
  for (int c = 0; c < 4; ++c) {
    half[c] = _mm512_set1_epi64(static_cast<long long>(readings.half[c]));
    shift[c] = _mm_cvtsi32_si128(readings.shift[c]);
  }
  const __m128i one = _mm_set1_epi8(1);
  const __m512i pack = _mm512_load_si512(RgbPackIndex);
  long long fragments = 0, won = 0;
  int lo = run.lo, hi = run.hi;
  for (; i < n; ++i) {
    const FusedSetup o = got[i];
    if (o == FusedSetup::General) break;
    if (o == FusedSetup::Empty) continue;
    const GouraudSpan& s = spans[i];
    fragments += s.x1 - s.x0;
    lo = std::min(lo, s.x0), hi = std::max(hi, s.x1);
    __m512i v[4], stride[4];
    for (int c = 0; c < 4; ++c) {
      const __m512i step = _mm512_set1_epi64(static_cast<long long>(s.step[c]));
      __m512i k_step = _mm512_maskz_mov_epi64(0xaa, step);
      k_step = _mm512_mask_add_epi64(k_step, 0xcc, k_step, _mm512_slli_epi64(step, 1));
      k_step = _mm512_mask_add_epi64(k_step, 0xf0, k_step, _mm512_slli_epi64(step, 2));
      v[c] = _mm512_add_epi64(_mm512_set1_epi64(static_cast<long long>(s.value[c])), k_step);
      stride[c] = _mm512_slli_epi64(step, 3);
    }
    const __m512i tie = _mm512_set1_epi64(static_cast<long long>(static_cast<std::uint32_t>(s.poly) & tie_mask));
    const __m256i poly = _mm256_set1_epi32(s.poly);
    won += gouraud_lanes_avx512(s, v, stride, half, shift, tie, poly, pack, one, out);
  }
  run.fragments += fragments, run.visible += won, run.lo = lo, run.hi = hi;
  return i;
}

__attribute__((target(WATKINS_AVX512))) void empty_keys_avx512(std::uint64_t* keys, int lo, int hi) {
  const __m512i empty = _mm512_set1_epi64(-1);
  for (int x = lo; x < hi; x += 8) {
    const int left = hi - x;
    _mm512_mask_storeu_epi64(keys + x, left >= 8 ? __mmask8(0xff) : static_cast<__mmask8>((1u << left) - 1), empty);
  }
}

__attribute__((target(WATKINS_AVX512))) long long phong_span_avx512(const GouraudSpan& s, const NormalReading& r,
                                                                     int material, const FrameLine::Row& out,
                                                                     std::array<i64, 3>* normal, int* materials) {
  static_assert(sizeof(std::array<i64, 3>) == 3 * sizeof(i64), "normals are three packed words");
  const __m512i lane = _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7);
  __m512i v[4], stride[4];
  for (int c = 0; c < 4; ++c) {
    const __m512i step = _mm512_set1_epi64(static_cast<long long>(s.step[c]));
    v[c] = _mm512_add_epi64(_mm512_set1_epi64(static_cast<long long>(s.value[c])), _mm512_mullo_epi64(lane, step));
    stride[c] = _mm512_slli_epi64(step, 3);
  }
  const __m512i z_half = _mm512_set1_epi64(static_cast<long long>(s.half[0]));
  const __m128i z_shift = _mm_cvtsi32_si128(s.shift[0]);
  __m512i n_half[3];
  __m128i n_shift[3];
  for (int c = 0; c < 3; ++c) {
    n_half[c] = _mm512_set1_epi64(static_cast<long long>(r.half[c]));
    n_shift[c] = _mm_cvtsi32_si128(r.shift[c]);
  }
  const __m512i n_hi = _mm512_set1_epi64((i64{1} << (fmt::NormalInBits - 1)) - 1);
  const __m512i n_lo = _mm512_set1_epi64(-(i64{1} << (fmt::NormalInBits - 1)));
  const __m512i tie = _mm512_set1_epi64(static_cast<long long>(s.tie));
  const __m256i poly = _mm256_set1_epi32(s.poly), id = _mm256_set1_epi32(material);
  const __m128i one = _mm_set1_epi8(1);
  const __m512i lane3 = _mm512_setr_epi64(0, 3, 6, 9, 12, 15, 18, 21);
  i64* const words = normal->data();
  long long won = 0;
  for (int x = s.x0; x < s.x1; x += 8) {
    const int left = s.x1 - x;
    const __mmask8 valid = left >= 8 ? __mmask8(0xff) : static_cast<__mmask8>((1u << left) - 1);
    const __m512i depth = _mm512_srl_epi64(_mm512_add_epi64(v[0], z_half), z_shift);
    const __m512i key = _mm512_or_si512(_mm512_slli_epi64(depth, 32), tie);
    const __mmask8 win = _mm512_mask_cmplt_epu64_mask(valid, key, _mm512_maskz_loadu_epi64(valid, out.keys + x));
    if (win) {
      _mm512_mask_storeu_epi64(out.keys + x, win, key);
      _mm_mask_storeu_epi8(out.covered + x, win, one);
      _mm256_mask_storeu_epi32(out.owner + x, win, poly);
      _mm256_mask_storeu_epi32(materials + x, win, id);
      const __m512i at = _mm512_add_epi64(_mm512_set1_epi64(3 * static_cast<i64>(x)), lane3);
      for (int c = 0; c < 3; ++c) {
        const __m512i reading = _mm512_sra_epi64(_mm512_add_epi64(v[c + 1], n_half[c]), n_shift[c]);
        _mm512_mask_i64scatter_epi64(words + c, win, at, _mm512_max_epi64(_mm512_min_epi64(reading, n_hi), n_lo), 8);
      }
      won += __builtin_popcount(win);
    }
    for (int c = 0; c < 4; ++c) v[c] = _mm512_add_epi64(v[c], stride[c]);
  }
  return won;
}

// PhongFrame::shade (Normalizer::normalize, then PhongShader::shade with the material's terms) on
// the covered pixels of a line, eight at a time: the same products, roundings and clamps in 64-bit
// lanes. A product takes the 32 x 32-bit multiply where both factors provably fit 32 bits (the
// bounds in normalizer.hpp, rsqrt_unit.hpp and phong_shader.hpp: |N_i| < 2^17, mant < 2^20,
// y0 < 2^15, 0 <= u < 2^26, y < 2^23, |unit| < 2^16, cos(i) and N.E below 2^25 in magnitude,
// powers <= 2^20; the light and the eye are checked per frame), the 64-bit one where a material
// term is a factor. An arithmetic shift of v + 2^(s-1) is round_shift62; the power is the stage
// list's square-and-multiply over every bit up to the lanes' highest (power_bits' skipped
// products change no bit).
// (a b + 2^(P-1)) >> P for powers a, b in [0, 1.0] (P fraction bits, below 2^32).
__attribute__((target(WATKINS_AVX512), always_inline)) inline __m512i pow_round(__m512i a, __m512i b, __m512i half) {
  return _mm512_srli_epi64(_mm512_add_epi64(_mm512_mul_epu32(a, b), half), PhongShader::P);
}
// The material terms of eight pixels (PhongFrame's by field), lane k that of material id[k] for
// a covered lane k: one broadcast when every covered pixel has the same material (most groups of
// eight do), a gather otherwise.
struct MaterialLanes {
  __m512i cp[3], one_minus_d, d_term, spec_scale, shininess;
};
__attribute__((target(WATKINS_AVX512), always_inline)) inline void material_lanes(const PhongFrame& ph, __mmask8 cov,
                                                                                 const int* id, MaterialLanes& m) {
  const int first = id[__builtin_ctz(cov)];
  const __m256i ids = _mm256_maskz_loadu_epi32(cov, id);
  const std::vector<i64>* const terms[7] = {&ph.cp[0],   &ph.cp[1],      &ph.cp[2],    &ph.one_minus_d,
                                            &ph.d_term,  &ph.spec_scale, &ph.shininess};
  __m512i* const lanes[7] = {&m.cp[0], &m.cp[1], &m.cp[2], &m.one_minus_d, &m.d_term, &m.spec_scale, &m.shininess};
  if (_mm256_mask_cmpeq_epi32_mask(cov, ids, _mm256_set1_epi32(first)) == cov) {
    for (int t = 0; t < 7; ++t) *lanes[t] = _mm512_set1_epi64((*terms[t])[static_cast<std::size_t>(first)]);
  } else {
    for (int t = 0; t < 7; ++t)
      *lanes[t] = _mm512_mask_i32gather_epi64(_mm512_setzero_si512(), cov, ids, terms[t]->data(), 8);
  }
}
__attribute__((target(WATKINS_AVX512 ",avx512cd"))) void phong_line_avx512(const PhongFrame& ph,
                                                                         const std::array<i64, 3>* normal,
                                                                         const int* material,
                                                                         const std::uint64_t* keys, int lo, int hi,
                                                                         std::uint8_t* rgb) {
  using RU = RsqrtUnit;
  using PS = PhongShader;
  static_assert(sizeof(std::array<i64, 3>) == 3 * sizeof(i64), "normals are three packed words");
  constexpr int S1 = (RU::W + 1) + 2 * RU::T - RU::G, S2 = RU::T + RU::G + 1 - RU::F;  // rsqrt_mant's
  constexpr int SDot = 2 * PS::UF - PS::D, SCs = 2 * PS::D - PS::P;                    // shade's
  const __m512i zero = _mm512_setzero_si512(), one = _mm512_set1_epi64(1);
  const __m512i lv[3] = {_mm512_set1_epi64(ph.light[0]), _mm512_set1_epi64(ph.light[1]), _mm512_set1_epi64(ph.light[2])};
  const __m512i ev[3] = {_mm512_set1_epi64(ph.eye[0]), _mm512_set1_epi64(ph.eye[1]), _mm512_set1_epi64(ph.eye[2])};
  const __m512i le_term = _mm512_set1_epi64(ph.le * (i64{1} << PS::D));
  const __m512i dot_hi = _mm512_set1_epi64((i64{1} << (PS::D + 1)) - 1);
  const __m512i dot_lo = _mm512_set1_epi64(-(i64{1} << (PS::D + 1)));
  const __m512i pow_one = _mm512_set1_epi64(PS::One), pow_half = _mm512_set1_epi64(i64{1} << (PS::P - 1));
  const __m512i level_half = _mm512_set1_epi64(i64{1} << (PS::OutFrac - 1)), level_max = _mm512_set1_epi64(fmt::ShadeMax);
  // Component c of pixel k is word 3k + c of the 24: words 0..15 picked from the first two
  // vectors, then words 16..23 from the third (index 8 + word - 16).
  const __m512i pick_x01 = _mm512_setr_epi64(0, 3, 6, 9, 12, 15, 0, 0), pick_x2 = _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 10, 13);
  const __m512i pick_y01 = _mm512_setr_epi64(1, 4, 7, 10, 13, 0, 0, 0), pick_y2 = _mm512_setr_epi64(0, 1, 2, 3, 4, 8, 11, 14);
  const __m512i pick_z01 = _mm512_setr_epi64(2, 5, 8, 11, 14, 0, 0, 0), pick_z2 = _mm512_setr_epi64(0, 1, 2, 3, 4, 9, 12, 15);
  const __m512i pack = _mm512_load_si512(RgbPackIndex);
  const i64* const words = normal->data();
  for (int x = lo; x < hi; x += 8) {
    const int left = hi - x;
    const __mmask8 valid = left >= 8 ? __mmask8(0xff) : static_cast<__mmask8>((1u << left) - 1);
    const __mmask8 cov = _mm512_mask_cmpneq_epu64_mask(valid, _mm512_maskz_loadu_epi64(valid, keys + x),
                                                      _mm512_set1_epi64(-1));
    if (!cov) continue;
    // Normalizer stages 0..7, on the eight pixels' normals: 24 words, three per pixel left of hi
    // (an uncovered pixel's words are a stale normal, shaded and dropped).
    const i64* const at = words + 3 * static_cast<std::ptrdiff_t>(x);
    const std::uint32_t word_bits = left >= 8 ? 0xffffffu : (1u << (3 * left)) - 1;
    const __m512i w0 = _mm512_maskz_loadu_epi64(static_cast<__mmask8>(word_bits), at);
    // A block of eight words past the array is not addressed (no load, no pointer past its end).
    const __m512i w1 = word_bits >> 8 ? _mm512_maskz_loadu_epi64(static_cast<__mmask8>(word_bits >> 8), at + 8) : zero;
    const __m512i w2 = word_bits >> 16 ? _mm512_maskz_loadu_epi64(static_cast<__mmask8>(word_bits >> 16), at + 16) : zero;
    const __m512i nx = _mm512_permutex2var_epi64(_mm512_permutex2var_epi64(w0, pick_x01, w1), pick_x2, w2);
    const __m512i ny = _mm512_permutex2var_epi64(_mm512_permutex2var_epi64(w0, pick_y01, w1), pick_y2, w2);
    const __m512i nz = _mm512_permutex2var_epi64(_mm512_permutex2var_epi64(w0, pick_z01, w1), pick_z2, w2);
    const __m512i m = _mm512_add_epi64(_mm512_add_epi64(_mm512_mul_epi32(nx, nx), _mm512_mul_epi32(ny, ny)),
                                       _mm512_mul_epi32(nz, nz));
    // j = (leading zeros in MBits bits) / 2; m = 0 gives j = 18 and mant = 0, so y = 0 and a zero
    // unit vector, as j = 0 does.
    const __m512i j = _mm512_srli_epi64(_mm512_sub_epi64(_mm512_lzcnt_epi64(m), _mm512_set1_epi64(64 - RU::MBits)), 1);
    const __m512i mant = _mm512_srli_epi64(_mm512_sllv_epi64(m, _mm512_add_epi64(j, j)), RU::MBits - RU::W);
    const __m512i y0 = _mm512_cvtepu32_epi64(
        _mm512_i64gather_epi32(_mm512_srli_epi64(mant, RU::W - RU::P), RsqrtSeedRom.data(), 4));
    const __m512i mc = _mm512_or_si512(_mm512_slli_epi64(mant, 1), one);
    const __m512i t = _mm512_srli_epi64(
        _mm512_add_epi64(_mm512_mul_epu32(mc, _mm512_mul_epu32(y0, y0)), _mm512_set1_epi64(i64{1} << (S1 - 1))), S1);
    const __m512i u = _mm512_sub_epi64(_mm512_set1_epi64(i64{3} << RU::G), t);
    const __m512i y = _mm512_srli_epi64(_mm512_add_epi64(_mm512_mul_epu32(y0, u), _mm512_set1_epi64(i64{1} << (S2 - 1))), S2);
    const __m512i shift = _mm512_sub_epi64(_mm512_set1_epi64(Normalizer::F + 4), j);
    const __m512i half = _mm512_sllv_epi64(one, _mm512_sub_epi64(shift, one));
    const __m512i n[3] = {_mm512_srav_epi64(_mm512_add_epi64(_mm512_mul_epi32(nx, y), half), shift),
                          _mm512_srav_epi64(_mm512_add_epi64(_mm512_mul_epi32(ny, y), half), shift),
                          _mm512_srav_epi64(_mm512_add_epi64(_mm512_mul_epi32(nz, y), half), shift)};
    // Shader stages 1..3.
    __m512i nl = _mm512_mul_epi32(n[0], lv[0]), ne = _mm512_mul_epi32(n[0], ev[0]);
    for (int c = 1; c < 3; ++c) {
      nl = _mm512_add_epi64(nl, _mm512_mul_epi32(n[c], lv[c]));
      ne = _mm512_add_epi64(ne, _mm512_mul_epi32(n[c], ev[c]));
    }
    const __m512i dot_half = _mm512_set1_epi64(i64{1} << (SDot - 1));
    const __m512i cos_i = _mm512_min_epi64(_mm512_srli_epi64(_mm512_add_epi64(_mm512_max_epi64(nl, zero), dot_half), SDot), dot_hi);
    ne = _mm512_max_epi64(_mm512_min_epi64(_mm512_srai_epi64(_mm512_add_epi64(ne, dot_half), SDot), dot_hi), dot_lo);
    const __m512i cs2 = _mm512_sub_epi64(_mm512_slli_epi64(_mm512_mul_epi32(cos_i, ne), 1), le_term);
    const __m512i cs = _mm512_min_epi64(
        _mm512_srli_epi64(_mm512_add_epi64(_mm512_max_epi64(cs2, zero), _mm512_set1_epi64(i64{1} << (SCs - 1))), SCs),
        pow_one);
    MaterialLanes mat;
    material_lanes(ph, cov, material + x, mat);
    const __m512i f = _mm512_add_epi64(_mm512_mullo_epi64(cos_i, mat.one_minus_d), mat.d_term);
    // Stages 4..11 on the lanes with a specular term.
    const __mmask8 spec = _mm512_mask_cmpgt_epi64_mask(_mm512_cmpgt_epi64_mask(cos_i, zero), cs, zero) & cov;
    __m512i bits = _mm512_maskz_mov_epi64(spec, mat.shininess), base = cs, acc = pow_one;
    for (;;) {
      acc = _mm512_mask_mov_epi64(acc, _mm512_test_epi64_mask(bits, one), pow_round(acc, base, pow_half));
      bits = _mm512_srli_epi64(bits, 1);
      if (!_mm512_test_epi64_mask(bits, bits)) break;
      base = pow_round(base, base, pow_half);
    }
    const __m512i specular = _mm512_maskz_mullo_epi64(spec, mat.spec_scale, acc);
    // Stages 12, 13.
    __m512i out = zero;
    for (int c = 0; c < 3; ++c) {
      const __m512i level = _mm512_add_epi64(_mm512_mullo_epi64(mat.cp[c], f), specular);
      const __m512i v = _mm512_min_epi64(
          _mm512_srli_epi64(_mm512_add_epi64(_mm512_max_epi64(level, zero), level_half), PS::OutFrac), level_max);
      out = _mm512_or_si512(out, _mm512_slli_epi64(v, 8 * c));
    }
    const std::uint32_t bit = _pdep_u32(cov, 0x249249u);
    _mm256_mask_storeu_epi8(rgb + 3 * x, bit | (bit << 1) | (bit << 2),
                            _mm512_castsi512_si256(_mm512_permutexvar_epi8(pack, out)));
  }
}

// The fused setups' common head: the span's pixels, its reciprocal, the step's rounding shift and
// alpha0, as PixelPath::in_range's scalar path works them out. Span when the setup goes on (h
// filled), else Empty or General.
struct SetupHead {
  // Channel deltas and offsets below it keep every product of the setup below 2^61.
  static constexpr i64 Limit = i64{1} << (62 - std::max(fmt::RecipBits, fmt::AlphaBits) - 1);
  i64 pixels = 0;  // x_end - x_start
  i64 recip = 0;   // SpanReciprocal::recip
  int shift = 0;   // the step's rounding: p + RecipBits - x.frac_bits
  i64 alpha0 = 0;  // AlphaBits fraction bits
};
[[gnu::always_inline]] inline FusedSetup setup_head(const Segment& s, const GouraudSetupConsts& k, GouraudSpan& g,
                                                    SetupHead& h) {
  const int fx = k.fx;
  const i64 xe = s.e[fmt::ChanX], xf = s.f[fmt::ChanX];
  const i64 centre = (i64{1} << fx) - 1 - (i64{1} << (fx - 1));  // first_centre_at_or_after's offset
  const i64 x_start = std::max<i64>(floor_shift64(xe + centre, fx), 0);
  const i64 x_end = std::max(std::min<i64>(floor_shift64(xf + centre, fx), k.width), x_start);
  g.x0 = static_cast<int>(x_start), g.x1 = static_cast<int>(x_end), g.poly = s.poly;
  if (x_end == x_start) return FusedSetup::Empty;
  const SpanReciprocal r = SpanReciprocal::of(xf - xe);
  constexpr i64 Limit = SetupHead::Limit;
  const i64 offset = x_start * (i64{1} << fx) + (i64{1} << (fx - 1)) - xe;
  const int shift = r.p + fmt::RecipBits - fx;  // the step's rounding
  if (offset >= Limit || shift < 1 || shift > 61 || x_end - x_start > (i64{1} << 21)) return FusedSetup::General;
  const i64 alpha0 = std::min<i64>(round_shift64(offset * r.recip, r.p + fmt::RecipBits - fmt::AlphaBits),
                                   i64{1} << fmt::AlphaBits);
  h.pixels = x_end - x_start, h.recip = r.recip, h.shift = shift, h.alpha0 = alpha0;
  return FusedSetup::Span;
}

// SegmentInterpolator::setup's 64-bit path for slots Z, R, G, B in the four lanes of one vector,
// then PixelPath::in_range<Shade>: the same formulas, products and roundings, so the same words.
// round_shift62(v, s) of a product |v| < 2^61 is (v + 2^(s-1)) >> s, the shift arithmetic
// (flooring); wrap_signed64 is a left shift by 64 - bits and an arithmetic shift back. Whatever
// the scalar path takes 128 bits or a range check for, this hands to the general path.
__attribute__((target(WATKINS_AVX512), always_inline)) inline FusedSetup gouraud_setup_avx512(
    const Segment& s, const GouraudSetupConsts& k, GouraudSpan& g) {
  SetupHead h;
  if (const FusedSetup head = setup_head(s, k, g, h); head != FusedSetup::Span) return head;
  const i64 recip = h.recip, alpha0 = h.alpha0, pixels = h.pixels;
  const int shift = h.shift;
  constexpr i64 Limit = SetupHead::Limit;
  const __m256i e = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(&s.e[fmt::ChanZ]));
  const __m256i f = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(&s.f[fmt::ChanZ]));
  const __m256i delta = _mm256_sub_epi64(f, e);
  // Signed overflow of f - e: f and e of opposite signs and the difference's sign not f's.
  const __m256i overflow = _mm256_and_si256(_mm256_xor_si256(f, e), _mm256_xor_si256(f, delta));
  // -Limit < delta < Limit: delta + Limit - 1, unsigned, below 2 Limit - 1.
  const __m256i biased = _mm256_add_epi64(delta, _mm256_set1_epi64x(Limit - 1));
  const __mmask8 small = _mm256_cmplt_epu64_mask(biased, _mm256_set1_epi64x(2 * Limit - 1)) &
                         _mm256_cmpge_epi64_mask(overflow, _mm256_setzero_si256());
  if (small != 0xf) return FusedSetup::General;
  const __m128i step_count = _mm_cvtsi32_si128(shift), alpha_count = _mm_cvtsi32_si128(fmt::AlphaBits);
  const __m256i hi = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(k.step_hi));
  __m256i step = _mm256_sra_epi64(
      _mm256_add_epi64(_mm256_mullo_epi64(delta, _mm256_set1_epi64x(recip)), _mm256_set1_epi64x(i64{1} << (shift - 1))),
      step_count);
  step = _mm256_max_epi64(_mm256_min_epi64(step, hi), _mm256_sub_epi64(_mm256_set1_epi64x(-1), hi));
  const __m256i wrap = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(k.wrap_shift));
  const __m256i moved = _mm256_sra_epi64(_mm256_add_epi64(_mm256_mullo_epi64(delta, _mm256_set1_epi64x(alpha0)),
                                                          _mm256_set1_epi64x(i64{1} << (fmt::AlphaBits - 1))),
                                         alpha_count);
  const __m256i value = _mm256_srav_epi64(_mm256_sllv_epi64(_mm256_add_epi64(e, moved), wrap), wrap);
  // In range: the first and the last pixel's values inside the readings' unclamped ranges. The
  // last is value + (n - 1) step in 64 bits: |step| < 2^41 and n <= 2^21 keep it from overflowing.
  const __m256i step_biased = _mm256_add_epi64(step, _mm256_set1_epi64x(i64{1} << 41));
  if (_mm256_cmplt_epu64_mask(step_biased, _mm256_set1_epi64x(i64{1} << 42)) != 0xf) return FusedSetup::General;
  const __m256i last = _mm256_add_epi64(value, _mm256_mullo_epi64(_mm256_set1_epi64x(pixels - 1), step));
  const __m256i lo = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(k.read_lo));
  const __m256i span = _mm256_sub_epi64(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(k.read_hi)), lo);
  const __mmask8 inside = _mm256_cmple_epu64_mask(_mm256_sub_epi64(value, lo), span) &
                          _mm256_cmple_epu64_mask(_mm256_sub_epi64(last, lo), span);
  if (inside != 0xf) return FusedSetup::General;
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(g.value), value);
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(g.step), step);
  return FusedSetup::Span;
}

__attribute__((target(WATKINS_AVX512))) void gouraud_setups_avx512(const Segment* s, std::size_t n,
                                                                   const GouraudSetupConsts& k, GouraudSpan* g,
                                                                   FusedSetup* got) {
  for (std::size_t i = 0; i < n; ++i) got[i] = gouraud_setup_avx512(s[i], k, g[i]);
}

// gouraud_setup_avx512's checks, products and roundings slot by slot in 64-bit scalars, for the
// kernels without 64-bit vector multiplies (AVX2's): the same words and the same outcome. The
// sums that may wrap (the wrap to the slot's word, the last pixel's value, the range checks) are
// unsigned, as the vector lanes compute them.
inline FusedSetup gouraud_setup_scalar(const Segment& s, const GouraudSetupConsts& k, GouraudSpan& g) {
  using u64 = std::uint64_t;
  SetupHead h;
  if (const FusedSetup head = setup_head(s, k, g, h); head != FusedSetup::Span) return head;
  const i64 recip = h.recip, alpha0 = h.alpha0, pixels = h.pixels;
  const int shift = h.shift;
  constexpr i64 Limit = SetupHead::Limit;
  i64 delta[4];
  for (int c = 0; c < 4; ++c)
    if (__builtin_sub_overflow(s.f[fmt::ChanZ + c], s.e[fmt::ChanZ + c], &delta[c]) || delta[c] <= -Limit ||
        delta[c] >= Limit)
      return FusedSetup::General;
  const u64 count = static_cast<u64>(pixels - 1);
  u64 value[4], step[4];
  for (int c = 0; c < 4; ++c) {
    // Products below 2^61 in magnitude (|delta| < Limit, recip and alpha0 <= 2^24): no overflow.
    const i64 st = std::clamp<i64>((delta[c] * recip + (i64{1} << (shift - 1))) >> shift, -1 - k.step_hi[c], k.step_hi[c]);
    if (st < -(i64{1} << 41) || st >= (i64{1} << 41)) return FusedSetup::General;
    const i64 moved = (delta[c] * alpha0 + (i64{1} << (fmt::AlphaBits - 1))) >> fmt::AlphaBits;
    const u64 w = k.wrap_shift[c];
    const u64 v = static_cast<u64>(static_cast<i64>((static_cast<u64>(s.e[fmt::ChanZ + c]) + static_cast<u64>(moved)) << w) >> w);
    const u64 last = v + count * static_cast<u64>(st);
    const u64 lo = static_cast<u64>(k.read_lo[c]), span = static_cast<u64>(k.read_hi[c]) - lo;
    if (v - lo > span || last - lo > span) return FusedSetup::General;
    value[c] = v, step[c] = static_cast<u64>(st);
  }
  for (int c = 0; c < 4; ++c) g.value[c] = value[c], g.step[c] = step[c];
  return FusedSetup::Span;
}

void gouraud_setups_scalar(const Segment* s, std::size_t n, const GouraudSetupConsts& k, GouraudSpan* g,
                           FusedSetup* got) {
  for (std::size_t i = 0; i < n; ++i) got[i] = gouraud_setup_scalar(s[i], k, g[i]);
}

__attribute__((target("avx2"))) long long gouraud_span_avx2(const GouraudSpan& s, const FrameLine::Row& out) {
  const __m256i lane = _mm256_setr_epi64x(0, 1, 2, 3);
  __m256i v[4], stride[4], half[4];
  __m128i shift[4];
  for (int c = 0; c < 4; ++c) {
    // value + k·step for k = 0..3, by additions (AVX2 has no 64-bit multiply).
    const __m256i step = _mm256_set1_epi64x(static_cast<long long>(s.step[c]));
    const __m256i step2 = _mm256_add_epi64(step, step);
    const __m256i base = _mm256_set1_epi64x(static_cast<long long>(s.value[c]));
    const __m256i odd = _mm256_blend_epi32(_mm256_setzero_si256(), step, 0xcc);     // 0, s, 0, s
    const __m256i pairs = _mm256_blend_epi32(_mm256_setzero_si256(), step2, 0xf0);  // 0, 0, 2s, 2s
    v[c] = _mm256_add_epi64(base, _mm256_add_epi64(odd, pairs));
    stride[c] = _mm256_add_epi64(step2, step2);
    half[c] = _mm256_set1_epi64x(static_cast<long long>(s.half[c]));
    shift[c] = _mm_cvtsi32_si128(s.shift[c]);
  }
  const __m256i tie = _mm256_set1_epi64x(static_cast<long long>(s.tie));
  const __m256i sign = _mm256_set1_epi64x(static_cast<long long>(std::uint64_t{1} << 63));
  const __m256i end = _mm256_set1_epi64x(s.x1);
  const __m128i poly = _mm_set1_epi32(s.poly);
  // Per 128-bit half (two pixels), bytes 0..2 and 8..10 packed: the low half to bytes 0..5, the
  // high half to bytes 6..11 (-1: zero).
  const __m256i pack = _mm256_setr_epi8(0, 1, 2, 8, 9, 10, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,  //
                                        -1, -1, -1, -1, -1, -1, 0, 1, 2, 8, 9, 10, -1, -1, -1, -1);
  long long won = 0;
  for (int x = s.x0; x < s.x1; x += 4) {
    const __m256i valid = _mm256_cmpgt_epi64(end, _mm256_add_epi64(lane, _mm256_set1_epi64x(x)));
    const __m256i depth = _mm256_srl_epi64(_mm256_add_epi64(v[0], half[0]), shift[0]);
    const __m256i key = _mm256_or_si256(_mm256_slli_epi64(depth, 32), tie);
    const __m256i old = _mm256_maskload_epi64(reinterpret_cast<const long long*>(out.keys + x), valid);
    // key < old, unsigned: both with the sign bit flipped, compared signed.
    const __m256i less = _mm256_cmpgt_epi64(_mm256_xor_si256(old, sign), _mm256_xor_si256(key, sign));
    const __m256i win = _mm256_and_si256(less, valid);
    unsigned bits = static_cast<unsigned>(_mm256_movemask_pd(_mm256_castsi256_pd(win)));
    if (bits) {
      _mm256_maskstore_epi64(reinterpret_cast<long long*>(out.keys + x), win, key);
      const __m256i r = _mm256_srl_epi64(_mm256_add_epi64(v[1], half[1]), shift[1]);
      const __m256i g = _mm256_srl_epi64(_mm256_add_epi64(v[2], half[2]), shift[2]);
      const __m256i b = _mm256_srl_epi64(_mm256_add_epi64(v[3], half[3]), shift[3]);
      const __m256i rgb4 = _mm256_or_si256(r, _mm256_or_si256(_mm256_slli_epi64(g, 8), _mm256_slli_epi64(b, 16)));
      won += __builtin_popcount(bits);
      if (bits == 0xf) {  // all four won: 12 rgb bytes, four coverage bytes, four owners
        const __m256i packed = _mm256_shuffle_epi8(rgb4, pack);
        const __m128i rgb12 = _mm_or_si128(_mm256_castsi256_si128(packed), _mm256_extracti128_si256(packed, 1));
        std::uint8_t* const dst = out.rgb + 3 * static_cast<std::size_t>(x);
        _mm_storel_epi64(reinterpret_cast<__m128i*>(dst), rgb12);
        const std::uint32_t tail = static_cast<std::uint32_t>(_mm_extract_epi32(rgb12, 2));
        std::memcpy(dst + 8, &tail, 4);
        const std::uint32_t ones = 0x01010101u;
        std::memcpy(out.covered + x, &ones, 4);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out.owner + x), poly);
        bits = 0;
      }
      alignas(32) std::uint64_t rgb[4];
      _mm256_store_si256(reinterpret_cast<__m256i*>(rgb), rgb4);
      for (; bits; bits &= bits - 1) {
        const int k = __builtin_ctz(bits);
        const std::size_t px = static_cast<std::size_t>(x + k);
        out.rgb[3 * px] = static_cast<std::uint8_t>(rgb[k]);
        out.rgb[3 * px + 1] = static_cast<std::uint8_t>(rgb[k] >> 8);
        out.rgb[3 * px + 2] = static_cast<std::uint8_t>(rgb[k] >> 16);
        out.covered[px] = 1;
        out.owner[px] = s.poly;
      }
    }
    for (int c = 0; c < 4; ++c) v[c] = _mm256_add_epi64(v[c], stride[c]);
  }
  return won;
}

__attribute__((target("avx2"))) void empty_keys_avx2(std::uint64_t* keys, int lo, int hi) {
  const __m256i empty = _mm256_set1_epi64x(-1);
  int x = lo;
  for (; x + 4 <= hi; x += 4) _mm256_storeu_si256(reinterpret_cast<__m256i*>(keys + x), empty);
  for (; x < hi; ++x) keys[x] = FrameLine::Empty;
}

// The AVX-512 Phong kernels' arithmetic on four lanes (AVX2 has no 64-bit minimum, maximum,
// arithmetic shift, low product or leading-zero count): each built from the operations it has,
// the same values.
__attribute__((target("avx2"), always_inline)) inline __m256i min64(__m256i a, __m256i b) {
  return _mm256_blendv_epi8(a, b, _mm256_cmpgt_epi64(a, b));
}
__attribute__((target("avx2"), always_inline)) inline __m256i max64(__m256i a, __m256i b) {
  return _mm256_blendv_epi8(b, a, _mm256_cmpgt_epi64(a, b));
}
// floor(v / 2^s) per lane for |v| < 2^62 and s in [0, 62]: the bias 2^62, a multiple of 2^s,
// makes the word non-negative for a logical shift and comes off after (round_shift62's argument).
__attribute__((target("avx2"), always_inline)) inline __m256i floor_shift_lanes(__m256i v, __m256i s) {
  const __m256i bias = _mm256_set1_epi64x(i64{1} << 62);
  return _mm256_sub_epi64(_mm256_srlv_epi64(_mm256_add_epi64(v, bias), s), _mm256_srlv_epi64(bias, s));
}
// a b modulo 2^64 (i64's product, where it does not overflow) from three 32 x 32-bit products.
__attribute__((target("avx2"), always_inline)) inline __m256i mullo64(__m256i a, __m256i b) {
  const __m256i cross = _mm256_add_epi64(_mm256_mul_epu32(_mm256_srli_epi64(a, 32), b),
                                         _mm256_mul_epu32(a, _mm256_srli_epi64(b, 32)));
  return _mm256_add_epi64(_mm256_mul_epu32(a, b), _mm256_slli_epi64(cross, 32));
}

__attribute__((target("avx2"))) long long phong_span_avx2(const GouraudSpan& s, const NormalReading& r, int material,
                                                          const FrameLine::Row& out, std::array<i64, 3>* normal,
                                                          int* materials) {
  __m256i v[4], stride[4];
  for (int c = 0; c < 4; ++c) {
    // value + k·step for k = 0..3, by additions.
    const __m256i step = _mm256_set1_epi64x(static_cast<long long>(s.step[c]));
    const __m256i step2 = _mm256_add_epi64(step, step);
    const __m256i odd = _mm256_blend_epi32(_mm256_setzero_si256(), step, 0xcc);
    const __m256i pairs = _mm256_blend_epi32(_mm256_setzero_si256(), step2, 0xf0);
    v[c] = _mm256_add_epi64(_mm256_set1_epi64x(static_cast<long long>(s.value[c])), _mm256_add_epi64(odd, pairs));
    stride[c] = _mm256_add_epi64(step2, step2);
  }
  const __m256i lane = _mm256_setr_epi64x(0, 1, 2, 3);
  const __m256i z_half = _mm256_set1_epi64x(static_cast<long long>(s.half[0]));
  const __m128i z_shift = _mm_cvtsi32_si128(s.shift[0]);
  const __m256i tie = _mm256_set1_epi64x(static_cast<long long>(s.tie));
  const __m256i sign = _mm256_set1_epi64x(static_cast<long long>(std::uint64_t{1} << 63));
  const __m256i end = _mm256_set1_epi64x(s.x1);
  __m256i n_half[3], n_shift[3];
  for (int c = 0; c < 3; ++c) {
    n_half[c] = _mm256_set1_epi64x(static_cast<long long>(r.half[c]));
    n_shift[c] = _mm256_set1_epi64x(r.shift[c]);
  }
  const __m256i n_hi = _mm256_set1_epi64x((i64{1} << (fmt::NormalInBits - 1)) - 1);
  const __m256i n_lo = _mm256_set1_epi64x(-(i64{1} << (fmt::NormalInBits - 1)));
  long long won = 0;
  for (int x = s.x0; x < s.x1; x += 4) {
    const __m256i valid = _mm256_cmpgt_epi64(end, _mm256_add_epi64(lane, _mm256_set1_epi64x(x)));
    const __m256i depth = _mm256_srl_epi64(_mm256_add_epi64(v[0], z_half), z_shift);
    const __m256i key = _mm256_or_si256(_mm256_slli_epi64(depth, 32), tie);
    const __m256i old = _mm256_maskload_epi64(reinterpret_cast<const long long*>(out.keys + x), valid);
    const __m256i less = _mm256_cmpgt_epi64(_mm256_xor_si256(old, sign), _mm256_xor_si256(key, sign));
    const __m256i win = _mm256_and_si256(less, valid);
    unsigned bits = static_cast<unsigned>(_mm256_movemask_pd(_mm256_castsi256_pd(win)));
    if (bits) {
      _mm256_maskstore_epi64(reinterpret_cast<long long*>(out.keys + x), win, key);
      alignas(32) i64 reading[3][4];
      for (int c = 0; c < 3; ++c) {
        const __m256i n = floor_shift_lanes(_mm256_add_epi64(v[c + 1], n_half[c]), n_shift[c]);
        _mm256_store_si256(reinterpret_cast<__m256i*>(reading[c]), max64(min64(n, n_hi), n_lo));
      }
      won += __builtin_popcount(bits);
      for (; bits; bits &= bits - 1) {
        const int k = __builtin_ctz(bits);
        const std::size_t px = static_cast<std::size_t>(x + k);
        out.covered[px] = 1;
        out.owner[px] = s.poly;
        materials[px] = material;
        normal[px] = {reading[0][k], reading[1][k], reading[2][k]};
      }
    }
    for (int c = 0; c < 4; ++c) v[c] = _mm256_add_epi64(v[c], stride[c]);
  }
  return won;
}

// phong_line_avx512 on four lanes, with the operations above.
__attribute__((target("avx2"))) void phong_line_avx2(const PhongFrame& ph, const std::array<i64, 3>* normal,
                                                     const int* material, const std::uint64_t* keys, int lo, int hi,
                                                     std::uint8_t* rgb) {
  using RU = RsqrtUnit;
  using PS = PhongShader;
  constexpr int S1 = (RU::W + 1) + 2 * RU::T - RU::G, S2 = RU::T + RU::G + 1 - RU::F;
  constexpr int SDot = 2 * PS::UF - PS::D, SCs = 2 * PS::D - PS::P;
  const __m256i zero = _mm256_setzero_si256(), one = _mm256_set1_epi64x(1), empty = _mm256_set1_epi64x(-1);
  const __m256i lv[3] = {_mm256_set1_epi64x(ph.light[0]), _mm256_set1_epi64x(ph.light[1]), _mm256_set1_epi64x(ph.light[2])};
  const __m256i ev[3] = {_mm256_set1_epi64x(ph.eye[0]), _mm256_set1_epi64x(ph.eye[1]), _mm256_set1_epi64x(ph.eye[2])};
  const __m256i le_term = _mm256_set1_epi64x(ph.le * (i64{1} << PS::D));
  const __m256i dot_hi = _mm256_set1_epi64x((i64{1} << (PS::D + 1)) - 1);
  const __m256i dot_lo = _mm256_set1_epi64x(-(i64{1} << (PS::D + 1)));
  const __m256i dot_shift = _mm256_set1_epi64x(SDot), dot_half = _mm256_set1_epi64x(i64{1} << (SDot - 1));
  const __m256i pow_one = _mm256_set1_epi64x(PS::One), pow_half = _mm256_set1_epi64x(i64{1} << (PS::P - 1));
  const __m256i level_half = _mm256_set1_epi64x(i64{1} << (PS::OutFrac - 1));
  const __m256i level_max = _mm256_set1_epi64x(fmt::ShadeMax);
  const __m256i lane = _mm256_setr_epi64x(0, 1, 2, 3), lane3 = _mm256_setr_epi64x(0, 3, 6, 9);
  // m as a double (exact below 2^52: the word 2^52 + m less 2^52): its exponent is m's top bit.
  const __m256i magic = _mm256_set1_epi64x(0x4330000000000000);
  const i64* const words = normal->data();
  const std::vector<i64>* const terms[7] = {&ph.cp[0], &ph.cp[1], &ph.cp[2], &ph.one_minus_d,
                                            &ph.d_term, &ph.spec_scale, &ph.shininess};
  for (int x = lo; x < hi; x += 4) {
    const __m256i valid = _mm256_cmpgt_epi64(_mm256_set1_epi64x(hi), _mm256_add_epi64(lane, _mm256_set1_epi64x(x)));
    const __m256i k = _mm256_maskload_epi64(reinterpret_cast<const long long*>(keys + x), valid);
    const __m256i cov = _mm256_andnot_si256(_mm256_cmpeq_epi64(k, empty), valid);
    const unsigned cov_bits = static_cast<unsigned>(_mm256_movemask_pd(_mm256_castsi256_pd(cov)));
    if (!cov_bits) continue;
    // Normalizer stages 0..7.
    const __m256i at = _mm256_add_epi64(_mm256_set1_epi64x(3 * static_cast<i64>(x)), lane3);
    const __m256i nx = _mm256_mask_i64gather_epi64(zero, reinterpret_cast<const long long*>(words), at, cov, 8);
    const __m256i ny = _mm256_mask_i64gather_epi64(zero, reinterpret_cast<const long long*>(words + 1), at, cov, 8);
    const __m256i nz = _mm256_mask_i64gather_epi64(zero, reinterpret_cast<const long long*>(words + 2), at, cov, 8);
    const __m256i m = _mm256_add_epi64(_mm256_add_epi64(_mm256_mul_epi32(nx, nx), _mm256_mul_epi32(ny, ny)),
                                       _mm256_mul_epi32(nz, nz));
    const __m256d md = _mm256_sub_pd(_mm256_castsi256_pd(_mm256_or_si256(m, magic)), _mm256_castsi256_pd(magic));
    const __m256i msb = _mm256_sub_epi64(_mm256_srli_epi64(_mm256_castpd_si256(md), 52), _mm256_set1_epi64x(1023));
    // j = (MBits - 1 - msb) / 2; m = 0 takes j = 0 (mant = 0: y = 0, a zero unit vector).
    const __m256i j = _mm256_andnot_si256(_mm256_cmpeq_epi64(m, zero),
                                          _mm256_srli_epi64(_mm256_sub_epi64(_mm256_set1_epi64x(RU::MBits - 1), msb), 1));
    const __m256i mant = _mm256_srli_epi64(_mm256_sllv_epi64(m, _mm256_add_epi64(j, j)), RU::MBits - RU::W);
    const __m256i y0 = _mm256_cvtepu32_epi64(_mm256_i64gather_epi32(reinterpret_cast<const int*>(RsqrtSeedRom.data()),
                                                                    _mm256_srli_epi64(mant, RU::W - RU::P), 4));
    const __m256i mc = _mm256_or_si256(_mm256_slli_epi64(mant, 1), one);
    const __m256i t = _mm256_srli_epi64(
        _mm256_add_epi64(_mm256_mul_epu32(mc, _mm256_mul_epu32(y0, y0)), _mm256_set1_epi64x(i64{1} << (S1 - 1))), S1);
    const __m256i u = _mm256_sub_epi64(_mm256_set1_epi64x(i64{3} << RU::G), t);
    const __m256i y = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(y0, u), _mm256_set1_epi64x(i64{1} << (S2 - 1))), S2);
    const __m256i shift = _mm256_sub_epi64(_mm256_set1_epi64x(Normalizer::F + 4), j);
    const __m256i half = _mm256_sllv_epi64(one, _mm256_sub_epi64(shift, one));
    const __m256i n[3] = {floor_shift_lanes(_mm256_add_epi64(_mm256_mul_epi32(nx, y), half), shift),
                          floor_shift_lanes(_mm256_add_epi64(_mm256_mul_epi32(ny, y), half), shift),
                          floor_shift_lanes(_mm256_add_epi64(_mm256_mul_epi32(nz, y), half), shift)};
    // Shader stages 1..3.
    __m256i nl = _mm256_mul_epi32(n[0], lv[0]), ne = _mm256_mul_epi32(n[0], ev[0]);
    for (int c = 1; c < 3; ++c) {
      nl = _mm256_add_epi64(nl, _mm256_mul_epi32(n[c], lv[c]));
      ne = _mm256_add_epi64(ne, _mm256_mul_epi32(n[c], ev[c]));
    }
    const __m256i cos_i = min64(_mm256_srli_epi64(_mm256_add_epi64(max64(nl, zero), dot_half), SDot), dot_hi);
    ne = max64(min64(floor_shift_lanes(_mm256_add_epi64(ne, dot_half), dot_shift), dot_hi), dot_lo);
    const __m256i cs2 = _mm256_sub_epi64(_mm256_slli_epi64(_mm256_mul_epi32(cos_i, ne), 1), le_term);
    const __m256i cs = min64(
        _mm256_srli_epi64(_mm256_add_epi64(max64(cs2, zero), _mm256_set1_epi64x(i64{1} << (SCs - 1))), SCs), pow_one);
    // The material's terms: broadcast when the covered pixels share one, gathered otherwise.
    const int first = material[x + __builtin_ctz(cov_bits)];
    bool one_material = true;
    for (unsigned b = cov_bits; b; b &= b - 1) one_material &= material[x + __builtin_ctz(b)] == first;
    __m256i mat[7];
    if (one_material) {
      for (int i = 0; i < 7; ++i) mat[i] = _mm256_set1_epi64x((*terms[i])[static_cast<std::size_t>(first)]);
    } else {
      alignas(16) int id[4] = {0, 0, 0, 0};
      for (unsigned b = cov_bits; b; b &= b - 1) id[__builtin_ctz(b)] = material[x + __builtin_ctz(b)];
      const __m128i ids = _mm_load_si128(reinterpret_cast<const __m128i*>(id));
      for (int i = 0; i < 7; ++i)
        mat[i] = _mm256_mask_i32gather_epi64(zero, reinterpret_cast<const long long*>(terms[i]->data()), ids, cov, 8);
    }
    const __m256i f = _mm256_add_epi64(mullo64(cos_i, mat[3]), mat[4]);
    // Stages 4..11 on the lanes with a specular term.
    const __m256i spec = _mm256_and_si256(
        _mm256_and_si256(_mm256_cmpgt_epi64(cos_i, zero), _mm256_cmpgt_epi64(cs, zero)), cov);
    __m256i bits = _mm256_and_si256(spec, mat[6]), base = cs, acc = pow_one;
    for (;;) {
      const __m256i take = _mm256_cmpeq_epi64(_mm256_and_si256(bits, one), one);
      const __m256i product = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(acc, base), pow_half), PS::P);
      acc = _mm256_blendv_epi8(acc, product, take);
      bits = _mm256_srli_epi64(bits, 1);
      if (_mm256_testz_si256(bits, bits)) break;
      base = _mm256_srli_epi64(_mm256_add_epi64(_mm256_mul_epu32(base, base), pow_half), PS::P);
    }
    const __m256i specular = _mm256_and_si256(spec, mullo64(mat[5], acc));
    // Stages 12, 13.
    alignas(32) i64 level[3][4];
    for (int c = 0; c < 3; ++c) {
      const __m256i sum = _mm256_add_epi64(mullo64(mat[c], f), specular);
      _mm256_store_si256(reinterpret_cast<__m256i*>(level[c]),
                         min64(_mm256_srli_epi64(_mm256_add_epi64(max64(sum, zero), level_half), PS::OutFrac), level_max));
    }
    for (unsigned b = cov_bits; b; b &= b - 1) {
      const int l = __builtin_ctz(b);
      std::uint8_t* const p = rgb + 3 * static_cast<std::size_t>(x + l);
      p[0] = static_cast<std::uint8_t>(level[0][l]), p[1] = static_cast<std::uint8_t>(level[1][l]);
      p[2] = static_cast<std::uint8_t>(level[2][l]);
    }
  }
}
#pragma GCC diagnostic pop
#endif

// The kernels for `path`: Auto takes the widest the processor has; a path it lacks falls back to
// the next narrower, down to the scalar loop.
SpanKernels span_kernels(SpanPath path) {
  SpanKernels k;
  k.empty = empty_keys;
  if (path == SpanPath::Scalar) return k;
#ifdef WATKINS_SPAN_KERNELS
  __builtin_cpu_init();
  const bool avx512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw") &&
                      __builtin_cpu_supports("avx512vbmi") && __builtin_cpu_supports("bmi2");
  if (path != SpanPath::Avx2 && avx512) {
    SpanKernels wide{gouraud_span_avx512, empty_keys_avx512, gouraud_setups_avx512};
    wide.phong_span = phong_span_avx512;
    wide.draw_run = gouraud_run_avx512;
    wide.phong_line = __builtin_cpu_supports("avx512cd") ? phong_line_avx512 : phong_line_avx2;
    return wide;
  }
  if (__builtin_cpu_supports("avx2")) {
    SpanKernels narrow{gouraud_span_avx2, empty_keys_avx2, gouraud_setups_scalar};
    narrow.phong_span = phong_span_avx2, narrow.phong_line = phong_line_avx2;
    return narrow;
  }
#endif
  return k;
}

// The segments of one scan line through the interpolator (and the Phong blocks) into the line
// buffer. What varies per frame is a template parameter, chosen once per frame: whether a bench
// observes the fragments (Observed: each gets both readings and is reported) and the shading,
// so the loop nobody observes holds no call, no test of the observer and no test of the mode.
struct LineCounts {
  long long fragments = 0, visible = 0;  // as PipelineStats counts them
};
// Phong with nobody observing: a pixel's shade is a function of its last winner's normal and
// material alone, so the line keeps those and shades each covered pixel once at read-out, not
// every fragment that wins on the way (the same pixels: overdraw costs a depth test, not a shade).
// A band's scratch, reused line after line: the deferred Phong inputs, and the fused setup's
// spans and outcomes (one per segment of the line).
struct LineScratch {
  std::vector<std::array<i64, 3>> normal;  // per pixel of the line (deferred Phong)
  std::vector<int> material;
  std::vector<GouraudSpan> spans;
  std::vector<FusedSetup> setups;
};
// The pipeline a frame takes: Gouraud's eq. (1), his eq. (2) (the shade divider after the
// interpolator) or Phong.
enum class Pipe { Gouraud, Eq2, Phong };
// What stays the same over a frame's lines: its configuration's paths and the Phong constants.
struct FrameSetup {
  const Frame& frame;
  ChannelFormats formats;
  PixelPath path;
  ShadeDivider divider;
  PhongFrame phong;
  SpanKernels kernels;
  GouraudSpan readings;  // the kernel's shifts and halves (PixelPath's in-range readings)
  NormalReading normal_reading;
  bool normal_kernel = true;  // every normal reading rounds (NormalReading): the span kernel may read
  // The fused span setup of the kernels, when the frame's readings have unclamped ranges
  // (nullptr: every span takes SegmentInterpolator::setup), and its constants.
  void (*fused_setup)(const Segment*, std::size_t, const GouraudSetupConsts&, GouraudSpan*, FusedSetup*) = nullptr;
  GouraudSetupConsts setup_consts;
  // One row of the background, uncovered: each line's row of the image starts as a copy.
  std::vector<std::uint8_t> background_rgb, background_covered;
  std::vector<int> background_owner;
  FrameSetup(const Frame& f, const ChannelFormats& cf, SpanKernels k)
      : frame(f), formats(cf), path(cf), divider(cf), phong(f, cf.phong), kernels(k),
        background_covered(static_cast<std::size_t>(f.width), 0), background_owner(static_cast<std::size_t>(f.width), -1) {
    for (int x = 0; x < f.width; ++x) background_rgb.insert(background_rgb.end(), f.background.begin(), f.background.end());
    for (int c = 0; c < 4; ++c) {
      const int shift = cf.frac[fmt::ChanZ + c];
      readings.shift[c] = shift;
      readings.half[c] = shift == 0 ? 0 : std::uint64_t{1} << (shift - 1);
    }
    for (int c = 0; c < 3; ++c) {
      const int shift = cf.frac[fmt::ChanNx + c] - fmt::FracBits;  // PixelPath's normal_shift_
      normal_kernel &= shift >= 0 && shift <= 61;
      normal_reading.shift[c] = shift;
      normal_reading.half[c] = shift <= 0 ? 0 : std::uint64_t{1} << (shift - 1);
    }
    const bool phong = f.shading == ShadingMode::Phong;
    setup_consts.width = f.width;
    setup_consts.fx = cf.x_frac();
    bool ranges = true;
    for (int c = 0; c < 4; ++c) {
      const int bits = cf.bits[fmt::ChanZ + c];
      setup_consts.wrap_shift[c] = static_cast<std::uint64_t>(64 - bits);
      setup_consts.step_hi[c] = (i64{1} << (bits - 1)) - 1;
      // Phong reads the normal slots with a clamp (PixelPath::in_range<Readings::Normal>): their
      // whole word is in range.
      const bool word = phong && c > 0;
      setup_consts.read_lo[c] = word ? -(i64{1} << (bits - 1)) : path.shade_lo(fmt::ChanZ + c);
      setup_consts.read_hi[c] = word ? (i64{1} << (bits - 1)) - 1 : path.shade_hi(fmt::ChanZ + c);
      ranges &= setup_consts.read_lo[c] <= setup_consts.read_hi[c];
    }
    if (ranges && (phong ? k.phong_span && normal_kernel : k.draw != nullptr)) fused_setup = k.setup;
  }
  GouraudSpan gouraud_span(const SpanSetup& span, std::uint64_t tie) const {
    GouraudSpan g = readings;
    g.x0 = span.x_start, g.x1 = span.x_end, g.tie = tie, g.poly = span.poly;
    for (int c = 0; c < 4; ++c) {
      g.value[c] = static_cast<std::uint64_t>(span.value[fmt::ChanZ + c]);
      g.step[c] = static_cast<std::uint64_t>(span.step[fmt::ChanZ + c]);
    }
    return g;
  }
};
template <bool Observed, Pipe P>
LineCounts draw_segments(const FrameSetup& fs, const std::vector<Segment>& segments, FrameLine& line, int y,
                         const PipelineObserver& observe, LineScratch& scratch) {
  const Frame& frame = fs.frame;
  const ChannelFormats& formats = fs.formats;
  const PixelPath& path = fs.path;
  const PhongFrame& phong = fs.phong;
  const ShadeDivider& divider = fs.divider;
  constexpr ShadingMode Shading = P == Pipe::Phong ? ShadingMode::Phong : ShadingMode::Gouraud;
  constexpr bool defer = !Observed && Shading == ShadingMode::Phong;
  // Eq. (2) reads the shade slots' words, not a reading of them: only their words' range matters
  // (the Normal reading's range check), and no reading is filled unless a bench observes.
  constexpr auto readings = Observed ? PixelPath::Readings::Both
                            : P != Pipe::Gouraud ? PixelPath::Readings::Normal
                                                 : PixelPath::Readings::Shade;
  // Local copies: the line buffer's stores cannot alias them, so the loop keeps them in registers.
  const PixelPath p = path;
  LineCounts n;
  SpanSetup span;
  span.formats = formats;
  // An unobserved Gouraud or Phong line whose kernels fuse the setup: every span set up first,
  // then drawn in order; a span the fused setup hands back (or a Phong span of a material past
  // the table, whose error the scalar loop raises) takes the general path in its turn.
  constexpr bool Fused = (P == Pipe::Gouraud || P == Pipe::Phong) && !Observed;
  const bool fused = Fused && fs.fused_setup;
  if (fused) {
    if (scratch.spans.size() < segments.size()) {
      scratch.spans.resize(segments.size(), fs.readings);
      scratch.setups.resize(segments.size());
    }
    fs.fused_setup(segments.data(), segments.size(), fs.setup_consts, scratch.spans.data(), scratch.setups.data());
  }
  // Gouraud with a run kernel: the runs of spans the fused setup drew go through it at once; it
  // stops at a span the setup handed back, which the general path below takes.
  const bool runs = P == Pipe::Gouraud && fused && fs.kernels.draw_run;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (runs) {
      SpanRun run{0, 0, line.lo(), line.hi()};
      i = fs.kernels.draw_run(scratch.spans.data(), scratch.setups.data(), i, segments.size(), fs.readings,
                              line.tie_mask(), line.row(), run);
      n.fragments += run.fragments, n.visible += run.visible;
      line.touch(run.lo, run.hi);
      if (i == segments.size()) break;
    }
    const Segment& s = segments[i];
    if (fused && scratch.setups[i] != FusedSetup::General && (P != Pipe::Phong || phong.valid(s.material))) {
      if (scratch.setups[i] == FusedSetup::Span) {
        GouraudSpan& g = scratch.spans[i];
        n.fragments += g.x1 - g.x0;
        line.touch(g.x0, g.x1);
        g.tie = line.tie_bits(s.poly);
        if (P == Pipe::Phong)
          n.visible += fs.kernels.phong_span(g, fs.normal_reading, s.material, line.row(), scratch.normal.data(),
                                             scratch.material.data());
        else
          n.visible += fs.kernels.draw(g, line.row());
      }
      continue;
    }
    SegmentInterpolator::setup(s, frame.width, formats, span);
    n.fragments += span.x_end - span.x_start;
    // A span whose values stay inside their words and readings (in_range) runs without wraps
    // and clamps; any other span, and every span a bench observes, takes the general path.
    auto run = [&](auto in_range) {
      constexpr bool InRange = decltype(in_range)::value;
      ChannelVector v = span.value;
      const ChannelVector step = span.step;
      const std::uint64_t tie_bits = line.tie_bits(span.poly);
      for (int x = span.x_start; x < span.x_end; ++x) {
        // The depth test first: a hidden fragment's readings (and Phong shade) are computed only
        // when a bench observes it. The RTL computes them all; the values kept are the same.
        Fragment f = p.head<InRange>(span, x, v);
        const std::uint64_t key = FrameLine::key(f.depth, tie_bits);
        const bool won = line.wins_key(x, key);
        if (won || Observed) {
          if (P != Pipe::Eq2 || Observed) p.fill<readings, InRange>(f, v);
          if (P == Pipe::Eq2) {
            const std::array<std::uint8_t, 3> rgb =
                divider.shade(f.depth, {v[fmt::ChanR], v[fmt::ChanG], v[fmt::ChanB]});
            for (int c = 0; c < 3; ++c) f.rgb[c] = rgb[c];
          }
          if (defer) {
            scratch.normal[static_cast<std::size_t>(x)] = f.normal;
            scratch.material[static_cast<std::size_t>(x)] = phong.check(f.material);  // shade(f)'s check
          } else if (Shading == ShadingMode::Phong) {
            phong.shade(f);
          }
          if (won) line.store(f, key);
          if (Observed) observe.fragment(y, f, won);
        }
        n.visible += won;
        p.step<InRange>(step, v);
      }
    };
    if (span.x_end <= span.x_start) continue;
    line.touch(span.x_start, span.x_end);
    if (!p.in_range<readings>(span)) {
      run(std::false_type{});
    } else if (P == Pipe::Gouraud && !Observed && fs.kernels.draw) {
      n.visible += fs.kernels.draw(fs.gouraud_span(span, line.tie_bits(span.poly)), line.row());
    } else if (defer && fs.kernels.phong_span && fs.normal_kernel && phong.valid(span.material)) {
      n.visible += fs.kernels.phong_span(fs.gouraud_span(span, line.tie_bits(span.poly)), fs.normal_reading,
                                         span.material, line.row(), scratch.normal.data(), scratch.material.data());
    } else {
      run(std::true_type{});
    }
  }
  return n;
}

using DrawSegments = LineCounts (*)(const FrameSetup&, const std::vector<Segment>&, FrameLine&, int,
                                    const PipelineObserver&, LineScratch&);

DrawSegments draw_segments_for(bool observed, const Frame& frame) {
  if (frame.shading == ShadingMode::Phong)
    return observed ? draw_segments<true, Pipe::Phong> : draw_segments<false, Pipe::Phong>;
  if (frame.eq2) return observed ? draw_segments<true, Pipe::Eq2> : draw_segments<false, Pipe::Eq2>;
  return observed ? draw_segments<true, Pipe::Gouraud> : draw_segments<false, Pipe::Gouraud>;
}

// Scan lines [y_begin, y_end) of the frame into their rows of img, counted into stats.
void draw_lines(const FrameSetup& fs, int capacity, int y_begin, int y_end, Image& img, const PipelineObserver& observe,
                PipelineStats& stats) {
  const Frame& frame = fs.frame;
  FrameLine line(frame.width, frame.depth_tie);
  const bool observing = static_cast<bool>(observe.fragment);
  const DrawSegments draw = draw_segments_for(observing, frame);
  const bool deferred = !observing && frame.shading == ShadingMode::Phong;
  LineScratch scratch;
  if (deferred) {
    scratch.normal.resize(static_cast<std::size_t>(frame.width));
    scratch.material.resize(static_cast<std::size_t>(frame.width));
  }
  walk_scan_lines(frame.edges, y_begin, y_end, capacity, fs.formats, [&](const ScanLine& sl) {
    const int y = sl.y;
    stats.edges += sl.entered;
    stats.max_active_edges = std::max(stats.max_active_edges, sl.active.size());
    if (observe.active_edge)
      for (const ActiveEdge& e : sl.active.edges()) observe.active_edge(y, e);
    if (observe.active_edges_end) observe.active_edges_end(y);
    stats.segments += static_cast<long long>(sl.segments.size());
    if (observe.segment)
      for (const Segment& s : sl.segments) observe.segment(y, s);
    if (observe.segments_end) observe.segments_end(y);
    const std::size_t row = std::size_t(y) * static_cast<std::size_t>(frame.width);
    std::copy(fs.background_rgb.begin(), fs.background_rgb.end(), img.rgb.begin() + static_cast<std::ptrdiff_t>(3 * row));
    std::copy(fs.background_covered.begin(), fs.background_covered.end(), img.covered.begin() + static_cast<std::ptrdiff_t>(row));
    std::copy(fs.background_owner.begin(), fs.background_owner.end(), img.owner.begin() + static_cast<std::ptrdiff_t>(row));
    line.start(img, y);
    const LineCounts n = draw(fs, sl.segments, line, y, observe, scratch);
    stats.fragments += n.fragments;
    stats.visible += n.visible;
    if (observe.fragments_end) observe.fragments_end(y);
    // Phong with nobody observing shades each covered pixel once, from its last winner.
    if (deferred && fs.kernels.phong_line && fs.phong.kernel_formats())
      fs.kernels.phong_line(fs.phong, scratch.normal.data(), scratch.material.data(), line.row().keys, line.lo(),
                            line.hi(), line.row().rgb);
    else if (deferred)
      line.each_covered([&](int x, std::uint8_t* rgb) {
        const std::array<int, 3> p = fs.phong.shade(scratch.normal[static_cast<std::size_t>(x)],
                                                    scratch.material[static_cast<std::size_t>(x)]);
        rgb[0] = static_cast<std::uint8_t>(p[0]), rgb[1] = static_cast<std::uint8_t>(p[1]);
        rgb[2] = static_cast<std::uint8_t>(p[2]);
      });
    fs.kernels.empty(line.row().keys, line.lo(), line.hi());
  });
}

}  // namespace

std::vector<SparseBeat> sparse_stream(const Image& img) {
  std::vector<SparseBeat> out;
  bool last_line_covered = false;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (img.is_covered(x, y)) {
        const std::uint8_t* p = img.at(x, y);
        out.push_back(SparseBeat{x, y, {p[0], p[1], p[2]}, true, false});
        last_line_covered = y == img.height - 1;
      }
  if (!last_line_covered && img.width > 0 && img.height > 0) {
    const std::uint8_t* p = img.at(img.width - 1, img.height - 1);  // background: not covered
    out.push_back(SparseBeat{img.width - 1, img.height - 1, {p[0], p[1], p[2]}, false, false});
  }
  if (!out.empty()) out.back().last = true;
  return out;
}

Image WatkinsTop::render(const Frame& frame, const FragmentObserver& observe) {
  PipelineObserver o;
  o.fragment = observe;
  return render(frame, o);
}

Image WatkinsTop::render(const Frame& frame, const PipelineObserver& observe) {
  Image img;
  render_into(frame, img, observe);
  return img;
}

void WatkinsTop::render_into(const Frame& frame, Image& img, const PipelineObserver& observe) {
  stats_ = PipelineStats{};
  // Every row is written by its band (background first): the storage is only sized here.
  const std::size_t pixels = std::size_t(frame.width) * static_cast<std::size_t>(std::max(frame.height, 0));
  img.width = frame.width, img.height = frame.height;
  img.rgb.resize(3 * pixels), img.covered.resize(pixels), img.owner.resize(pixels);
  const ChannelFormats formats = config_.channels(frame.shading);
  // The shade or the normal reading, as the frame's pipeline uses; both for an observer (the
  // benches compare the interpolator's ports, which carry both).
  const bool observing = static_cast<bool>(observe.fragment);
  const FrameSetup fs(frame, formats, span_kernels(span_path_));
  // Bands of scan lines, each walked from its exact first-line state (walk_scan_lines' range
  // form) into its own rows of the image: the same lines, values and counts as one walk. Stage
  // streams are reported in order, so an observed frame is one band.
  const bool observed_stage = observing || observe.active_edge || observe.active_edges_end || observe.segment ||
                              observe.segments_end || observe.fragments_end;
  const int bands = observed_stage ? 1 : std::max(1, std::min(threads_, frame.height));
  std::vector<PipelineStats> band_stats(static_cast<std::size_t>(bands));
  std::vector<std::exception_ptr> band_error(static_cast<std::size_t>(bands));
  auto draw_band = [&](int b) {
    try {
      const int y0 = static_cast<int>(static_cast<long long>(frame.height) * b / bands);
      const int y1 = static_cast<int>(static_cast<long long>(frame.height) * (b + 1) / bands);
      draw_lines(fs, max_active_edges_, y0, y1, img, observe, band_stats[static_cast<std::size_t>(b)]);
    } catch (...) {
      band_error[static_cast<std::size_t>(b)] = std::current_exception();
    }
  };
  if (bands == 1) {
    draw_band(0);
  } else {
    std::vector<std::thread> workers;
    for (int b = 1; b < bands; ++b) workers.emplace_back(draw_band, b);
    draw_band(0);
    for (std::thread& t : workers) t.join();
  }
  // The first band's error is the first line's: a walk from line 0 stops there.
  for (const std::exception_ptr& e : band_error)
    if (e) std::rethrow_exception(e);
  for (const PipelineStats& b : band_stats) {
    stats_.edges += b.edges, stats_.segments += b.segments;
    stats_.fragments += b.fragments, stats_.visible += b.visible;
    stats_.max_active_edges = std::max(stats_.max_active_edges, b.max_active_edges);
  }
  // The smoother after the line buffer, when the frame enables it (it sees the full raster).
  if (frame.smoothed()) img = Smoother(frame.smooth_w).apply(img);
}

}  // namespace watkins
