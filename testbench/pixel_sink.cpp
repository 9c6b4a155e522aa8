// The frame driver's sink: stalls, pixel assembly and the pixel check (pixel_sink.hpp).
#include "pixel_sink.hpp"

#include <cstdio>

#include "edge_source.hpp"

namespace watkins::tb::detail {
namespace {

std::string rgb_text(std::uint32_t rgb, bool covered) {
  char b[96];
  std::snprintf(b, sizeof b, "rgb (%u, %u, %u) %s", (rgb >> 16) & 255u, (rgb >> 8) & 255u, rgb & 255u,
                covered ? "covered" : "background");
  return b;
}

void put_pixel(Image& img, int x, int y, std::uint32_t rgb) {
  std::uint8_t* px = img.at(x, y);
  px[0] = static_cast<std::uint8_t>(rgb >> 16);
  px[1] = static_cast<std::uint8_t>(rgb >> 8);
  px[2] = static_cast<std::uint8_t>(rgb);
}

}  // namespace

PixelSink::PixelSink(const std::vector<const PreparedScene*>& scenes, const std::vector<const Image*>& expected,
                     const RtlOptions& opt, RtlResult& r)
    : r_(r), expected_(expected), sparse_want_(scenes.size()), opt_(opt), stall_rng_(opt.seed * 2 + 2),
      stall_threshold_(Rng::threshold(opt.stall)), stall_burst_(opt.stall_burst) {
  r.frames.assign(scenes.size(), RtlFrame{});
  for (std::size_t f = 0; f < scenes.size(); ++f) {
    const PreparedScene& s = *scenes[f];
    RtlFrame& fr = r.frames[f];
    fr.image = Image(s.width, s.height);
    for (std::size_t i = 0; i < fr.image.rgb.size(); i += 3)
      for (int c = 0; c < 3; ++c) fr.image.rgb[i + c] = s.background[c];
    // A smoothed frame is emitted in full whatever sparse_i says (rtl/watkins_top.sv).
    fr.sparse = sparse_frame(opt, static_cast<int>(f)) && s.smooth_w == 0;
    if (fr.sparse && f < expected.size() && expected[f]) {
      sparse_want_[f] = sparse_stream(*expected[f]);
      fr.expected_beats = static_cast<long long>(sparse_want_[f].size());
    }
  }
}

bool PixelSink::next_ready(long long cycle) {
  if (drain_left_ >= 0) {
    ready_ = true;
  } else if (opt_.pixel_ready) {
    const long long first = r_.frames[std::size_t(frame_)].first_edge_cycle;
    ready_ = first < 0 || opt_.pixel_ready(cycle - first, pixel_);
  } else if (burst_left_ > 0) {
    ready_ = false;
    --burst_left_;
  } else if (stall_rng_.chance(stall_threshold_)) {
    ready_ = false;
    burst_left_ = stall_burst_ > 1 ? stall_rng_.below(stall_burst_) : 0;
  } else {
    ready_ = true;
  }
  return ready_;
}

void PixelSink::protocol(const std::string& what) {
  if (r_.protocol_error.empty()) r_.protocol_error = what;
}

// The one record of a mismatching pixel or beat: counted in the frame and the run; the first
// one's text (built only then) becomes first_pixel_mismatch, and first_mismatch when no stage
// diverged before.
template <class Text>
void PixelSink::mismatch(RtlFrame& fr, const Text& text) {
  ++fr.mismatches;
  ++r_.mismatches;
  if (!r_.first_pixel_mismatch.empty()) return;
  r_.first_pixel_mismatch = text();
  if (r_.first_mismatch.empty()) {
    r_.first_mismatch = r_.first_pixel_mismatch;
    r_.first_stage = "pixel output";
  }
}

void PixelSink::watch(const PinsOut& o, long long cycle) {
  if (held_) {
    if (!o.pixel_valid)
      protocol("pixel output: pixel_valid_o dropped at cycle " + std::to_string(cycle) + " without a transfer");
    else if (o.pixel_rgb != held_out_.pixel_rgb || o.pixel_covered != held_out_.pixel_covered ||
             o.pixel_last != held_out_.pixel_last || o.pixel_x != held_out_.pixel_x ||
             o.pixel_y != held_out_.pixel_y)
      protocol("pixel output: pixel changed at cycle " + std::to_string(cycle) + " while stalled by pixel_ready_i");
  }
  held_ = o.pixel_valid && !ready_;
  held_out_ = o;
}

void PixelSink::take(const PinsOut& o, long long cycle) {
  if (frame_ >= static_cast<int>(r_.frames.size())) {
    protocol("pixel output: pixel after the last pixel of the last frame, at cycle " + std::to_string(cycle));
  } else if (r_.frames[frame_].sparse) {
    if (sparse(o, cycle)) next_frame();
    else ++pixel_;
  } else {
    dense(o, cycle);
  }
}

void PixelSink::next_frame() {
  ++frame_;
  pixel_ = 0;
  if (frame_ == static_cast<int>(r_.frames.size())) drain_left_ = DrainCycles;
}

void PixelSink::dense(const PinsOut& o, long long cycle) {
  RtlFrame& fr = r_.frames[frame_];
  const int w = fr.image.width, h = fr.image.height;
  const int x = static_cast<int>(pixel_ % w), y = static_cast<int>(pixel_ / w);
  auto at = [&] {  // built only for a report
    return "frame " + std::to_string(frame_) + " pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
  };
  if (o.pixel_x != std::uint32_t(x) || o.pixel_y != std::uint32_t(y))
    protocol("pixel output: pixel_x_o/pixel_y_o (" + std::to_string(o.pixel_x) + ", " + std::to_string(o.pixel_y) +
             ") on " + at());
  put_pixel(fr.image, x, y, o.pixel_rgb);
  fr.image.covered[std::size_t(pixel_)] = o.pixel_covered;
  ++fr.pixels;
  ++r_.pixels;
  const Image* want = frame_ < static_cast<int>(expected_.size()) ? expected_[frame_] : nullptr;
  if (fr.first_edge_cycle >= 0) fr.take_cycles.push_back(cycle - fr.first_edge_cycle);
  if (want) {
    const std::uint8_t* m = want->at(x, y);
    const std::uint32_t mrgb = pack_rgb({m[0], m[1], m[2]});
    const bool mcov = want->is_covered(x, y);
    if (mrgb != o.pixel_rgb || mcov != o.pixel_covered)
      mismatch(fr, [&] {
        return "pixel output: " + at() + " at cycle " + std::to_string(cycle) + ": RTL " +
               rgb_text(o.pixel_rgb, o.pixel_covered) + ", model " + rgb_text(mrgb, mcov);
      });
  }
  const bool last = pixel_ == static_cast<long long>(w) * h - 1;
  if (o.pixel_last != last)
    protocol("pixel output: pixel_last_o " + std::string(o.pixel_last ? "high" : "low") + " at " + at() + " of a " +
             std::to_string(w) + "x" + std::to_string(h) + " frame");
  if (last) {
    fr.complete = o.pixel_last;
    fr.last_pixel_cycle = cycle;
    next_frame();
  } else {
    ++pixel_;
  }
}

// One beat of a sparse frame: assembled into the frame's image and checked against the model's
// sparse stream (its beat pixel_, when the model was rendered).
bool PixelSink::sparse(const PinsOut& o, long long cycle) {
  RtlFrame& fr = r_.frames[frame_];
  const std::vector<SparseBeat>& want = sparse_want_[frame_];
  const long long k = pixel_;
  const int w = fr.image.width, h = fr.image.height;
  const std::string at = "frame " + std::to_string(frame_) + " beat " + std::to_string(k) + " pixel (" +
                         std::to_string(o.pixel_x) + ", " + std::to_string(o.pixel_y) + ") at cycle " +
                         std::to_string(cycle);
  ++fr.pixels;
  ++r_.pixels;
  if (fr.first_edge_cycle >= 0) fr.take_cycles.push_back(cycle - fr.first_edge_cycle);
  const bool inside = o.pixel_x < std::uint32_t(w) && o.pixel_y < std::uint32_t(h);
  const long long pos = inside ? static_cast<long long>(o.pixel_y) * w + o.pixel_x : -1;
  if (!inside)
    protocol("pixel output: sparse " + at + " outside the " + std::to_string(w) + "x" + std::to_string(h) + " frame");
  else if (pos <= sparse_pos_ && k > 0)
    protocol("pixel output: sparse " + at + " not after the previous beat in raster order");
  sparse_pos_ = pos;
  if (inside && o.pixel_covered) {
    put_pixel(fr.image, o.pixel_x, o.pixel_y, o.pixel_rgb);
    fr.image.covered[std::size_t(pos)] = 1;
  }
  if (!o.pixel_covered && !o.pixel_last)
    protocol("pixel output: sparse " + at + " not covered and not the frame's last beat");
  const bool have_model = fr.expected_beats >= 0;
  if (have_model) {
    const bool beyond = k >= static_cast<long long>(want.size());
    const SparseBeat m = beyond ? SparseBeat{} : want[std::size_t(k)];
    const std::uint32_t mrgb = pack_rgb(m.rgb);
    const bool same = !beyond && o.pixel_x == std::uint32_t(m.x) && o.pixel_y == std::uint32_t(m.y) &&
                      o.pixel_rgb == mrgb && o.pixel_covered == m.covered && o.pixel_last == m.last;
    if (!same)
      mismatch(fr, [&] {
        return "pixel output: sparse " + at + ": RTL " + rgb_text(o.pixel_rgb, o.pixel_covered) +
               (o.pixel_last ? " last" : "") + ", model " +
               (beyond ? std::string("no beat (its stream has ") + std::to_string(want.size()) + " beats)"
                       : "pixel (" + std::to_string(m.x) + ", " + std::to_string(m.y) + ") " +
                             rgb_text(mrgb, m.covered) + (m.last ? " last" : ""));
      });
  }
  if (!o.pixel_last) return false;
  fr.complete = !have_model || k + 1 == fr.expected_beats;
  fr.last_pixel_cycle = cycle;
  if (have_model && k + 1 < fr.expected_beats)  // beats the RTL never sent
    mismatch(fr, [&] {
      const SparseBeat& m = want[std::size_t(k + 1)];
      return "pixel output: sparse frame " + std::to_string(frame_) + " ended after " + std::to_string(k + 1) +
             " beats at cycle " + std::to_string(cycle) + "; model beat " + std::to_string(k + 1) + " pixel (" +
             std::to_string(m.x) + ", " + std::to_string(m.y) + ") " + rgb_text(pack_rgb(m.rgb), m.covered) +
             " missing";
    });
  return true;
}

std::string PixelSink::position() const {
  if (frame_ >= static_cast<int>(r_.frames.size())) return "";
  const Image& img = r_.frames[frame_].image;
  return "frame " + std::to_string(frame_) + " has " + std::to_string(pixel_) + " of " +
         std::to_string(static_cast<long long>(img.width) * img.height) + " pixels (next (" +
         std::to_string(pixel_ % img.width) + ", " + std::to_string(pixel_ / img.width) + "))";
}

}  // namespace watkins::tb::detail
