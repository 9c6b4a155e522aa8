// Scene preparation, the software preprocessor of Watkins' scheme: quantize screen-space
// polygons to fixed point and build the y-sorted edge-record stream the pipeline reads.
// All arithmetic after quantization is integer, so the stream is deterministic and bit-exact.
#pragma once

#include <string>
#include <vector>

#include "config.hpp"
#include "frame.hpp"
#include "scene.hpp"
#include "scene_needs.hpp"

namespace watkins {

// A vertex in the pipeline's fixed-point formats.
struct QuantizedVertex {
  i64 x16 = 0, y16 = 0;  // position in 1/16 pixel (SubPixelBits)
  ChannelVector ch{};    // channel values at the vertex (X = x16 << SubPixelToFrac)
};

// Shorthand for the default configuration with another active-edge list capacity.
struct PrepareOptions {
  int max_active_edges = fmt::MaxActiveEdges;  // capacity of the active-edge list
};

// The frame watkins_top renders (its pins and edge stream), with what scene preparation learnt
// on the way: the polygon count, what the frame needs from the hardware, and which hardware.
struct PreparedScene : Frame {
  int polygons = 0;
  SceneNeeds needs;
  Config config;  // the configuration it was prepared for: WatkinsTop(config) and the RTL built for it
};

// Channels ChanR.. carry the shade (Gouraud) or the unit normal (Phong, ChanNx..); throws
// SceneError when a value is out of range. With eq2 (Gouraud's eq. (2), Frame::eq2) they carry
// the numerator S·Z instead, Z the vertex's quantized depth as a fraction of 1
// (model/twins/shade_divider.hpp divides it by the interpolated depth).
// Each channel is rounded to its group's fraction bits in `config` and must fit its word.
QuantizedVertex quantize_vertex(const ScreenVertex& v, ShadingMode shading = ShadingMode::Gouraud,
                                const Config& config = Config{}, bool eq2 = false);
// A material in the phong_shader's formats; throws SceneError when a value does not fit.
QuantizedMaterial quantize_material(const PhongMaterial& m);
// Herman & Liu's weight W in the smoother's format (Frame::smooth_w): W · 2^SmoothWFracBits
// rounded, clamped to the SmoothWBits word.
int quantize_smooth_weight(double W);

// Edge record of the edge from a to b for a screen of `height` lines; false when it crosses no
// pixel centre on screen (horizontal, between two centres, or above/below the screen).
// Values and slopes wrap to the channel words of `formats` (a slope wrapped to its word steps the
// same values; prepare() checks that the values themselves fit).
bool make_edge_record(const QuantizedVertex& a, const QuantizedVertex& b, int poly, int height,
                      const ChannelFormats& formats, EdgeRecord& out);
bool make_edge_record(const QuantizedVertex& a, const QuantizedVertex& b, int poly, int height,
                      EdgeRecord& out);

// Throws SceneError when a capacity limit is exceeded (naming the limit, the need and the line).
// Gouraud scenes carry material id 0 on every edge (the id is unused there, so any number of
// materials fits); Phong scenes carry each polygon's material and need at most 2^MaterialIdBits.
// The frame for the pipeline built for `config` (which must pass Config::check()). Besides the
// capacities, every channel value the pipeline will hold — vertices, edge values on every scan
// line, span values on every pixel — must fit its group's word: a configuration too narrow for
// the scene is refused with a SceneError naming the group and the bits it needs, never wrapped.
PreparedScene prepare(const BuiltScene& scene, const Config& config);
PreparedScene prepare(const BuiltScene& scene, const PrepareOptions& opt = {});

// `base` with the integer bits of every channel group the frame uses (X, depth, and the shade or
// the normal) cut to exactly what the scene's values need at base's fraction bits (SceneNeeds,
// measured on a prepare() with the widest words those fractions allow and an unbounded
// active-edge list); the unused group and every capacity stay base's. The one derivation of
// integer bits: `watkins size` and `watkins sweep` both size their configurations with it.
// Throws SceneError when base's fractions are no valid configuration or the scene cannot be
// prepared at them; `probe` (optional) receives that widest preparation.
// `base` with the edge order the scene needs: 3 (cubic forward differences) when it has curved
// edges (BuiltScene::curves), else base's; and with the eq. (2) shade divider (eq2) when it is a
// Gouraud scene interpolating by eq2. `watkins render` without --config and fit_int_bits use it.
Config with_scene_edge_order(const BuiltScene& scene, Config base);

Config fit_int_bits(const BuiltScene& scene, const Config& base, PreparedScene* probe = nullptr);

}  // namespace watkins
