// The board bench (board_bench.hpp).
#include "board_bench.hpp"

#include <array>
#include <chrono>
#include <stdexcept>

#include "Vulx3s_top.h"
#include "Vulx3s_top___024root.h"
#include "Vulx3s_top_native.h"
#include "Vulx3s_top_native___024root.h"
#include "Vulx3s_top_phong.h"
#include "Vulx3s_top_phong___024root.h"
#include "verilated.h"

namespace watkins::board_tb {
namespace {

// One period of the three clocks: 400 ticks = 8 pixel clocks = 25 pipeline clocks = 40 TMDS
// clocks. Each entry is a tick at which some clock toggles and the three levels after it.
struct ClockEvent {
  int tick;
  bool tmds, pixel, pipe;
  bool pixel_rise, pipe_rise;
};
constexpr int PeriodTicks = 400;

std::vector<ClockEvent> clock_events(bool tmds_clock) {
  std::vector<ClockEvent> events;
  for (int t = 0; t < PeriodTicks; ++t) {
    const bool tmds_edge = tmds_clock && t % 5 == 0, pixel_edge = t % 25 == 0, pipe_edge = t % 8 == 0;
    if (!tmds_edge && !pixel_edge && !pipe_edge) continue;
    ClockEvent e;
    e.tick = t;
    e.tmds = tmds_clock && (t / 5) % 2 == 0;
    e.pixel = (t / 25) % 2 == 0;
    e.pipe = (t / 8) % 2 == 0;
    e.pixel_rise = pixel_edge && e.pixel;
    e.pipe_rise = pipe_edge && e.pipe;
    events.push_back(e);
  }
  return events;
}

}  // namespace

VideoSample expected_video(long long k) {
  const long long h = k % LineClocks, v = (k / LineClocks) % FrameLines;
  VideoSample s;
  s.de = h < VideoWidth && v < VideoHeight;
  s.hsync_n = !(h >= 656 && h < 752);
  s.vsync_n = !(v >= 490 && v < 492);
  return s;
}

Image doubled(const Image& frame, int doubling) {
  Image out(frame.width * doubling, frame.height * doubling);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 3; ++c)
        out.rgb[(std::size_t(y) * out.width + x) * 3 + c] =
            frame.rgb[(std::size_t(y / doubling) * frame.width + x / doubling) * 3 + c];
  return out;
}

template <class Model>
BoardRun run_top(std::unique_ptr<VerilatedContext>& context, const BoardOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  context = std::make_unique<VerilatedContext>();
  std::vector<std::string> args{"board_bench"};
  if (!opt.bank_file.empty()) args.push_back("+watkins_bank=" + opt.bank_file);
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  context->commandArgs(static_cast<int>(argv.size()), argv.data());
  auto dut = std::make_unique<Model>(context.get());
  auto& root = *dut->rootp;
  auto& clk_tmds = root.ulx3s_top__DOT__u_pll__DOT__u_ehxplll__DOT__clkop;
  auto& clk_pixel = root.ulx3s_top__DOT__u_pll__DOT__u_ehxplll__DOT__clkos;
  auto& clk_pipe = root.ulx3s_top__DOT__u_pll__DOT__u_ehxplll__DOT__clkos2;

  BoardRun r;
  const std::vector<ClockEvent> events = clock_events(opt.tmds_clock);
  // Before tick 0 every clock is low, so tick 0 is a rising edge of all three.
  clk_tmds = clk_pixel = clk_pipe = 0;
  root.ulx3s_top__DOT__u_pll__DOT__u_ehxplll__DOT__lock = 1;
  dut->btn = 1;  // btn[0] (PWR) up
  dut->ftdi_txd = 1;
  dut->clk_25mhz = 0;
  dut->eval();

  long long pixel_clock = 0, pipe_clock = 0;
  long long cycle_ticks = 0;  // the tick at which this period of the clocks starts
  const long long frames = opt.video_frames;
  long long frame_pixels_left = -1;  // pixel clocks still to capture once the first is seen
  long long start_clock = -1;
  bool last_request = false;
  Image* frame = nullptr;
  for (;;) {
    for (const ClockEvent& e : events) {
      // The values the coming edges sample.
      if (e.pipe_rise) {
        if (root.ulx3s_top__DOT__start_pulse) {
          start_clock = pipe_clock;
          r.start_clocks.push_back(pipe_clock);
        }
        if (root.ulx3s_top__DOT__frame_begin) r.begin_clocks.push_back(pipe_clock);
        if (root.ulx3s_top__DOT__line_done)
          r.lines.push_back({root.ulx3s_top__DOT__w_q, pipe_clock, start_clock < 0 ? -1 : pipe_clock - start_clock});
      }
      if (e.pixel_rise && root.ulx3s_top__DOT__line_missed)
        r.missed.push_back({root.ulx3s_top__DOT__s_q, pixel_clock});
      if (opt.ftdi_txd) dut->ftdi_txd = opt.ftdi_txd((static_cast<double>(cycle_ticks) + e.tick) / 1.26e9);
      const bool begin = e.pipe_rise && root.ulx3s_top__DOT__frame_begin;
      clk_tmds = e.tmds;
      clk_pixel = e.pixel;
      clk_pipe = e.pipe;
      dut->eval();
      ++r.evals;
      if (begin) r.begin_banks.push_back(root.ulx3s_top__DOT__bank_active);  // as the edge swapped it
      if (e.pipe_rise) ++pipe_clock;
      if (!e.pixel_rise) continue;
      // The encoders' inputs of this pixel clock.
      const bool request = root.ulx3s_top__DOT__request_toggle_q;
      if (request != last_request) r.request_pixel_clocks.push_back(pixel_clock);
      last_request = request;
      VideoSample s;
      s.de = root.ulx3s_top__DOT__enc_de_q;
      s.hsync_n = root.ulx3s_top__DOT__enc_hsync_nq;
      s.vsync_n = root.ulx3s_top__DOT__enc_vsync_nq;
      if (r.first_visible < 0 && s.de) {
        r.first_visible = pixel_clock;
        frame_pixels_left = frames * FrameClocks;
        if (opt.record_video) r.video.reserve(static_cast<std::size_t>(frame_pixels_left));
      }
      if (r.first_visible >= 0) {
        const long long k = pixel_clock - r.first_visible;
        const long long h = k % LineClocks, v = (k / LineClocks) % FrameLines;
        if (h == 0 && v == 0) {
          r.frames.emplace_back(VideoWidth, VideoHeight);
          frame = &r.frames.back();
        }
        if (opt.record_video) r.video.push_back(s);
        if (s.de && h < VideoWidth && v < VideoHeight) {
          const std::uint32_t rgb = root.ulx3s_top__DOT__enc_rgb;
          std::uint8_t* p = &frame->rgb[(std::size_t(v) * VideoWidth + std::size_t(h)) * 3];
          p[0] = std::uint8_t(rgb >> 16);
          p[1] = std::uint8_t(rgb >> 8);
          p[2] = std::uint8_t(rgb);
        }
        --frame_pixels_left;
        if (opt.on_frame && k % FrameClocks == FrameClocks - 1) {
          r.pixel_clocks = pixel_clock + 1;
          r.pipe_clocks = pipe_clock;
          r.missed_count = root.ulx3s_top__DOT__missed_count_q;
          r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          opt.on_frame(r);
        }
      }
      ++pixel_clock;
      if (frame_pixels_left == 0) break;
    }
    if (frame_pixels_left == 0) break;
    cycle_ticks += PeriodTicks;
    if (context->gotFinish()) throw std::runtime_error("board bench: the RTL called $finish");
  }
  r.missed_count = root.ulx3s_top__DOT__missed_count_q;
  r.link_frames = root.ulx3s_top__DOT__link_frames;
  r.link_errors = root.ulx3s_top__DOT__link_errors;
  r.overflow = root.ulx3s_top__DOT__overflow;
  r.pixel_clocks = pixel_clock;
  r.pipe_clocks = pipe_clock;
  dut->final();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

TopBuild top_build(BoardTop top) {
  if (top == BoardTop::Native) return {WATKINS_BOARD_NATIVE_CONFIG, ShadingMode::Gouraud, 1, WATKINS_BOARD_BANK_WORDS};
  if (top == BoardTop::Phong)
    return {WATKINS_BOARD_PHONG_CONFIG, ShadingMode::Phong, WATKINS_BOARD_DOUBLING, WATKINS_BOARD_BANK_WORDS};
  return {WATKINS_BOARD_DEFAULT_CONFIG, ShadingMode::Gouraud, WATKINS_BOARD_DOUBLING, WATKINS_BOARD_BANK_WORDS};
}

BoardBench::BoardBench(BoardTop top) : top_(top), context_(std::make_unique<VerilatedContext>()) {}
BoardBench::~BoardBench() = default;

BoardRun BoardBench::run(const BoardOptions& options) {
  switch (top_) {
    case BoardTop::Native: return run_top<Vulx3s_top_native>(context_, options);
    case BoardTop::Phong: return run_top<Vulx3s_top_phong>(context_, options);
    case BoardTop::Default: break;
  }
  return run_top<Vulx3s_top>(context_, options);
}

}  // namespace watkins::board_tb
