// Co-simulation of the Verilated watkins_top against the bit-exact model.
//
// run_rtl() streams a prepared scene's edge records into the RTL (seeded random input gaps),
// collects the pixel stream (seeded random back-pressure), checks it pixel by pixel against the
// model image, watches for hangs and protocol errors, and counts cycles. The bench is built once
// per process on first use (SystemC elaborates only once) and runs frames one after another;
// frames within one run_rtl_frames() call follow each other back to back. Each call starts with
// a reset (RtlOptions::reset), so its cycle counts and images are the same whatever ran before.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "edge_record.hpp"
#include "image.hpp"
#include "prepare.hpp"

namespace watkins::tb {

// The model's internal stage streams of one frame, item by item (WatkinsTop's
// PipelineObserver), as the bench expects them at the four internal stage boundaries of
// watkins_top. Per stage, the items of line y are followed by an end-of-line marker
// (eol, no payload), for y = 0 .. height-1. `index` numbers the items of a line from 0 (the
// marker gets the number of items before it).
struct StageEdge {      // active_edge_list -> segment_former (ae_*)
  int line = 0, index = 0;
  bool eol = false;
  int poly = 0;
  int material = 0;
  ChannelVector value{};
};
struct StageSegment {   // segment_former -> segment_interpolator (sg_*)
  int line = 0, index = 0;
  bool eol = false;
  int poly = 0;
  int material = 0;
  ChannelVector e{}, f{};
};
struct StageFragment {  // segment_interpolator -> shading (fr_*) and shading -> scanline_buffer (sh_*)
  int line = 0, index = 0;
  bool eol = false;
  int x = 0;
  std::uint32_t depth = 0;
  int poly = 0;                 // the polygon id (the scanline buffer's equal-depth rule)
  int material = 0;
  std::array<i64, 3> normal{};  // fr_*: the normal reading of channels 2..4
  std::uint32_t rgb = 0;        // sh_*: {R, G, B} as shaded (Gouraud: the interpolated shade)
};
struct StageStreams {
  int width = 0;          // screen width of the frame (to name the pixels a mismatch affects)
  std::vector<StageEdge> edges;
  std::vector<StageSegment> segments;
  std::vector<StageFragment> fragments;  // segment_interpolator output (x, depth, material, normal)
  std::vector<StageFragment> shaded;     // shading output (x, depth, rgb): the same items
};

// The bench that runs frames of the default configuration (other configurations have one --cc
// top each, assertions on): the SystemC bench (sc_bench.hpp: --sc tops with assertions and FST
// tracing; the co-simulation tests' bench) or the plain C++ harness on --cc tops built for speed
// (no assertions, no tracing; `watkins render --rtl`). Both run the same drive loop and checks,
// so they agree on every cycle. A run with a trace_path uses the SystemC bench.
enum class RtlHarness { SystemC, Fast };

struct RtlOptions {
  std::uint64_t seed = 1;
  double gap = 0.0;        // probability that the edge source idles a cycle before presenting a beat
  double stall = 0.0;      // probability that the pixel sink starts a stall (pixel_ready_i low)
  int stall_burst = 1;     // stalls last 1..stall_burst cycles (> 1: all-stall bursts)
  std::string trace_path;  // FST waveform of the whole run when not empty
  long long watchdog = 100000;  // cycles without any handshake before the run counts as hung
  bool compare = true;     // render the model (unless given the expected images) and compare
  // Reset the top before the run (its pins at rest, ResetCycles clocks), so that the run's
  // result never depends on the runs before it on the same top. false continues from the state
  // the previous run left (a test of the RTL running frames after frames without a reset); the
  // first run of a top and a run after a failed one reset regardless.
  bool reset = true;
  // Compare the three internal stage streams (active edges, segments, fragments) with the
  // model's, transfer by transfer (needs `compare`); the first difference names its stage.
  bool check_stages = true;
  // Sparse output mode (sparse_i = 1): the RTL emits only the covered pixels with their (x, y);
  // the sink assembles the image from them (background elsewhere) and checks every beat, in
  // order, against the model's sparse stream (sparse_stream() in model/twins/watkins_top.hpp).
  bool sparse = false;
  // Per-frame mode for run_rtl_frames (frame f uses sparse_frames[f] when f < size, else sparse).
  std::vector<bool> sparse_frames;
  // Test hook for the checker itself: called with each frame's model stage streams before the
  // run (a test corrupts one item and checks that the report names that stage).
  std::function<void(int frame, StageStreams&)> edit_stage_streams;
  RtlHarness harness = RtlHarness::SystemC;  // the default configuration's bench (last: tests list the fields above in order)
  // pixel_ready_i chosen by the test instead of the seeded stalls when set: called every cycle
  // with the cycle counted from the current output frame's first edge beat offered (its
  // RtlFrame::first_edge_cycle; the cycle model's count) and the pixels (beats) of that frame
  // taken before it. Before that frame's first beat and in the drain, ready is high.
  std::function<bool(long long cycle, long long pixels_taken)> pixel_ready;
};

struct RtlFrame {
  Image image;                     // as the RTL produced it (background where pixels are missing)
  bool sparse = false;             // the frame ran in sparse output mode
  long long pixels = 0;            // pixels (beats, in sparse mode) received
  long long expected_beats = -1;   // sparse mode: beats of the model's sparse stream (-1: unknown)
  long long first_edge_cycle = -1; // cycle the frame's first beat is offered (edge_valid_i rises:
                                   // the RTL starts the frame then and may emit empty lines early)
  long long last_pixel_cycle = -1; // cycle of its last pixel
  std::vector<long long> take_cycles;  // the cycle each pixel (beat) was taken, from first_edge_cycle
  long long cycles() const {       // frame cycles: first edge beat offered to last pixel, inclusive
    return last_pixel_cycle < 0 || first_edge_cycle < 0 ? 0 : last_pixel_cycle - first_edge_cycle + 1;
  }
  long long mismatches = 0;        // pixels whose RGB or coverage differ from the model
  bool complete = false;           // all width*height pixels (sparse: all expected beats) arrived,
                                   // pixel_last_o on the last
};

struct RtlResult {
  std::vector<RtlFrame> frames;
  std::string top;              // the Verilated top that ran the frames (which build, which configuration)
  long long cycles = 0;         // first beat offered of the first frame to last pixel of the last frame
  long long sim_cycles = 0;     // every clock of the run, including reset and drain
  long long pixels = 0;
  long long mismatches = 0;     // mismatching pixels
  // The first difference from the model, in simulation order: a stage stream's
  // ("segment_former output: frame 0 line 37 segment 2 at cycle C: RTL ..., model ...; affects
  // pixels (..)") or, when every stage stream agreed up to then, a pixel's ("pixel output: frame 0
  // pixel (x, y) at cycle C: RTL ... model ..."); empty when there is none.
  std::string first_mismatch;
  std::string first_stage;          // the stage of first_mismatch ("active_edge_list", "shading",
                                    // "segment_former", "segment_interpolator" or "pixel output")
  std::string first_pixel_mismatch; // the first mismatching pixel, or empty
  // Per stage that diverged, its first mismatch, in the order found (a stage is no longer
  // compared after its first mismatch: its stream may have lost step with the model's).
  std::vector<std::string> stage_mismatches;
  long long stage_items = 0;        // internal stage transfers compared with the model
  bool hang = false;            // the watchdog fired
  std::string hang_reason;      // names the stuck interface
  bool overflow = false;        // overflow_o was seen high
  long long overflow_cycle = -1;
  std::string protocol_error;   // first valid/ready or pixel_last_o violation, or empty
  std::string assertion;        // an RTL assertion (or $stop/$finish) ended the run, or empty
  std::string model_error;      // the model could not render the scene (so nothing was compared)
  // This build has no Verilated top for the frames' configuration (nothing ran): one line naming
  // its parameters and the CMake option that builds it (rtl_unavailable()).
  std::string unavailable;
  double wall_seconds = 0;      // simulation wall time of the run
  double cycles_per_second() const { return wall_seconds > 0 ? sim_cycles / wall_seconds : 0; }
  bool ok() const {  // every frame complete, no pixel or stage mismatch, hang, protocol error, assertion
    bool all = !frames.empty();
    for (const RtlFrame& f : frames) all = all && f.complete;
    return all && mismatches == 0 && stage_mismatches.empty() && !hang && protocol_error.empty() &&
           assertion.empty();
  }
  std::string summary() const {  // one line per problem (empty when ok())
    std::string s;
    auto line = [&](const std::string& t) { s += (s.empty() ? "" : "\n") + t; };
    if (!unavailable.empty()) line(unavailable);
    for (std::size_t f = 0; f < frames.size(); ++f)
      if (!frames[f].complete)
        line("frame " + std::to_string(f) + " incomplete: " + std::to_string(frames[f].pixels) + " of " +
             std::to_string(frames[f].sparse ? frames[f].expected_beats
                                             : static_cast<long long>(frames[f].image.width) * frames[f].image.height) +
             (frames[f].sparse ? " sparse beats" : " pixels"));
    if (!stage_mismatches.empty()) {
      line("stage streams diverge from the model; first: " + first_mismatch);
      for (const std::string& m : stage_mismatches)
        if (m != first_mismatch) line("  and: " + m);
    }
    if (mismatches) line(std::to_string(mismatches) + " mismatching pixels; first: " + first_pixel_mismatch);
    if (hang) line("hang: " + hang_reason);
    if (!protocol_error.empty()) line("protocol: " + protocol_error);
    if (!assertion.empty()) line("assertion: " + assertion);
    return s;
  }
};

// "" when this build has the SystemC bench (RtlHarness::SystemC, --trace), else why not.
std::string rtl_systemc_unavailable();
// Power-up state of the SystemC bench's two tops (Verilated with --x-initial unique): seed 0
// starts every register and RAM word without a reset at zero (the default); another seed at
// values drawn from it (Verilator's randReset(2) and randSeed(seed)). The tops are built once
// per process, at its first RTL run: call this before that run; after it, it throws
// std::logic_error. A run resets the top first, so a correct design renders the same image in
// the same cycles whatever the seed (tests/cosim/test_x_initial.cpp). The per-configuration
// --cc tops always start at zero.
void rtl_initial_state(int seed);
// The Verilated tops: at the default configuration (Phong = 0 and 1) the speed build's two --cc
// tops and the SystemC bench's two (RtlHarness), and one plain --cc top per other configuration
// the build was asked for (CMake option WATKINS_RTL_CONFIGS, testbench/CMakeLists.txt).
// run_rtl_frames runs frames on the top whose parameters equal rtl_parameters(frames'
// PreparedScene::config, shading).
//
// "" when this build has a top for frames prepared for `config` with `shading`; else one line
// naming the configuration's parameters and how to build its top (`file`: the configuration's
// file for the hint, e.g. the CLI's --config).
std::string rtl_unavailable(const Config& config, ShadingMode shading, const std::string& file = "F");
// Width of the line buffer (MaxWidth) of the top that runs frames prepared for `config` with
// `shading` (0 when there is none): wider scenes are refused.
int rtl_max_width(const Config& config = Config{}, ShadingMode shading = ShadingMode::Gouraud);

// Runs frames back to back in one simulation, all prepared for one configuration and one shading
// (else std::invalid_argument; so is a smoothed frame for a configuration with smoothing false,
// whose top has no smoother); with no top for them, the result's `unavailable` says so: the next frame's edges follow the previous frame's
// end-of-frame beat at once when screen size and background are the same; otherwise the source
// waits for the previous frame's last pixel before changing width_i/height_i/background_i.
RtlResult run_rtl_frames(const std::vector<const PreparedScene*>& scenes, const RtlOptions& opt = {},
                         const std::vector<const Image*>& expected = {});

// Runs one frame. `expected` (the model image) is rendered here when null and opt.compare is set.
inline RtlResult run_rtl(const PreparedScene& scene, const RtlOptions& opt = {}, const Image* expected = nullptr) {
  return run_rtl_frames({&scene}, opt, {expected});
}

}  // namespace watkins::tb
