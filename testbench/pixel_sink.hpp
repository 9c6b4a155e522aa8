// The frame driver's sink (frame_driver.hpp): pixel_ready_i with seeded stalls and all-stall
// bursts; every pixel (dense frames, raster order) or beat (sparse frames, covered pixels with
// their (x, y)) assembled into RtlResult::frames and checked against the model's image or
// sparse stream; the pixel-stream protocol (a stalled pixel held unchanged, pixel_x_o/pixel_y_o,
// pixel_last_o on the last pixel, no pixel after the last frame).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image.hpp"
#include "watkins_top.hpp"
#include "rng.hpp"
#include "rtl_bench.hpp"
#include "top_pins.hpp"

namespace watkins::tb::detail {

class PixelSink {
 public:
  static constexpr int DrainCycles = 32;  // cycles after the last pixel in which no pixel may appear

  // Fills r.frames (background images, output modes) for the frames of `scenes`; expected[f]
  // (when given and not null) is frame f's model image.
  PixelSink(const std::vector<const PreparedScene*>& scenes, const std::vector<const Image*>& expected,
            const RtlOptions& opt, RtlResult& r);

  bool next_ready(long long cycle);  // pixel_ready_i for cycle `cycle` (counted from the run's start)
  bool ready() const { return ready_; }
  // Every cycle, the outputs before the rising edge (`cycle` counted from the run's start).
  void watch(const PinsOut& o, long long cycle);
  // A transfer (pixel_valid_o && pixel_ready_i) on this rising edge.
  void take(const PinsOut& o, long long cycle);
  // True once the drain after the last frame's last pixel is over (counts one drain cycle).
  bool drained() { return drain_left_ >= 0 && drain_left_-- == 0; }

  int frame() const { return frame_; }  // frames whose last pixel was taken
  // "frame F has K of N pixels (next (x, y))", or empty after the last frame.
  std::string position() const;

 private:
  void dense(const PinsOut& o, long long cycle);
  bool sparse(const PinsOut& o, long long cycle);  // true on the frame's last beat
  void next_frame();
  void protocol(const std::string& what);
  template <class Text>
  void mismatch(RtlFrame& fr, const Text& text);

  RtlResult& r_;
  const std::vector<const Image*>& expected_;
  std::vector<std::vector<SparseBeat>> sparse_want_;  // sparse frames: the model's beats
  const RtlOptions& opt_;
  Rng stall_rng_;
  std::uint64_t stall_threshold_;
  int stall_burst_;
  int frame_ = 0;
  long long pixel_ = 0;  // pixels (sparse: beats) of frame_ taken
  bool ready_ = false;
  int burst_left_ = 0;
  bool held_ = false;  // a pixel was offered and not taken: it must stay, unchanged
  PinsOut held_out_;
  long long sparse_pos_ = -1;  // raster position of the previous sparse beat
  int drain_left_ = -1;
};

}  // namespace watkins::tb::detail
