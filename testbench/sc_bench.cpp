// SystemC bench (sc_bench.hpp): the Verilated (--sc) watkins_top bound to sc_signals and clocked
// by one SC_THREAD that also runs the drive loop (frame_driver.hpp) through TopPins on the signals.
// Two Verilated builds of the one top: Phong = 0 (Vwatkins_top) and Phong = 1
// (Vwatkins_top_phong), each in its own bench module; a run clocks only the one its scenes need.
// Compiled with WATKINS_SC_SPEED=1 it is the speed build instead (sc_bench.hpp): the tops
// Vwatkins_top_sc_fast and Vwatkins_top_sc_fast_phong, Verilated without --assert and without
// tracing, and the functions in namespace sc_speed; nothing else differs.
//
// Why one thread and no sc_clock: the driver is the same plain C++ as the plain harness's
// (so both run identical checks and must agree on every cycle), a cycle is two timed waits with
// the model's SC_METHOD evaluating once per half cycle, and with no sc_clock the kernel starves
// when a run is over, so sc_start() returns after each run and the next run continues the same
// simulation. Speed is within ~1.3x of the plain harness, like the per-signal style
// (testbench/README.md has the measurement).
#include "sc_bench.hpp"

#include <cstdlib>
#include <functional>
#include <memory>
#include <stdexcept>

#include <systemc.h>
#include <verilated.h>
#include <verilated_fst_c.h>

#if WATKINS_SC_SPEED
#include "Vwatkins_top_sc_fast.h"
#include "Vwatkins_top_sc_fast___024root.h"  // the public internal stage signals
#include "Vwatkins_top_sc_fast_phong.h"
#include "Vwatkins_top_sc_fast_phong___024root.h"
#else
#include "Vwatkins_top.h"
#include "Vwatkins_top___024root.h"  // the public internal stage signals
#include "Vwatkins_top_phong.h"
#include "Vwatkins_top_phong___024root.h"
#endif
#include "config.hpp"
#include "expectations.hpp"
#include "formats.hpp"
#include "fst_trace.hpp"
#include "frame_driver.hpp"
#include "sc_top_signals.hpp"
#include "top_pins.hpp"
#include "verilated_stop.hpp"

// libsystemc's own main() calls sc_main; our programs have their own main() and run the kernel
// from ordinary code (run_rtl), but the shared library still needs the symbol. The speed build's
// is weak: a program may link both builds (watkins_rtl_speed_sc_fast links watkins_tb too).
#if WATKINS_SC_SPEED
__attribute__((weak))
#endif
int sc_main(int, char**) { return 0; }

namespace watkins::tb::detail {
namespace {

// The two tops of this build, and what run_systemc and systemc_description call them.
#if WATKINS_SC_SPEED
using GouraudTop = Vwatkins_top_sc_fast;
using PhongTop = Vwatkins_top_sc_fast_phong;
constexpr bool Asserts = false;
constexpr const char* BuildName = "speed build: no assertions, no tracing";
#else
using GouraudTop = Vwatkins_top;
using PhongTop = Vwatkins_top_phong;
constexpr bool Asserts = true;
constexpr const char* BuildName = "with assertions";
#endif

// The SystemC tops at their default parameters (not overridden in testbench/CMakeLists.txt but
// for Phong): the default configuration's.
constexpr int MaxWidth = fmt::DefaultMaxWidth;

template <class Dut>
struct TopBench : sc_module, TopPins {
  sc_signal<bool> clk{"clk"};
  TopSignals io;  // every other port
  Dut dut{"dut"};

  sc_event start;
  std::function<void()> job;  // runs inside the thread, so it may wait()
  bool job_done = false;

  SC_HAS_PROCESS(TopBench);
  explicit TopBench(sc_module_name name) : sc_module(name) {
    io.bind(dut, clk);
    SC_THREAD(main);
  }

  void main() {
    for (;;) {
      wait(start);
      job();
      job_done = true;
    }
  }

  // ---- TopPins (top_pins.hpp) ----
  void reset_pin(bool v) override { io.rst_n.write(v); }
  void frame_pins(std::uint32_t w, std::uint32_t h, std::uint32_t bg, bool sp, bool tie, std::uint32_t sw,
                  bool e2) override {
    io.width.write(w);
    io.height.write(h);
    io.background.write(bg);
    io.sparse.write(sp);
    io.tie_submission.write(tie);
    io.smooth_w.write(sw);
    io.eq2.write(e2);
  }
  void phong_pins(std::uint64_t l, std::uint64_t e) override {
    io.light.write(l);
    io.eye.write(e);
  }
  void material_pins(const MaterialPins& m) override {
    io.material_we.write(m.we);
    io.material_addr.write(m.addr);
    io.material_cp.write(m.cp);
    io.material_d.write(m.d);
    io.material_w.write(m.w);
    io.material_n.write(m.n);
  }
  void edge_pins(bool valid, bool eof, const EdgeWords& data) override {
    io.edge_valid.write(valid);
    io.edge_eof.write(eof);
    if (data != last_edge_) {  // a 466-bit sc_bv write is the costly one; skip it when unchanged
      last_edge_ = data;
      for (int i = 0; i < default_edge_layout().words; ++i) edge_bv_.set_word(i, data[i]);
      io.edge.write(edge_bv_);
    }
  }
  void ready_pin(bool v) override { io.pixel_ready.write(v); }
  void settle(std::uint64_t t) override {
    clk.write(false);
    wait(half_);
    trace_.dump(t);
  }
  PinsOut sample() override {
    PinsOut o;
    o.edge_ready = io.edge_ready.read();
    o.pixel_valid = io.pixel_valid.read();
    o.pixel_last = io.pixel_last.read();
    o.pixel_covered = io.pixel_covered.read();
    o.pixel_rgb = io.pixel_rgb.read();
    o.pixel_x = io.pixel_x.read();
    o.pixel_y = io.pixel_y.read();
    o.overflow = io.overflow.read();
    return o;
  }
  void posedge(std::uint64_t t) override {
    clk.write(true);
    wait(half_);
    trace_.dump(t);
  }
  bool stopped() override { return take_stop(*dut.contextp()); }
  bool trace_open(const std::string& path) override {
#if WATKINS_SC_SPEED
    (void)path;
    throw std::invalid_argument("RTL: --trace: the SystemC bench's speed build is Verilated without tracing");
#else
    return trace_.open(dut, path);
#endif
  }
  void trace_close() override { trace_.close(); }
  const StageTaps* stage_taps() override {
    if (!taps_.ae_valid) taps_ = detail::stage_taps(*dut.rootp);
    return &taps_;
  }

 private:
  const sc_time half_{5, SC_NS};
  EdgeWords last_edge_{};
  sc_bv<fmt::EdgeRecordBits> edge_bv_;
  FstTrace trace_;
  StageTaps taps_;
};

// One Verilated top, its bench module and its driver.
template <class Dut>
struct Side {
  TopBench<Dut>* top = nullptr;
  FrameDriver* driver = nullptr;
  explicit Side(const char* name) : top(new TopBench<Dut>(name)), driver(new FrameDriver(*top)) {}
};

struct Bench {
  Side<GouraudTop> gouraud{Asserts ? "watkins_tb" : "watkins_tb_speed"};
  Side<PhongTop> phong{Asserts ? "watkins_tb_phong" : "watkins_tb_speed_phong"};
  bool dead = false;
};

// The process's choice of power-up state for the bench's tops (rtl_initial_state()), and whether
// the tops exist already (then it is too late to choose).
struct InitialState {
  int seed = 0;
  bool built = false;
};
InitialState& initial_state() {
  static InitialState s;
  return s;
}

// Built once per process and never destroyed (SystemC cannot elaborate twice, and its kernel is
// torn down by static destructors in an order we do not control).
Bench& bench() {
  static Bench* b = [] {
    setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
    Verilated::traceEverOn(true);  // tracing can then be switched on for any later run
    Verilated::threadContextp()->fatalOnError(false);  // an assertion ends the run, not the process
    // The tops' constructors draw the initial value of every variable (--x-initial unique).
    const int seed = initial_state().seed;
    Verilated::threadContextp()->randReset(seed == 0 ? 0 : 2);
    if (seed != 0) Verilated::threadContextp()->randSeed(seed);
    initial_state().built = true;
    sc_report_handler::set_actions(SC_INFO, SC_DO_NOTHING);
    auto* x = new Bench;
    sc_start(SC_ZERO_TIME);  // elaborate and park the thread on `start`
    return x;
  }();
  return *b;
}

}  // namespace

#if WATKINS_SC_SPEED
namespace sc_speed {
#endif

void systemc_initial_state(int seed) {
  if (initial_state().built && seed != initial_state().seed)
    throw std::logic_error("rtl_initial_state: the Verilated tops of this process are built already");
  initial_state().seed = seed;
}

std::string systemc_description() {
  return std::string("SystemC bench (Verilated --sc watkins_top, ") + BuildName +
         ", Phong = 0 and 1, one SC_THREAD each, SystemC " + sc_release() + ")";
}

namespace {

// Runs the frames on one side's thread and returns when it is done.
template <class Dut, class Work>
void run_on(Bench& b, Side<Dut>& side, const Work& work) {
  std::exception_ptr error;
  side.top->job = [&] {
    try {
      work(*side.driver);
    } catch (...) {
      error = std::current_exception();
    }
  };
  side.top->job_done = false;
  side.top->start.notify(SC_ZERO_TIME);
  sc_start();  // returns when the thread waits for the next job (nothing left to simulate)
  if (!side.top->job_done) {
    b.dead = true;
    throw std::runtime_error("RTL bench: the SystemC kernel stopped before the run finished");
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace

void run_systemc(const std::vector<const PreparedScene*>& scenes, const RtlOptions& opt,
                 const std::vector<const Image*>& expected, RtlResult& r) {
  const bool phong = phong_frames(scenes);
  const ShadingMode shading = phong ? ShadingMode::Phong : ShadingMode::Gouraud;
  // run_rtl_frames checks this for the assertion build; the speed build is called directly.
  if (rtl_parameters(frames_config(scenes), shading) != rtl_parameters(Config{}, shading))
    throw std::invalid_argument("RTL: the SystemC bench has the default configuration's tops only");
  r.top = std::string("SystemC bench, Verilated --sc watkins_top at the default configuration, ") + BuildName +
          " (Phong = " + (phong ? "1)" : "0)");
  const Expectations want = expect(scenes, opt, expected, r, MaxWidth);
  Bench& b = bench();
  if (b.dead) throw std::runtime_error("RTL bench: the SystemC kernel stopped in an earlier run");
  auto work = [&](FrameDriver& d) { d.run(scenes, want.images, want.stages, opt, r); };
  if (phong)
    run_on(b, b.phong, work);
  else
    run_on(b, b.gouraud, work);
}

#if WATKINS_SC_SPEED
}  // namespace sc_speed
#endif

}  // namespace watkins::tb::detail
