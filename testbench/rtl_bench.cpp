// run_rtl_frames (rtl_bench.hpp): picks the Verilated top of the frames' configuration and
// shading and runs the one drive loop (frame_driver.hpp) on it. The default configuration has two
// benches: the plain C++ harness on --cc tops built for speed (no assertions, no tracing) and the
// SystemC bench (sc_bench.hpp: assertions, FST tracing); every other configuration its --cc top
// from the generated registry (cc_models.hpp), assertions on.
#include "rtl_bench.hpp"

#include <map>
#include <memory>
#include <stdexcept>

#include "cc_models.hpp"
#include "expectations.hpp"
#include "frame_driver.hpp"
#if WATKINS_HAVE_SYSTEMC_BENCH
#include "sc_bench.hpp"
#endif

namespace watkins::tb {
namespace {

// The --cc tops of configurations other than the default.
std::size_t other_tops() {
  std::size_t n = 0;
  for (const detail::CcModelEntry& m : detail::cc_models()) n += m.default_config ? 0 : 1;
  return n;
}

}  // namespace

void rtl_initial_state(int seed) {
#if WATKINS_HAVE_SYSTEMC_BENCH
  detail::systemc_initial_state(seed);
#else
  if (seed != 0) throw std::logic_error("rtl_initial_state: this build has no SystemC bench (WATKINS_RTL_SYSTEMC=OFF)");
#endif
}

std::string rtl_systemc_unavailable() {
#if WATKINS_HAVE_SYSTEMC_BENCH
  return "";
#else
  return "this build has no SystemC bench (configured with -DWATKINS_RTL_SYSTEMC=OFF)";
#endif
}

namespace {

// The --cc model built with `params` (the default configuration's speed tops included), or null.
const detail::CcModelEntry* find_cc_model(const std::vector<RtlParameter>& params) {
  for (const detail::CcModelEntry& m : detail::cc_models())
    if (m.params == params) return &m;
  return nullptr;
}

std::string parameter_text(const std::vector<RtlParameter>& params) {
  std::string s;
  for (const RtlParameter& p : params) s += (s.empty() ? "" : " ") + std::string(p.name) + "=" + std::to_string(p.value);
  return s;
}

// A --cc top and its driver, made on first use and kept (the driver resets it before every run
// unless RtlOptions::reset is false, and then still before its first run and after a failed one).
struct CcSide {
  std::unique_ptr<detail::CcModel> model;
  std::unique_ptr<detail::FrameDriver> driver;
};

CcSide& cc_side(const detail::CcModelEntry& m) {
  // Never destroyed, like the SystemC bench: a Verilated model destroyed by a static destructor
  // after Verilator's own statics deadlocks at exit.
  static auto* sides = new std::map<const detail::CcModelEntry*, CcSide>;
  CcSide& side = (*sides)[&m];
  if (!side.model) {
    side.model = m.make();
    side.driver = std::make_unique<detail::FrameDriver>(side.model->pins());
  }
  return side;
}

}  // namespace

std::string rtl_unavailable(const Config& config, ShadingMode shading, const std::string& file) {
  const std::vector<RtlParameter> params = rtl_parameters(config, shading);
  if (find_cc_model(params)) return "";
  const char* s = shading == ShadingMode::Phong ? "phong" : "gouraud";
  return std::string("no Verilated watkins_top for this configuration (") + parameter_text(params) +
         "): this build has the default configuration's and " + std::to_string(other_tops()) +
         " other(s); build one with cmake -DWATKINS_RTL_CONFIGS=" + file + "@" + s + " (or add it to the list)";
}

int rtl_max_width(const Config& config, ShadingMode shading) {
  if (const detail::CcModelEntry* m = find_cc_model(rtl_parameters(config, shading)))
    for (const RtlParameter& p : m->params)
      if (std::string(p.name) == "MaxWidth") return static_cast<int>(p.value);
  return 0;
}

RtlResult run_rtl_frames(const std::vector<const PreparedScene*>& scenes, const RtlOptions& opt,
                         const std::vector<const Image*>& expected) {
  const ShadingMode shading = detail::phong_frames(scenes) ? ShadingMode::Phong : ShadingMode::Gouraud;
  const Config& config = detail::frames_config(scenes);
  // A top without the smoother ignores smooth_w_i (and asserts it 0): never drive it a smoothed frame.
  if (!config.smoothing)
    for (std::size_t f = 0; f < scenes.size(); ++f)
      if (scenes[f]->smoothed())
        throw std::invalid_argument("RTL: smoothing: frame " + std::to_string(f) + " smooths (smooth_w " +
                                    std::to_string(scenes[f]->smooth_w) +
                                    ") but its configuration has smoothing false (the top has no smoother)");
  // Likewise a top without the eq. (2) divider ignores eq2_i (and asserts it 0).
  if (!config.eq2 || shading == ShadingMode::Phong)
    for (std::size_t f = 0; f < scenes.size(); ++f)
      if (scenes[f]->eq2)
        throw std::invalid_argument("RTL: eq2: frame " + std::to_string(f) +
                                    " divides by eq. (2) but its configuration has eq2 false (the top has no shade divider)");
  // A compact top emits full frames only (its scanline buffer asserts sparse_i 0 at frame start).
  if (config.compact)
    for (std::size_t f = 0; f < scenes.size(); ++f)
      if (f < opt.sparse_frames.size() ? opt.sparse_frames[f] : opt.sparse)
        throw std::invalid_argument("RTL: sparse: frame " + std::to_string(f) +
                                    " asks for sparse output but its configuration has compact true (the compact "
                                    "top emits full frames only)");
  const std::vector<RtlParameter> params = rtl_parameters(config, shading);
  RtlResult r;
  const detail::CcModelEntry* m = find_cc_model(params);
  if (!m) {
    r.unavailable = rtl_unavailable(config, shading, "F");
    return r;
  }
  // The default configuration's waveforms come from the SystemC bench: its tops are the traced ones.
  if (m->default_config && (opt.harness == RtlHarness::SystemC || !opt.trace_path.empty())) {
#if WATKINS_HAVE_SYSTEMC_BENCH
    detail::run_systemc(scenes, opt, expected, r);
#else
    r.unavailable = (opt.trace_path.empty() ? "the SystemC bench: " : "--trace needs the SystemC bench: ") +
                    rtl_systemc_unavailable();
#endif
    return r;
  }
  if (!opt.trace_path.empty())
    throw std::invalid_argument("RTL: --trace: the top built for " + m->built_for +
                                " is Verilated without FST tracing (only the default configuration's traces)");
  r.top = "Verilated --cc watkins_top built for " + m->built_for + " (" + parameter_text(params) + ")";
  const detail::Expectations want = detail::expect(scenes, opt, expected, r, rtl_max_width(config, shading));
  cc_side(*m).driver->run(scenes, want.images, want.stages, opt, r);
  return r;
}

}  // namespace watkins::tb
