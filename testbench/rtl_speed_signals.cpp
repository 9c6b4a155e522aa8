// The rejected SystemC bench style, kept as a measurement: an sc_clock, the Verilated --sc top on
// sc_signals, and one SC_METHOD per interface (edge source, pixel sink) on the rising clock edge —
// the textbook "per-signal" bench. Same model library as watkins_tb (its own bench is never built
// here). Full throughput (no gaps, no stalls), pixels counted but not compared.
//   watkins_rtl_speed_signals [SCENE] [--repeat N]
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <vector>

#include <systemc.h>

#include "Vwatkins_top.h"
#include "edge_packing.hpp"
#include "prepare.hpp"
#include "sc_top_signals.hpp"
#include "scene.hpp"

namespace {

using namespace watkins;

SC_MODULE(SignalBench) {
  sc_clock clk{"clk", 10, SC_NS};
  tb::TopSignals io;  // every other port
  Vwatkins_top dut{"dut"};

  std::vector<sc_bv<fmt::EdgeRecordBits>> beats;  // the frame's edges, then the end-of-frame beat
  int frames = 1;
  long long pixels_per_frame = 0;
  // Source / sink state.
  int src_frame = 0, sink_frame = 0;
  std::size_t src_beat = 0;
  long long sink_pixels = 0, bad_last = 0;
  sc_time done_at;

  SC_CTOR(SignalBench) {
    io.bind(dut, clk);
    SC_THREAD(reset);
    SC_METHOD(source);
    sensitive << clk.posedge_event();
    dont_initialize();
    SC_METHOD(sink);
    sensitive << clk.posedge_event();
    dont_initialize();
  }

  void reset() {
    io.rst_n.write(false);
    wait(40, SC_NS);
    io.rst_n.write(true);
    io.pixel_ready.write(true);
  }

  void present() {
    if (src_frame >= frames) {
      io.edge_valid.write(false);
      return;
    }
    io.edge_valid.write(true);
    io.edge_eof.write(src_beat + 1 == beats.size());
    io.edge.write(beats[src_beat]);
  }

  void source() {  // on the rising edge: a transfer if valid and ready were both high before it
    if (!io.rst_n.read()) return;
    if (!io.edge_valid.read()) {
      present();
      return;
    }
    if (io.edge_ready.read()) {
      if (++src_beat == beats.size()) {
        src_beat = 0;
        ++src_frame;
      }
      present();
    }
  }

  void sink() {
    if (!io.rst_n.read() || !(io.pixel_valid.read() && io.pixel_ready.read())) return;
    ++sink_pixels;
    const bool last = sink_pixels == pixels_per_frame;
    if (io.pixel_last.read() != last) ++bad_last;
    if (last) {
      sink_pixels = 0;
      if (++sink_frame == frames) {
        done_at = sc_time_stamp();
        sc_stop();
      }
    }
  }
};

}  // namespace

int sc_main(int, char**) { return 0; }  // required by libsystemc; main() below runs the kernel

int main(int argc, char** argv) {
  CLI::App app{"watkins_rtl_speed_signals: the per-signal SystemC bench style, for the speed comparison"};
  std::string scene_path;
  int repeat = 3;
  app.add_option("scene", scene_path, "scene file (JSON); the embedded default scene if none");
  app.add_option("--repeat", repeat, "frames to run back to back")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
    const BuiltScene scene = load_scene_or_default(scene_path);
    const PreparedScene prepared = prepare(scene);
    auto* b = new SignalBench("signal_bench");  // never destroyed (SystemC teardown order)
    for (const EdgeRecord& e : prepared.edges) {
      const tb::EdgeWords w = tb::pack_edge(tb::default_edge_layout(), e);
      sc_bv<fmt::EdgeRecordBits> bv;
      for (int i = 0; i < tb::default_edge_layout().words; ++i) bv.set_word(i, w[i]);
      b->beats.push_back(bv);
    }
    b->beats.emplace_back();  // end-of-frame beat
    b->frames = repeat;
    b->pixels_per_frame = static_cast<long long>(prepared.width) * prepared.height;
    b->io.width.write(prepared.width);
    b->io.height.write(prepared.height);
    b->io.background.write((prepared.background[0] << 16) | (prepared.background[1] << 8) | prepared.background[2]);
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t cpu0 = std::clock();
    sc_start();
    const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cycles = b->done_at.to_seconds() / 10e-9;
    std::printf("harness       SystemC per-signal bench (sc_clock, SC_METHOD source and sink)\n");
    std::printf("scene         %s %dx%d, %zu edge records\n", scene.name.c_str(), prepared.width,
                prepared.height, prepared.edges.size());
    std::printf("speed         %.0f cycles/s over %d frames (%.0f cycles in %.3f s wall, %.3f s CPU: %.0f cycles/CPU s)%s\n",
                cycles / wall, repeat, cycles, wall, cpu, cpu > 0 ? cycles / cpu : 0.0, b->sink_frame == repeat && !b->bad_last ? "" : "  [FRAMES INCOMPLETE OR BAD pixel_last]");
    return b->sink_frame == repeat && !b->bad_last ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "watkins_rtl_speed_signals: error: %s\n", e.what());
    return 1;
  }
}
