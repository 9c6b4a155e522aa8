#include "scanline_buffer.hpp"

namespace watkins {

bool ScanlineBuffer::write(const Fragment& f) {
  if (written_[f.x] && !(f.depth < depth_[f.x])) return false;
  written_[f.x] = 1;
  depth_[f.x] = f.depth;
  rgb_[f.x] = {f.rgb[0], f.rgb[1], f.rgb[2]};
  poly_[f.x] = f.poly;
  return true;
}

}  // namespace watkins
