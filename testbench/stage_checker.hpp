// Per-stage checking for the bench (frame_driver.hpp): the four internal valid/ready streams of
// watkins_top (active_edge_list -> segment_former -> segment_interpolator -> shading
// (Phong: normalizer + phong_shader; Gouraud: a wire) -> scanline_buffer), read from the
// Verilated model's public signals (the /*verilator public_flat_rd*/ ae_*, sg_*, fr_*, sh_* of
// rtl/watkins_top.sv), are compared transfer by
// transfer with the model's stage streams (WatkinsTop's PipelineObserver). The first
// difference names its stage, line and item, both values, and the pixels it affects; the pixel
// check stays the last one.
//
// Cost: four valid && ready tests per clock through pointers into the model, and a comparison
// per transfer against a precomputed stream (the model is rendered once per frame before the run).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "formats.hpp"
#include "watkins_top.hpp"
#include "rtl_bench.hpp"
#include "segment_interpolator.hpp"

namespace watkins::tb::detail {

// Pointers to the internal stage signals of the Verilated top (valid/ready/eol are CData, the
// channel vectors VlWide<7> words, channel c at bits [c*ChannelBits +: ChannelBits]).
struct StageTaps {
  const std::uint8_t *ae_valid = nullptr, *ae_ready = nullptr, *ae_eol = nullptr;
  const std::uint16_t* ae_poly = nullptr;
  const std::uint8_t* ae_material = nullptr;
  const std::uint32_t* ae_value = nullptr;
  const std::uint8_t *sg_valid = nullptr, *sg_ready = nullptr, *sg_eol = nullptr;
  const std::uint16_t* sg_poly = nullptr;
  const std::uint8_t* sg_material = nullptr;
  const std::uint32_t *sg_e = nullptr, *sg_f = nullptr;
  const std::uint8_t *fr_valid = nullptr, *fr_ready = nullptr, *fr_eol = nullptr;
  const std::uint16_t* fr_x = nullptr;
  const std::uint8_t* fr_material = nullptr;
  const std::uint32_t* fr_depth = nullptr;
  const std::uint64_t* fr_normal = nullptr;  // {Nz, Ny, Nx}, NormalInBits each (54 bits)
  const std::uint8_t *sh_valid = nullptr, *sh_ready = nullptr, *sh_eol = nullptr;
  const std::uint16_t* sh_x = nullptr;
  const std::uint32_t *sh_depth = nullptr, *sh_rgb = nullptr;
};

// `root` is the Verilated model's root (model.rootp, Vwatkins_top___024root).
template <class Root>
StageTaps stage_taps(const Root& root) {
  StageTaps t;
  t.ae_valid = &root.watkins_top__DOT__ae_valid;
  t.ae_ready = &root.watkins_top__DOT__ae_ready;
  t.ae_eol = &root.watkins_top__DOT__ae_eol;
  t.ae_poly = &root.watkins_top__DOT__ae_poly;
  t.ae_material = &root.watkins_top__DOT__ae_material;
  t.ae_value = root.watkins_top__DOT__ae_value.data();
  t.sg_valid = &root.watkins_top__DOT__sg_valid;
  t.sg_ready = &root.watkins_top__DOT__sg_ready;
  t.sg_eol = &root.watkins_top__DOT__sg_eol;
  t.sg_poly = &root.watkins_top__DOT__sg_poly;
  t.sg_material = &root.watkins_top__DOT__sg_material;
  t.sg_e = root.watkins_top__DOT__sg_e.data();
  t.sg_f = root.watkins_top__DOT__sg_f.data();
  t.fr_valid = &root.watkins_top__DOT__fr_valid;
  t.fr_ready = &root.watkins_top__DOT__fr_ready;
  t.fr_eol = &root.watkins_top__DOT__fr_eol;
  t.fr_x = &root.watkins_top__DOT__fr_x;
  t.fr_depth = &root.watkins_top__DOT__fr_depth;
  t.fr_material = &root.watkins_top__DOT__fr_material;
  t.fr_normal = &root.watkins_top__DOT__fr_normal;
  t.sh_valid = &root.watkins_top__DOT__sh_valid;
  t.sh_ready = &root.watkins_top__DOT__sh_ready;
  t.sh_eol = &root.watkins_top__DOT__sh_eol;
  t.sh_x = &root.watkins_top__DOT__sh_x;
  t.sh_depth = &root.watkins_top__DOT__sh_depth;
  t.sh_rgb = &root.watkins_top__DOT__sh_rgb;
  return t;
}

// Channel c of a packed NumChannels x ChannelBits vector, sign-extended.
inline i64 unpack_channel(const std::uint32_t* w, int c) {
  constexpr int Words = (fmt::NumChannels * fmt::ChannelBits + 31) / 32;
  const int lo = c * fmt::ChannelBits, wi = lo / 32;
  unsigned __int128 v = 0;
  for (int k = 0; k < 3 && wi + k < Words; ++k) v |= static_cast<unsigned __int128>(w[wi + k]) << (32 * k);
  const std::uint64_t bits = static_cast<std::uint64_t>(v >> (lo % 32)) & ((1ull << fmt::ChannelBits) - 1);
  return static_cast<i64>(bits << (64 - fmt::ChannelBits)) >> (64 - fmt::ChannelBits);
}

inline ChannelVector unpack_channels(const std::uint32_t* w) {
  ChannelVector v{};
  for (int c = 0; c < fmt::NumChannels; ++c) v[c] = unpack_channel(w, c);
  return v;
}

// The three NormalInBits components of a packed {Nz, Ny, Nx}, sign-extended.
inline std::array<i64, 3> unpack_normal(std::uint64_t w) {
  std::array<i64, 3> n{};
  constexpr int B = fmt::NormalInBits;
  for (int c = 0; c < 3; ++c)
    n[c] = static_cast<i64>((w >> (c * B)) << (64 - B)) >> (64 - B);
  return n;
}

inline const char* channel_name(int c) {
  static const char* const names[] = {"x", "z", "r", "g", "b"};
  return c < 5 ? names[c] : "?";
}

inline std::string channels_text(const ChannelVector& v) {
  std::string s = "(";
  for (int c = 0; c < fmt::NumChannels; ++c)
    s += std::string(c ? " " : "") + channel_name(c) + " " + std::to_string(v[c]);
  return s + ")";
}

inline void channel_diffs(const std::string& prefix, const ChannelVector& a, const ChannelVector& b,
                          std::string& out) {
  for (int c = 0; c < fmt::NumChannels; ++c)
    if (a[c] != b[c]) out += (out.empty() ? "" : ", ") + prefix + channel_name(c);
}

// The model's stage streams of one frame (and its image when `image` is given).
inline StageStreams model_stage_streams(const PreparedScene& scene, Image* image) {
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
    s.fragments.push_back(StageFragment{y, kf++, false, f.x, f.depth, f.material, f.normal, rgb});
    s.shaded.push_back(s.fragments.back());
  };
  o.fragments_end = [&](int y) {
    s.fragments.push_back(StageFragment{y, kf, true, 0, 0, 0, {}, 0});
    s.shaded.push_back(s.fragments.back());
    kf = 0;
  };
  WatkinsTop pipe(fmt::MaxActiveEdges);
  Image img = pipe.render(scene, o);
  if (image) *image = std::move(img);
  return s;
}

class StageChecker {
 public:
  // Starts a run: `streams` holds the expected streams of every frame of the run in order (the
  // checker is off when it is empty). Items are counted into r.stage_items, mismatches reported
  // into r.stage_mismatches / r.first_mismatch / r.first_stage.
  void begin(const StageTaps* taps, const std::vector<StageStreams>* streams, RtlResult* r, long long start_cycle) {
    taps_ = taps;
    streams_ = streams;
    r_ = r;
    start_ = start_cycle;
    on_ = taps && streams && !streams->empty();
    ae_ = sg_ = fr_ = sh_ = Cursor{};
  }
  void end() { on_ = false; }

  // Called once per clock after the inputs settled, before the rising edge: checks every stage
  // boundary whose valid && ready is high (a transfer on this edge).
  void clock(long long c) {
    if (!on_) return;
    const StageTaps& t = *taps_;
    if (*t.ae_valid && *t.ae_ready && !ae_.dead) edge(c);
    if (*t.sg_valid && *t.sg_ready && !sg_.dead) segment(c);
    if (*t.fr_valid && *t.fr_ready && !fr_.dead) fragment(c);
    if (*t.sh_valid && *t.sh_ready && !sh_.dead) shaded(c);
  }

 private:
  struct Cursor {
    int frame = 0;
    std::size_t i = 0;
    bool dead = false;
  };

  // The next expected item of a stage (nullptr past the last frame) and its frame.
  template <class Item>
  const Item* next(Cursor& k, std::vector<Item> StageStreams::*stream) const {
    while (k.frame < static_cast<int>(streams_->size()) && k.i >= ((*streams_)[k.frame].*stream).size()) {
      ++k.frame;
      k.i = 0;
    }
    if (k.frame >= static_cast<int>(streams_->size())) return nullptr;
    return &((*streams_)[k.frame].*stream)[k.i];
  }

  std::string where(const char* stage, const char* item, const Cursor& k, int line, int index, bool eol,
                    long long c) const {
    return std::string(stage) + " output: frame " + std::to_string(k.frame) + " line " + std::to_string(line) +
           " " + (eol ? "end-of-line marker (after " + std::to_string(index) + " " + item + "s)"
                      : std::string(item) + " " + std::to_string(index)) +
           " at cycle " + std::to_string(c - start_) + ": ";
  }

  void fail(Cursor& k, const char* stage, const std::string& what) {
    k.dead = true;
    r_->stage_mismatches.push_back(what);
    if (r_->first_mismatch.empty()) {
      r_->first_mismatch = what;
      r_->first_stage = stage;
    }
  }

  std::string past_end() const {
    return "model: nothing (its streams ended with frame " + std::to_string(streams_->size() - 1) + ")";
  }

  int width_of(const Cursor& k) const {
    return k.frame < static_cast<int>(streams_->size()) ? (*streams_)[k.frame].width : 0;
  }

  void edge(long long c) {
    ++r_->stage_items;
    const StageTaps& t = *taps_;
    const StageEdge* m = next(ae_, &StageStreams::edges);
    const bool eol = *t.ae_eol;
    if (m && m->eol == eol) {
      if (eol || (m->poly == *t.ae_poly && m->material == *t.ae_material &&
                  m->value == unpack_channels(t.ae_value))) {
        ++ae_.i;
        return;
      }
    }
    const ChannelVector v = eol ? ChannelVector{} : unpack_channels(t.ae_value);
    auto text = [](int poly, int material, const ChannelVector& value) {
      return "poly " + std::to_string(poly) + " material " + std::to_string(material) + " " + channels_text(value);
    };
    const std::string rtl = eol ? "end of line" : text(*t.ae_poly, *t.ae_material, v);
    std::string what;
    if (!m) {
      what = "active_edge_list output: after the last frame at cycle " + std::to_string(c - start_) + ": RTL " +
             rtl + ", " + past_end();
    } else {
      what = where("active_edge_list", "edge", ae_, m->line, m->index, m->eol, c) + "RTL " + rtl + ", model " +
             (m->eol ? std::string("end of line") : text(m->poly, m->material, m->value));
      std::string d;
      if (!eol && !m->eol) {
        if (m->poly != *t.ae_poly) d = "poly";
        if (m->material != *t.ae_material) d += d.empty() ? "material" : ", material";
        channel_diffs("", v, m->value, d);
        what += " (differs in " + d + ")";
      }
      const i64 x = m->eol ? v[fmt::ChanX] : m->value[fmt::ChanX];
      const int px = std::clamp(static_cast<int>(x >> fmt::FracBits), 0, std::max(0, width_of(ae_) - 1));
      what += (eol && m->eol) ? "" : "; affects line " + std::to_string(m->line) + " near pixel (" +
                                         std::to_string(px) + ", " + std::to_string(m->line) + ")";
    }
    fail(ae_, "active_edge_list", what);
  }

  void segment(long long c) {
    ++r_->stage_items;
    const StageTaps& t = *taps_;
    const StageSegment* m = next(sg_, &StageStreams::segments);
    const bool eol = *t.sg_eol;
    if (m && m->eol == eol) {
      if (eol || (m->poly == *t.sg_poly && m->material == *t.sg_material && m->e == unpack_channels(t.sg_e) &&
                  m->f == unpack_channels(t.sg_f))) {
        ++sg_.i;
        return;
      }
    }
    Segment rs;
    if (!eol) rs = Segment{*t.sg_poly, *t.sg_material, unpack_channels(t.sg_e), unpack_channels(t.sg_f)};
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
        const SpanSetup span = SegmentInterpolator::setup(m->eol ? rs : ms, std::max(1, width_of(sg_)));
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
  void fragment_stage(long long c, Cursor& k, std::vector<StageFragment> StageStreams::*stream, const char* stage,
                      bool eol, int rtl_x, Same same, Text text, Diff diff) {
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

  static void add(std::string& d, bool differs, const char* name) {
    if (differs) d += (d.empty() ? "" : ", ") + std::string(name);
  }

  // segment_interpolator output: x, depth, material and the normal reading of the channels.
  void fragment(long long c) {
    const StageTaps& t = *taps_;
    const std::array<i64, 3> n = unpack_normal(*t.fr_normal);
    auto text = [&](const StageFragment* m) {
      const std::array<i64, 3>& v = m ? m->normal : n;
      char b[160];
      std::snprintf(b, sizeof b, "x %d depth %u material %d normal (%lld, %lld, %lld)", m ? m->x : int(*t.fr_x),
                    m ? m->depth : *t.fr_depth, m ? m->material : int(*t.fr_material), static_cast<long long>(v[0]),
                    static_cast<long long>(v[1]), static_cast<long long>(v[2]));
      return std::string(b);
    };
    auto same = [&](const StageFragment& m) {
      return m.x == *t.fr_x && m.depth == *t.fr_depth && m.material == *t.fr_material && m.normal == n;
    };
    auto diff = [&](const StageFragment& m) {
      std::string d;
      add(d, m.x != *t.fr_x, "x");
      add(d, m.depth != *t.fr_depth, "depth");
      add(d, m.material != *t.fr_material, "material");
      add(d, m.normal != n, "normal");
      return d;
    };
    fragment_stage(c, fr_, &StageStreams::fragments, "segment_interpolator", *t.fr_eol, *t.fr_x, same, text, diff);
  }

  // shading output (what the depth test receives): x, depth and the shade.
  void shaded(long long c) {
    const StageTaps& t = *taps_;
    auto text = [&](const StageFragment* m) {
      const std::uint32_t rgb = m ? m->rgb : *t.sh_rgb;
      char b[96];
      std::snprintf(b, sizeof b, "x %d depth %u rgb (%u, %u, %u)", m ? m->x : int(*t.sh_x), m ? m->depth : *t.sh_depth,
                    (rgb >> 16) & 255u, (rgb >> 8) & 255u, rgb & 255u);
      return std::string(b);
    };
    auto same = [&](const StageFragment& m) {
      return m.x == *t.sh_x && m.depth == *t.sh_depth && m.rgb == *t.sh_rgb;
    };
    auto diff = [&](const StageFragment& m) {
      std::string d;
      add(d, m.x != *t.sh_x, "x");
      add(d, m.depth != *t.sh_depth, "depth");
      add(d, m.rgb != *t.sh_rgb, "rgb");
      return d;
    };
    fragment_stage(c, sh_, &StageStreams::shaded, "shading", *t.sh_eol, *t.sh_x, same, text, diff);
  }

  const StageTaps* taps_ = nullptr;
  const std::vector<StageStreams>* streams_ = nullptr;
  RtlResult* r_ = nullptr;
  long long start_ = 0;
  bool on_ = false;
  Cursor ae_, sg_, fr_, sh_;
};

}  // namespace watkins::tb::detail
