// The drive loop (frame_driver.hpp): per clock, settle the inputs, check the outputs, clock the
// top, then let the source and the sink choose the next inputs; a watchdog names a stuck
// interface.
#include "frame_driver.hpp"

#include <chrono>
#include <stdexcept>
#include <string>

#include "edge_source.hpp"
#include "expectations.hpp"
#include "pixel_sink.hpp"
#include "stage_checker.hpp"

namespace watkins::tb::detail {
namespace {

// Trace time in ps (Verilator's default time unit): a 10 ns clock, rising edge at +5 ns.
std::uint64_t tick_time(long long c) { return static_cast<std::uint64_t>(c) * 10000; }

// The last cycle of each kind of progress, and why a run without progress is stuck.
class Watchdog {
 public:
  Watchdog(long long start, long long limit) : limit_(limit), progress_(start), pixel_valid_(start) {}
  void clock(long long c, bool edge_waiting, bool edge_fire, bool pixel_valid, bool pixel_fire) {
    if (edge_fire || pixel_fire) progress_ = c;
    if (pixel_valid) pixel_valid_ = c;
    if (!edge_waiting) edge_blocked_since_ = -1;
    else if (edge_blocked_since_ < 0) edge_blocked_since_ = c;
  }
  bool fired(long long c) const { return c - progress_ >= limit_; }

  std::string reason(long long c, const EdgeSource& source, const PixelSink& sink, double stall) const {
    const std::string where = sink.position();
    const long long idle = c - pixel_valid_;
    const std::string no_pixels = "pixel_valid_o low for " + std::to_string(idle) + " cycles";
    if (edge_blocked_since_ >= 0 && !source.done())
      return "edge input stalled: edge_valid_i high and edge_ready_o low for " +
             std::to_string(c - edge_blocked_since_ + 1) + " cycles on " + source.waiting_beat() + "; " + no_pixels +
             "; " + where;
    if (idle >= limit_)
      return "pipeline not producing pixels: " + no_pixels + " after " +
             (source.frame() > sink.frame()
                  ? "all edge beats of frame " + std::to_string(sink.frame()) + " were accepted"
                  : std::string("the source went idle")) +
             "; " + where;
    return "pixel output blocked: pixel_valid_o high but pixel_ready_i held low by the sink (stall " +
           std::to_string(stall) + "); " + where;
  }

 private:
  long long limit_, progress_, pixel_valid_;
  long long edge_blocked_since_ = -1;
};

}  // namespace

void FrameDriver::run(const std::vector<const PreparedScene*>& scenes, const std::vector<const Image*>& expected,
                      const std::vector<StageStreams>& stages, const RtlOptions& opt, RtlResult& r) {
  const auto t0 = std::chrono::steady_clock::now();
  EdgeSource source(pins_, scenes, opt);  // packs first: a bad record fails before the simulation
  PixelSink sink(scenes, expected, opt, r);

  if (opt.trace_path.size() && !pins_.trace_open(opt.trace_path))
    throw std::runtime_error("cannot open trace file " + opt.trace_path);
  const long long start = cycle_;
  if (need_reset_ || opt.reset) reset(source.poison());
  need_reset_ = true;  // until this run ends cleanly

  StageChecker stage_check;
  stage_check.begin(pins_.stage_taps(), &stages, &r, start, frames_config(scenes),
                    phong_frames(scenes) ? ShadingMode::Phong : ShadingMode::Gouraud);
  Watchdog watchdog(cycle_, opt.watchdog);

  source.idle();
  source.drive(cycle_ - start, sink.frame(), r.frames);
  pins_.ready_pin(sink.next_ready(cycle_ - start));
  for (;;) {
    const long long c = cycle_;
    pins_.settle(tick_time(c));
    const PinsOut o = pins_.sample();
    if (pins_.stopped()) {
      r.assertion = "RTL stopped the simulation at cycle " + std::to_string(c - start) +
                    ": an assertion, $stop or $finish fired (Verilator's message is on stdout)";
      break;
    }
    if (o.overflow && !r.overflow) {
      r.overflow = true;
      r.overflow_cycle = c - start;
    }
    const bool edge_fire = source.presenting() && o.edge_ready;
    const bool pixel_fire = o.pixel_valid && sink.ready();
    sink.watch(o, c - start);
    stage_check.clock(c);
    pins_.posedge(tick_time(c) + 5000);
    ++cycle_;

    if (edge_fire) source.taken();
    watchdog.clock(c, source.presenting(), edge_fire, o.pixel_valid, pixel_fire);
    if (pixel_fire) sink.take(o, c - start);
    if (sink.drained()) break;
    if (watchdog.fired(c)) {
      r.hang = true;
      r.hang_reason = watchdog.reason(c, source, sink, opt.stall);
      break;
    }
    source.drive(cycle_ - start, sink.frame(), r.frames);
    pins_.ready_pin(sink.next_ready(cycle_ - start));
  }
  stage_check.end();
  r.sim_cycles = cycle_ - start;
  if (!r.frames.empty() && r.frames.front().first_edge_cycle >= 0 && r.frames.back().last_pixel_cycle >= 0)
    r.cycles = r.frames.back().last_pixel_cycle - r.frames.front().first_edge_cycle + 1;
  // Idle the inputs so a trace shows the end of the run cleanly.
  source.idle();
  pins_.ready_pin(false);
  pins_.trace_close();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  need_reset_ = !r.ok() || (r.overflow && policy_.reset_after_overflow);
}

void FrameDriver::reset(const EdgeWords& poison) {
  pins_.reset_pin(false);
  pins_.frame_pins(0, 0, 0, false, false, 0, false);
  pins_.phong_pins(0, 0);
  pins_.material_pins(MaterialPins{});
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

}  // namespace watkins::tb::detail
