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

  void clear() { std::fill(written_.begin(), written_.end(), 0); }
  // Depth test and write. Returns true when the fragment won the pixel.
  bool write(const Fragment& f);
  // The finished line's pixel at x (background where nothing was written).
  std::array<std::uint8_t, 3> pixel(int x) const { return written_[x] ? rgb_[x] : background_; }
  bool covered(int x) const { return written_[x] != 0; }
  // Sparse read-out (the RTL's find-next-written search): the first covered x >= x, or width()
  // when there is none.
  int next_covered(int x) const {
    while (x < width() && !written_[x]) ++x;
    return x;
  }
  int owner(int x) const { return written_[x] ? poly_[x] : -1; }
  int width() const { return static_cast<int>(depth_.size()); }

 private:
  std::array<std::uint8_t, 3> background_;
  DepthTie tie_;
  std::vector<std::uint32_t> depth_;
  std::vector<std::array<std::uint8_t, 3>> rgb_;
  std::vector<int> poly_;  // visible polygon per pixel (the RTL keeps it beside the depth for the tie rule)
  std::vector<std::uint8_t> written_;
};

}  // namespace watkins
