// The loop of the stream unit benches: one unit with a valid/ready input stream and a valid/ready
// output stream, run against its model twin. Each cycle: offer the next input unless a random
// gap holds valid low; hold ready low at random (back-pressure); compare an output transfer with
// the oldest item the model expects (the scoreboard); clock; on an input transfer let the model
// append what that input must produce. A watchdog ends a run that stops moving or overruns.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <random>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "rtl_harness.hpp"

namespace watkins::rtl {

// The handshake ports of a stream unit (Verilator's one-bit ports are CData).
struct StreamPorts {
  CData& in_valid;         // driven: an input is offered
  const CData& in_ready;   // the unit takes it
  const CData& out_valid;  // the unit offers an output
  CData& out_ready;        // driven: low is back-pressure
};

// Reset with the driven handshake ports low: nothing offered, nothing taken.
template <class V>
void reset_stream(Harness<V>& h, StreamPorts p) {
  p.in_valid = 0;
  p.out_ready = 0;
  h.reset();
}

// One item on the input ports (the caller set its data), the output always taken: the clocks,
// counted from this call, in which it is taken and in which its result is first offered (-1 when
// that does not happen within limit clocks). The input's valid falls after the take.
template <class V>
std::pair<int, int> take_and_offer(Harness<V>& h, StreamPorts p, int limit) {
  p.in_valid = 1;
  p.out_ready = 1;
  int taken = -1, offered = -1;
  for (int c = 0; c < limit && offered < 0; ++c) {
    h.dut.eval();
    if (p.out_valid) offered = c;
    const bool take = p.in_valid && p.in_ready;
    h.tick();
    if (take) {
      taken = c;
      p.in_valid = 0;
    }
  }
  return {taken, offered};
}

// Item: what the scoreboard holds for one expected output (the model's output, or what the
// bench needs to compute it). The counters run over every run() of the bench.
template <class Item>
struct StreamBench {
  Stalls gaps, bp;            // input valid gaps, output back-pressure (percent of cycles)
  std::deque<Item> expect;    // the model's outputs not seen yet, oldest first
  std::uint64_t checked = 0;  // output transfers compared
  std::uint64_t mismatches = 0;
  std::uint64_t in_stalls = 0;     // cycles an offered input waited (ready_o low)
  std::uint64_t max_cycles = 0;    // watchdog: cycles one run may take (0: no limit)
  std::uint64_t stuck_cycles = 100000;  // watchdog: cycles without any transfer
  int report_limit = 8;            // mismatches reported in full
  bool until_expected = false;     // end when the scoreboard empties, inputs left or not
  // Called every clock with the ports driven and the unit evaluated, just before the edge (a
  // cycle twin's comparison and step); empty: nothing.
  std::function<void()> on_clock;

  StreamBench(std::mt19937_64& rng, int gap_pct, int bp_pct) : gaps{rng, gap_pct}, bp{rng, bp_pct} {}

  // more(): whether an input is left; offer(): drive it on the ports, false when the source ran
  // dry after all; taken(expect): the offered input went in; check(item): the output ports
  // against the oldest expected item, "" when they match, else what differs.
  // Ends when no input is left, none is offered and nothing is expected (or, with
  // until_expected, when nothing is expected). False when the run failed and stopped early.
  template <class V, class More, class Offer, class Taken, class Check>
  bool run(Harness<V>& h, StreamPorts p, More more, Offer offer, Taken taken, Check check) {
    const std::uint64_t start = h.cycles;
    std::uint64_t moved = start;
    bool dry = false;
    auto inputs_left = [&] { return !dry && more(); };
    while (until_expected ? !expect.empty() : (inputs_left() || p.in_valid || !expect.empty())) {
      if (!p.in_valid && inputs_left() && !gaps.stall()) {
        if (offer()) p.in_valid = 1;
        else dry = true;
      }
      p.out_ready = !bp.stall();
      h.dut.eval();
      const bool in_fire = p.in_valid && p.in_ready;
      if (p.in_valid && !p.in_ready) ++in_stalls;
      if (p.out_valid && p.out_ready) {
        if (expect.empty()) {
          ADD_FAILURE() << "output " << checked << " without an expected item";
          return false;
        }
        const std::string diff = check(expect.front());
        if (!diff.empty() && mismatches++ < static_cast<std::uint64_t>(report_limit))
          ADD_FAILURE() << "output " << checked << ": " << diff;
        expect.pop_front();
        ++checked;
        moved = h.cycles;
      }
      if (on_clock) on_clock();
      h.tick();
      if (in_fire) {
        taken(expect);
        p.in_valid = 0;
        moved = h.cycles;
      }
      if (h.cycles - moved > stuck_cycles || (max_cycles && h.cycles - start > max_cycles)) {
        ADD_FAILURE() << "hang after " << h.cycles - start << " cycles: " << expect.size()
                      << " expected outputs left, input " << (p.in_valid ? "offered" : "not offered")
                      << (inputs_left() ? ", more inputs to come" : "");
        return false;
      }
    }
    return true;
  }
};

}  // namespace watkins::rtl
