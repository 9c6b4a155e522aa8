// The iCEBreaker bench (icebreaker_bench.hpp).
#include "icebreaker_bench.hpp"

#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "flash_image.hpp"
#include "spi_flash.hpp"

#include "Vicebreaker_top.h"
#include "Vicebreaker_top___024root.h"
#include "Vicebreaker_top_pipelined.h"
#include "Vicebreaker_top_pipelined___024root.h"
#ifdef WATKINS_ICEBREAKER_PHONG_CONFIG
#include "Vicebreaker_top_phong.h"
#include "Vicebreaker_top_phong___024root.h"
#endif
#include "verilated.h"

namespace watkins::board_tb {
namespace {

template <class Model>
IcebreakerRun run_top(std::unique_ptr<VerilatedContext>& context, const IcebreakerOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  context = std::make_unique<VerilatedContext>();
  SpiFlash flash(opt.flash, board::SpramBank::FlashAddress);
  auto dut = std::make_unique<Model>(context.get());
  auto& root = *dut->rootp;
  auto& clk = root.icebreaker_top__DOT__u_pll__DOT__u_sb_pll40_pad__DOT__clk;

  IcebreakerRun out;
  BoardRun& r = out.run;
  clk = 0;  // low before clock 0's rising edge
  root.icebreaker_top__DOT__u_pll__DOT__u_sb_pll40_pad__DOT__lock = 1;
  dut->btn_n = 1;
  dut->clk_12mhz = 0;
  dut->flash_miso = 0;
  dut->eval();

  const long long frames = opt.video_frames;
  long long frames_left = -1;  // clocks still to capture once the first visible pixel is seen
  long long start_clock = -1;
  bool last_request = false;
  Image* frame = nullptr;
  for (long long m = 0;; ++m) {
    // The values the rising edge samples.
    if (root.icebreaker_top__DOT__start_pulse) {
      start_clock = m;
      r.start_clocks.push_back(m);
    }
    if (root.icebreaker_top__DOT__frame_begin) r.begin_clocks.push_back(m);
    if (root.icebreaker_top__DOT__line_done)
      r.lines.push_back({root.icebreaker_top__DOT__w_q, m, start_clock < 0 ? -1 : m - start_clock});
    if (root.icebreaker_top__DOT__line_missed) r.missed.push_back({root.icebreaker_top__DOT__s_q, m});
    clk = 1;
    dut->eval();
    ++r.evals;
    // The flash sees the pins the edge set and answers before the next one.
    flash.pins(dut->flash_ss_n, dut->flash_sck, dut->flash_mosi);
    dut->flash_miso = flash.miso();
    const bool clock_low = dut->dvi_clk == 0;
    const bool request = root.icebreaker_top__DOT__request_toggle_q;
    if (request != last_request) r.request_pixel_clocks.push_back(m);
    last_request = request;
    // The pins after the rising edge.
    VideoSample s;
    s.de = dut->dvi_de;
    s.hsync_n = dut->dvi_hsync;
    s.vsync_n = dut->dvi_vsync;
    if (r.first_visible < 0 && s.de) {
      r.first_visible = m;
      frames_left = frames * FrameClocks;
      if (opt.record_video) r.video.reserve(static_cast<std::size_t>(frames_left));
    }
    if (r.first_visible >= 0) {
      const long long k = m - r.first_visible;
      const long long h = k % LineClocks, v = (k / LineClocks) % FrameLines;
      if (h == 0 && v == 0) {
        r.frames.emplace_back(VideoWidth, VideoHeight);
        frame = &r.frames.back();
      }
      if (opt.record_video) r.video.push_back(s);
      if (s.de && h < VideoWidth && v < VideoHeight) {
        std::uint8_t* p = &frame->rgb[(std::size_t(v) * VideoWidth + std::size_t(h)) * 3];
        p[0] = std::uint8_t(dut->dvi_r << 4);
        p[1] = std::uint8_t(dut->dvi_g << 4);
        p[2] = std::uint8_t(dut->dvi_b << 4);
      }
      --frames_left;
    }
    clk = 0;
    dut->eval();
    ++r.evals;
    out.dvi_clk_bad += !(clock_low && dut->dvi_clk == 1);
    if (opt.on_frame && r.first_visible >= 0 && (m - r.first_visible) % FrameClocks == FrameClocks - 1) {
      r.pixel_clocks = r.pipe_clocks = m + 1;
      r.missed_count = root.icebreaker_top__DOT__missed_count_q;
      r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      opt.on_frame(r);
    }
    if (frames_left == 0) {
      r.pixel_clocks = r.pipe_clocks = m + 1;
      break;
    }
    if (context->gotFinish()) throw std::runtime_error("icebreaker bench: the RTL called $finish");
  }
  out.flash_bits = flash.bits_read();
  out.flash_bad_commands = flash.bad_commands();
  r.missed_count = root.icebreaker_top__DOT__missed_count_q;
  r.overflow = root.icebreaker_top__DOT__overflow;
  dut->final();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace

bool top_built(IcebreakerTop top) {
#ifdef WATKINS_ICEBREAKER_PHONG_CONFIG
  (void)top;
  return true;
#else
  return top != IcebreakerTop::Phong;
#endif
}

TopBuild top_build(IcebreakerTop top) {
  switch (top) {
    case IcebreakerTop::Compact: break;
    case IcebreakerTop::Pipelined:
      return {WATKINS_ICEBREAKER_PIPELINED_CONFIG, ShadingMode::Gouraud, 2, WATKINS_ICEBREAKER_BANK_WORDS};
    case IcebreakerTop::Phong:
#ifdef WATKINS_ICEBREAKER_PHONG_CONFIG
      return {WATKINS_ICEBREAKER_PHONG_CONFIG, ShadingMode::Phong, 2, WATKINS_ICEBREAKER_BANK_WORDS};
#else
      throw std::logic_error("icebreaker bench: this build has no Phong top (WATKINS_BOARD_ICEBREAKER_PHONG_CONFIG)");
#endif
  }
  return {WATKINS_ICEBREAKER_CONFIG, ShadingMode::Gouraud, 2, WATKINS_ICEBREAKER_BANK_WORDS};
}

IcebreakerBench::IcebreakerBench(IcebreakerTop top) : top_(top), context_(std::make_unique<VerilatedContext>()) {}
IcebreakerBench::~IcebreakerBench() = default;

IcebreakerRun IcebreakerBench::run(const IcebreakerOptions& options) {
  switch (top_) {
    case IcebreakerTop::Pipelined: return run_top<Vicebreaker_top_pipelined>(context_, options);
    case IcebreakerTop::Phong:
#ifdef WATKINS_ICEBREAKER_PHONG_CONFIG
      return run_top<Vicebreaker_top_phong>(context_, options);
#else
      (void)top_build(top_);  // throws: not built
      break;
#endif
    case IcebreakerTop::Compact: break;
  }
  return run_top<Vicebreaker_top>(context_, options);
}

}  // namespace watkins::board_tb
