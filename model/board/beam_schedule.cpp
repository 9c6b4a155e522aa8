#include "beam_schedule.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "cycle_model.hpp"

namespace watkins::board {
namespace {

long long floor_div(long long a, long long b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }

// The frame's fixed pixel edges, video frame f: the request at (639, 479) (the last visible
// pixel), a rendered line's release at h = 639 on its last video line, its start at h = 799 on
// the video line before its first.
class Video {
 public:
  Video(int doubling, int start) : d_(doubling), lines_(VVisible / doubling), start_(start) {}

  long long request(int f) const { return start_ + f * FramePixelClocks + (VVisible - 1) * HTotal + (HVisible - 1); }
  long long check(int frame, int y) const {
    return start_ + (y == 0 ? frame * FramePixelClocks + (VTotal - 1) * HTotal + (HTotal - 1)
                            : (frame + 1) * FramePixelClocks + static_cast<long long>(d_ * y - 1) * HTotal + (HTotal - 1));
  }
  // Releases at pixel edges up to m. The request arms the counts: video frame 0 releases nothing
  // (its request is at its last release's edge, which sees the count not yet armed).
  long long releases_by(long long m) const {
    m -= start_;
    if (m < 0) return 0;
    const long long f = m / FramePixelClocks, pos = m % FramePixelClocks;
    if (f == 0) return 0;
    const long long v = floor_div(pos - (HVisible - 1), HTotal);  // last video line released by pos
    const long long in_frame = std::clamp<long long>(floor_div(v - d_ + 1, d_) + 1, 0, lines_);
    return (f - 1) * lines_ + in_frame;
  }

 private:
  int d_, lines_, start_;
};

// pixel_ready_i on the board: the slot of the line being written is free, (w - r_sync) < S,
// signed in line_count_bits; w from the pixels this frame took, r_sync the releases visible at
// the pipeline edge.
class LineBufferReady : public PixelReady {
 public:
  LineBufferReady(const BoardTiming& t, long long first_beat, long long lines_before, int width)
      : t_(t), first_beat_(first_beat), lines_before_(lines_before), width_(width) {}

  bool ready(long long cycle, long long taken) override {
    const long long edge = first_beat_ + cycle;
    const long long w = lines_before_ + taken / width_;
    const long long r = releases_seen(t_, edge);
    const long long span = 1LL << t_.line_count_bits;
    long long in_use = (w - r) & (span - 1);
    if (in_use >= span / 2) in_use -= span;
    return in_use < t_.line_slots;
  }

 private:
  const BoardTiming& t_;
  long long first_beat_, lines_before_;
  int width_;
};

}  // namespace

long long first_edge_after(long long tick, long long period) { return floor_div(tick, period) + 1; }

long long visible_from(long long tick, long long period, int stages) { return first_edge_after(tick, period) + stages; }

long long releases_seen(const BoardTiming& t, long long edge) {
  // Releases at pixel edges m with t_pixel m < t_pipe (edge - stages): visible_from <= edge.
  const long long limit = static_cast<long long>(t.ticks_per_pipe) * (edge - t.count_stages);
  return limit <= 0 ? 0 : Video(t.doubling, t.video_start).releases_by(floor_div(limit - 1, t.ticks_per_pixel));
}

BoardTiming board_timing(Board board) {
  BoardTiming t;
  if (board == Board::Icebreaker) {
    t.ticks_per_pixel = t.ticks_per_pipe = 1;
    t.sync_stages = t.count_stages = 0;
    t.ticks_per_us = 25.125;
    t.bank_read_bits = 64;
  }
  return t;
}

int start_to_first_beat(const Config& cfg) { return 11 + (1 << id_bits(cfg.max_materials)); }

int spram_start_to_first_beat(const Config& cfg, int parts) { return 10 + (1 << id_bits(cfg.max_materials)) + parts; }

double BeamSchedule::budget_per_line() const {
  return static_cast<double>(timing.doubling) * HTotal * timing.ticks_per_pixel / timing.ticks_per_pipe;
}

BeamSchedule beam_schedule(const Frame& frame, const Config& cfg, const BoardTiming& timing) {
  BoardTiming t = timing;
  if (t.doubling != 1 && t.doubling != 2)
    throw std::invalid_argument("board: doubling " + std::to_string(t.doubling) + " (1 or 2)");
  if (t.line_slots < 1 || (t.line_slots & (t.line_slots - 1)) != 0 || t.line_slots >= (1 << (t.line_count_bits - 1)))
    throw std::invalid_argument("board: line slots " + std::to_string(t.line_slots) + " (a power of two)");
  if (t.frames < 3) throw std::invalid_argument("board: frames " + std::to_string(t.frames) + " (at least 3)");
  if (t.ticks_per_pixel < 1 || t.ticks_per_pipe < 1 || t.sync_stages < 0 || t.count_stages < 0 || t.video_start < 0)
    throw std::invalid_argument("board: clock periods must be positive and synchronizer stages not negative");
  const int width = HVisible / t.doubling, height = VVisible / t.doubling;
  if (frame.width != width)
    throw std::invalid_argument("board: screen width " + std::to_string(frame.width) + " (doubling " +
                                std::to_string(t.doubling) + " shows " + std::to_string(width) + ")");
  if (frame.height != height)
    throw std::invalid_argument("board: screen height " + std::to_string(frame.height) + " (doubling " +
                                std::to_string(t.doubling) + " shows " + std::to_string(height) + ")");
  if (t.bank_read_bits < 0) throw std::invalid_argument("board: bank read bits " + std::to_string(t.bank_read_bits));
  // A record's reads from the bank: its pace into the top.
  const int parts = t.bank_read_bits > 0
                        ? (cfg.edge_record_bits(frame.shading) + t.bank_read_bits - 1) / t.bank_read_bits
                        : 0;
  if (t.start_to_first_beat < 0)
    t.start_to_first_beat = parts > 0 ? spram_start_to_first_beat(cfg, parts) : start_to_first_beat(cfg);

  const Video video(t.doubling, t.video_start);
  BeamSchedule s;
  s.width = width;
  s.height = height;
  std::vector<long long> takes;
  for (int k = 0; k < t.frames; ++k) {
    FrameRun run;
    run.request = video.request(k);
    run.start_pulse = visible_from(run.request * t.ticks_per_pixel, t.ticks_per_pipe, t.sync_stages);
    run.begin = k == 0 ? run.start_pulse : std::max(run.start_pulse, s.frames.back().last_pixel + 1);
    run.first_beat = run.begin + t.start_to_first_beat;
    LineBufferReady ready(t, run.first_beat, static_cast<long long>(k) * height, width);
    CycleOptions opt;
    opt.output = PixelOutput::FullFrame;
    opt.max_active_edges = cfg.max_active_edges;
    opt.pixel_ready = &ready;
    if (parts > 0) {
      opt.edge_interval = parts;
      opt.edge_gap = 2;
    }
    takes.clear();
    opt.take_cycles = &takes;
    const CyclePrediction c = predict_cycles(frame, cfg, opt);
    if (static_cast<long long>(takes.size()) != static_cast<long long>(width) * height)
      throw std::logic_error("board: the frame took " + std::to_string(takes.size()) + " pixels, not " +
                             std::to_string(width * height));
    run.last_pixel = run.first_beat + c.cycles - 1;
    for (int y = 0; y < height; ++y) {
      LineSlack l;
      l.frame = k;
      l.y = y;
      l.completion = run.first_beat + takes[std::size_t(y) * width + width - 1];
      l.check = video.check(k, y);
      // The last pipeline edge E with visible_from(t_pipe E, t_pixel) <= check.
      l.deadline = floor_div(static_cast<long long>(t.ticks_per_pixel) * (l.check - t.count_stages) - 1, t.ticks_per_pipe);
      l.slack = l.deadline - l.completion;
      l.missed = l.slack < 0;
      s.missed += l.missed;
      if (s.lines.empty() || l.slack < s.lines[s.worst].slack) s.worst = s.lines.size();
      s.lines.push_back(l);
    }
    s.frames.push_back(run);
  }
  s.timing = t;
  return s;
}

}  // namespace watkins::board
