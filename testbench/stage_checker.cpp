// The stage checker's comparisons and reports (stage_checker.hpp has the per-clock test).
#include "stage_checker.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>

#include "bit_field.hpp"
#include "formats.hpp"
#include "segment_interpolator.hpp"

namespace watkins::tb::detail {
namespace {

// The three NormalInBits components of a packed {Nz, Ny, Nx}, sign-extended.
std::array<i64, 3> unpack_normal(std::uint64_t w) {
  std::array<i64, 3> n{};
  for (int c = 0; c < 3; ++c) n[c] = wrap_signed(static_cast<i128>(w >> (c * fmt::NormalInBits)), fmt::NormalInBits);
  return n;
}

const char* channel_name(int c) {
  static const char* const names[] = {"x", "z", "r", "g", "b"};
  return c < 5 ? names[c] : "?";
}

std::string channels_text(const ChannelVector& v) {
  std::string s = "(";
  for (int c = 0; c < fmt::NumChannels; ++c)
    s += std::string(c ? " " : "") + channel_name(c) + " " + std::to_string(v[c]);
  return s + ")";
}

void channel_diffs(const std::string& prefix, const ChannelVector& a, const ChannelVector& b,
                          std::string& out) {
  for (int c = 0; c < fmt::NumChannels; ++c)
    if (a[c] != b[c]) out += (out.empty() ? "" : ", ") + prefix + channel_name(c);
}

void add(std::string& d, bool differs, const char* name) {
  if (differs) d += (d.empty() ? "" : ", ") + std::string(name);
}

}  // namespace

void StageChecker::begin(const StageTaps* taps, const std::vector<StageStreams>* streams, RtlResult* r,
                         long long start_cycle, const Config& config, ShadingMode shading) {
  taps_ = taps;
  channels_ = EdgeLayout::of(config, shading).channels;
  formats_ = config.channels(shading);
  streams_ = streams;
  r_ = r;
  start_ = start_cycle;
  on_ = taps && streams && !streams->empty();
  ae_ = sg_ = fr_ = sh_ = Cursor{};
}

// The next expected item of a stage (nullptr past the last frame) and its frame.
template <class Item>
const Item* StageChecker::next(Cursor& k, std::vector<Item> StageStreams::*stream) const {
  while (k.frame < static_cast<int>(streams_->size()) && k.i >= ((*streams_)[k.frame].*stream).size()) {
    ++k.frame;
    k.i = 0;
  }
  if (k.frame >= static_cast<int>(streams_->size())) return nullptr;
  return &((*streams_)[k.frame].*stream)[k.i];
}

std::string StageChecker::where(const char* stage, const char* item, const Cursor& k, int line, int index, bool eol,
                                long long c) const {
  return std::string(stage) + " output: frame " + std::to_string(k.frame) + " line " + std::to_string(line) + " " +
         (eol ? "end-of-line marker (after " + std::to_string(index) + " " + item + "s)"
              : std::string(item) + " " + std::to_string(index)) +
         " at cycle " + std::to_string(c - start_) + ": ";
}

void StageChecker::fail(Cursor& k, const char* stage, const std::string& what) {
  k.dead = true;
  r_->stage_mismatches.push_back(what);
  if (r_->first_mismatch.empty()) {
    r_->first_mismatch = what;
    r_->first_stage = stage;
  }
}

std::string StageChecker::past_end() const {
  return "model: nothing (its streams ended with frame " + std::to_string(streams_->size() - 1) + ")";
}

int StageChecker::width_of(const Cursor& k) const {
  return k.frame < static_cast<int>(streams_->size()) ? (*streams_)[k.frame].width : 0;
}

void StageChecker::edge(long long c) {
  ++r_->stage_items;
  const StageTaps& t = *taps_;
  const StageEdge* m = next(ae_, &StageStreams::edges);
  const bool eol = *t.ae_eol;
  if (m && m->eol == eol) {
    if (eol || (m->poly == t.ae_poly.as_int() && m->material == t.ae_material.as_int() &&
                m->value == channels(t.ae_value))) {
      ++ae_.i;
      return;
    }
  }
  const ChannelVector v = eol ? ChannelVector{} : channels(t.ae_value);
  auto text = [](int poly, int material, const ChannelVector& value) {
    return "poly " + std::to_string(poly) + " material " + std::to_string(material) + " " + channels_text(value);
  };
  const std::string rtl = eol ? "end of line" : text(t.ae_poly.as_int(), t.ae_material.as_int(), v);
  std::string what;
  if (!m) {
    what = "active_edge_list output: after the last frame at cycle " + std::to_string(c - start_) + ": RTL " +
           rtl + ", " + past_end();
  } else {
    what = where("active_edge_list", "edge", ae_, m->line, m->index, m->eol, c) + "RTL " + rtl + ", model " +
           (m->eol ? std::string("end of line") : text(m->poly, m->material, m->value));
    std::string d;
    if (!eol && !m->eol) {
      if (m->poly != t.ae_poly.as_int()) d = "poly";
      if (m->material != t.ae_material.as_int()) d += d.empty() ? "material" : ", material";
      channel_diffs("", v, m->value, d);
      what += " (differs in " + d + ")";
    }
    const i64 x = m->eol ? v[fmt::ChanX] : m->value[fmt::ChanX];
    const int px = std::clamp(static_cast<int>(x >> formats_.x_frac()), 0, std::max(0, width_of(ae_) - 1));
    what += (eol && m->eol) ? "" : "; affects line " + std::to_string(m->line) + " near pixel (" +
                                       std::to_string(px) + ", " + std::to_string(m->line) + ")";
  }
  fail(ae_, "active_edge_list", what);
}

void StageChecker::segment(long long c) {
  ++r_->stage_items;
  const StageTaps& t = *taps_;
  const StageSegment* m = next(sg_, &StageStreams::segments);
  const bool eol = *t.sg_eol;
  if (m && m->eol == eol) {
    if (eol || (m->poly == t.sg_poly.as_int() && m->material == t.sg_material.as_int() && m->e == channels(t.sg_e) &&
                m->f == channels(t.sg_f))) {
      ++sg_.i;
      return;
    }
  }
  Segment rs;
  if (!eol) rs = Segment{t.sg_poly.as_int(), t.sg_material.as_int(), channels(t.sg_e), channels(t.sg_f)};
  auto text = [](const Segment& s) {
    return "poly " + std::to_string(s.poly) + " material " + std::to_string(s.material) + " E" +
           channels_text(s.e) + " F" + channels_text(s.f);
  };
  const std::string rtl = eol ? "end of line" : text(rs);
  std::string what;
  if (!m) {
    what = "segment_former output: after the last frame at cycle " + std::to_string(c - start_) + ": RTL " + rtl +
           ", " + past_end();
  } else {
    const Segment ms{m->poly, m->material, m->e, m->f};
    what = where("segment_former", "segment", sg_, m->line, m->index, m->eol, c) + "RTL " + rtl + ", model " +
           (m->eol ? std::string("end of line") : text(ms));
    if (!eol && !m->eol) {
      std::string d;
      if (ms.poly != rs.poly) d = "poly";
      if (ms.material != rs.material) d += d.empty() ? "material" : ", material";
      channel_diffs("E.", rs.e, ms.e, d);
      channel_diffs("F.", rs.f, ms.f, d);
      what += " (differs in " + d + ")";
    }
    if (!(eol && m->eol)) {
      const SpanSetup span = SegmentInterpolator::setup(m->eol ? rs : ms, std::max(1, width_of(sg_)), formats_);
      what += span.x_end > span.x_start
                  ? "; affects pixels (" + std::to_string(span.x_start) + ".." + std::to_string(span.x_end - 1) +
                        ", " + std::to_string(m->line) + ")"
                  : "; an empty span on line " + std::to_string(m->line) + " (no pixel)";
    }
  }
  fail(sg_, "segment_former", what);
}

// Shared by the two fragment stages: `same` compares an RTL transfer with the model's item,
// `text` prints either, `diff` names the differing fields.
template <class Same, class Text, class Diff>
void StageChecker::fragment_stage(long long c, Cursor& k, std::vector<StageFragment> StageStreams::*stream,
                                  const char* stage, bool eol, int rtl_x, Same same, Text text, Diff diff) {
  ++r_->stage_items;
  const StageFragment* m = next(k, stream);
  if (m && m->eol == eol && (eol || same(*m))) {
    ++k.i;
    return;
  }
  const std::string rtl = eol ? "end of line" : text(nullptr);
  std::string what;
  if (!m) {
    what = std::string(stage) + " output: after the last frame at cycle " + std::to_string(c - start_) +
           ": RTL " + rtl + ", " + past_end();
  } else {
    what = where(stage, "fragment", k, m->line, m->index, m->eol, c) + "RTL " + rtl + ", model " +
           (m->eol ? std::string("end of line") : text(m));
    if (!eol && !m->eol) what += " (differs in " + diff(*m) + ")";
    if (!(eol && m->eol))
      what += "; pixel (" + std::to_string(m->eol ? rtl_x : m->x) + ", " + std::to_string(m->line) + ")";
  }
  fail(k, stage, what);
}

// segment_interpolator output: x, depth, material and the normal reading of the channels (lane 0;
// lane 1, x + 1 of a Gouraud-only beat, carries no normal).
void StageChecker::fragment(long long c, int lane) {
  const StageTaps& t = *taps_;
  const std::array<i64, 3> n = unpack_normal(*t.fr_normal);
  const int x = int(*t.fr_x) + lane;
  const std::uint32_t depth = static_cast<std::uint32_t>(lane ? *t.fr_depth1 : *t.fr_depth);
  const bool eol = lane ? false : bool(*t.fr_eol);
  auto text = [&](const StageFragment* m) {
    const std::array<i64, 3>& v = m ? m->normal : n;
    char b[160];
    if (lane && !m)
      std::snprintf(b, sizeof b, "x %d depth %u material %d (lane 1)", x, depth, t.fr_material.as_int());
    else
      std::snprintf(b, sizeof b, "x %d depth %u material %d normal (%lld, %lld, %lld)", m ? m->x : x,
                    m ? m->depth : depth, m ? m->material : t.fr_material.as_int(), static_cast<long long>(v[0]),
                    static_cast<long long>(v[1]), static_cast<long long>(v[2]));
    return std::string(b);
  };
  auto same = [&](const StageFragment& m) {
    return m.x == x && m.depth == depth && m.material == t.fr_material.as_int() && (lane || m.normal == n);
  };
  auto diff = [&](const StageFragment& m) {
    std::string d;
    add(d, m.x != x, "x");
    add(d, m.depth != depth, "depth");
    add(d, m.material != t.fr_material.as_int(), "material");
    add(d, !lane && m.normal != n, "normal");
    return d;
  };
  fragment_stage(c, fr_, &StageStreams::fragments, "segment_interpolator", eol, x, same, text, diff);
}

// shading output (what the depth test receives): x, depth, polygon id and the shade.
void StageChecker::shaded(long long c, int lane) {
  const StageTaps& t = *taps_;
  const int x = int(*t.sh_x) + lane;
  const std::uint32_t depth = static_cast<std::uint32_t>(lane ? *t.sh_depth1 : *t.sh_depth);
  const std::uint32_t sh_rgb = lane ? *t.sh_rgb1 : *t.sh_rgb;
  const bool eol = lane ? false : bool(*t.sh_eol);
  auto text = [&](const StageFragment* m) {
    const std::uint32_t rgb = m ? m->rgb : sh_rgb;
    char b[128];
    std::snprintf(b, sizeof b, "x %d depth %u poly %d rgb (%u, %u, %u)", m ? m->x : x, m ? m->depth : depth,
                  m ? m->poly : t.sh_poly.as_int(), (rgb >> 16) & 255u, (rgb >> 8) & 255u, rgb & 255u);
    return std::string(b);
  };
  auto same = [&](const StageFragment& m) {
    return m.x == x && m.depth == depth && m.poly == t.sh_poly.as_int() && m.rgb == sh_rgb;
  };
  auto diff = [&](const StageFragment& m) {
    std::string d;
    add(d, m.x != x, "x");
    add(d, m.depth != depth, "depth");
    add(d, m.poly != t.sh_poly.as_int(), "poly");
    add(d, m.rgb != sh_rgb, "rgb");
    return d;
  };
  fragment_stage(c, sh_, &StageStreams::shaded, "shading", eol, x, same, text, diff);
}

}  // namespace watkins::tb::detail
