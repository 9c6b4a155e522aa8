// What a run of the RTL is checked against, prepared before the simulation on every harness:
// the model's image of every frame (rendered unless given) and, for the stage check, its stage
// streams (StageStreams, rtl_bench.hpp).
#pragma once

#include <vector>

#include "image.hpp"
#include "prepare.hpp"
#include "rtl_bench.hpp"

namespace watkins::tb::detail {

struct Expectations {
  std::vector<Image> rendered;       // the model images rendered here
  std::vector<const Image*> images;  // per frame: the given image, one of `rendered`, or null
  std::vector<StageStreams> stages;  // per frame; empty: stages not checked
};

// Checks that the frames share one configuration, that every screen fits the RTL (width <= max_width) and renders what opt asks for:
// with opt.compare the images that were not given, with opt.check_stages too the stage streams
// of every frame (edited by opt.edit_stage_streams). A frame the model cannot render leaves
// its image null, the stages empty and r.model_error set.
Expectations expect(const std::vector<const PreparedScene*>& scenes, const RtlOptions& opt,
                    const std::vector<const Image*>& given, RtlResult& r, int max_width);

// The model's stage streams of one frame (and its image when `image` is given).
StageStreams model_stage_streams(const PreparedScene& scene, Image* image);

// The configuration every frame was prepared for (PreparedScene::config; the default for no
// frames): the model renders with it and the top must be built for it. Frames of one run share
// one configuration, so differing ones throw std::invalid_argument.
const Config& frames_config(const std::vector<const PreparedScene*>& scenes);

// True when the frames need the Phong top (Phong = 1), false for the Gouraud top; frames of one
// run use one top, so mixing the two throws std::invalid_argument.
bool phong_frames(const std::vector<const PreparedScene*>& scenes);

}  // namespace watkins::tb::detail
