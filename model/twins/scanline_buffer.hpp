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
      : background_(background), tie_(tie), depth_(width), rgb_(width), poly_(width), written_(width, 0) {}

  // Empties the line: only the pixels written since the last clear are touched, so a line costs
  // its fragments, not its width.
  void clear() {
    for (const int x : written_x_) written_[static_cast<std::size_t>(x)] = 0;
    written_x_.clear();
  }
  // The depth test alone: whether the fragment (its x, depth and, for the Submission rule, its
  // polygon) would win its pixel.
  bool wins(const Fragment& f) const {
    const auto x = static_cast<std::size_t>(f.x);
    if (!written_[x]) return true;
    const bool nearer = f.depth < depth_[x];
    const bool tie_won = tie_ == DepthTie::Submission && f.depth == depth_[x] && f.poly < poly_[x];
    return nearer || tie_won;
  }
  // Writes a fragment that wins its pixel (wins(f) is true).
  void store(const Fragment& f) {
    const auto x = static_cast<std::size_t>(f.x);
    if (!written_[x]) {
      written_[x] = 1;
      written_x_.push_back(f.x);
    }
    depth_[x] = f.depth;
    // Byte by byte: the fragment's bytes were just stored one by one, and a wider load of them
    // would wait for the stores to retire (no store forwarding across sizes).
    rgb_[x][0] = f.rgb[0];
    rgb_[x][1] = f.rgb[1];
    rgb_[x][2] = f.rgb[2];
    poly_[x] = f.poly;
  }
  // Depth test and write. Returns true when the fragment won the pixel.
  bool write(const Fragment& f) {
    if (!wins(f)) return false;
    store(f);
    return true;
  }
  // The finished line's pixel at x (background where nothing was written).
  std::array<std::uint8_t, 3> pixel(int x) const { return written_[x] ? rgb_[x] : background_; }
  bool covered(int x) const { return written_[x] != 0; }
  // Sparse read-out: the first covered x >= x, or width() when there is none. The RTL takes the
  // lowest written bit of its read bank, the same pixel: every bit below x is already cleared.
  int next_covered(int x) const {
    while (x < width() && !written_[x]) ++x;
    return x;
  }
  int owner(int x) const { return written_[x] ? poly_[x] : -1; }
  // The covered pixels since the last clear, in the order they were first written, and the
  // shade and polygon of one of them (no background test: the read-out of a covered pixel).
  const std::vector<int>& written() const { return written_x_; }
  const std::array<std::uint8_t, 3>& written_rgb(int x) const { return rgb_[static_cast<std::size_t>(x)]; }
  int written_poly(int x) const { return poly_[static_cast<std::size_t>(x)]; }
  int width() const { return static_cast<int>(depth_.size()); }

 private:
  std::array<std::uint8_t, 3> background_;
  DepthTie tie_;
  std::vector<std::uint32_t> depth_;
  std::vector<std::array<std::uint8_t, 3>> rgb_;
  std::vector<int> poly_;  // visible polygon per pixel (the RTL keeps it beside the depth for the tie rule)
  std::vector<std::uint8_t> written_;
  std::vector<int> written_x_;
};

}  // namespace watkins
