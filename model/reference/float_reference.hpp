// Double-precision reference of the same algorithm (GLM): the same edges, the same pixel-centre
// coverage rule, even-odd pairing into segments, Gouraud's α interpolation evaluated directly
// (S = (1 − α)S_E + αS_F, no stepping, no quantization), the same depth test and tie rule
// (BuiltScene::depth_tie: first arrival, segments in closing-X order, or the smaller polygon id).
// Phong shading (BuiltScene::shading): the vertex normal is interpolated the same way, normalized
// in double and shaded with phong_levels (eq. 3). The fixed-point model's difference from it is
// the cost of quantization alone. Gouraud's eq. (2) (BuiltScene::interpolation Eq2): the shade
// slots carry S·Z, interpolated the same way, and a pixel's shade is their quotient by its
// interpolated Z. With BuiltScene::smooth > 0 the levels are then smoothed by
// Herman & Liu's 3x3 weighted mean in double (W unrounded; the smoother twin's rule for f_i).
// Curved surfaces (BuiltScene::curves) as Whitted draws them: on each scan line the crossings of
// each region's edges (found by Newton in model/curves) sorted by X and paired into segments,
// depth linear along a segment, the normal interpolated and shaded as Phong (or the Gouraud shade
// interpolated), depth-tested per pixel with the polygons; region r is id polygons.size() + r.
#pragma once

#include "image_io.hpp"
#include "scene.hpp"

namespace watkins {

struct FloatReferenceStats {
  long long fragments = 0;
};

Image render_float_reference(const BuiltScene& scene, FloatReferenceStats* stats = nullptr);

}  // namespace watkins
