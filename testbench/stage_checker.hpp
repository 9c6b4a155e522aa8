// Per-stage checking for the bench (frame_driver.hpp): the three internal valid/ready streams of
// watkins_top (active_edge_list -> segment_former -> segment_interpolator ->
// scanline_buffer), read from the Verilated model's public signals (the /*verilator
// public_flat_rd*/ ae_*, sg_*, fr_* of rtl/watkins_top.sv), are compared transfer by
// transfer with the model's stage streams (Pipeline's PipelineObserver). The first
// difference names its stage, line and item, both values, and the pixels it affects; the pixel
// check stays the last one.
//
// Cost: three valid && ready tests per clock through pointers into the model, and a comparison
// per transfer against a precomputed stream (the model is rendered once per frame before the run).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "formats.hpp"
#include "pipeline.hpp"
#include "rtl_bench.hpp"
#include "segment_interpolator.hpp"

namespace watkins::tb::detail {

// Pointers to the internal stage signals of the Verilated top (valid/ready/eol are CData, the
// channel vectors VlWide<7> words, channel c at bits [c*ChannelBits +: ChannelBits]).
struct StageTaps {
  const std::uint8_t *ae_valid = nullptr, *ae_ready = nullptr, *ae_eol = nullptr;
  const std::uint16_t* ae_poly = nullptr;
  const std::uint32_t* ae_value = nullptr;
  const std::uint8_t *sg_valid = nullptr, *sg_ready = nullptr, *sg_eol = nullptr;
  const std::uint16_t* sg_poly = nullptr;
  const std::uint32_t *sg_e = nullptr, *sg_f = nullptr;
  const std::uint8_t *fr_valid = nullptr, *fr_ready = nullptr, *fr_eol = nullptr;
  const std::uint16_t* fr_x = nullptr;
  const std::uint32_t *fr_depth = nullptr, *fr_rgb = nullptr;
};

// `root` is the Verilated model's root (model.rootp, Vwatkins_top___024root).
template <class Root>
StageTaps stage_taps(const Root& root) {
  StageTaps t;
  t.ae_valid = &root.watkins_top__DOT__ae_valid;
  t.ae_ready = &root.watkins_top__DOT__ae_ready;
  t.ae_eol = &root.watkins_top__DOT__ae_eol;
  t.ae_poly = &root.watkins_top__DOT__ae_poly;
  t.ae_value = root.watkins_top__DOT__ae_value.data();
  t.sg_valid = &root.watkins_top__DOT__sg_valid;
  t.sg_ready = &root.watkins_top__DOT__sg_ready;
  t.sg_eol = &root.watkins_top__DOT__sg_eol;
  t.sg_poly = &root.watkins_top__DOT__sg_poly;
  t.sg_e = root.watkins_top__DOT__sg_e.data();
  t.sg_f = root.watkins_top__DOT__sg_f.data();
  t.fr_valid = &root.watkins_top__DOT__fr_valid;
  t.fr_ready = &root.watkins_top__DOT__fr_ready;
  t.fr_eol = &root.watkins_top__DOT__fr_eol;
  t.fr_x = &root.watkins_top__DOT__fr_x;
  t.fr_depth = &root.watkins_top__DOT__fr_depth;
  t.fr_rgb = &root.watkins_top__DOT__fr_rgb;
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
    s.edges.push_back(StageEdge{y, ke++, false, e.rec.poly, e.rec.value});
  };
  o.active_edges_end = [&](int y) {
    s.edges.push_back(StageEdge{y, ke, true, 0, {}});
    ke = 0;
  };
  o.segment = [&](int y, const Segment& g) { s.segments.push_back(StageSegment{y, ks++, false, g.poly, g.e, g.f}); };
  o.segments_end = [&](int y) {
    s.segments.push_back(StageSegment{y, ks, true, 0, {}, {}});
    ks = 0;
  };
  o.fragment = [&](int y, const Fragment& f, bool) {
    const std::uint32_t rgb = (std::uint32_t(f.rgb[0]) << 16) | (std::uint32_t(f.rgb[1]) << 8) | f.rgb[2];
    s.fragments.push_back(StageFragment{y, kf++, false, f.x, f.depth, rgb});
  };
  o.fragments_end = [&](int y) {
    s.fragments.push_back(StageFragment{y, kf, true, 0, 0, 0});
    kf = 0;
  };
  Pipeline pipe(fmt::MaxActiveEdges);
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
    ae_ = sg_ = fr_ = Cursor{};
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
      if (eol || (m->poly == *t.ae_poly && m->value == unpack_channels(t.ae_value))) {
        ++ae_.i;
        return;
      }
    }
    const ChannelVector v = eol ? ChannelVector{} : unpack_channels(t.ae_value);
    const std::string rtl = eol ? "end of line" : "poly " + std::to_string(*t.ae_poly) + " " + channels_text(v);
    std::string what;
    if (!m) {
      what = "active_edge_list output: after the last frame at cycle " + std::to_string(c - start_) + ": RTL " +
             rtl + ", " + past_end();
    } else {
      what = where("active_edge_list", "edge", ae_, m->line, m->index, m->eol, c) + "RTL " + rtl + ", model " +
             (m->eol ? std::string("end of line") : "poly " + std::to_string(m->poly) + " " + channels_text(m->value));
      std::string d;
      if (!eol && !m->eol) {
        if (m->poly != *t.ae_poly) d = "poly";
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
      if (eol || (m->poly == *t.sg_poly && m->e == unpack_channels(t.sg_e) && m->f == unpack_channels(t.sg_f))) {
        ++sg_.i;
        return;
      }
    }
    Segment rs;
    if (!eol) rs = Segment{*t.sg_poly, unpack_channels(t.sg_e), unpack_channels(t.sg_f)};
    auto text = [](const Segment& s) {
      return "poly " + std::to_string(s.poly) + " E" + channels_text(s.e) + " F" + channels_text(s.f);
    };
    const std::string rtl = eol ? "end of line" : text(rs);
    std::string what;
    if (!m) {
      what = "segment_former output: after the last frame at cycle " + std::to_string(c - start_) + ": RTL " + rtl +
             ", " + past_end();
    } else {
      const Segment ms{m->poly, m->e, m->f};
      what = where("segment_former", "segment", sg_, m->line, m->index, m->eol, c) + "RTL " + rtl + ", model " +
             (m->eol ? std::string("end of line") : text(ms));
      if (!eol && !m->eol) {
        std::string d;
        if (ms.poly != rs.poly) d = "poly";
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

  void fragment(long long c) {
    ++r_->stage_items;
    const StageTaps& t = *taps_;
    const StageFragment* m = next(fr_, &StageStreams::fragments);
    const bool eol = *t.fr_eol;
    if (m && m->eol == eol) {
      if (eol || (m->x == *t.fr_x && m->depth == *t.fr_depth && m->rgb == *t.fr_rgb)) {
        ++fr_.i;
        return;
      }
    }
    auto text = [](int x, std::uint32_t depth, std::uint32_t rgb) {
      char b[96];
      std::snprintf(b, sizeof b, "x %d depth %u rgb (%u, %u, %u)", x, depth, (rgb >> 16) & 255u, (rgb >> 8) & 255u,
                    rgb & 255u);
      return std::string(b);
    };
    const std::string rtl = eol ? "end of line" : text(*t.fr_x, *t.fr_depth, *t.fr_rgb);
    std::string what;
    if (!m) {
      what = "segment_interpolator output: after the last frame at cycle " + std::to_string(c - start_) +
             ": RTL " + rtl + ", " + past_end();
    } else {
      what = where("segment_interpolator", "fragment", fr_, m->line, m->index, m->eol, c) + "RTL " + rtl +
             ", model " + (m->eol ? std::string("end of line") : text(m->x, m->depth, m->rgb));
      if (!eol && !m->eol) {
        std::string d;
        if (m->x != *t.fr_x) d = "x";
        if (m->depth != *t.fr_depth) d += d.empty() ? "depth" : ", depth";
        if (m->rgb != *t.fr_rgb) d += d.empty() ? "rgb" : ", rgb";
        what += " (differs in " + d + ")";
      }
      if (!(eol && m->eol))
        what += "; pixel (" + std::to_string(m->eol ? int(*t.fr_x) : m->x) + ", " + std::to_string(m->line) + ")";
    }
    fail(fr_, "segment_interpolator", what);
  }

  const StageTaps* taps_ = nullptr;
  const std::vector<StageStreams>* streams_ = nullptr;
  RtlResult* r_ = nullptr;
  long long start_ = 0;
  bool on_ = false;
  Cursor ae_, sg_, fr_;
};

}  // namespace watkins::tb::detail
