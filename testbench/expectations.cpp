// The model side of a run: images and stage streams, rendered before the simulation starts.
#include "expectations.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>

#include "formats.hpp"
#include "watkins_top.hpp"
#include "twin_error.hpp"

namespace watkins::tb::detail {

StageStreams model_stage_streams(const PreparedScene& scene, Image* image) {
  StageStreams s;
  s.width = scene.width;
  int ke = 0, ks = 0, kf = 0;
  PipelineObserver o;
  o.active_edge = [&](int y, const ActiveEdge& e) {
    s.edges.push_back(StageEdge{y, ke++, false, e.rec.poly, e.rec.material, e.rec.value});
  };
  o.active_edges_end = [&](int y) {
    s.edges.push_back(StageEdge{y, ke, true, 0, 0, {}});
    ke = 0;
  };
  o.segment = [&](int y, const Segment& g) {
    s.segments.push_back(StageSegment{y, ks++, false, g.poly, g.material, g.e, g.f});
  };
  o.segments_end = [&](int y) {
    s.segments.push_back(StageSegment{y, ks, true, 0, 0, {}, {}});
    ks = 0;
  };
  o.fragment = [&](int y, const Fragment& f, bool) {
    const std::uint32_t rgb = (std::uint32_t(f.rgb[0]) << 16) | (std::uint32_t(f.rgb[1]) << 8) | f.rgb[2];
    s.fragments.push_back(StageFragment{y, kf++, false, f.x, f.depth, f.poly, f.material, f.normal, rgb});
    s.shaded.push_back(s.fragments.back());
  };
  o.fragments_end = [&](int y) {
    s.fragments.push_back(StageFragment{y, kf, true, 0, 0, 0, 0, {}, 0});
    s.shaded.push_back(s.fragments.back());
    kf = 0;
  };
  WatkinsTop pipe(scene.config);
  Image img = pipe.render(scene, o);
  if (image) *image = std::move(img);
  return s;
}

bool phong_frames(const std::vector<const PreparedScene*>& scenes) {
  int phong = 0;
  for (const PreparedScene* s : scenes) phong += s->shading == ShadingMode::Phong;
  if (phong != 0 && phong != static_cast<int>(scenes.size()))
    throw std::invalid_argument("RTL: one run_rtl_frames call renders Gouraud or Phong frames, not both");
  return phong != 0;
}

const Config& frames_config(const std::vector<const PreparedScene*>& scenes) {
  static const Config def;
  if (scenes.empty()) return def;
  for (const PreparedScene* s : scenes)
    if (s->config != scenes.front()->config)
      throw std::invalid_argument("RTL: one run_rtl_frames call renders frames prepared for one configuration, "
                                  "not several (the RTL is built for one)");
  return scenes.front()->config;
}

Expectations expect(const std::vector<const PreparedScene*>& scenes, const RtlOptions& opt,
                    const std::vector<const Image*>& given, RtlResult& r, int max_width) {
  (void)frames_config(scenes);
  Expectations x;
  x.rendered.assign(scenes.size(), Image{});  // never resized again: `images` points into it
  x.images.assign(scenes.size(), nullptr);
  const bool want_stages = opt.compare && opt.check_stages;
  if (want_stages) x.stages.resize(scenes.size());
  bool stages_failed = false;
  for (std::size_t f = 0; f < scenes.size(); ++f) {
    const PreparedScene& s = *scenes[f];
    if (s.width < 1 || s.height < 1 || s.width > max_width || s.height >= (1 << fmt::LineBits))
      throw std::invalid_argument("RTL: a " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                                  " screen does not fit the RTL (line buffer MaxWidth = " +
                                  std::to_string(max_width) + " pixels)");
    const bool have = f < given.size() && given[f];
    if (have) x.images[f] = given[f];
    if (!want_stages && (have || !opt.compare)) continue;
    try {
      if (want_stages) {
        x.stages[f] = model_stage_streams(s, have ? nullptr : &x.rendered[f]);
        if (opt.edit_stage_streams) opt.edit_stage_streams(static_cast<int>(f), x.stages[f]);
      } else {
        x.rendered[f] = WatkinsTop(s.config).render(s);
      }
      if (!have) x.images[f] = &x.rendered[f];
    } catch (const CapacityError& e) {  // the twin's active-edge list overflowed
      stages_failed = true;
      if (!have && r.model_error.empty()) r.model_error = "frame " + std::to_string(f) + ": " + e.what();
    }
  }
  if (stages_failed) x.stages.clear();
  return x;
}

}  // namespace watkins::tb::detail
