#include "scanline_buffer.hpp"

namespace watkins {

bool ScanlineBuffer::write(const Fragment& f) {
  if (written_[f.x]) {
    const bool nearer = f.depth < depth_[f.x];
    const bool tie_won = tie_ == DepthTie::Submission && f.depth == depth_[f.x] && f.poly < poly_[f.x];
    if (!nearer && !tie_won) return false;
  }
  written_[f.x] = 1;
  depth_[f.x] = f.depth;
  rgb_[f.x] = {f.rgb[0], f.rgb[1], f.rgb[2]};
  poly_[f.x] = f.poly;
  return true;
}

}  // namespace watkins
