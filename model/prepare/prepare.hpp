// Scene preparation, the software preprocessor of Watkins' scheme: quantize screen-space
// polygons to fixed point and build the y-sorted edge-record stream the pipeline reads.
// All arithmetic after quantization is integer, so the stream is deterministic and bit-exact.
#pragma once

#include <string>
#include <vector>

#include "frame.hpp"
#include "scene.hpp"
#include "scene_needs.hpp"

namespace watkins {

// A vertex in the pipeline's fixed-point formats.
struct QuantizedVertex {
  i64 x16 = 0, y16 = 0;  // position in 1/16 pixel (SubPixelBits)
  ChannelVector ch{};    // channel values at the vertex (X = x16 << SubPixelToFrac)
};

struct PrepareOptions {
  int max_active_edges = fmt::MaxActiveEdges;  // capacity of the active-edge list
};

// The frame watkins_top renders (its pins and edge stream), with what scene preparation learnt
// on the way: the polygon count and what the frame needs from the hardware.
struct PreparedScene : Frame {
  int polygons = 0;
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
