// rtl/active_edge_list.sv (with its edge_incrementer) against ActiveEdgeList + EdgeIncrementer
// driven like the frame loop of WatkinsTop::render: for every scan line of a frame, the
// active edges in (X, edge id) order (polygon id and every channel word) and the end-of-line
// marker. Synthesized y-sorted edge streams (many edges starting on one line, equal X broken by
// arrival index, edges crossing in X between lines, n = 1, edges on line 0 and on the last line,
// empty lines, full-range wrapping channel words, records past the last line, late records behind
// the line being filled, which are read and skipped), streams of
// prepare()d random scenes and meshes, frames with no edges, frames back to back, exactly
// MaxActiveEdges active and one more (sticky overflow_o), under random valid gaps, random output
// back-pressure and start_i pulses while busy.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <deque>

#include "Vactive_edge_list.h"
#include "active_edge_list.hpp"
#include "prepare.hpp"
#include "edge_packing.hpp"
#include "random_scene.hpp"
#include "rtl_harness.hpp"
#include "scene.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

constexpr int N = WATKINS_RTL_PARAM_MaxActiveEdges;  // PARAMS in tests/rtl/CMakeLists.txt
constexpr int CB = fmt::ChannelBits;
constexpr int NC = fmt::NumChannels;
constexpr i64 One = i64{1} << fmt::FracBits;

struct EdgeFrame {
  int height = 1;
  std::vector<EdgeRecord> edges;  // sorted by y0, id = index
};

struct OutEdge {
  int poly = 0;
  int material = 0;
  ChannelVector value{};
  bool operator==(const OutEdge& o) const { return poly == o.poly && material == o.material && value == o.value; }
};
using Line = std::vector<OutEdge>;

// The model's lines: with capacity N (as the pipeline), and unbounded (what an overflowing
// frame's lines must be a subsequence of: a dropped edge never comes back, the others step on).
struct Expect {
  std::vector<Line> lines, unbounded;
  int ov_line = -1;  // first line where the capacity-N list refused an edge
  long long ideal_cycles = 0;  // sum over lines of (active + new + 7)
};

Line to_line(const ActiveEdgeList& a) {
  Line l;
  for (const auto& e : a.edges()) l.push_back({e.rec.poly, e.rec.material, e.rec.value});
  return l;
}

Expect model(const EdgeFrame& f) {
  Expect x;
  ActiveEdgeList a(N), u(1 << 30);
  std::size_t next = 0;
  for (int y = 0; y < f.height; ++y) {
    int fresh = 0;
    // A record behind the line (an unsorted stream) is read and skipped, as the RTL's drop_late.
    for (; next < f.edges.size() && f.edges[next].y0 <= y; ++next) {
      if (f.edges[next].y0 < y) continue;
      if (!a.insert(f.edges[next]) && x.ov_line < 0) x.ov_line = y;
      u.insert(f.edges[next]);
      ++fresh;
    }
    x.lines.push_back(to_line(a));
    x.unbounded.push_back(to_line(u));
    x.ideal_cycles += a.size() + fresh + 7;
    a.advance();
    u.advance();
  }
  return x;
}

void sort_and_number(EdgeFrame& f) {
  std::stable_sort(f.edges.begin(), f.edges.end(),
                   [](const EdgeRecord& a, const EdgeRecord& b) { return a.y0 < b.y0; });
  for (std::size_t i = 0; i < f.edges.size(); ++i) f.edges[i].id = static_cast<int>(i);
}

i64 rnd(std::mt19937_64& rng, i64 lo, i64 hi) {
  return lo + static_cast<i64>(rng() % static_cast<std::uint64_t>(hi - lo + 1));
}
i64 full_word(std::mt19937_64& rng) { return wrap_signed(static_cast<i128>(rng()), CB); }

enum class Values { Realistic, Ties, FullRange };

// An edge record with X and its slope given, the other channels random.
EdgeRecord edge(std::mt19937_64& rng, int y0, int n, i64 x, i64 dx, Values v = Values::Realistic) {
  EdgeRecord e;
  e.y0 = y0;
  e.n = n;
  e.poly = (rng() % 8 == 0) ? ((rng() % 2) ? 0 : 65535) : static_cast<int>(rng() % 65536);
  e.material = static_cast<int>(rng() % (1u << fmt::MaterialIdBits));
  e.value[fmt::ChanX] = x;
  e.slope[fmt::ChanX] = dx;
  for (int c = fmt::ChanZ; c < NC; ++c) {
    if (v == Values::FullRange || rng() % 16 == 0) {
      e.value[c] = full_word(rng);
      e.slope[c] = full_word(rng);
    } else {
      e.value[c] = rnd(rng, -(i64{1} << 36), i64{1} << 40);
      e.slope[c] = rnd(rng, -(i64{1} << 30), i64{1} << 30);
    }
  }
  return e;
}

// A random y-sorted frame that never needs more than `cap` active edges (cap <= N: no overflow).
EdgeFrame random_frame(std::mt19937_64& rng, int height, int target_edges, Values v, int cap = N,
                   bool beyond = true) {
  EdgeFrame f;
  f.height = height;
  std::vector<int> cnt(height, 0);
  std::vector<int> bursts;  // lines where many edges start
  for (int i = 0, nb = static_cast<int>(rng() % 4); i < nb; ++i) bursts.push_back(static_cast<int>(rng() % height));
  bursts.push_back(0);
  bursts.push_back(height - 1);
  for (int tries = 0; tries < 8 * target_edges && static_cast<int>(f.edges.size()) < target_edges; ++tries) {
    int y0;
    const int k = static_cast<int>(rng() % 10);
    if (k < 4) y0 = bursts[rng() % bursts.size()];
    else y0 = static_cast<int>(rng() % height);
    int n;
    const int kn = static_cast<int>(rng() % 10);
    if (kn < 3) n = 1;
    else if (kn < 5) n = height - y0 + static_cast<int>(rng() % 3);  // to the last line or past it
    else n = 1 + static_cast<int>(rng() % std::max(1, std::min(height, 24)));
    bool fits = true;
    for (int y = y0; y < std::min(height, y0 + n); ++y) fits = fits && cnt[y] < cap;
    if (!fits) continue;
    for (int y = y0; y < std::min(height, y0 + n); ++y) ++cnt[y];
    i64 x, dx;
    switch (v) {
      case Values::Ties:  // few X positions and slopes: many equal X, crossings every line
        x = rnd(rng, 0, 6) * (One / 2);
        dx = rnd(rng, -1, 1) * (One / 2);
        break;
      case Values::FullRange:  // wrapping X words: order by the wrapped signed value
        x = full_word(rng);
        dx = (rng() % 2) ? full_word(rng) : rnd(rng, -(i64{1} << 40), i64{1} << 40);
        break;
      default:
        x = rnd(rng, -8 * One, 80 * One);
        dx = (rng() % 4 == 0) ? 0 : rnd(rng, -3 * One, 3 * One);
        break;
    }
    f.edges.push_back(edge(rng, y0, n, x, dx, v));
  }
  // Records at or past the last line: never active, read up to the EOF beat.
  if (beyond && rng() % 8 == 0)
    for (int i = 0, m = 1 + static_cast<int>(rng() % 3); i < m; ++i)
      f.edges.push_back(edge(rng, height + static_cast<int>(rng() % 3), 1 + static_cast<int>(rng() % 4),
                             rnd(rng, 0, 40 * One), 0, v));
  sort_and_number(f);
  return f;
}

// prepare() of a random scene (triangles and quads, bow-ties among them, partly off screen) or of
// a jittered quad mesh (shared edges: equal X); retried until the scene fits N active edges.
EdgeFrame prepared_frame(std::mt19937_64& rng, bool mesh) {
  for (;;) {
    BuiltScene s;
    if (mesh) {
      const int w = 8 + static_cast<int>(rng() % 56), h = 1 + static_cast<int>(rng() % 48);
      const int cols = 1 + static_cast<int>(rng() % 7), rows = 1 + static_cast<int>(rng() % 6);
      s = test::mesh_scene(rng, w, h, cols, rows);
    } else {
      test::RandomSceneSpec spec;
      spec.max_width = 63, spec.min_height = 1, spec.max_height = 48;
      spec.min_polygons = 0, spec.max_polygons = 8;
      spec.convex_quads = false;
      s = test::random_scene(rng, spec);
    }
    try {
      const PreparedScene p = prepare(s, PrepareOptions{N});
      EdgeFrame f;
      f.height = p.height;
      f.edges = p.edges;  // already y-sorted and numbered by prepare
      return f;
    } catch (const SceneError&) {
    }
  }
}

struct Totals {
  std::uint64_t frames = 0, lines = 0, edges_out = 0, records_in = 0, cycles = 0;
  std::uint64_t ties = 0, crossings = 0, empty_lines = 0, full_lines = 0, overflow_frames = 0;
  long long ideal = 0;
};

struct Ael {
  Harness<Vactive_edge_list> h;
  std::mt19937_64 rng;
  bool ov_seen = false;  // overflow_o was seen high since the last reset (sticky)
  int bad = 0;
  Totals tot;

  explicit Ael(std::uint64_t seed) : rng(seed) {
    h.dut.start_i = 0;
    h.dut.edge_valid_i = 0;
    h.dut.out_ready_i = 0;
    h.reset();
  }
  void reset() {
    h.dut.start_i = 0;
    h.dut.edge_valid_i = 0;
    h.reset();
    ov_seen = false;
    h.dut.eval();
    EXPECT_FALSE(h.dut.overflow_o) << "overflow_o not cleared by reset";
    EXPECT_FALSE(h.dut.busy_o);
  }

  void fail(const std::string& what) {
    if (bad++ < 8) ADD_FAILURE() << what;
  }

  static std::string show(const Line& l) {
    std::string s = "[";
    for (const auto& e : l) s += " p" + std::to_string(e.poly) + ":x" + std::to_string(e.value[fmt::ChanX]);
    return s + " ]";
  }

  // Runs one frame back to back with the previous one. pre: cycles the first beat is offered
  // before start_i; poke: random start_i pulses while busy (ignored).
  void frame(const EdgeFrame& f, int gap_pct, int bp_pct, bool poke = false) {
    auto& d = h.dut;
    Stalls gaps{rng, gap_pct}, bp{rng, bp_pct};
    const Expect x = model(f);
    const bool ov_before = ov_seen;
    const bool ov_allowed = ov_before || x.ov_line >= 0;
    if (d.busy_o) return fail("busy_o high before the frame starts");
    d.height_i = static_cast<std::uint16_t>(f.height);
    int pre = poke ? static_cast<int>(rng() % 3) : 0;
    bool started = false, eof_done = false;
    std::size_t next = 0;
    int line = 0;
    Line cur;
    const std::uint64_t start = h.cycles;
    const std::uint64_t limit = 64ull * (std::uint64_t(f.height) * (N + 4) + f.edges.size() + 16) + 2000;
    for (;;) {
      d.start_i = 0;
      if (!started && pre == 0) d.start_i = 1;
      else if (started && poke && d.busy_o && rng() % 8 == 0) d.start_i = 1;  // ignored while busy
      if (!d.edge_valid_i && !eof_done && !gaps.stall()) {
        d.edge_eof_i = next == f.edges.size();
        if (!d.edge_eof_i) tb::write_edge(d.edge_i, tb::pack_edge(tb::default_edge_layout(), f.edges[next]));
        d.edge_valid_i = 1;
      }
      d.out_ready_i = !bp.stall();
      d.eval();
      const bool efire = d.edge_valid_i && d.edge_ready_o;
      if (!started && efire) return fail("edge beat taken before start_i");
      if (d.overflow_o) ov_seen = true;
      else if (ov_seen) return fail("overflow_o fell: not sticky");
      if (d.overflow_o && !ov_allowed) return fail("overflow_o set without an overflow, line " + std::to_string(line));
      if (started && !d.busy_o && !eof_done) return fail("busy_o low before the EOF beat was read");
      if (d.out_valid_o && d.out_ready_i) {
        if (!started || line >= f.height)
          return fail("output beyond the frame (line " + std::to_string(line) + " of " + std::to_string(f.height) + ")");
        if (x.ov_line >= 0 && line >= x.ov_line && !d.overflow_o)
          fail("overflow_o low on line " + std::to_string(line) + " after an overflow on line " + std::to_string(x.ov_line));
        if (x.ov_line >= 0 && line <= x.ov_line - 2 && !ov_before && d.overflow_o)
          fail("overflow_o set early, on line " + std::to_string(line) + " (overflow on line " + std::to_string(x.ov_line) + ")");
        if (d.out_eol_o) {
          check_line(x, line, cur);
          ++line;
          ++tot.lines;
          cur.clear();
        } else {
          OutEdge o;
          o.poly = d.out_poly_o;
          o.material = d.out_material_o;
          for (int c = 0; c < NC; ++c) o.value[c] = get_signed(d.out_value_o, c * CB, CB);
          cur.push_back(o);
          ++tot.edges_out;
          if (static_cast<int>(cur.size()) > N)
            return fail("line " + std::to_string(line) + ": more than MaxActiveEdges edges without an end-of-line");
        }
      }
      h.tick();
      if (!started) {
        if (pre == 0) {
          started = true;
          if (!d.busy_o) return fail("busy_o not raised by start_i");
        } else {
          --pre;
        }
      }
      if (efire) {
        if (d.edge_eof_i) eof_done = true;
        else ++next, ++tot.records_in;
        d.edge_valid_i = 0;
      }
      if (eof_done && !d.busy_o) break;
      if (h.cycles - start > limit)
        return fail("hang: line " + std::to_string(line) + " of " + std::to_string(f.height) + ", " +
                    std::to_string(next) + " of " + std::to_string(f.edges.size()) + " records, eof " +
                    std::to_string(eof_done));
    }
    d.start_i = 0;
    d.out_ready_i = 1;
    d.eval();
    if (line != f.height)
      fail("frame ended after " + std::to_string(line) + " of " + std::to_string(f.height) + " lines");
    if (next != f.edges.size()) fail("frame ended with records unread");
    if (d.out_valid_o) fail("output valid after the frame");
    if (x.ov_line >= 0 && !d.overflow_o) fail("overflow_o not set by an overflowing frame");
    // Coverage: equal X on a line, order changes between lines, empty and full lines.
    for (int y = 0; y < f.height; ++y) {
      const Line& l = x.lines[y];
      tot.empty_lines += l.empty();
      tot.full_lines += static_cast<int>(l.size()) == N;
      for (std::size_t i = 1; i < l.size(); ++i) tot.ties += l[i].value[fmt::ChanX] == l[i - 1].value[fmt::ChanX];
      if (y > 0 && x.lines[y - 1].size() == l.size())
        for (std::size_t i = 1; i < l.size(); ++i) tot.crossings += x.lines[y - 1][i].poly != l[i].poly;
    }
    tot.overflow_frames += x.ov_line >= 0;
    ++tot.frames;
    tot.cycles += h.cycles - start;
    tot.ideal += x.ideal_cycles;
  }

  void check_line(const Expect& x, int line, const Line& got) {
    const std::string where = "frame " + std::to_string(tot.frames) + " line " + std::to_string(line) + ": ";
    if (x.ov_line < 0 || line < x.ov_line) {
      if (got != x.lines[line]) fail(where + "rtl " + show(got) + " model " + show(x.lines[line]));
      return;
    }
    // After an overflow: which edge the RTL dropped depends on the insertion order of stepped and
    // new edges; the survivors must be the model's edges, in order, with their values.
    const Line& u = x.unbounded[line];
    std::size_t j = 0;
    for (const auto& e : got) {
      while (j < u.size() && !(u[j] == e)) ++j;
      if (j == u.size()) return fail(where + "after overflow, rtl " + show(got) + " not a subsequence of " + show(u));
      ++j;
    }
    if (line == x.ov_line && static_cast<int>(got.size()) != N)
      fail(where + "overflow line holds " + std::to_string(got.size()) + " edges, not MaxActiveEdges");
  }

  void report(const char* name) {
    auto u = [](std::uint64_t v) { return static_cast<unsigned long long>(v); };
    std::printf("%s: %llu frames (%llu overflowing), %llu lines (%llu empty, %llu full), %llu edge records in,"
                " %llu active edges checked (%llu equal-X neighbours, %llu order changes), %llu cycles"
                " (%.2f x active+new+6 per line)\n",
                name, u(tot.frames), u(tot.overflow_frames), u(tot.lines), u(tot.empty_lines), u(tot.full_lines),
                u(tot.records_in), u(tot.edges_out), u(tot.ties), u(tot.crossings), u(tot.cycles),
                tot.ideal ? double(tot.cycles) / double(tot.ideal) : 0.0);
    EXPECT_EQ(bad, 0);
  }
};

// ------------------------------------------------------------ directed frames

EdgeFrame empty_frame(int height) {
  EdgeFrame f;
  f.height = height;
  return f;
}

// N edges starting on one line with equal X and slope: order by id on every line; they retire
// at different lines.
EdgeFrame same_line_ties(std::mt19937_64& rng, int height, int y0) {
  EdgeFrame f;
  f.height = height;
  const i64 x = rnd(rng, -4 * One, 40 * One), dx = rnd(rng, -One, One);
  for (int i = 0; i < N; ++i) f.edges.push_back(edge(rng, y0, 1 + static_cast<int>(rng() % (height - y0)), x, dx));
  sort_and_number(f);
  return f;
}

// Edges whose X order reverses (and ties) between lines: x_i = i, slope -i/2.
EdgeFrame crossing(std::mt19937_64& rng, int height, int count) {
  EdgeFrame f;
  f.height = height;
  for (int i = 0; i < count; ++i) f.edges.push_back(edge(rng, 0, height, i * One, -i * (One / 2)));
  for (int i = 0; i < count / 2; ++i)  // a second group, starting later, crossing the first
    f.edges.push_back(edge(rng, 3, height - 3, 2 * One - i * One, i * One));
  sort_and_number(f);
  return f;
}

// n = 1 edges on every line, edges on line 0 and on the last line, empty lines between.
EdgeFrame sparse_lines(std::mt19937_64& rng, int height) {
  EdgeFrame f;
  f.height = height;
  f.edges.push_back(edge(rng, 0, 1, 5 * One, 0));
  f.edges.push_back(edge(rng, 0, 1, 5 * One, 0));
  f.edges.push_back(edge(rng, 0, height, -3 * One, One / 3));
  for (int y = 4; y < height - 1; y += 5) f.edges.push_back(edge(rng, y, 1, rnd(rng, 0, 20 * One), 0));
  f.edges.push_back(edge(rng, height - 1, 1, 7 * One, 0));
  f.edges.push_back(edge(rng, height - 1, 9, 7 * One, One));
  f.edges.push_back(edge(rng, height - 1, 1, 6 * One, 0));
  sort_and_number(f);
  return f;
}

// The longest frame: edges over all 4096 lines, one starting on line 4095.
EdgeFrame tall_frame(std::mt19937_64& rng) {
  EdgeFrame f;
  f.height = fmt::MaxScreen;
  f.edges.push_back(edge(rng, 0, fmt::MaxScreen, 0, One / 64));
  f.edges.push_back(edge(rng, 0, fmt::MaxScreen, 64 * One, -One / 64));
  f.edges.push_back(edge(rng, 2047, 1, 3 * One, 0));
  f.edges.push_back(edge(rng, fmt::MaxScreen - 1, 1, 3 * One, 0));
  sort_and_number(f);
  return f;
}

// Exactly N active, stepped and new edges together: N - 1 long edges from line 0, one more on
// line 3; then N edges starting on the line where N others retire.
EdgeFrame exactly_full(std::mt19937_64& rng) {
  EdgeFrame f;
  f.height = 12;
  for (int i = 0; i < N - 1; ++i) f.edges.push_back(edge(rng, 0, 6, rnd(rng, 0, 30 * One), rnd(rng, -One, One)));
  f.edges.push_back(edge(rng, 3, 3, rnd(rng, 0, 30 * One), rnd(rng, -One, One)));
  for (int i = 0; i < N; ++i) f.edges.push_back(edge(rng, 6, 6, rnd(rng, 0, 30 * One), rnd(rng, -One, One)));
  sort_and_number(f);
  return f;
}

// N + 1 edges starting on one line with nothing else active: the last record is dropped (as the
// model's refused insert), the output stays exact.
EdgeFrame one_too_many_same_line(std::mt19937_64& rng, int y0) {
  EdgeFrame f;
  f.height = y0 + 6;
  for (int i = 0; i <= N; ++i) f.edges.push_back(edge(rng, y0, 1 + static_cast<int>(rng() % 6), rnd(rng, 0, 30 * One), rnd(rng, -One, One)));
  sort_and_number(f);
  return f;
}

// N active edges stepping on, one more starting later: some edge is dropped.
EdgeFrame one_too_many_mixed(std::mt19937_64& rng) {
  EdgeFrame f;
  f.height = 10;
  for (int i = 0; i < N; ++i) f.edges.push_back(edge(rng, 0, 10, rnd(rng, 0, 30 * One), rnd(rng, -One, One)));
  f.edges.push_back(edge(rng, 4, 3, rnd(rng, 0, 30 * One), 0));
  f.edges.push_back(edge(rng, 8, 2, rnd(rng, 0, 30 * One), 0));
  sort_and_number(f);
  return f;
}

// A y-sorted random frame with late records (y0 below the record before them) put in: the RTL
// reads and skips them; their stream positions still count as edge ids (ties break by id).
EdgeFrame with_late_records(std::mt19937_64& rng, EdgeFrame f, int count) {
  for (int k = 0; k < count && !f.edges.empty(); ++k) {
    const std::size_t at = 1 + rng() % f.edges.size();
    const int before = f.edges[at - 1].y0;
    if (before == 0) continue;
    const int y0 = static_cast<int>(rng() % static_cast<unsigned>(std::min(before, f.height)));
    f.edges.insert(f.edges.begin() + static_cast<long>(at), edge(rng, y0, 1 + static_cast<int>(rng() % 8),
                                                                  rnd(rng, 0, 30 * One), 0));
  }
  for (std::size_t i = 0; i < f.edges.size(); ++i) f.edges[i].id = static_cast<int>(i);
  return f;
}

}  // namespace

TEST(RtlActiveEdgeList, LateRecordsSkipped) {
  Ael a(6);
  for (int i = 0; i < 600; ++i) {
    const EdgeFrame base = random_frame(a.rng, 2 + static_cast<int>(a.rng() % 30), static_cast<int>(a.rng() % (2 * N)),
                                        static_cast<Values>(i % 3));
    const EdgeFrame f = with_late_records(a.rng, base, 1 + static_cast<int>(a.rng() % 6));
    a.frame(f, (i % 3) * 30, (i % 4) * 25, i % 5 == 0);
  }
  a.report("active_edge_list late records");
}

TEST(RtlActiveEdgeList, DirectedCorners) {
  for (int pass = 0; pass < 3; ++pass) {
    Ael a(10 + pass);
    const int gap = pass == 0 ? 0 : 30, bp = pass == 0 ? 0 : (pass == 1 ? 30 : 75);
    auto& rng = a.rng;
    a.frame(empty_frame(1), gap, bp);  // only EOF
    a.frame(empty_frame(7), gap, bp);
    a.frame(empty_frame(1), gap, bp, true);
    for (int y0 : {0, 5, 9}) a.frame(same_line_ties(rng, 10, y0), gap, bp, true);
    a.frame(crossing(rng, 24, 10), gap, bp);  // 10 + 5 edges: fits
    a.frame(crossing(rng, 9, 6), gap, bp);
    a.frame(sparse_lines(rng, 23), gap, bp, true);
    a.frame(sparse_lines(rng, 2), gap, bp);
    {  // a single edge on a single line
      EdgeFrame f;
      f.height = 1;
      f.edges.push_back(edge(rng, 0, 1, One, 0));
      a.frame(f, gap, bp);
    }
    a.frame(exactly_full(rng), gap, bp);
    a.frame(empty_frame(3), gap, bp);
    a.frame(tall_frame(rng), gap, bp);
    a.report("active_edge_list directed");
  }
}

TEST(RtlActiveEdgeList, Capacity) {
  Ael a(20);
  auto& rng = a.rng;
  // Exactly full, on line 0 and on the last line, at full rate and under stalls.
  for (int bp : {0, 50}) {
    EdgeFrame f;
    f.height = 5;
    for (int i = 0; i < N; ++i) f.edges.push_back(edge(rng, 0, 5, rnd(rng, 0, 4) * One, rnd(rng, -1, 1) * One));
    sort_and_number(f);
    a.frame(f, bp, bp);
    EdgeFrame g;
    g.height = 5;
    for (int i = 0; i < N; ++i) g.edges.push_back(edge(rng, 4, 1, rnd(rng, 0, 4) * One, 0));
    sort_and_number(g);
    a.frame(g, bp, bp);
    a.frame(exactly_full(rng), bp, bp);
  }
  EXPECT_FALSE(a.h.dut.overflow_o);
  // One more than fits, all new on one line: the last one dropped, sticky flag.
  a.frame(one_too_many_same_line(rng, 0), 20, 20);
  EXPECT_TRUE(a.h.dut.overflow_o);
  a.frame(one_too_many_same_line(rng, 3), 0, 0);
  a.frame(random_frame(rng, 20, 40, Values::Realistic), 20, 20);  // exact output, flag stays set
  EXPECT_TRUE(a.h.dut.overflow_o);
  a.frame(empty_frame(4), 0, 0);
  EXPECT_TRUE(a.h.dut.overflow_o);
  a.reset();
  // Stepped edges competing with a new one: survivors checked, flag set from that line on.
  for (int i = 0; i < 6; ++i) {
    a.frame(one_too_many_mixed(rng), i % 2 ? 40 : 0, i % 3 ? 40 : 0);
    EXPECT_TRUE(a.h.dut.overflow_o);
    a.frame(random_frame(rng, 12, 30, Values::Ties), 10, 10);
    a.reset();
  }
  // Random frames allowed twice the capacity.
  for (int i = 0; i < 400; ++i) {
    a.frame(random_frame(rng, 2 + static_cast<int>(rng() % 20), 3 * N, Values::Ties, 2 * N), 25, 25);
    if (rng() % 2) a.reset();
  }
  a.reset();
  a.frame(exactly_full(rng), 0, 0);
  EXPECT_FALSE(a.h.dut.overflow_o);
  a.report("active_edge_list capacity");
}

TEST(RtlActiveEdgeList, RandomFramesFullRate) {
  Ael a(1);
  for (int i = 0; i < 3000; ++i) {
    const Values v = static_cast<Values>(i % 3);
    a.frame(random_frame(a.rng, 1 + static_cast<int>(a.rng() % 40), static_cast<int>(a.rng() % (3 * N)), v, N, false), 0, 0);
  }
  a.report("active_edge_list full rate");
  // About (active + new edges + 7) cycles per line when nothing stalls (rtl/active_edge_list.sv).
  EXPECT_LT(double(a.tot.cycles), 1.25 * double(a.tot.ideal) + 4.0 * double(a.tot.frames));
}

TEST(RtlActiveEdgeList, RandomFramesGapsAndBackPressure) {
  Ael a(2);
  for (int i = 0; i < 4000; ++i) {
    const Values v = static_cast<Values>(i % 3);
    a.frame(random_frame(a.rng, 1 + static_cast<int>(a.rng() % 40), static_cast<int>(a.rng() % (3 * N)), v), 40, 40,
            i % 4 == 0);
  }
  a.report("active_edge_list gaps and back-pressure");
}

TEST(RtlActiveEdgeList, HeavyBackPressure) {
  Ael a(3);
  for (int i = 0; i < 1500; ++i)
    a.frame(random_frame(a.rng, 1 + static_cast<int>(a.rng() % 30), static_cast<int>(a.rng() % (3 * N)),
                         static_cast<Values>(i % 3)),
            5, 85);
  a.report("active_edge_list heavy back-pressure");
}

TEST(RtlActiveEdgeList, HeavyInputGaps) {
  Ael a(4);
  for (int i = 0; i < 1500; ++i)
    a.frame(random_frame(a.rng, 1 + static_cast<int>(a.rng() % 30), static_cast<int>(a.rng() % (3 * N)),
                         static_cast<Values>(i % 3)),
            85, 5);
  a.report("active_edge_list heavy input gaps");
}

TEST(RtlActiveEdgeList, PreparedScenes) {
  Ael a(5);
  for (int i = 0; i < 1500; ++i) a.frame(prepared_frame(a.rng, i % 2 == 1), (i % 3) * 25, (i % 4) * 20, i % 5 == 0);
  a.report("active_edge_list prepared scenes");
}
