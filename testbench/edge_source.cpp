// The frame driver's source: edge beats, frame pins and the material table (edge_source.hpp).
#include "edge_source.hpp"

#include <algorithm>

#include "expectations.hpp"
#include "fixed_point.hpp"
#include "formats.hpp"

namespace watkins::tb::detail {
namespace {

// {z, y, x} of a Q2.14 unit vector, as light_i / eye_i take it.
std::uint64_t pack_unit(const std::array<i64, 3>& v) {
  std::uint64_t w = 0;
  for (int c = 0; c < 3; ++c) w |= wrap_unsigned(v[c], fmt::UnitBits) << (c * fmt::UnitBits);
  return w;
}

MaterialPins material_write(std::size_t addr, const QuantizedMaterial& m) {
  MaterialPins p;
  p.we = true;
  p.addr = static_cast<std::uint32_t>(addr);
  p.cp = pack_rgb({std::uint8_t(m.cp[0]), std::uint8_t(m.cp[1]), std::uint8_t(m.cp[2])});
  p.d = static_cast<std::uint32_t>(m.d);
  p.w = static_cast<std::uint32_t>(m.w);
  p.n = static_cast<std::uint32_t>(m.shininess);
  return p;
}

}  // namespace

bool sparse_frame(const RtlOptions& opt, int f) {
  return f < static_cast<int>(opt.sparse_frames.size()) ? opt.sparse_frames[f] : opt.sparse;
}

bool FrameConfig::operator==(const FrameConfig& o) const {
  auto same_material = [](const QuantizedMaterial& a, const QuantizedMaterial& b) {
    return a.cp == b.cp && a.d == b.d && a.w == b.w && a.shininess == b.shininess;
  };
  return width == o.width && height == o.height && background == o.background && sparse == o.sparse &&
         tie_submission == o.tie_submission && smooth_w == o.smooth_w && eq2 == o.eq2 &&
         light == o.light && eye == o.eye && materials.size() == o.materials.size() &&
         std::equal(materials.begin(), materials.end(), o.materials.begin(), same_material);
}

EdgeSource::EdgeSource(TopPins& pins, const std::vector<const PreparedScene*>& scenes, const RtlOptions& opt)
    : pins_(pins), scenes_(scenes), opt_(opt),
      layout_(EdgeLayout::of(frames_config(scenes), phong_frames(scenes) ? ShadingMode::Phong : ShadingMode::Gouraud)),
      beats_(scenes.size()), poison_(poison_edge(layout_)), gap_rng_(opt.seed * 2 + 1),
      gap_threshold_(Rng::threshold(opt.gap)) {
  for (std::size_t f = 0; f < scenes.size(); ++f) {
    beats_[f].reserve(scenes[f]->edges.size());
    for (const EdgeRecord& e : scenes[f]->edges) beats_[f].push_back(pack_edge(layout_, e));
  }
}

FrameConfig EdgeSource::needs(int f) const {
  const PreparedScene& s = *scenes_[f];
  FrameConfig k;
  k.width = std::uint32_t(s.width);
  k.height = std::uint32_t(s.height);
  k.background = pack_rgb(s.background);
  k.sparse = sparse_frame(opt_, f);
  k.tie_submission = s.depth_tie == DepthTie::Submission;
  k.smooth_w = std::uint32_t(s.smooth_w);
  k.eq2 = s.eq2;
  if (s.shading == ShadingMode::Phong) {
    k.light = pack_unit(s.light);
    k.eye = pack_unit(s.eye);
    k.materials = s.materials;
  }
  return k;
}

void EdgeSource::drive(long long cycle, int frames_done, std::vector<RtlFrame>& frames) {
  if (presenting_ || done()) return;
  const bool starts = beat_ == 0;
  const bool same = configured_ && needs(frame_) == config_;
  const bool may_start = !starts || same || frames_done >= frame_;  // else wait for the previous frames to drain
  if (may_start && starts && !same && loading_ == 0) {
    config_ = needs(frame_);
    pins_.frame_pins(config_.width, config_.height, config_.background, config_.sparse, config_.tie_submission,
                     config_.smooth_w, config_.eq2);
    pins_.phong_pins(config_.light, config_.eye);
    configured_ = true;
    loading_ = config_.materials.size() + 1;  // the writes, then write enable low again
  }
  if (loading_ > 0) {
    const std::size_t k = config_.materials.size() + 1 - loading_;
    pins_.material_pins(k < config_.materials.size() ? material_write(k, config_.materials[k]) : MaterialPins{});
    --loading_;
  } else if (may_start && !gap_rng_.chance(gap_threshold_)) {
    presenting_ = true;
    if (starts) frames[frame_].first_edge_cycle = cycle;  // the RTL starts the frame here
    const bool eof = beat_ == beats_[frame_].size();
    pins_.edge_pins(true, eof, eof ? poison_ : beats_[frame_][beat_]);
  }
}

void EdgeSource::taken() {
  presenting_ = false;
  if (++beat_ > beats_[frame_].size()) {
    ++frame_;
    beat_ = 0;
  }
  idle();
}

std::string EdgeSource::waiting_beat() const {
  std::string beat;
  if (beat_ == beats_[frame_].size()) {
    beat = "the end-of-frame beat";
  } else {
    const EdgeRecord& e = scenes_[frame_]->edges[beat_];
    beat = "edge " + std::to_string(beat_) + " (y0 " + std::to_string(e.y0) + ", n " + std::to_string(e.n) +
           ", poly " + std::to_string(e.poly) + ")";
  }
  return "frame " + std::to_string(frame_) + " " + beat + " of " + std::to_string(beats_[frame_].size() + 1) +
         " beats";
}

}  // namespace watkins::tb::detail
