// Twin of rtl/scanline_buffer.sv: the scan-line depth buffer that resolves visibility per pixel
// (Watkins' "hidden-parts computation" done per pixel, so intersecting polygons are exact to the
// pixel). A fragment is kept when the pixel is empty or its depth is strictly smaller; at equal
// depth the rule of the frame decides (depth_tie.hpp): Arrival keeps the fragment that arrived
// first (segments arrive in the segment former's order), Submission the smaller polygon id.
//
// Widths from the configuration (config.hpp), as the RTL takes them: MaxWidth = max_width entries;
// the depth word DepthBits = depth_bits (ChannelFormats::depth_bits); rgb stays rgb_t.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "depth_tie.hpp"
#include "segment_interpolator.hpp"

namespace watkins {

class ScanlineBuffer {
 public:
  ScanlineBuffer(int width, std::array<std::uint8_t, 3> background, DepthTie tie = DepthTie::Arrival)
      : background_(background),
        poly_key_mask_(tie == DepthTie::Submission ? 0xffffffffu : 0u),
        key_(static_cast<std::size_t>(width), Empty),
        rgb_(static_cast<std::size_t>(width)),
        poly_(static_cast<std::size_t>(width)) {}

  // Empties the line: only the pixels written since the last clear are touched, so a line costs
  // its fragments, not its width.
  void clear() {
    for (const int x : written_x_) key_[static_cast<std::size_t>(x)] = Empty;
    written_x_.clear();
  }
  // The depth test alone: whether a fragment at x with this depth and polygon would win its
  // pixel. One comparison of keys (see key()): an empty pixel holds a key above every fragment's.
  bool wins(int x, std::uint32_t depth, int poly) const {
    return key_of(depth, poly) < key_[static_cast<std::size_t>(x)];
  }
  bool wins(const Fragment& f) const { return wins(f.x, f.depth, f.poly); }
  // The same in two parts, for a loop over one polygon's span: its key's low word once
  // (tie_bits), then per fragment the comparison of key(depth, tie_bits).
  std::uint64_t tie_bits(int poly) const { return static_cast<std::uint32_t>(poly) & poly_key_mask_; }
  static std::uint64_t key(std::uint32_t depth, std::uint64_t tie_bits) { return (std::uint64_t{depth} << 32) | tie_bits; }
  bool wins_key(int x, std::uint64_t key) const { return key < key_[static_cast<std::size_t>(x)]; }
  // Writes a fragment that wins its pixel (wins(f) is true); `key` is its key.
  void store(const Fragment& f) { store(f, key_of(f.depth, f.poly)); }
  void store(const Fragment& f, std::uint64_t key) {
    const auto x = static_cast<std::size_t>(f.x);
    // push_back of a copy: a reference into f would make the caller keep f in memory.
    if (key_[x] == Empty) written_x_.push_back(static_cast<int>(x));
    key_[x] = key;
    rgb_[x] = pack(f.rgb[0], f.rgb[1], f.rgb[2]);
    poly_[x] = f.poly;
  }
  // Depth test and write. Returns true when the fragment won the pixel.
  bool write(const Fragment& f) {
    if (!wins(f)) return false;
    store(f);
    return true;
  }
  // The finished line's pixel at x (background where nothing was written).
  std::array<std::uint8_t, 3> pixel(int x) const { return covered(x) ? written_rgb(x) : background_; }
  bool covered(int x) const { return key_[static_cast<std::size_t>(x)] != Empty; }
  // Sparse read-out: the first covered x >= x, or width() when there is none. The RTL takes the
  // lowest written bit of its read bank, the same pixel: every bit below x is already cleared.
  int next_covered(int x) const {
    while (x < width() && !covered(x)) ++x;
    return x;
  }
  int owner(int x) const { return covered(x) ? poly_[static_cast<std::size_t>(x)] : -1; }
  // The covered pixels since the last clear, in the order they were first written, and the
  // shade and polygon of one of them (no background test: the read-out of a covered pixel).
  const std::vector<int>& written() const { return written_x_; }
  std::array<std::uint8_t, 3> written_rgb(int x) const {
    const std::uint32_t p = rgb_[static_cast<std::size_t>(x)];
    return {static_cast<std::uint8_t>(p), static_cast<std::uint8_t>(p >> 8), static_cast<std::uint8_t>(p >> 16)};
  }
  int written_poly(int x) const { return poly_[static_cast<std::size_t>(x)]; }
  int width() const { return static_cast<int>(key_.size()); }

 private:
  // A pixel's depth-test key: the depth above, and below it the polygon id under the Submission
  // rule (0 under Arrival), so "nearer, or as near and a smaller polygon" is one unsigned
  // comparison, and an equal key (Arrival at equal depth) loses. Depth is at most 32 bits and a
  // polygon id below 2^31, so no fragment's key reaches Empty.
  std::uint64_t key_of(std::uint32_t depth, int poly) const { return key(depth, tie_bits(poly)); }
  static constexpr std::uint64_t Empty = ~std::uint64_t{0};
  // rgb in one 32-bit word per pixel (R in the low byte): stored without byte stores, which the
  // compiler must assume alias everything else the loop holds.
  static std::uint32_t pack(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    return std::uint32_t{r} | (std::uint32_t{g} << 8) | (std::uint32_t{b} << 16);
  }

  std::array<std::uint8_t, 3> background_;
  std::uint32_t poly_key_mask_;     // all ones under Submission, 0 under Arrival
  std::vector<std::uint64_t> key_;  // Empty where nothing was written since the last clear
  std::vector<std::uint32_t> rgb_;
  std::vector<int> poly_;  // visible polygon per pixel (the RTL keeps it beside the depth for the tie rule)
  std::vector<int> written_x_;
};

}  // namespace watkins
