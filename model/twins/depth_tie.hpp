// Which fragment keeps a pixel when two have equal depth (watkins_top's tie_submission_i, chosen
// per frame). Either way a strictly nearer fragment wins and a farther one loses.
//  - Arrival: the fragment that reached the scanline buffer first stays. Segments leave the
//    segment former in closing order, so in effect the segment with the smaller right-edge X wins.
//  - Submission: the fragment of the smaller polygon id wins, whatever the arrival order. Polygon
//    ids number the polygons in the order the scene submits them (prepare.hpp), so this is the
//    rule of GL's default depth test (GL_LESS: a later polygon at equal depth does not replace the
//    earlier one), e.g. for decals and coplanar overlaps.
#pragma once

namespace watkins {

enum class DepthTie { Arrival, Submission };

}  // namespace watkins
