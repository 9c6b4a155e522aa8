// The frame driver's source (frame_driver.hpp): the edge records of every frame of a run, each
// frame ended by its end-of-frame beat, with seeded input gaps; and the frame pins (size,
// background, output mode, equal-depth rule, Phong light, eye and material table), changed only when the previous
// frames have drained. A source holds valid and data until the transfer (valid/ready as in
// AXI-Stream); between beats edge_i carries a poison word the RTL must ignore.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "edge_packing.hpp"
#include "prepare.hpp"
#include "rng.hpp"
#include "rtl_bench.hpp"
#include "top_pins.hpp"

namespace watkins::tb::detail {

// Frame f of a run in sparse output mode (RtlOptions::sparse_frames, else RtlOptions::sparse).
bool sparse_frame(const RtlOptions& opt, int f);

// What the top samples or holds per frame: changing any of it waits for the previous frames'
// last pixel (the material table is written between frames).
struct FrameConfig {
  std::uint32_t width = 0, height = 0, background = 0;
  bool sparse = false;
  bool tie_submission = false;  // the frame's depth_tie is Submission
  std::uint32_t smooth_w = 0;   // the frame's smoothing weight (smooth_w_i)
  bool eq2 = false;             // Gouraud's eq. (2) (eq2_i)
  std::uint64_t light = 0, eye = 0;
  std::vector<QuantizedMaterial> materials;
  bool operator==(const FrameConfig& o) const;
};

class EdgeSource {
 public:
  // Packs every record first, so that a bad one throws before the simulation starts. The records
  // take the layout of the configuration and shading the frames were prepared for (one for all).
  EdgeSource(TopPins& pins, const std::vector<const PreparedScene*>& scenes, const RtlOptions& opt);

  const EdgeLayout& layout() const { return layout_; }
  const EdgeWords& poison() const { return poison_; }
  void idle() { pins_.edge_pins(false, false, poison_); }  // edge_valid_i low
  // Sets the source's pins for the next cycle (`cycle` counted from the run's start): a frame's
  // configuration, a material table write, or the next beat (unless a gap is drawn).
  // `frames_done`: frames whose last pixel has been taken; frames[f].first_edge_cycle is set
  // when frame f's first beat is offered.
  void drive(long long cycle, int frames_done, std::vector<RtlFrame>& frames);
  bool presenting() const { return presenting_; }
  void taken();  // the beat on the pins was transferred on this rising edge

  int frame() const { return frame_; }  // the frame of the next beat (== scene count when done)
  bool done() const { return frame_ >= frames(); }
  // The beat waiting for edge_ready_o: "frame F edge K (y0, n, poly) of N beats".
  std::string waiting_beat() const;

 private:
  int frames() const { return static_cast<int>(scenes_.size()); }
  FrameConfig needs(int f) const;

  TopPins& pins_;
  const std::vector<const PreparedScene*>& scenes_;
  const RtlOptions& opt_;
  EdgeLayout layout_;
  std::vector<std::vector<EdgeWords>> beats_;  // per frame, the packed records
  EdgeWords poison_{};
  Rng gap_rng_;
  std::uint64_t gap_threshold_;
  int frame_ = 0;
  std::size_t beat_ = 0;   // beats_[frame_].size(): the end-of-frame beat
  bool presenting_ = false;
  bool configured_ = false;  // the frame pins hold config_
  FrameConfig config_;
  std::size_t loading_ = 0;  // > 0: material table writes left before the frame may start
};

}  // namespace watkins::tb::detail
