// rtl/compact_active_edge_list.sv against the ActiveEdgeList twin (driven like the frame loop of
// WatkinsTop::render: every line's active edges in (X, edge id) order, polygon, material and
// every channel word, then the end-of-line marker) and against its cycle twin
// (model/twins/compact_active_edge_list_timing.hpp) clocked alongside with the same inputs: on
// every clock the same edge_ready, out_valid, out_eol, busy and overflow, so every beat on both
// streams happens on the same cycle. The unit is built at a configuration's parameters (PARAMS
// in tests/rtl/CMakeLists.txt: the sized default scene's, or the default configuration's); the
// streams are the shipped scenes prepared at that configuration, prepared random scenes and
// meshes, and synthesized y-sorted streams at its word widths (many crossings every line: ties
// and reversing fans; equal X broken by id; full-range wrapping words; late records, which are
// read and skipped; records past the last line; capacity exactly and one more, the model's
// refused insert), with no gaps and under random input gaps, output stalls and start_i pulses
// while busy. Prints each shipped scene's clocks: the frame and its longest line at full rate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include "Vcompact_active_edge_list.h"
#include "active_edge_list.hpp"
#include "build_options.hpp"
#include "compact_active_edge_list_timing.hpp"
#include "config_file.hpp"
#include "edge_packing.hpp"
#include "prepare.hpp"
#include "random_scene.hpp"
#include "rtl_harness.hpp"
#include "scene.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

#ifdef WATKINS_RTL_PARAM_MaxActiveEdges
constexpr int N = WATKINS_RTL_PARAM_MaxActiveEdges;
#else
constexpr int N = fmt::MaxActiveEdges;
#endif

// The configuration the unit was built at: the sized default scene's when PARAMS set the widths.
Config unit_config() {
#ifdef WATKINS_RTL_PARAM_XBits
  Config c = load_config(WATKINS_SOURCE_DIR "/scenes/sized/default.gouraud.json");
#else
  Config c;
#endif
  c.max_active_edges = N;
  return c;
}

struct EdgeFrame {
  int height = 1;
  std::vector<EdgeRecord> edges;  // y-sorted (late records aside), id = index
};

struct OutEdge {
  int poly = 0, material = 0;
  ChannelVector value{};
  bool operator==(const OutEdge& o) const { return poly == o.poly && material == o.material && value == o.value; }
};
using Line = std::vector<OutEdge>;

struct Totals {
  std::uint64_t frames = 0, lines = 0, edges_out = 0, cycles = 0, crossings = 0, ties = 0, overflows = 0;
};

class Bench {
 public:
  Config cfg = unit_config();
  ChannelFormats formats = cfg.channels(ShadingMode::Gouraud);
  tb::EdgeLayout layout = tb::EdgeLayout::of(cfg, ShadingMode::Gouraud);
  Harness<Vcompact_active_edge_list> h;
  CompactActiveEdgeListTiming twin{N, formats, id_bits(cfg.max_edges)};
  std::mt19937_64 rng;
  int bad = 0;
  Totals tot;
  int worst_line = 0;  // the longest line (clocks from one line's first to the next's) of the last frame

  explicit Bench(std::uint64_t seed) : rng(seed) {
    h.dut.start_i = 0;
    h.dut.edge_valid_i = 0;
    h.dut.out_ready_i = 0;
    reset();
  }
  void reset() {
    h.dut.start_i = 0;
    h.dut.edge_valid_i = 0;
    h.reset();
    twin.reset();
  }
  void fail(const std::string& what) {
    if (bad++ < 8) ADD_FAILURE() << what;
  }

  // The twin's lines: new records join at their first line (late ones skipped, as the RTL reads
  // and skips them; a full list refuses the record), then the line, then the step.
  std::vector<Line> model(const EdgeFrame& f, int& overflow_line) const {
    std::vector<Line> lines;
    ActiveEdgeList a(N, formats);
    overflow_line = -1;
    std::size_t next = 0;
    for (int y = 0; y < f.height; ++y) {
      for (; next < f.edges.size() && f.edges[next].y0 <= y; ++next)
        if (f.edges[next].y0 == y && !a.insert(f.edges[next]) && overflow_line < 0) overflow_line = y;
      Line l;
      for (const ActiveEdge& e : a.edges()) l.push_back({e.rec.poly, e.rec.material, e.rec.value});
      lines.push_back(l);
      a.advance();
    }
    return lines;
  }

  // The clock of each line's end-of-line beat at full rate (no gaps, no stalls; clock 0 the
  // start_i clock), by the RTL header's formula from the twin's lists: E(0) = I(0) + K(0) + 1,
  // E(y+1) = E(y) + F(y) + I(y+1) + K(y+1) + 1.
  std::vector<std::uint64_t> formula_eols(const EdgeFrame& f) const {
    using Key = std::pair<i64, int>;
    auto key = [](const ActiveEdge& e) { return Key{e.rec.value[fmt::ChanX], e.rec.id}; };
    std::vector<std::uint64_t> eol;
    ActiveEdgeList a(N, formats);
    std::size_t next = 0;
    std::uint64_t t = 0;
    for (int y = 0; y < f.height; ++y) {
      std::uint64_t ins = 1;  // the head beat past the line
      for (; next < f.edges.size() && f.edges[next].y0 <= y; ++next) {
        const EdgeRecord& r = f.edges[next];
        if (r.y0 < y || a.size() == N) {
          ins += 1;
          continue;
        }
        const Key k{r.value[fmt::ChanX], r.id};
        std::uint64_t m = 0;
        for (const ActiveEdge& e : a.edges()) m += k < key(e);
        ins += a.size() == 0 ? 1 : m + 2;
        a.insert(r);
      }
      t += ins + static_cast<std::uint64_t>(a.size()) + 1;
      eol.push_back(t);
      // FIX: the stepped, kept keys in this line's order, sorted by insertion from the first
      // crossing.
      std::vector<Key> kept;
      for (ActiveEdge e : a.edges()) {
        EdgeIncrementer::step(e, formats);
        if (e.remaining > 0) kept.push_back(key(e));
      }
      std::size_t d = 1;
      while (d < kept.size() && !(kept[d] < *std::max_element(kept.begin(), kept.begin() + static_cast<long>(d)))) ++d;
      if (y + 1 < f.height && d < kept.size()) {
        t += 1 + kept.size() - d;  // the first read, then one clock per scanned entry
        for (std::size_t j = d; j < kept.size(); ++j) {
          if (!(kept[j] < kept[j - 1])) continue;
          std::size_t m = 0;
          while (m < j && kept[j] < kept[j - 1 - m]) ++m;
          t += m + 2 - (m == j ? 1 : 0);
          std::rotate(kept.begin() + static_cast<long>(j - m), kept.begin() + static_cast<long>(j),
                      kept.begin() + static_cast<long>(j + 1));
        }
      }
      a.advance();
    }
    return eol;
  }

  static std::string show(const Line& l) {
    std::string s = "[";
    for (const auto& e : l) s += " p" + std::to_string(e.poly) + ":x" + std::to_string(e.value[fmt::ChanX]);
    return s + " ]";
  }

  // One frame, back to back with the previous one. gap/bp: percent of clocks with the input's
  // valid low / the output's ready low; poke: start_i pulses while busy (ignored).
  void frame(const EdgeFrame& f, int gap_pct, int bp_pct, bool poke = false) {
    auto& d = h.dut;
    Stalls gaps{rng, gap_pct}, bp{rng, bp_pct};
    int ov_line = -1;
    const std::vector<Line> want = model(f, ov_line);
    const bool full_rate = gap_pct == 0 && bp_pct == 0 && !poke;
    const std::vector<std::uint64_t> eols = full_rate ? formula_eols(f) : std::vector<std::uint64_t>{};
    CompactActiveEdgeListTiming::Inputs in;
    in.height = f.height;
    d.height_i = static_cast<std::uint16_t>(f.height);
    bool started = false, eof_done = false, offered = false;
    std::size_t next = 0;
    int line = 0;
    Line cur;
    const std::uint64_t start = h.cycles;
    std::uint64_t line_start = start;
    worst_line = 0;
    const std::uint64_t limit = 8ull * (std::uint64_t(f.height) * (N + 4) * (N + 4) + f.edges.size() + 16) + 4000;
    for (;;) {
      in.start = !started || (poke && rng() % 8 == 0);
      if (!offered && !eof_done && !gaps.stall()) {
        offered = true;
        in.edge_eof = next == f.edges.size();
        if (!in.edge_eof) {
          in.edge = f.edges[next];
          tb::write_edge(d.edge_i, tb::pack_edge(layout, f.edges[next]));
        }
      }
      in.edge_valid = offered;
      in.out_ready = !bp.stall();
      d.start_i = in.start;
      d.edge_valid_i = in.edge_valid;
      d.edge_eof_i = in.edge_eof;
      d.out_ready_i = in.out_ready;
      d.eval();
      const CompactActiveEdgeListTiming::Outputs t = twin.eval(in);
      const std::string when = "frame " + std::to_string(tot.frames) + " line " + std::to_string(line) +
                               " cycle " + std::to_string(h.cycles - start) + ": ";
      if (bool(d.busy_o) != t.busy || bool(d.edge_ready_o) != t.edge_ready || bool(d.out_valid_o) != t.out_valid ||
          bool(d.overflow_o) != t.overflow || (t.out_valid && bool(d.out_eol_o) != t.out_eol))
        return fail(when + "rtl busy/edge_ready/out_valid/out_eol/overflow " + std::to_string(d.busy_o) +
                    std::to_string(d.edge_ready_o) + std::to_string(d.out_valid_o) + std::to_string(d.out_eol_o) +
                    std::to_string(d.overflow_o) + ", cycle twin " + std::to_string(t.busy) +
                    std::to_string(t.edge_ready) + std::to_string(t.out_valid) + std::to_string(t.out_eol) +
                    std::to_string(t.overflow));
      if (d.out_valid_o && d.out_ready_i) {
        if (line >= f.height) return fail(when + "output beyond the frame");
        if (d.out_eol_o) {
          if (full_rate && h.cycles - start != eols[static_cast<std::size_t>(line)])
            fail(when + "end of line at clock " + std::to_string(h.cycles - start) + ", the header's formula says " +
                 std::to_string(eols[static_cast<std::size_t>(line)]));
          if (cur != want[static_cast<std::size_t>(line)])
            fail(when + "rtl " + show(cur) + " model " + show(want[static_cast<std::size_t>(line)]));
          ++line, ++tot.lines;
          cur.clear();
        } else {
          OutEdge o;
          o.poly = d.out_poly_o;
          o.material = d.out_material_o;
          for (int c = 0; c < fmt::NumChannels; ++c)
            o.value[c] = get_signed(d.out_value_o, layout.channels.lsb[c], layout.channels.bits[c]);
          const ActiveEdge& e = *t.edge;
          if (!(o == OutEdge{e.rec.poly, e.rec.material, e.rec.value})) fail(when + "rtl edge differs from the cycle twin's");
          cur.push_back(o);
          ++tot.edges_out;
        }
      }
      const bool efire = d.edge_valid_i && d.edge_ready_o;
      const int twin_line = twin.line();
      h.tick();
      twin.tick(in);
      if (twin.line() != twin_line) {
        worst_line = std::max(worst_line, static_cast<int>(h.cycles - line_start));
        line_start = h.cycles;
      }
      started = true;
      if (efire) {
        if (in.edge_eof) eof_done = true;
        else ++next;
        offered = false;
      }
      if (eof_done && !d.busy_o) break;
      if (h.cycles - start > limit) return fail(when + "hang");
    }
    d.start_i = 0;
    if (line != f.height) fail("frame ended after " + std::to_string(line) + " of " + std::to_string(f.height) + " lines");
    if (ov_line >= 0 && !d.overflow_o) fail("overflow_o not set by an overflowing frame");
    for (std::size_t y = 0; y < want.size(); ++y) {
      for (std::size_t i = 1; i < want[y].size(); ++i) tot.ties += want[y][i].value[fmt::ChanX] == want[y][i - 1].value[fmt::ChanX];
      if (y > 0 && want[y - 1].size() == want[y].size())
        for (std::size_t i = 0; i < want[y].size(); ++i) tot.crossings += want[y - 1][i].poly != want[y][i].poly;
    }
    tot.overflows += ov_line >= 0;
    ++tot.frames;
    tot.cycles += h.cycles - start;
  }

  void report(const char* name) {
    auto u = [](std::uint64_t v) { return static_cast<unsigned long long>(v); };
    std::printf("%s: %llu frames (%llu overflowing), %llu lines, %llu edges checked (%llu equal-X neighbours, %llu "
                "order changes), %llu cycles\n",
                name, u(tot.frames), u(tot.overflows), u(tot.lines), u(tot.edges_out), u(tot.ties), u(tot.crossings),
                u(tot.cycles));
    EXPECT_EQ(bad, 0);
  }

  // ------------------------------------------------------------ synthesized streams
  i64 one() const { return i64{1} << formats.x_frac(); }
  i64 rnd(i64 lo, i64 hi) { return lo + static_cast<i64>(rng() % static_cast<std::uint64_t>(hi - lo + 1)); }
  i64 word(int c) { return wrap_signed(static_cast<i128>(rng()), formats.bits[static_cast<std::size_t>(c)]); }

  enum class Values { Realistic, Ties, FullRange };
  EdgeRecord edge(int y0, int n, i64 x, i64 dx, Values v = Values::Realistic) {
    EdgeRecord e;
    e.y0 = y0;
    e.n = n;
    e.poly = static_cast<int>(rng() % static_cast<unsigned>(cfg.max_polygons));
    e.material = static_cast<int>(rng() % static_cast<unsigned>(cfg.max_materials));
    e.value[fmt::ChanX] = wrap_signed(x, formats.bits[fmt::ChanX]);
    e.slope[fmt::ChanX] = wrap_signed(dx, formats.bits[fmt::ChanX]);
    for (int c = fmt::ChanZ; c < fmt::NumChannels; ++c) {
      e.value[c] = word(c);
      e.slope[c] = v == Values::FullRange || rng() % 4 == 0 ? word(c) : wrap_signed(rnd(-64, 64), formats.bits[c]);
    }
    return e;
  }
  void sort_and_number(EdgeFrame& f) {
    std::stable_sort(f.edges.begin(), f.edges.end(), [](const EdgeRecord& a, const EdgeRecord& b) { return a.y0 < b.y0; });
    for (std::size_t i = 0; i < f.edges.size(); ++i) f.edges[i].id = static_cast<int>(i);
  }

  // A random frame needing at most cap active edges on any line (cap > N: overflows).
  EdgeFrame random_frame(int height, int target, Values v, int cap = N, bool beyond = true) {
    EdgeFrame f;
    f.height = height;
    std::vector<int> cnt(static_cast<std::size_t>(height), 0);
    std::vector<int> bursts{0, height - 1};
    for (int i = 0, nb = static_cast<int>(rng() % 4); i < nb; ++i) bursts.push_back(static_cast<int>(rng() % height));
    const i64 o = one();
    for (int tries = 0; tries < 8 * target && static_cast<int>(f.edges.size()) < target; ++tries) {
      const int y0 = rng() % 10 < 4 ? bursts[rng() % bursts.size()] : static_cast<int>(rng() % height);
      const int kn = static_cast<int>(rng() % 10);
      const int n = kn < 3 ? 1 : kn < 5 ? height - y0 + static_cast<int>(rng() % 3)
                                        : 1 + static_cast<int>(rng() % std::max(1, std::min(height, 24)));
      bool fits = true;
      for (int y = y0; y < std::min(height, y0 + n); ++y) fits = fits && cnt[static_cast<std::size_t>(y)] < cap;
      if (!fits) continue;
      for (int y = y0; y < std::min(height, y0 + n); ++y) ++cnt[static_cast<std::size_t>(y)];
      i64 x, dx;
      if (v == Values::Ties) {  // few X positions and slopes: equal X and crossings on every line
        x = rnd(0, 6) * (o / 2);
        dx = rnd(-1, 1) * (o / 2);
      } else if (v == Values::FullRange) {  // wrapping X words: the order of the wrapped value
        x = word(fmt::ChanX);
        dx = rng() % 2 ? word(fmt::ChanX) : rnd(-16 * o, 16 * o);
      } else {
        x = rnd(-8 * o, 80 * o);
        dx = rng() % 4 == 0 ? 0 : rnd(-3 * o, 3 * o);
      }
      f.edges.push_back(edge(y0, n, x, dx, v));
    }
    if (beyond && rng() % 8 == 0)  // records at or past the last line: read up to the EOF beat
      for (int i = 0, m = 1 + static_cast<int>(rng() % 3); i < m; ++i)
        f.edges.push_back(edge(height + static_cast<int>(rng() % 3), 1 + static_cast<int>(rng() % 4), rnd(0, 40 * o), 0));
    sort_and_number(f);
    return f;
  }

  // count edges from line 0 fanning out from one point and reversing their order every few lines
  // (every pair crosses), and a second fan from line 3 crossing the first: the FIX phase's worst.
  EdgeFrame reversing(int height, int count) {
    EdgeFrame f;
    f.height = height;
    const i64 o = one();
    for (int i = 0; i < count; ++i) f.edges.push_back(edge(0, height, i * o, -i * (o / 2)));
    for (int i = 0; i < count / 2; ++i) f.edges.push_back(edge(3, height - 3, 2 * o - i * o, i * o));
    sort_and_number(f);
    return f;
  }

  // Records of one line in descending X: each new one goes to the front (the INS phase's worst).
  EdgeFrame descending(int height, int count, int y0) {
    EdgeFrame f;
    f.height = height;
    for (int i = 0; i < count; ++i) f.edges.push_back(edge(y0, 1 + static_cast<int>(rng() % (height - y0)), (count - i) * one(), 0));
    sort_and_number(f);
    return f;
  }

  // Late records (y0 below the record before them) put into a sorted frame.
  EdgeFrame with_late_records(EdgeFrame f, int count) {
    for (int k = 0; k < count && !f.edges.empty(); ++k) {
      const std::size_t at = 1 + rng() % f.edges.size();
      const int before = f.edges[at - 1].y0;
      if (before == 0) continue;
      const int y0 = static_cast<int>(rng() % static_cast<unsigned>(std::min(before, f.height)));
      f.edges.insert(f.edges.begin() + static_cast<long>(at), edge(y0, 1 + static_cast<int>(rng() % 8), rnd(0, 30 * one()), 0));
    }
    for (std::size_t i = 0; i < f.edges.size(); ++i) f.edges[i].id = static_cast<int>(i);
    return f;
  }

  // prepare() at the unit's configuration of a random scene (bow-ties among its quads) or a
  // jittered quad mesh (shared edges: equal X); retried until one fits.
  EdgeFrame prepared_frame(bool mesh) {
    for (;;) {
      BuiltScene s;
      if (mesh) {
        const int w = 8 + static_cast<int>(rng() % 120), hh = 1 + static_cast<int>(rng() % 64);
        s = test::mesh_scene(rng, w, hh, 1 + static_cast<int>(rng() % 9), 1 + static_cast<int>(rng() % 8));
      } else {
        test::RandomSceneSpec spec;
        spec.max_width = 200, spec.min_height = 1, spec.max_height = 64;
        spec.min_polygons = 0, spec.max_polygons = 16;
        spec.convex_quads = false;
        s = test::random_scene(rng, spec);
      }
      try {
        const PreparedScene p = prepare(s, cfg);
        return EdgeFrame{p.height, p.edges};
      } catch (const std::exception&) {
      }
    }
  }
};

EdgeFrame empty(int height) { return EdgeFrame{height, {}}; }

}  // namespace

// Every shipped scene (scenes/*.json) that prepares at the unit's configuration, at full rate (its
// frame and longest line printed) and under gaps and stalls.
TEST(RtlCompactActiveEdgeList, ShippedScenes) {
  Bench b(1);
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(WATKINS_SOURCE_DIR "/scenes"))
    if (e.path().extension() == ".json") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  int ran = 0;
  for (const std::string& file : files) {
    EdgeFrame f;
    try {
      const PreparedScene p = prepare(load_scene(file, test::shading_options(ShadingMode::Gouraud)), b.cfg);
      if (p.config.edge_order != b.cfg.edge_order) continue;
      f = EdgeFrame{p.height, p.edges};
    } catch (const std::exception&) {
      continue;  // needs more than this configuration (wider words, more edges, curves)
    }
    const std::uint64_t c0 = b.h.cycles;
    b.frame(f, 0, 0);
    std::printf("  %s: %d lines, %zu records: %llu clocks, longest line %d clocks\n",
                std::filesystem::path(file).filename().c_str(), f.height, f.edges.size(),
                static_cast<unsigned long long>(b.h.cycles - c0), b.worst_line);
    b.frame(f, 30, 30, true);
    b.frame(f, 10, 70);
    ++ran;
  }
  std::printf("%d shipped scenes at MaxActiveEdges %d\n", ran, N);
  EXPECT_GT(ran, 0);
  b.report("compact_active_edge_list shipped scenes");
}

TEST(RtlCompactActiveEdgeList, PreparedRandomScenes) {
  Bench b(2);
  for (int i = 0; i < 400; ++i) b.frame(b.prepared_frame(i % 2 == 1), (i % 3) * 25, (i % 4) * 20, i % 5 == 0);
  b.report("compact_active_edge_list prepared scenes");
}

TEST(RtlCompactActiveEdgeList, RandomFrames) {
  Bench b(3);
  const int frames = N > 36 ? 600 : 1500;  // a few seconds at either capacity
  for (int i = 0; i < frames; ++i) {
    const auto v = static_cast<Bench::Values>(i % 3);
    const int gap = i % 4 == 0 ? 0 : static_cast<int>(b.rng() % 90), bp = i % 4 == 0 ? 0 : static_cast<int>(b.rng() % 90);
    EdgeFrame f = b.random_frame(1 + static_cast<int>(b.rng() % 40), static_cast<int>(b.rng() % (3 * N)), v);
    if (i % 7 == 0) f = b.with_late_records(f, 1 + static_cast<int>(b.rng() % 6));
    b.frame(f, gap, bp, i % 5 == 0);
  }
  b.report("compact_active_edge_list random frames");
  EXPECT_GT(b.tot.crossings, 1000u);
  EXPECT_GT(b.tot.ties, 1000u);
}

TEST(RtlCompactActiveEdgeList, CrossingsAndTies) {
  Bench b(4);
  for (int pass = 0; pass < 3; ++pass) {
    const int gap = pass == 0 ? 0 : 30, bp = pass == 0 ? 0 : (pass == 1 ? 30 : 75);
    b.frame(b.reversing(24, std::min(N, 12)), gap, bp);
    b.frame(b.reversing(40, N * 2 / 3), gap, bp);
    b.frame(b.descending(8, N, 0), gap, bp);
    b.frame(b.descending(9, N, 5), gap, bp);
    for (int i = 0; i < 40; ++i) b.frame(b.random_frame(2 + static_cast<int>(b.rng() % 30), 2 * N, Bench::Values::Ties), gap, bp);
  }
  b.report("compact_active_edge_list crossings and ties");
}

TEST(RtlCompactActiveEdgeList, DirectedAndCapacity) {
  Bench b(5);
  b.frame(empty(1), 0, 0);
  b.frame(empty(7), 20, 20, true);
  {
    EdgeFrame f{fmt::MaxScreen, {}};  // the tallest frame
    f.edges.push_back(b.edge(0, fmt::MaxScreen, 0, b.one() / 64));
    f.edges.push_back(b.edge(0, fmt::MaxScreen, 64 * b.one(), -b.one() / 64));
    f.edges.push_back(b.edge(fmt::MaxScreen - 1, 1, 3 * b.one(), 0));
    b.sort_and_number(f);
    b.frame(f, 0, 0);
  }
  EXPECT_FALSE(b.h.dut.overflow_o);
  // One more than fits on one line: the last record refused (as the twin's insert), sticky flag.
  EdgeFrame f = b.descending(6, N + 1, 0);
  b.frame(f, 20, 20);
  EXPECT_TRUE(b.h.dut.overflow_o);
  b.frame(b.random_frame(20, 40, Bench::Values::Realistic), 20, 20);
  EXPECT_TRUE(b.h.dut.overflow_o);
  b.reset();
  EXPECT_FALSE(b.h.dut.overflow_o);
  // Random frames needing up to twice the capacity: exact, the refused records the model's.
  for (int i = 0; i < 300; ++i) {
    b.frame(b.random_frame(2 + static_cast<int>(b.rng() % 20), 3 * N, static_cast<Bench::Values>(i % 3), 2 * N), 25, 25);
    if (b.rng() % 2) b.reset();
  }
  b.report("compact_active_edge_list directed and capacity");
  EXPECT_GT(b.tot.overflows, 100u);
}
