// Scene preparation, the software preprocessor of Watkins' scheme: quantize screen-space
// polygons to fixed point and build the y-sorted edge-record stream the pipeline reads.
// All arithmetic after quantization is integer, so the stream is deterministic and bit-exact.
#pragma once

#include <string>
#include <vector>

#include "edge_record.hpp"
#include "scene.hpp"

namespace watkins {

// A vertex in the pipeline's fixed-point formats.
struct QuantizedVertex {
  i64 x16 = 0, y16 = 0;  // position in 1/16 pixel (SubPixelBits)
  ChannelVector ch{};    // channel values at the vertex (X = x16 << SubPixelToFrac)
};

// What the scene needs from the hardware: capacities and ranges, so the hardware can be sized
// to the scene instead of a worst case.
struct SceneNeeds {
  int polygons = 0;
  int edges = 0;              // edge records after dropping horizontal and off-screen edges
  int max_active_edges = 0;   // largest active-edge list on any scan line
  int max_active_line = -1;   // the scan line where it occurs
  int max_edge_lines = 0;     // largest n of an edge record
  int max_segment_pixels = 0; // widest span, in pixels (after clipping to the screen)
  ChannelVector value_min{}, value_max{};  // ranges of edge-record channel values
  ChannelVector slope_min{}, slope_max{};  // and of their per-scan-line slopes
  int bits_for_value(int channel) const;   // signed bits the channel's values and slopes need
};

struct PrepareOptions {
  int max_active_edges = fmt::MaxActiveEdges;  // capacity of the active-edge list
};

// A material in the phong_shader's formats (see model/phong_shader.hpp).
struct QuantizedMaterial {
  std::array<int, 3> cp{};  // R, G, B reflectance, 8-bit levels (255 = 1.0)
  int d = 0, w = 0;         // MaterialBits, 1.0 = 2^MaterialFracBits
  int shininess = 0;        // ShininessBits
};

struct PreparedScene {
  int width = 0, height = 0;
  std::array<std::uint8_t, 3> background{};
  // Phong: edge channels ChanNx.. hold normals, every edge a material id; light and eye are
  // unit vectors in Q2.14 (UnitBits), frame constants of the shader.
  ShadingMode shading = ShadingMode::Gouraud;
  std::vector<QuantizedMaterial> materials;  // at most 2^MaterialIdBits
  std::array<i64, 3> light{}, eye{};
  int polygons = 0;
  std::vector<EdgeRecord> edges;  // sorted by (y0, id)
  SceneNeeds needs;
};

// Channels ChanR.. carry the shade (Gouraud) or the unit normal (Phong, ChanNx..); throws
// SceneError when a value is out of range.
QuantizedVertex quantize_vertex(const ScreenVertex& v, ShadingMode shading = ShadingMode::Gouraud);
// A material in the phong_shader's formats; throws SceneError when a value does not fit.
QuantizedMaterial quantize_material(const PhongMaterial& m);

// Edge record of the edge from a to b for a screen of `height` lines; false when it crosses no
// pixel centre on screen (horizontal, between two centres, or above/below the screen).
bool make_edge_record(const QuantizedVertex& a, const QuantizedVertex& b, int poly, int height,
                      EdgeRecord& out);

// Throws SceneError when a capacity limit is exceeded (naming the limit, the need and the line).
// Gouraud scenes carry material id 0 on every edge (the id is unused there, so any number of
// materials fits); Phong scenes carry each polygon's material and need at most 2^MaterialIdBits.
PreparedScene prepare(const BuiltScene& scene, const PrepareOptions& opt = {});

}  // namespace watkins
