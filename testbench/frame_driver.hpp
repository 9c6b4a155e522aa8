// The transaction-level part of the bench, shared by the SystemC bench (rtl_bench.cpp) and the
// plain C++ harness (rtl_harness_cc.cpp): edge-record source, pixel sink, checker, watchdog and
// cycle counting. It talks to the Verilated top only through a small `Pins` class:
//
//   void reset_pin(bool rst_n);
//   void frame_pins(uint32_t width, uint32_t height, uint32_t background_rgb, bool sparse);
//   void phong_pins(uint64_t light, uint64_t eye);   // {z, y, x} Q2.14 (Phong frames)
//   void material_pin(bool we, int addr, const QuantizedMaterial& m);  // one table write
//   void edge_pins(bool valid, bool eof, const EdgeWords& data);
//   void ready_pin(bool pixel_ready);
//   void settle(uint64_t t);   // clock low with the new inputs; combinational outputs valid
//   PinsOut sample();          // outputs as settle() left them (the values the edge samples)
//   void posedge(uint64_t t);  // rising clock edge
//   bool trace_open(const std::string& path); void trace_close();
//   std::string stopped();     // non-empty once an RTL assertion, $stop or $finish fired
//   const StageTaps& stage_taps();  // the internal stage streams (stage_checker.hpp)
//
// One clock cycle is: settle → sample → posedge. A transfer happens on the rising edge when valid
// and ready were both high after settle (valid/ready as in AXI-Stream: a source holds valid and
// data until the transfer; ready may come and go). The internal stage streams are checked on the
// same clocks (stage_checker.hpp), the pixels after them.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "edge_packing.hpp"
#include "watkins_top.hpp"
#include "rtl_bench.hpp"
#include "scene.hpp"
#include "stage_checker.hpp"

namespace watkins::tb::detail {

struct PinsOut {
  bool edge_ready = false;
  bool pixel_valid = false, pixel_last = false, pixel_covered = false;
  std::uint32_t pixel_rgb = 0;
  std::uint32_t pixel_x = 0, pixel_y = 0;
  bool overflow = false;
};

// xorshift64*: cheap enough to draw twice per simulated cycle.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) {
    std::uint64_t z = seed + 0x9E3779B97F4A7C15ull;  // splitmix64 of the seed
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    s_ = (z ^ (z >> 31)) | 1;
  }
  std::uint64_t next() {
    s_ ^= s_ >> 12;
    s_ ^= s_ << 25;
    s_ ^= s_ >> 27;
    return s_ * 0x2545F4914F6CDD1Dull;
  }
  // Threshold for "true with probability p" tests against next() >> 11 (53 bits).
  static std::uint64_t threshold(double p) {
    if (!(p > 0)) return 0;
    if (p >= 1) return 1ull << 53;
    return static_cast<std::uint64_t>(p * 9007199254740992.0);
  }
  bool chance(std::uint64_t thr) { return thr != 0 && (next() >> 11) < thr; }
  int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }

 private:
  std::uint64_t s_;
};

inline std::uint32_t pack_rgb(const std::array<std::uint8_t, 3>& c) {
  return (std::uint32_t(c[0]) << 16) | (std::uint32_t(c[1]) << 8) | c[2];
}

// {z, y, x} of a Q2.14 unit vector, as light_i / eye_i take it.
inline std::uint64_t pack_unit(const std::array<i64, 3>& v) {
  std::uint64_t w = 0;
  for (int c = 0; c < 3; ++c) w |= wrap_unsigned(v[c], fmt::UnitBits) << (c * fmt::UnitBits);
  return w;
}

// What the top samples or holds per frame: changing any of it waits for the previous frames'
// last pixel (the material table is written between frames).
struct FrameConfig {
  std::uint32_t width = 0, height = 0, background = 0;
  bool sparse = false;
  std::uint64_t light = 0, eye = 0;
  std::vector<QuantizedMaterial> materials;
  bool operator==(const FrameConfig& o) const {
    auto same_material = [](const QuantizedMaterial& a, const QuantizedMaterial& b) {
      return a.cp == b.cp && a.d == b.d && a.w == b.w && a.shininess == b.shininess;
    };
    return width == o.width && height == o.height && background == o.background && sparse == o.sparse &&
           light == o.light && eye == o.eye && materials.size() == o.materials.size() &&
           std::equal(materials.begin(), materials.end(), o.materials.begin(), same_material);
  }
};

inline std::string rgb_text(std::uint32_t rgb, bool covered) {
  char b[96];
  std::snprintf(b, sizeof b, "rgb (%u, %u, %u) %s", (rgb >> 16) & 255u, (rgb >> 8) & 255u, rgb & 255u,
                covered ? "covered" : "background");
  return b;
}

template <class Pins>
class FrameDriver {
 public:
  static constexpr int ResetCycles = 4;
  static constexpr int DrainCycles = 32;  // cycles after the last pixel in which no pixel may appear

  explicit FrameDriver(Pins& pins) : pins_(pins) {}

  // `stages`: the model's stage streams of every frame (empty: stages not checked).
  void run(const std::vector<const PreparedScene*>& scenes, const std::vector<const Image*>& expected,
           const std::vector<StageStreams>& stages, const RtlOptions& opt, RtlResult& r) {
    const auto t0 = std::chrono::steady_clock::now();
    const int n = static_cast<int>(scenes.size());
    // Pack everything first so that a bad record fails before the simulation starts.
    std::vector<std::vector<EdgeWords>> beats(n);
    for (int f = 0; f < n; ++f) {
      beats[f].reserve(scenes[f]->edges.size());
      for (const EdgeRecord& e : scenes[f]->edges) beats[f].push_back(pack_edge(e));
    }
    r.frames.assign(n, RtlFrame{});
    std::vector<std::vector<SparseBeat>> sparse_want(n);  // sparse frames: the model's beats
    for (int f = 0; f < n; ++f) {
      const PreparedScene& s = *scenes[f];
      Image img(s.width, s.height);
      for (std::size_t i = 0; i < img.rgb.size(); i += 3)
        for (int c = 0; c < 3; ++c) img.rgb[i + c] = s.background[c];
      r.frames[f].image = std::move(img);
      r.frames[f].sparse = f < static_cast<int>(opt.sparse_frames.size()) ? opt.sparse_frames[f] : opt.sparse;
      if (r.frames[f].sparse && f < static_cast<int>(expected.size()) && expected[f]) {
        sparse_want[f] = sparse_stream(*expected[f]);
        r.frames[f].expected_beats = static_cast<long long>(sparse_want[f].size());
      }
    }
    EdgeWords poison;  // what edge_i carries when no edge is offered (the RTL must ignore it)
    poison.fill(0xDEADBEEFu);
    poison[edge_layout::Words - 1] &= (1u << (edge_layout::Bits % 32)) - 1;

    if (opt.trace_path.size() && !pins_.trace_open(opt.trace_path))
      throw std::runtime_error("cannot open trace file " + opt.trace_path);
    const long long start_cycle = cycle_;
    if (need_reset_ || opt.reset) reset(poison);
    need_reset_ = true;  // until this run ends cleanly

    Rng gap_rng(opt.seed * 2 + 1), stall_rng(opt.seed * 2 + 2);
    const std::uint64_t gap_thr = Rng::threshold(opt.gap), stall_thr = Rng::threshold(opt.stall);

    // Source: frame sf, beat sb (beats[sf].size() edges, then the end-of-frame beat).
    int sf = 0;
    std::size_t sb = 0;
    bool presenting = false;
    // Sink: frame kf, pixel kp.
    int kf = 0;
    long long kp = 0;
    bool ready = false;
    int burst_left = 0;
    // Pixel-stream protocol check: a pixel offered and not taken must stay, unchanged.
    bool held = false;
    PinsOut held_out;
    // Watchdog.
    long long last_progress = cycle_, edge_blocked_since = -1, pixel_valid_last = cycle_;
    long long drain_left = -1;
    bool frame_pins_set = false;

    auto frame_needs = [&](int f) {
      const PreparedScene& s = *scenes[f];
      FrameConfig k;
      k.width = std::uint32_t(s.width);
      k.height = std::uint32_t(s.height);
      k.background = pack_rgb(s.background);
      k.sparse = r.frames[f].sparse;
      if (s.shading == ShadingMode::Phong) {
        k.light = pack_unit(s.light);
        k.eye = pack_unit(s.eye);
        k.materials = s.materials;
      }
      return k;
    };
    std::size_t loading = 0;  // > 0: material table writes left before the frame may start
    auto next_inputs = [&]() {
      // Edge source.
      if (!presenting && sf < n) {
        const bool starts = sb == 0;
        const bool same = frame_pins_set && frame_needs(sf) == cur_;
        const bool may_start = !starts || same || kf >= sf;  // else wait for the previous frames to drain
        if (may_start && starts && !same && loading == 0) {
          cur_ = frame_needs(sf);
          pins_.frame_pins(cur_.width, cur_.height, cur_.background, cur_.sparse);
          pins_.phong_pins(cur_.light, cur_.eye);
          frame_pins_set = true;
          loading = cur_.materials.size() + 1;  // the writes, then write enable low again
        }
        if (loading > 0) {
          const std::size_t k = cur_.materials.size() + 1 - loading;
          if (k < cur_.materials.size()) pins_.material_pin(true, static_cast<int>(k), cur_.materials[k]);
          else pins_.material_pin(false, 0, QuantizedMaterial{});
          --loading;
        } else if (may_start && !gap_rng.chance(gap_thr)) {
          presenting = true;
          if (starts) r.frames[sf].first_edge_cycle = cycle_ - start_cycle;  // the RTL starts the frame here
          const bool eof = sb == beats[sf].size();
          pins_.edge_pins(true, eof, eof ? poison : beats[sf][sb]);
        }
      }
      // Pixel sink.
      if (drain_left >= 0) {
        ready = true;
      } else if (burst_left > 0) {
        ready = false;
        --burst_left;
      } else if (stall_rng.chance(stall_thr)) {
        ready = false;
        burst_left = opt.stall_burst > 1 ? stall_rng.below(opt.stall_burst) : 0;
      } else {
        ready = true;
      }
      pins_.ready_pin(ready);
    };
    auto protocol = [&](const std::string& what) {
      if (r.protocol_error.empty()) r.protocol_error = what;
    };

    StageChecker stage_check;
    stage_check.begin(&pins_.stage_taps(), &stages, &r, start_cycle);

    pins_.edge_pins(false, false, poison);
    next_inputs();
    for (;;) {
      const long long c = cycle_;
      pins_.settle(tick_time(c));
      const PinsOut o = pins_.sample();
      const std::string stop = pins_.stopped();
      if (!stop.empty()) {
        r.assertion = "RTL stopped the simulation at cycle " + std::to_string(c - start_cycle) + ": " + stop;
        break;
      }
      if (o.overflow && !r.overflow) {
        r.overflow = true;
        r.overflow_cycle = c - start_cycle;
      }
      const bool edge_fire = presenting && o.edge_ready;
      const bool pixel_fire = o.pixel_valid && ready;
      if (held) {
        if (!o.pixel_valid)
          protocol("pixel output: pixel_valid_o dropped at cycle " + std::to_string(c - start_cycle) +
                   " without a transfer");
        else if (o.pixel_rgb != held_out.pixel_rgb || o.pixel_covered != held_out.pixel_covered ||
                 o.pixel_last != held_out.pixel_last || o.pixel_x != held_out.pixel_x ||
                 o.pixel_y != held_out.pixel_y)
          protocol("pixel output: pixel changed at cycle " + std::to_string(c - start_cycle) +
                   " while stalled by pixel_ready_i");
      }
      held = o.pixel_valid && !ready;
      held_out = o;
      stage_check.clock(c);
      pins_.posedge(tick_time(c) + 5000);
      ++cycle_;

      if (edge_fire) {
        presenting = false;
        if (++sb > beats[sf].size()) {
          ++sf;
          sb = 0;
        }
        pins_.edge_pins(false, false, poison);
        last_progress = c;
      }
      if (o.pixel_valid) pixel_valid_last = c;
      if (edge_fire || !presenting) edge_blocked_since = -1;
      else if (edge_blocked_since < 0) edge_blocked_since = c;

      if (pixel_fire) {
        last_progress = c;
        if (kf >= n) {
          protocol("pixel output: pixel after the last pixel of the last frame, at cycle " +
                   std::to_string(c - start_cycle));
        } else if (r.frames[kf].sparse) {
          if (sparse_beat(o, c - start_cycle, kf, kp, sparse_want[kf], r)) {
            ++kf;
            kp = 0;
            if (kf == n) drain_left = DrainCycles;
          } else {
            ++kp;
          }
        } else {
          RtlFrame& fr = r.frames[kf];
          const int w = fr.image.width, h = fr.image.height;
          const int x = static_cast<int>(kp % w), y = static_cast<int>(kp / w);
          if (o.pixel_x != std::uint32_t(x) || o.pixel_y != std::uint32_t(y))
            protocol("pixel output: pixel_x_o/pixel_y_o (" + std::to_string(o.pixel_x) + ", " +
                     std::to_string(o.pixel_y) + ") on frame " + std::to_string(kf) + " pixel (" +
                     std::to_string(x) + ", " + std::to_string(y) + ")");
          std::uint8_t* px = fr.image.at(x, y);
          px[0] = static_cast<std::uint8_t>(o.pixel_rgb >> 16);
          px[1] = static_cast<std::uint8_t>(o.pixel_rgb >> 8);
          px[2] = static_cast<std::uint8_t>(o.pixel_rgb);
          fr.image.covered[std::size_t(kp)] = o.pixel_covered;
          ++fr.pixels;
          ++r.pixels;
          const Image* want = kf < static_cast<int>(expected.size()) ? expected[kf] : nullptr;
          if (want) {
            const std::uint8_t* m = want->at(x, y);
            const std::uint32_t mrgb = (std::uint32_t(m[0]) << 16) | (std::uint32_t(m[1]) << 8) | m[2];
            const bool mcov = want->is_covered(x, y);
            if (mrgb != o.pixel_rgb || mcov != o.pixel_covered) {
              ++fr.mismatches;
              ++r.mismatches;
              if (r.first_pixel_mismatch.empty()) {
                r.first_pixel_mismatch = "pixel output: frame " + std::to_string(kf) + " pixel (" +
                                         std::to_string(x) + ", " + std::to_string(y) + ") at cycle " +
                                         std::to_string(c - start_cycle) + ": RTL " +
                                         rgb_text(o.pixel_rgb, o.pixel_covered) + ", model " +
                                         rgb_text(mrgb, mcov);
                if (r.first_mismatch.empty()) {
                  r.first_mismatch = r.first_pixel_mismatch;
                  r.first_stage = "pixel output";
                }
              }
            }
          }
          const bool last = kp == static_cast<long long>(w) * h - 1;
          if (o.pixel_last != last)
            protocol("pixel output: pixel_last_o " + std::string(o.pixel_last ? "high" : "low") +
                     " at frame " + std::to_string(kf) + " pixel (" + std::to_string(x) + ", " +
                     std::to_string(y) + ") of a " + std::to_string(w) + "x" + std::to_string(h) + " frame");
          if (last) {
            fr.complete = o.pixel_last;
            fr.last_pixel_cycle = c - start_cycle;
            ++kf;
            kp = 0;
            if (kf == n) drain_left = DrainCycles;
          } else {
            ++kp;
          }
        }
      }
      if (drain_left >= 0 && drain_left-- == 0) break;
      if (c - last_progress >= opt.watchdog) {
        r.hang = true;
        r.hang_reason = hang_reason(c, edge_blocked_since, pixel_valid_last, sf, sb, beats, kf, kp, scenes,
                                    opt);
        break;
      }
      next_inputs();
    }
    stage_check.end();
    r.sim_cycles = cycle_ - start_cycle;
    if (n > 0 && r.frames.front().first_edge_cycle >= 0 && r.frames.back().last_pixel_cycle >= 0)
      r.cycles = r.frames.back().last_pixel_cycle - r.frames.front().first_edge_cycle + 1;
    // Idle the inputs so a trace shows the end of the run cleanly.
    pins_.edge_pins(false, false, poison);
    pins_.ready_pin(false);
    pins_.trace_close();
    r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    need_reset_ = !r.ok() || r.overflow;
  }

 private:
  // One beat of a sparse frame: assemble it into the frame's image and check it against the
  // model's sparse stream (beat k of `want`, when the model was rendered). Returns true when the
  // beat ends the frame (pixel_last_o).
  bool sparse_beat(const PinsOut& o, long long cycle, int kf, long long k, const std::vector<SparseBeat>& want,
                   RtlResult& r) {
    RtlFrame& fr = r.frames[kf];
    const int w = fr.image.width, h = fr.image.height;
    auto protocol = [&](const std::string& what) {
      if (r.protocol_error.empty()) r.protocol_error = what;
    };
    const std::string at = "frame " + std::to_string(kf) + " beat " + std::to_string(k) + " pixel (" +
                           std::to_string(o.pixel_x) + ", " + std::to_string(o.pixel_y) + ") at cycle " +
                           std::to_string(cycle);
    ++fr.pixels;
    ++r.pixels;
    const bool inside = o.pixel_x < std::uint32_t(w) && o.pixel_y < std::uint32_t(h);
    const long long pos = inside ? static_cast<long long>(o.pixel_y) * w + o.pixel_x : -1;
    if (!inside)
      protocol("pixel output: sparse " + at + " outside the " + std::to_string(w) + "x" + std::to_string(h) +
               " frame");
    else if (pos <= sparse_pos_ && k > 0)
      protocol("pixel output: sparse " + at + " not after the previous beat in raster order");
    sparse_pos_ = pos;
    if (inside && o.pixel_covered) {
      std::uint8_t* px = fr.image.at(o.pixel_x, o.pixel_y);
      px[0] = static_cast<std::uint8_t>(o.pixel_rgb >> 16);
      px[1] = static_cast<std::uint8_t>(o.pixel_rgb >> 8);
      px[2] = static_cast<std::uint8_t>(o.pixel_rgb);
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
      if (!same) {
        ++fr.mismatches;
        ++r.mismatches;
        if (r.first_pixel_mismatch.empty()) {
          r.first_pixel_mismatch =
              "pixel output: sparse " + at + ": RTL " + rgb_text(o.pixel_rgb, o.pixel_covered) +
              (o.pixel_last ? " last" : "") + ", model " +
              (beyond ? std::string("no beat (its stream has ") + std::to_string(want.size()) + " beats)"
                      : "pixel (" + std::to_string(m.x) + ", " + std::to_string(m.y) + ") " +
                            rgb_text(mrgb, m.covered) + (m.last ? " last" : ""));
          if (r.first_mismatch.empty()) {
            r.first_mismatch = r.first_pixel_mismatch;
            r.first_stage = "pixel output";
          }
        }
      }
    }
    if (o.pixel_last) {
      fr.complete = !have_model || k + 1 == fr.expected_beats;
      fr.last_pixel_cycle = cycle;
      if (have_model && k + 1 < fr.expected_beats) {
        ++fr.mismatches;  // beats the RTL never sent
        ++r.mismatches;
        if (r.first_pixel_mismatch.empty()) {
          const SparseBeat& m = want[std::size_t(k + 1)];
          r.first_pixel_mismatch = "pixel output: sparse frame " + std::to_string(kf) + " ended after " +
                                   std::to_string(k + 1) + " beats at cycle " + std::to_string(cycle) +
                                   "; model beat " + std::to_string(k + 1) + " pixel (" + std::to_string(m.x) +
                                   ", " + std::to_string(m.y) + ") " + rgb_text(pack_rgb(m.rgb), m.covered) +
                                   " missing";
          if (r.first_mismatch.empty()) {
            r.first_mismatch = r.first_pixel_mismatch;
            r.first_stage = "pixel output";
          }
        }
      }
      return true;
    }
    return false;
  }

  // Trace time in ps (Verilator's default time unit): a 10 ns clock, rising edge at +5 ns.
  std::uint64_t tick_time(long long c) const { return static_cast<std::uint64_t>(c) * 10000; }

  void reset(const EdgeWords& poison) {
    pins_.reset_pin(false);
    pins_.edge_pins(false, false, poison);
    pins_.ready_pin(false);
    for (int i = 0; i < ResetCycles; ++i) {
      pins_.settle(tick_time(cycle_));
      pins_.posedge(tick_time(cycle_) + 5000);
      ++cycle_;
    }
    pins_.reset_pin(true);
    (void)pins_.stopped();  // an assertion of a previous run is forgiven by the reset
  }

  std::string hang_reason(long long c, long long edge_blocked_since, long long pixel_valid_last, int sf,
                          std::size_t sb, const std::vector<std::vector<EdgeWords>>& beats, int kf, long long kp,
                          const std::vector<const PreparedScene*>& scenes, const RtlOptions& opt) const {
    const int n = static_cast<int>(scenes.size());
    std::string where;
    if (kf < n) {
      const PreparedScene& s = *scenes[kf];
      where = "frame " + std::to_string(kf) + " has " + std::to_string(kp) + " of " +
              std::to_string(static_cast<long long>(s.width) * s.height) + " pixels (next (" +
              std::to_string(kp % s.width) + ", " + std::to_string(kp / s.width) + "))";
    }
    const long long idle = c - pixel_valid_last;
    const std::string no_pixels = "pixel_valid_o low for " + std::to_string(idle) + " cycles";
    if (edge_blocked_since >= 0 && sf < n) {
      std::string beat;
      if (sb == beats[sf].size()) {
        beat = "the end-of-frame beat";
      } else {
        const EdgeRecord& e = scenes[sf]->edges[sb];
        beat = "edge " + std::to_string(sb) + " (y0 " + std::to_string(e.y0) + ", n " + std::to_string(e.n) +
               ", poly " + std::to_string(e.poly) + ")";
      }
      return "edge input stalled: edge_valid_i high and edge_ready_o low for " +
             std::to_string(c - edge_blocked_since + 1) + " cycles on frame " + std::to_string(sf) + " " + beat +
             " of " + std::to_string(beats[sf].size() + 1) + " beats; " + no_pixels + "; " + where;
    }
    if (idle >= opt.watchdog)
      return "pipeline not producing pixels: " + no_pixels + " after " +
             (sf > kf ? "all edge beats of frame " + std::to_string(kf) + " were accepted"
                      : std::string("the source went idle")) +
             "; " + where;
    return "pixel output blocked: pixel_valid_o high but pixel_ready_i held low by the sink (stall " +
           std::to_string(opt.stall) + "); " + where;
  }

  Pins& pins_;
  bool need_reset_ = true;
  long long cycle_ = 0;  // cycles since the bench was built
  FrameConfig cur_;  // what the frame pins and the material table hold
  long long sparse_pos_ = -1;  // raster position of the previous sparse beat
};

// True when the frames need the Phong top (Phong = 1), false for the Gouraud top; frames of one
// run use one top, so mixing the two throws std::invalid_argument.
inline bool phong_frames(const std::vector<const PreparedScene*>& scenes) {
  int phong = 0;
  for (const PreparedScene* s : scenes) phong += s->shading == ShadingMode::Phong;
  if (phong != 0 && phong != static_cast<int>(scenes.size()))
    throw std::invalid_argument("RTL: one run_rtl_frames call renders Gouraud or Phong frames, not both");
  return phong != 0;
}

// What run_rtl_frames does before the driver on either harness: check that every screen fits the
// RTL and render the model images that were not given (into `rendered`, which `use` points into).
// With opt.compare and opt.check_stages, also record the model's stage streams of every frame
// into `stages` (left empty when any frame's model fails: the stages are then not checked).
inline void expected_images(const std::vector<const PreparedScene*>& scenes, const RtlOptions& opt,
                            const std::vector<const Image*>& given, std::vector<Image>& rendered,
                            std::vector<const Image*>& use, std::vector<StageStreams>& stages, RtlResult& r,
                            int max_width) {
  rendered.assign(scenes.size(), Image{});
  use.assign(scenes.size(), nullptr);
  stages.clear();
  const bool want_stages = opt.compare && opt.check_stages;
  if (want_stages) stages.resize(scenes.size());
  bool stages_failed = false;
  for (std::size_t f = 0; f < scenes.size(); ++f) {
    const PreparedScene& s = *scenes[f];
    if (s.width < 1 || s.height < 1 || s.width > max_width || s.height >= (1 << fmt::LineBits))
      throw std::invalid_argument("RTL: a " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                                  " screen does not fit the RTL (line buffer MaxWidth = " +
                                  std::to_string(max_width) + " pixels)");
    const bool have = f < given.size() && given[f];
    if (have) use[f] = given[f];
    if (!want_stages && (have || !opt.compare)) continue;
    try {
      if (want_stages) {
        stages[f] = model_stage_streams(s, have ? nullptr : &rendered[f]);
        if (opt.edit_stage_streams) opt.edit_stage_streams(static_cast<int>(f), stages[f]);
      } else {
        rendered[f] = WatkinsTop(fmt::MaxActiveEdges).render(s);
      }
      if (!have) use[f] = &rendered[f];
    } catch (const SceneError& e) {
      stages_failed = true;
      if (!have && r.model_error.empty()) r.model_error = "frame " + std::to_string(f) + ": " + e.what();
    }
  }
  if (stages_failed) stages.clear();
}

}  // namespace watkins::tb::detail
