#include "watkins_top.hpp"

#include <algorithm>
#include <type_traits>

#include "normalizer.hpp"
#include "phong_shader.hpp"
#include "scan_lines.hpp"
#include "shade_divider.hpp"
#include "smoother.hpp"

namespace watkins {
namespace {

// The Phong blocks' frame constants: light, eye, L.E (PhongShader::frame_le) and each material's
// terms (PhongShader::material_terms), worked out once per frame instead of per pixel.
struct PhongFrame {
  PhongShader::Vec light{}, eye{};
  i64 le = 0;
  std::vector<PhongShader::MaterialTerms> materials;  // by material id, as frame.materials
  explicit PhongFrame(const Frame& frame)
      : light(frame.light), eye(frame.eye), le(PhongShader::frame_le(frame.light, frame.eye)) {
    if (frame.shading != ShadingMode::Phong) return;
    materials.reserve(frame.materials.size());
    for (const QuantizedMaterial& m : frame.materials)
      materials.push_back(PhongShader::material_terms(m.cp, m.d, m.w, m.shininess));
  }
  // normalizer → phong_shader on one normal of material `id` (checked by the caller).
  std::array<int, 3> shade(const std::array<i64, 3>& normal, int id) const {
    const Normalizer::Unit u = Normalizer::normalize(normal[0], normal[1], normal[2]);
    return PhongShader::shade(u.n, materials[static_cast<std::size_t>(id)], light, eye, le);
  }
  // The same on a fragment: its rgb becomes the shade of its material (std::out_of_range for an id
  // past the table, as the material table's read).
  void shade(Fragment& f) const {
    const std::array<int, 3> rgb = shade(f.normal, check(f.material));
    for (int c = 0; c < 3; ++c) f.rgb[c] = static_cast<std::uint8_t>(rgb[c]);
  }
  int check(int id) const {
    (void)materials.at(static_cast<std::size_t>(id));
    return id;
  }
};

// The segments of one scan line through the interpolator (and the Phong blocks) into the line
// buffer. What varies per frame is a template parameter, chosen once per frame: whether a bench
// observes the fragments (Observed: each gets both readings and is reported) and the shading,
// so the loop nobody observes holds no call, no test of the observer and no test of the mode.
struct LineCounts {
  long long fragments = 0, visible = 0;  // as PipelineStats counts them
};
// Phong with nobody observing: a pixel's shade is a function of its last winner's normal and
// material alone, so the line keeps those and shades each covered pixel once at read-out, not
// every fragment that wins on the way (the same pixels: overdraw costs a depth test, not a shade).
struct DeferredPhong {
  std::vector<std::array<i64, 3>> normal;  // per pixel of the line
  std::vector<int> material;
};
// The pipeline a frame takes: Gouraud's eq. (1), his eq. (2) (the shade divider after the
// interpolator) or Phong.
enum class Pipe { Gouraud, Eq2, Phong };
template <bool Observed, Pipe P>
LineCounts draw_segments(const Frame& frame, const std::vector<Segment>& segments, const ChannelFormats& formats,
                        const PixelPath& path, const PhongFrame& phong, const ShadeDivider& divider,
                        ScanlineBuffer& line, int y, const PipelineObserver& observe, DeferredPhong& later) {
  constexpr ShadingMode Shading = P == Pipe::Phong ? ShadingMode::Phong : ShadingMode::Gouraud;
  constexpr bool defer = !Observed && Shading == ShadingMode::Phong;
  // Eq. (2) reads the shade slots' words, not a reading of them: only their words' range matters
  // (the Normal reading's range check), and no reading is filled unless a bench observes.
  constexpr auto readings = Observed ? PixelPath::Readings::Both
                            : P != Pipe::Gouraud ? PixelPath::Readings::Normal
                                                 : PixelPath::Readings::Shade;
  // Local copies: the line buffer's stores cannot alias them, so the loop keeps them in registers.
  const PixelPath p = path;
  LineCounts n;
  for (const Segment& s : segments) {
    const SpanSetup span = SegmentInterpolator::setup(s, frame.width, formats);
    n.fragments += span.x_end - span.x_start;
    // A span whose values stay inside their words and readings (in_range) runs without wraps
    // and clamps; any other span, and every span a bench observes, takes the general path.
    auto run = [&](auto in_range) {
      constexpr bool InRange = decltype(in_range)::value;
      ChannelVector v = span.value;
      const ChannelVector step = span.step;
      const std::uint64_t tie_bits = line.tie_bits(span.poly);
      for (int x = span.x_start; x < span.x_end; ++x) {
        // The depth test first: a hidden fragment's readings (and Phong shade) are computed only
        // when a bench observes it. The RTL computes them all; the values kept are the same.
        Fragment f = p.head<InRange>(span, x, v);
        const std::uint64_t key = ScanlineBuffer::key(f.depth, tie_bits);
        const bool won = line.wins_key(x, key);
        if (won || Observed) {
          if (P != Pipe::Eq2 || Observed) p.fill<readings, InRange>(f, v);
          if (P == Pipe::Eq2) {
            const std::array<std::uint8_t, 3> rgb =
                divider.shade(f.depth, {v[fmt::ChanR], v[fmt::ChanG], v[fmt::ChanB]});
            for (int c = 0; c < 3; ++c) f.rgb[c] = rgb[c];
          }
          if (defer) {
            later.normal[static_cast<std::size_t>(x)] = f.normal;
            later.material[static_cast<std::size_t>(x)] = phong.check(f.material);  // shade(f)'s check
          } else if (Shading == ShadingMode::Phong) {
            phong.shade(f);
          }
          if (won) line.store(f, key);
          if (Observed) observe.fragment(y, f, won);
        }
        n.visible += won;
        p.step<InRange>(step, v);
      }
    };
    if (span.x_end <= span.x_start) continue;
    if (p.in_range<readings>(span))
      run(std::true_type{});
    else
      run(std::false_type{});
  }
  return n;
}

using DrawSegments = LineCounts (*)(const Frame&, const std::vector<Segment>&, const ChannelFormats&,
                                   const PixelPath&, const PhongFrame&, const ShadeDivider&, ScanlineBuffer&, int,
                                   const PipelineObserver&, DeferredPhong&);

DrawSegments draw_segments_for(bool observed, const Frame& frame) {
  if (frame.shading == ShadingMode::Phong)
    return observed ? draw_segments<true, Pipe::Phong> : draw_segments<false, Pipe::Phong>;
  if (frame.eq2) return observed ? draw_segments<true, Pipe::Eq2> : draw_segments<false, Pipe::Eq2>;
  return observed ? draw_segments<true, Pipe::Gouraud> : draw_segments<false, Pipe::Gouraud>;
}

}  // namespace

std::vector<SparseBeat> sparse_stream(const Image& img) {
  std::vector<SparseBeat> out;
  bool last_line_covered = false;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (img.is_covered(x, y)) {
        const std::uint8_t* p = img.at(x, y);
        out.push_back(SparseBeat{x, y, {p[0], p[1], p[2]}, true, false});
        last_line_covered = y == img.height - 1;
      }
  if (!last_line_covered && img.width > 0 && img.height > 0) {
    const std::uint8_t* p = img.at(img.width - 1, img.height - 1);  // background: not covered
    out.push_back(SparseBeat{img.width - 1, img.height - 1, {p[0], p[1], p[2]}, false, false});
  }
  if (!out.empty()) out.back().last = true;
  return out;
}

Image WatkinsTop::render(const Frame& frame, const FragmentObserver& observe) {
  PipelineObserver o;
  o.fragment = observe;
  return render(frame, o);
}

Image WatkinsTop::render(const Frame& frame, const PipelineObserver& observe) {
  Image img;
  render_into(frame, img, observe);
  return img;
}

void WatkinsTop::render_into(const Frame& frame, Image& img, const PipelineObserver& observe) {
  stats_ = PipelineStats{};
  img.reset(frame.width, frame.height, frame.background);
  ScanlineBuffer line(frame.width, frame.background, frame.depth_tie);
  const ChannelFormats formats = config_.channels(frame.shading);
  // The shade or the normal reading, as the frame's pipeline uses; both for an observer (the
  // benches compare the interpolator's ports, which carry both).
  const bool observing = static_cast<bool>(observe.fragment);
  const PixelPath path(formats);
  const DrawSegments draw = draw_segments_for(observing, frame);
  const ShadeDivider divider(formats);
  const PhongFrame phong(frame);
  const bool deferred = !observing && frame.shading == ShadingMode::Phong;
  DeferredPhong later;
  if (deferred) {
    later.normal.resize(static_cast<std::size_t>(frame.width));
    later.material.resize(static_cast<std::size_t>(frame.width));
  }
  walk_scan_lines(frame.edges, frame.height, max_active_edges_, formats, [&](const ScanLine& sl) {
    const int y = sl.y;
    stats_.edges += sl.entered;
    stats_.max_active_edges = std::max(stats_.max_active_edges, sl.active.size());
    if (observe.active_edge)
      for (const ActiveEdge& e : sl.active.edges()) observe.active_edge(y, e);
    if (observe.active_edges_end) observe.active_edges_end(y);
    stats_.segments += static_cast<long long>(sl.segments.size());
    if (observe.segment)
      for (const Segment& s : sl.segments) observe.segment(y, s);
    if (observe.segments_end) observe.segments_end(y);
    line.clear();
    const LineCounts n = draw(frame, sl.segments, formats, path, phong, divider, line, y, observe, later);
    stats_.fragments += n.fragments;
    stats_.visible += n.visible;
    if (observe.fragments_end) observe.fragments_end(y);
    // The image starts as background, uncovered: only the line's covered pixels are copied.
    const std::size_t row = std::size_t(y) * frame.width;
    // Two loops, the test of the mode outside them.
    auto copy_out = [&](auto shade) {
      for (const int x : line.written()) {
        const std::array<std::uint8_t, 3> p = shade(x);
        std::uint8_t* out = &img.rgb[(row + x) * 3];
        out[0] = p[0], out[1] = p[1], out[2] = p[2];  // byte stores: no library call per pixel
        img.covered[row + x] = 1;
        img.owner[row + x] = line.written_poly(x);
      }
    };
    if (deferred)
      copy_out([&](int x) {
        const std::array<int, 3> rgb =
            phong.shade(later.normal[static_cast<std::size_t>(x)], later.material[static_cast<std::size_t>(x)]);
        return std::array<std::uint8_t, 3>{static_cast<std::uint8_t>(rgb[0]), static_cast<std::uint8_t>(rgb[1]),
                                           static_cast<std::uint8_t>(rgb[2])};
      });
    else
      copy_out([&](int x) { return line.written_rgb(x); });
  });
  // The smoother after the line buffer, when the frame enables it (it sees the full raster).
  if (frame.smoothed()) img = Smoother(frame.smooth_w).apply(img);
}

}  // namespace watkins
