// One frame as watkins_top receives it: the pins that are stable for the frame (size, background,
// equal-depth rule, shading mode, the Phong material table, light and eye) and the y-sorted edge-record stream.
// Scene preparation (model/prepare/) writes it; the twins and the RTL benches read nothing else.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "depth_tie.hpp"
#include "edge_record.hpp"
#include "fixed_point.hpp"
#include "formats.hpp"
#include "shading_mode.hpp"

namespace watkins {

// One entry of the Phong top's material table, in the phong_shader's formats.
struct QuantizedMaterial {
  std::array<int, 3> cp{};  // R, G, B reflectance, 8-bit levels (255 = 1.0)
  int d = 0, w = 0;         // MaterialBits, 1.0 = 2^MaterialFracBits
  int shininess = 0;        // ShininessBits
};

struct Frame {
  int width = 0, height = 0;
  std::array<std::uint8_t, 3> background{};
  DepthTie depth_tie = DepthTie::Arrival;  // tie_submission_i = (depth_tie == Submission)
  // Phong: edge channels ChanNx.. hold normals, every edge a material id; light and eye are
  // unit vectors in Q2.14 (UnitBits), frame constants of the shader.
  ShadingMode shading = ShadingMode::Gouraud;
  std::vector<QuantizedMaterial> materials;  // at most 2^MaterialIdBits
  std::array<i64, 3> light{}, eye{};
  // Herman & Liu's 3x3 smoothing of the finished image (model/twins/smoother.hpp, the top's
  // smooth_w_i): W with SmoothWFracBits fraction bits; 0 = off (the smoother is bypassed).
  int smooth_w = 0;
  // Gouraud's eq. (2) (the top's eq2_i, a Gouraud top built with HasEq2): the shade slots carry
  // each vertex's S·Z and the depth slot Z, and every pixel's shade is their quotient
  // (model/twins/shade_divider.hpp). false: eq. (1), the shade slots interpolated as they are.
  bool eq2 = false;
  // Whether the frame is smoothed: the pin's SmoothWBits word is not zero (as the RTL tests it).
  bool smoothed() const { return (smooth_w & ((1 << fmt::SmoothWBits) - 1)) != 0; }
  std::vector<EdgeRecord> edges;  // sorted by (y0, id)
};

}  // namespace watkins
