// rtl/segment_former.sv against SegmentFormer::form, line by line: streams of X-ordered edges
// (polygon id, channel words) with end-of-line markers; polygons with 2 and 4 edges on a line
// (concave and bow-tie quads: even-odd pairing), interleaved and nested polygons, an unpaired
// edge at the end of a line (draws nothing and must not pair with the next line's edge of the
// same polygon), MaxActiveEdges distinct polygons open at once, empty lines, polygon ids 0 and
// 65535, under random valid gaps and segment back-pressure; every segment's E, F and polygon in
// closing order and every marker.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <deque>
#include <sstream>
#include <string>

#include "Vsegment_former.h"
#include "rtl_harness.hpp"
#include "segment_former.hpp"
#include "stream_bench.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

constexpr int N = WATKINS_RTL_PARAM_MaxActiveEdges;  // PARAMS in tests/rtl/CMakeLists.txt: at most N edges per line
constexpr int CB = fmt::ChannelBits;
constexpr int NC = fmt::NumChannels;
constexpr i64 One = i64{1} << fmt::FracBits;

struct In {
  bool eol = false;
  int poly = 0;
  int material = 0;  // random per edge: a segment takes its closing edge's
  ChannelVector value{};
};
struct Out {
  bool eol = false;
  Segment seg;
};

ChannelVector random_value(std::mt19937_64& rng) {
  ChannelVector v{};
  const bool full = rng() % 4 == 0;
  for (int c = 0; c < NC; ++c)
    v[c] = full ? wrap_signed(static_cast<i128>(rng()), CB)
                : static_cast<i64>(rng() % static_cast<std::uint64_t>(300 * One)) - 20 * One;
  return v;
}

int random_poly(std::mt19937_64& rng) {
  switch (rng() % 8) {
    case 0: return 0;
    case 1: return 65535;
    case 2: return static_cast<int>(rng() % 4);  // few ids: same ids across lines
    default: return static_cast<int>(rng() % 65536);
  }
}

// `count` distinct polygon ids.
std::vector<int> distinct_polys(std::mt19937_64& rng, int count) {
  std::vector<int> p;
  while (static_cast<int>(p.size()) < count) {
    const int q = random_poly(rng);
    if (std::find(p.begin(), p.end(), q) == p.end()) p.push_back(q);
  }
  return p;
}

// The polygon ids of one line's edges, left to right (at most N edges).
std::vector<int> random_line(std::mt19937_64& rng) {
  std::vector<int> l;
  switch (rng() % 9) {
    case 0:  // empty line
      break;
    case 1: {  // one polygon with 4 edges (bow-tie / concave), maybe with others around it
      const auto p = distinct_polys(rng, 3);
      l = {p[0], p[0], p[0], p[0]};
      if (rng() % 2) l.insert(l.begin() + static_cast<long>(rng() % 5), 2, p[1]);
      if (rng() % 2) {
        l.insert(l.begin() + static_cast<long>(rng() % (l.size() + 1)), p[2]);
        l.insert(l.begin() + static_cast<long>(rng() % (l.size() + 1)), p[2]);
      }
      break;
    }
    case 2: {  // interleaved / nested pairs: a random permutation of pairs
      const int k = 1 + static_cast<int>(rng() % (N / 2));
      for (int q : distinct_polys(rng, k)) l.insert(l.end(), 2, q);
      std::shuffle(l.begin(), l.end(), rng);
      break;
    }
    case 3: {  // pairs then an unpaired edge at the end of the line
      const int k = static_cast<int>(rng() % (N / 2));
      const auto p = distinct_polys(rng, k + 1);
      for (int i = 0; i < k; ++i) l.insert(l.end(), 2, p[i]);
      std::shuffle(l.begin(), l.end(), rng);
      l.push_back(rng() % 2 || k == 0 ? p[k] : p[0]);  // a new polygon, or a third edge of one
      break;
    }
    case 4:  // N distinct polygons: the open table full, nothing drawn
      l = distinct_polys(rng, N);
      break;
    case 5: {  // odd counts of one polygon: 1, 3, 5 edges
      const auto p = distinct_polys(rng, 2);
      const int c = 1 + 2 * static_cast<int>(rng() % 3);
      l.assign(c, p[0]);
      if (rng() % 2) l.insert(l.begin() + static_cast<long>(rng() % (l.size() + 1)), 2, p[1]);
      break;
    }
    default: {  // anything: up to N edges from a few polygons (even-odd pairing within each)
      const int k = static_cast<int>(rng() % (N + 1));
      const auto p = distinct_polys(rng, 1 + static_cast<int>(rng() % 4));
      for (int i = 0; i < k; ++i) l.push_back(p[rng() % p.size()]);
      break;
    }
  }
  return l;
}

void add_line(std::mt19937_64& rng, const std::vector<int>& polys, std::deque<In>& in, std::deque<Out>& want) {
  std::vector<ActiveEdge> edges;
  for (int q : polys) {
    ActiveEdge e;
    e.rec.poly = q;
    e.rec.material = static_cast<int>(rng() % (1u << fmt::MaterialIdBits));
    e.rec.value = random_value(rng);
    e.remaining = 1;
    edges.push_back(e);
    in.push_back({false, q, e.rec.material, e.rec.value});
  }
  in.push_back({true, 0, 0, random_value(rng)});  // the marker's data is don't-care
  std::vector<Segment> segs;
  SegmentFormer::form(edges, segs);
  for (const auto& s : segs) want.push_back({false, s});
  want.push_back({true, Segment{}});
}

struct Counts {
  std::uint64_t edges = 0, lines = 0, segments = 0, cycles = 0, stalled_inputs = 0;
};

// Streams `in` through the unit and checks the output against `want`.
Counts run(std::deque<In> in, std::deque<Out> want, int gap_pct, int bp_pct, std::uint64_t seed) {
  Harness<Vsegment_former> h;
  std::mt19937_64 rng(seed);
  StreamBench<Out> b(rng, gap_pct, bp_pct);
  b.expect = std::move(want);
  b.max_cycles = 64ull * (in.size() + b.expect.size()) + 1000;
  auto& d = h.dut;
  const StreamPorts ports{d.edge_valid_i, d.edge_ready_o, d.seg_valid_o, d.seg_ready_i};
  reset_stream(h, ports);
  Counts n;
  const std::uint64_t start = h.cycles;
  b.run(
      h, ports, [&] { return !in.empty(); },
      [&] {
        const In& i = in.front();
        d.edge_eol_i = i.eol;
        d.edge_poly_i = static_cast<std::uint16_t>(i.poly);
        d.edge_material_i = static_cast<std::uint8_t>(i.material);
        for (int c = 0; c < NC; ++c) set_bits(d.edge_value_i, c * CB, CB, to_bits(i.value[c], CB));
        return true;
      },
      [&](std::deque<Out>&) {
        if (!in.front().eol) ++n.edges;
        in.pop_front();
      },
      [&](const Out& w) {
        bool ok = bool(d.seg_eol_o) == w.eol;
        ChannelVector e{}, f{};
        for (int c = 0; c < NC; ++c) {
          e[c] = get_signed(d.seg_e_o, c * CB, CB);
          f[c] = get_signed(d.seg_f_o, c * CB, CB);
        }
        if (ok && !w.eol)
          ok = int(d.seg_poly_o) == w.seg.poly && int(d.seg_material_o) == w.seg.material && e == w.seg.e &&
               f == w.seg.f;
        const std::uint64_t line = n.lines;
        if (w.eol) ++n.lines;
        else ++n.segments;
        if (ok) return std::string();
        std::ostringstream diff;
        diff << "line " << line << ": rtl eol " << int(d.seg_eol_o) << " poly " << d.seg_poly_o << " material "
               << int(d.seg_material_o) << " E.x " << e[fmt::ChanX] << " F.x " << f[fmt::ChanX] << "; model eol "
               << w.eol << " poly " << w.seg.poly << " material " << w.seg.material << " E.x "
               << w.seg.e[fmt::ChanX] << " F.x " << w.seg.f[fmt::ChanX];
        return diff.str();
      });
  n.stalled_inputs = b.in_stalls;
  d.seg_ready_i = 1;
  for (int i = 0; i < 4; ++i) {
    d.eval();
    EXPECT_FALSE(d.seg_valid_o) << "extra output after the stream";
    h.tick();
  }
  EXPECT_EQ(b.mismatches, 0u);
  n.cycles = h.cycles - start;
  std::printf("segment_former: %llu edges, %llu lines, %llu segments checked in %llu cycles\n",
              static_cast<unsigned long long>(n.edges), static_cast<unsigned long long>(n.lines),
              static_cast<unsigned long long>(n.segments), static_cast<unsigned long long>(n.cycles));
  return n;
}

Counts run_random(int lines, int gap_pct, int bp_pct, std::uint64_t seed) {
  std::mt19937_64 rng(seed * 7919 + 1);
  std::deque<In> in;
  std::deque<Out> want;
  for (int i = 0; i < lines; ++i) add_line(rng, random_line(rng), in, want);
  return run(std::move(in), std::move(want), gap_pct, bp_pct, seed);
}

}  // namespace

TEST(RtlSegmentFormer, Directed) {
  std::mt19937_64 rng(99);
  std::deque<In> in;
  std::deque<Out> want;
  const std::vector<std::vector<int>> lines = {
      {},                          // empty line first
      {5, 5},                      // one segment
      {5, 5, 5, 5},                // bow-tie / concave: two segments, even-odd
      {1, 2, 1, 2},                // interleaved: close order 1, 2
      {1, 2, 2, 1},                // nested: close order 2, 1
      {7},                         // unpaired alone: draws nothing
      {7, 7},                      // the next line's 7 opens afresh (no leak from the line above)
      {3, 3, 9},                   // unpaired at the end
      {9, 4, 4},                   // 9 opens here, not closes the previous line's 9
      {0, 65535, 0, 65535},        // extreme ids
      {1, 2, 3, 4, 5, 6, 7, 8},    // table full, nothing drawn
      {8, 7, 6, 5, 4, 3, 2, 1},    // all must have been cleared: nothing drawn again
      {1, 1, 1, 1, 1, 1, 1, 1},    // four segments of one polygon
      {1, 2, 3, 4, 4, 3, 2, 1},    // deepest nesting
      {1, 1, 1},                   // third edge unpaired
      {1},                         // opens afresh, unpaired
      {},
      {},                          // back-to-back markers
      {2, 3, 3, 2, 2, 2},          // reopen after close within a line
  };
  for (const auto& l : lines) add_line(rng, l, in, want);
  for (int gap : {0, 30, 80})
    for (int bp : {0, 30, 80}) run(in, want, gap, bp, 100 + gap + bp);
}

TEST(RtlSegmentFormer, RandomLinesFullRate) {
  const Counts n = run_random(100000, 0, 0, 1);
  EXPECT_EQ(n.stalled_inputs, 0u) << "one edge per clock without back-pressure";
}
TEST(RtlSegmentFormer, RandomLinesGapsAndBackPressure) { run_random(100000, 40, 40, 2); }
TEST(RtlSegmentFormer, HeavyBackPressure) { run_random(40000, 5, 85, 3); }
TEST(RtlSegmentFormer, HeavyInputGaps) { run_random(40000, 85, 5, 4); }
