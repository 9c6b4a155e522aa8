// Co-simulation of the Verilated watkins_gouraud_top against the bit-exact model.
//
// run_rtl() streams a prepared scene's edge records into the RTL (seeded random input gaps),
// collects the pixel stream (seeded random back-pressure), checks it pixel by pixel against the
// model image, watches for hangs and protocol errors, and counts cycles. The bench is built once
// per process on first use (SystemC elaborates only once) and runs frames one after another;
// frames within one run_rtl_frames() call follow each other back to back.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image.hpp"
#include "prepare.hpp"

namespace watkins::tb {

struct RtlOptions {
  std::uint64_t seed = 1;
  double gap = 0.0;        // probability that the edge source idles a cycle before presenting a beat
  double stall = 0.0;      // probability that the pixel sink starts a stall (pixel_ready_i low)
  int stall_burst = 1;     // stalls last 1..stall_burst cycles (> 1: all-stall bursts)
  std::string trace_path;  // FST waveform of the whole run when not empty
  long long watchdog = 100000;  // cycles without any handshake before the run counts as hung
  bool compare = true;     // render the model (unless given the expected images) and compare
  bool reset = false;      // reset before the run (always done first and after a failed run)
};

struct RtlFrame {
  Image image;                     // as the RTL produced it (background where pixels are missing)
  long long pixels = 0;            // pixels received
  long long first_edge_cycle = -1; // cycle the frame's first beat is offered (edge_valid_i rises:
                                   // the RTL starts the frame then and may emit empty lines early)
  long long last_pixel_cycle = -1; // cycle of its last pixel
  long long cycles() const {       // frame cycles: first edge beat offered to last pixel, inclusive
    return last_pixel_cycle < 0 || first_edge_cycle < 0 ? 0 : last_pixel_cycle - first_edge_cycle + 1;
  }
  long long mismatches = 0;        // pixels whose RGB or coverage differ from the model
  bool complete = false;           // all width*height pixels arrived, pixel_last_o on the last
};

struct RtlResult {
  std::vector<RtlFrame> frames;
  long long cycles = 0;         // first beat offered of the first frame to last pixel of the last frame
  long long sim_cycles = 0;     // every clock of the run, including reset and drain
  long long pixels = 0;
  long long mismatches = 0;
  std::string first_mismatch;   // "pixel output: frame 0 pixel (x, y): RTL ... model ..." or empty
  bool hang = false;            // the watchdog fired
  std::string hang_reason;      // names the stuck interface
  bool overflow = false;        // overflow_o was seen high
  long long overflow_cycle = -1;
  std::string protocol_error;   // first valid/ready or pixel_last_o violation, or empty
  std::string assertion;        // an RTL assertion (or $stop/$finish) ended the run, or empty
  std::string model_error;      // the model could not render the scene (so nothing was compared)
  double wall_seconds = 0;      // simulation wall time of the run
  double cycles_per_second() const { return wall_seconds > 0 ? sim_cycles / wall_seconds : 0; }
  bool ok() const {             // every frame complete, no mismatch, hang, protocol error, assertion
    bool all = !frames.empty();
    for (const RtlFrame& f : frames) all = all && f.complete;
    return all && mismatches == 0 && !hang && protocol_error.empty() && assertion.empty();
  }
  std::string summary() const {  // one line per problem (empty when ok())
    std::string s;
    auto line = [&](const std::string& t) { s += (s.empty() ? "" : "\n") + t; };
    for (std::size_t f = 0; f < frames.size(); ++f)
      if (!frames[f].complete)
        line("frame " + std::to_string(f) + " incomplete: " + std::to_string(frames[f].pixels) + " of " +
             std::to_string(static_cast<long long>(frames[f].image.width) * frames[f].image.height) + " pixels");
    if (mismatches) line(std::to_string(mismatches) + " mismatching pixels; first: " + first_mismatch);
    if (hang) line("hang: " + hang_reason);
    if (!protocol_error.empty()) line("protocol: " + protocol_error);
    if (!assertion.empty()) line("assertion: " + assertion);
    return s;
  }
};

// Which harness this library drives ("SystemC bench (...)" or "plain C++ harness (...)").
std::string rtl_description();
// Width of the RTL's line buffer (the top's MaxWidth): wider scenes are refused.
int rtl_max_width();

// Runs one frame. `expected` (the model image) is rendered here when null and opt.compare is set.
RtlResult run_rtl(const PreparedScene& scene, const RtlOptions& opt = {}, const Image* expected = nullptr);

// Runs frames back to back in one simulation: the next frame's edges follow the previous frame's
// end-of-frame beat at once when screen size and background are the same; otherwise the source
// waits for the previous frame's last pixel before changing width_i/height_i/background_i.
RtlResult run_rtl_frames(const std::vector<const PreparedScene*>& scenes, const RtlOptions& opt = {},
                         const std::vector<const Image*>& expected = {});

}  // namespace watkins::tb
