// watkins sweep (sweep.hpp). The grid is a list of axes, each a name and its values; a point is
// one value index per axis (mixed radix, the last axis fastest), numbered 0..N-1 in that order so
// shards and jobs are reproducible. Adding an axis is one more entry in make_axes() and one more
// read in evaluate().
//
// Axes: scene, shading, tess, then the fraction bits of the channel groups (attr_frac: the
// shading's attribute group — shade for flat and Gouraud, normal for Phong; x_frac; depth_frac).
// A point's configuration (watkins::Config) has those fractions and, for every group, exactly the
// integer bits its scene needs at them (point_config()); the capacities stay the default's except
// the active-edge list (--max-active-edges) and the line width (the scene's screen width). Its
// cost is that configuration's edge-record and line-buffer bits; a configuration Config::check()
// or prepare() refuses leaves its message in the point's `error` and the sweep goes on.
//
// Each point: the scene text with its first object's "u", "v" scaled (or set, --uv), built with the
// point's shading (flat: Gouraud pipeline with one shade per polygon; gouraud-eq1: the shade
// interpolated, depth 1/Z (Gouraud's eq. 1); gouraud-eq2: his eq. 2, S·Z and Z interpolated and
// divided per pixel (interpolation eq2, the top's shade divider); phong: the Phong pipeline; whitted: the
// Phong pipeline with the patch objects drawn by Whitted's curved edges, the first one's k_u = u
// and k_v = v subpatches per patch, so its cells are the polygons' at the same point), prepared,
// rendered by the fixed-point model (WatkinsTop), the double reference and the analytic truth,
// compared.
#include "sweep.hpp"

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "analytic_truth.hpp"
#include "config.hpp"
#include "cycle_model.hpp"
#include "error_stats.hpp"
#include "float_reference.hpp"
#include "formats.hpp"
#include "hardware_cost.hpp"
#include "image_io.hpp"
#include "options.hpp"
#include "prepare.hpp"
#include "run_files.hpp"
#include "scene.hpp"
#include "scene_types.hpp"
#include "usage_error.hpp"
#include "watkins_top.hpp"

#ifdef WATKINS_HAVE_RTL
#include "rtl_bench.hpp"
#endif

namespace watkins::sweep {

namespace {

// ---- the grid -------------------------------------------------------------------------------

struct Axis {
  std::string name;                 // CSV column
  std::vector<std::string> values;  // as written in the CSV
};

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::vector<Axis> make_axes(const SweepArgs& a) {
  std::vector<Axis> axes;
  Axis scene{"scene", a.scenes}, shading{"shading", a.shadings}, tess{a.uv.empty() ? "tess" : "uv", {}};
  if (a.uv.empty())
    for (double f : a.tess) tess.values.push_back(number(f));
  else
    for (int n : a.uv) tess.values.push_back(std::to_string(n));
  axes.push_back(scene);
  axes.push_back(shading);
  axes.push_back(tess);
  auto bits_axis = [](const std::string& name, const std::vector<int>& v) {
    Axis ax{name, {}};
    for (int b : v) ax.values.push_back(std::to_string(b));
    return ax;
  };
  axes.push_back(bits_axis("attr_frac", a.attr_frac));
  axes.push_back(bits_axis("x_frac", a.x_frac));
  axes.push_back(bits_axis("depth_frac", a.depth_frac));
  return axes;
}

// Point k's value index on every axis.
std::vector<int> decode(const std::vector<Axis>& axes, long long k) {
  std::vector<int> idx(axes.size());
  for (std::size_t i = axes.size(); i-- > 0;) {
    const long long n = static_cast<long long>(axes[i].values.size());
    idx[i] = static_cast<int>(k % n);
    k /= n;
  }
  return idx;
}

long long grid_size(const std::vector<Axis>& axes) {
  long long n = 1;
  for (const Axis& a : axes) n *= static_cast<long long>(a.values.size());
  return n;
}

// ---- hardware cost --------------------------------------------------------------------------

// Storage the hardware built for `cfg` needs: one edge record ($bits(edge_t)) and the ping-pong
// scan-line buffer (hardware_cost.hpp) over cfg.max_width pixels (the sweep sets it to the
// scene's screen width).
struct HardwareBits {
  long long edge_record = 0;  // one edge record
  long long line_buffer = 0;  // two scan-line buffers
};
HardwareBits hardware_bits(const Config& cfg, ShadingMode shading) {
  HardwareBits b;
  b.edge_record = cfg.edge_record_bits(shading);
  b.line_buffer = line_buffer_bits(cfg);
  return b;
}

// The point's configuration: the given fractions, capacities as the default's except the
// active-edge list and the line width (the scene's screen width), and in every group the integer
// bits the scene needs at those fractions, exactly (measured on a prepare() with the widest words
// the fractions allow: fit_int_bits(), as `watkins size` sizes; test_config's NarrowConfig tests
// hold one bit fewer refused). Throws SceneError ("configuration: ...") when the fractions are no
// valid configuration or the scene cannot be prepared at them.
Config point_config(const BuiltScene& scene, int attr_frac, int x_frac, int depth_frac, int max_active_edges,
                    PreparedScene* prepared) {
  Config cfg;
  cfg.max_active_edges = max_active_edges;
  cfg.max_width = scene.width;
  cfg.x.frac_bits = x_frac;
  cfg.depth.frac_bits = depth_frac;
  (scene.shading == ShadingMode::Phong ? cfg.normal : cfg.shade).frac_bits = attr_frac;
  cfg = fit_int_bits(scene, cfg);  // refuses fractions no configuration can hold
  if (std::string e = cfg.check(); !e.empty()) throw std::runtime_error("configuration: " + e);
  *prepared = prepare(scene, cfg);  // the configuration's own preparation (it refuses a wrap)
  return cfg;
}

// ---- one point --------------------------------------------------------------------------------

struct Result {
  long long point = 0;
  std::vector<std::string> axis_values;
  int u = 0, v = 0;
  long long polygons = 0, edge_records = 0, active_edges = 0, fragments = 0;
  int edge_order = 0, regions = 0;                  // regions: Whitted's (polygon ids after the polygons')
  long long curve_edge_records = 0, curve_active_edges = 0;  // curved edge records; most active on a line
  int attr_frac = 0, x_frac = 0, depth_frac = 0;   // the point's fractions (also its axes)
  int attr_int = 0, x_int = 0, depth_int = 0;      // integer bits the scene needs at them (0: unknown)
  std::string attr_group;                          // shade or normal
  ErrorStats truth, double_truth, vs_double;  // model vs truth, double reference vs truth, model vs double
  double truth_mach = 0, double_truth_mach = 0, vs_double_mach = 0, image_mach = 0;
  int truth_coverage_differs = 0, double_truth_coverage_differs = 0;
  double truth_ssim = 0, double_truth_ssim = 0;  // structural similarity to the truth (error_stats.hpp)
  int vs_double_visibility_differs = 0, vs_double_coverage_differs = 0;
  bool has_truth = false;
  long long cycles = -1;
  std::string cycles_source = "none";
  // predicted-sparse / predicted-full-frame (the cycle model, exact for the RTL without stalls),
  // rtl-sparse / rtl-full-frame / rtl-compact-full-frame (Verilated, with --rtl; the compact top
  // with --compact), none (an error before the frame)
  long long rtl_mismatches = -1;
  HardwareBits bits;
  double seconds = 0;
  std::string error;  // the point could not be rendered (the message); the row keeps its axes
  std::vector<unsigned char> png, truth_png;  // with --images: the fixed-point image, the truth
};

// The scene text with the first "u" and "v" (the first tessellated object's) scaled by f (set to
// f when `absolute`): u >= 3 (a closed ring), v >= 1; a cross_vault's or portico's u rounded to the
// nearest even count, at least 2 (the key of the vault is a vertex); a patch object's u >= 2 (its
// grid is open). Returns the values used.
std::string retessellate(const std::string& text, const std::string& path, double f, bool absolute, int& u,
                         int& v) {
  std::string out = text;
  for (int axis = 0; axis < 2; ++axis) {
    const std::regex re(axis == 0 ? R"re("u"\s*:\s*(\d+))re" : R"re("v"\s*:\s*(\d+))re");
    std::smatch m;
    if (!std::regex_search(out, m, re))
      throw std::runtime_error(path + ": no tessellated object (\"u\", \"v\") to sweep");
    const double n0 = absolute ? 1.0 : std::stod(m[1].str());
    int n = std::max(axis == 0 ? 3 : 1, static_cast<int>(std::lround(n0 * f)));
    if (axis == 0) {
      // The object holding this "u": scene objects are flat (no nested objects), so it spans the
      // braces around the match.
      const std::size_t at = std::size_t(m.position(0));
      const std::size_t open = out.rfind('{', at), close = out.find('}', at);
      const std::string object = out.substr(open == std::string::npos ? 0 : open,
                                            close == std::string::npos ? std::string::npos : close - open);
      if (std::regex_search(object, std::regex(R"re("type"\s*:\s*"(cross_vault|portico)")re")))
        n = std::max(2, 2 * static_cast<int>(std::lround(n0 * f / 2)));
      else if (std::regex_search(object, std::regex(R"re("type"\s*:\s*"(bezier_patch|patches)")re")))
        n = std::max(2, static_cast<int>(std::lround(n0 * f)));  // a patch's grid is open: 2 segments suffice
    }
    (axis == 0 ? u : v) = n;
    out = m.prefix().str() + (axis == 0 ? "\"u\": " : "\"v\": ") + std::to_string(n) + m.suffix().str();
  }
  return out;
}

// The scene text with Whitted's interior edges of the first tessellated object (the one holding
// the first "u") set to k_u = u and k_v = v equal parts: its existing "k_u", "k_v" replaced, or
// both added before its "u". The caller draws the patch objects as curves.
std::string with_subpatches(const std::string& text, int u, int v) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(R"re("u"\s*:\s*\d+)re"))) return text;
  const std::size_t at = std::size_t(m.position(0));
  const std::size_t open = text.rfind('{', at), close = text.find('}', at);
  const std::size_t begin = open == std::string::npos ? 0 : open;  // the object: flat, as in retessellate
  const std::size_t end = close == std::string::npos ? text.size() : close;
  std::string object = text.substr(begin, end - begin);
  for (const char* key : {"k_u", "k_v"}) {
    const std::regex re(std::string("\"") + key + R"re("\s*:\s*(\d+|\[[^\]]*\]))re");
    const std::string value = "\"" + std::string(key) + "\": " + std::to_string(key[2] == 'u' ? u : v);
    if (std::regex_search(object, re))
      object = std::regex_replace(object, re, value);
    else
      object.insert(object.find(m.str()), value + ", ");  // before the object's "u"
  }
  return text.substr(0, begin) + object + text.substr(end);
}

#ifdef WATKINS_HAVE_RTL
std::mutex rtl_mutex;  // the SystemC bench is one per process
#endif

Result evaluate(const SweepArgs& a, const std::vector<Axis>& axes, long long k) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  Result r;
  r.point = k;
  const std::vector<int> idx = decode(axes, k);
  for (std::size_t i = 0; i < axes.size(); ++i) r.axis_values.push_back(axes[i].values[idx[i]]);
  const std::string& path = axes[0].values[idx[0]];
  const std::string& shading = axes[1].values[idx[1]];
  const bool absolute = !a.uv.empty();
  const double f = absolute ? a.uv.at(idx[2]) : a.tess.at(idx[2]);
  r.attr_frac = a.attr_frac.at(idx[3]);
  r.x_frac = a.x_frac.at(idx[4]);
  r.depth_frac = a.depth_frac.at(idx[5]);
  const bool curves = shading == "whitted";
  r.attr_group = shading == "phong" || curves ? "normal" : "shade";
  try {
    BuildOptions opt;
    opt.rule = parse_shading_rule(a.rule);
    const bool eq2 = shading == "gouraud-eq2";
    opt.interpolation = eq2 ? Interpolation::Eq2 : Interpolation::Eq1;
    opt.depth = eq2 ? DepthMode::Z : DepthMode::InverseZ;
    opt.shading = shading == "phong" || curves ? ShadingMode::Phong : ShadingMode::Gouraud;
    opt.flat = shading == "flat";
    opt.patches_as_curves = curves;  // the polygon shadings tessellate a scene's "draw": "curves" too
    std::string text = retessellate(read_scene_text(path), path, f, absolute, r.u, r.v);
    if (curves) text = with_subpatches(text, r.u, r.v);
    const BuiltScene scene =
        load_scene_text(text, path, std::filesystem::path(path).parent_path().string(), opt);
    PreparedScene prepared;
    const Config cfg = point_config(scene, r.attr_frac, r.x_frac, r.depth_frac, a.max_active_edges, &prepared);
    r.bits = hardware_bits(cfg, scene.shading);
    r.x_int = cfg.x.int_bits;
    r.depth_int = cfg.depth.int_bits;
    r.attr_int = (scene.shading == ShadingMode::Phong ? cfg.normal : cfg.shade).int_bits;
    r.polygons = static_cast<long long>(scene.polygons.size());
    r.regions = scene.curve_regions;
    if (curves && scene.curves.empty()) throw std::runtime_error("whitted: the scene has no patch object to draw as curves");
    r.edge_order = cfg.edge_order;
    r.edge_records = static_cast<long long>(prepared.edges.size());
    r.active_edges = prepared.needs.max_active_edges;
    r.curve_edge_records = prepared.needs.curve_edges;
    r.curve_active_edges = prepared.needs.max_curve_edges;

    WatkinsTop pipe(cfg);
    Image image = pipe.render(prepared);
    r.fragments = pipe.stats().fragments;
    const Image reference = render_float_reference(scene);
    const ErrorStats vs_double = error_stats(image, reference);
    const ImageError counts = compare_images(image, reference);
    r.vs_double = vs_double;
    r.vs_double_mach = mach_band(image, image.owner, &reference);
    r.vs_double_visibility_differs = counts.visibility_differs;
    r.vs_double_coverage_differs = counts.coverage_differs;
    r.image_mach = mach_band(image, image.owner);
    if (!a.images.empty()) r.png = encode_png(image);

    // Cycles from the cycle model (model/twins/cycle_model.hpp, equal to Verilator's without
    // stalls); --rtl replaces them with the Verilated run's where the RTL holds the scene.
    const CyclePrediction predicted = predict_cycles(
        prepared, a.full_frame ? PixelOutput::FullFrame : PixelOutput::Sparse, a.max_active_edges, cfg);
    r.cycles = predicted.cycles;
    r.cycles_source = a.full_frame ? "predicted-full-frame" : "predicted-sparse";
    if (a.rtl) {
#ifdef WATKINS_HAVE_RTL
      // The Verilated RTL is built for the default fractions; integer bits the scene does not
      // use change no value, so it checks every point at the default fractions.
      const Config def;
      const bool default_fractions = cfg.x.frac_bits == def.x.frac_bits &&
                                     cfg.depth.frac_bits == def.depth.frac_bits &&
                                     cfg.shade.frac_bits == def.shade.frac_bits &&
                                     cfg.normal.frac_bits == def.normal.frac_bits;
      // The Verilated top is the default configuration's, edge_order 1: a whitted point's curved
      // edges need an order-3 top, so its cycles stay the cycle model's. --compact: the compact
      // top at the default sizes (no smoother), which runs Gouraud's eq. (1) only (flat and
      // gouraud-eq1 points); the other points keep the cycle model's cycles.
      const bool on_compact = scene.shading == ShadingMode::Gouraud && !prepared.eq2;
      if (r.active_edges <= fmt::MaxActiveEdges && default_fractions && cfg.edge_order == 1 &&
          (!a.compact || on_compact)) {
        tb::RtlOptions ro;
        ro.sparse = !a.full_frame;
        // Its frame is prepared for the default configuration: the point's words wrap slopes to
        // the point's widths, which the RTL's wider words would not sign-extend the same way.
        PrepareOptions popt;
        popt.max_active_edges = a.max_active_edges;
        Config compact_top;
        compact_top.compact = true;
        compact_top.smoothing = false;
        const PreparedScene rtl_frame = a.compact ? prepare(scene, compact_top) : prepare(scene, popt);
        std::lock_guard<std::mutex> lock(rtl_mutex);
        const tb::RtlResult rr = tb::run_rtl(rtl_frame, ro, &image);
        r.cycles = rr.cycles;
        r.cycles_source = a.compact ? "rtl-compact-full-frame" : a.full_frame ? "rtl-full-frame" : "rtl-sparse";
        r.rtl_mismatches = rr.mismatches + static_cast<long long>(rr.stage_mismatches.size());
        if (!rr.ok() || rr.overflow) r.error = "RTL run failed: " + rr.summary();
      }
#endif
    }

    const AnalyticTruth truth = render_analytic_truth(scene);
    r.has_truth = truth.unavailable.empty();
    if (r.has_truth) {
      const Image mine = by_object(scene, image), ref = by_object(scene, reference);
      r.truth = error_stats(mine, truth.image);
      r.truth_mach = mach_band(mine, image.owner, &truth.image);
      r.truth_coverage_differs = compare_images(mine, truth.image).coverage_differs;
      r.double_truth = error_stats(ref, truth.image);
      r.double_truth_mach = mach_band(ref, reference.owner, &truth.image);
      r.double_truth_coverage_differs = compare_images(ref, truth.image).coverage_differs;
      r.truth_ssim = ssim(mine, truth.image);
      r.double_truth_ssim = ssim(ref, truth.image);
      if (!a.images.empty()) r.truth_png = encode_png(truth.image);
    }
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return r;
}

// ---- output -------------------------------------------------------------------------------

std::string fixed(double v, int digits) {
  if (std::isinf(v)) return "inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// CSV cells; an error, a missing truth or no cycles leave cells empty.
std::string csv_text(const std::vector<Axis>& axes, const std::vector<Result>& rows) {
  std::ostringstream out;
  out << "point";
  for (const Axis& ax : axes) out << ',' << ax.name;
  out << ",attr_group,x_int,depth_int,attr_int,u,v,polygons,edge_records,active_edges,fragments"
         ",truth_max,truth_mean,truth_rmse,truth_psnr,truth_mach,truth_compared,truth_coverage_differs"
         ",double_truth_max,double_truth_mean,double_truth_rmse,double_truth_psnr,double_truth_mach"
         ",double_max,double_mean,double_rmse,double_psnr,double_mach,double_visibility_differs,double_coverage_differs"
         ",image_mach,cycles,cycles_source,rtl_mismatches,edge_record_bits,line_buffer_bits,active_list_bits"
         ",edge_order,regions,curve_edge_records,curve_active_edges,double_truth_coverage_differs"
         ",truth_ssim,double_truth_ssim,truth_over_one,double_truth_over_one"
         ",seconds,error\n";
  for (const Result& r : rows) {
    out << r.point;
    for (const std::string& v : r.axis_values) out << ',' << v;
    const bool ok = r.error.empty() || r.polygons > 0;
    auto stats = [&](const ErrorStats& e, double mach, bool have) {
      if (!have) return std::string(",,,,,");
      return "," + std::to_string(e.max_abs) + "," + fixed(e.mean_abs, 4) + "," + fixed(e.rmse, 4) + "," +
             fixed(e.psnr, 2) + "," + fixed(mach, 2);
    };
    auto known = [](int bits) { return bits > 0 ? std::to_string(bits) : std::string(); };
    out << ',' << r.attr_group << ',' << known(r.x_int) << ',' << known(r.depth_int) << ',' << known(r.attr_int);
    out << ',' << r.u << ',' << r.v;
    if (ok)
      out << ',' << r.polygons << ',' << r.edge_records << ',' << r.active_edges << ',' << r.fragments;
    else
      out << ",,,,";
    out << stats(r.truth, r.truth_mach, ok && r.has_truth);
    if (ok && r.has_truth)
      out << ',' << r.truth.compared << ',' << r.truth_coverage_differs;
    else
      out << ",,";
    out << stats(r.double_truth, r.double_truth_mach, ok && r.has_truth);
    out << stats(r.vs_double, r.vs_double_mach, ok);
    if (ok)
      out << ',' << r.vs_double_visibility_differs << ',' << r.vs_double_coverage_differs << ','
          << fixed(r.image_mach, 2);
    else
      out << ",,,";
    out << ',' << (r.cycles >= 0 ? std::to_string(r.cycles) : "") << ',' << r.cycles_source << ','
        << (r.rtl_mismatches >= 0 ? std::to_string(r.rtl_mismatches) : "") << ','
        << (r.bits.edge_record > 0 ? std::to_string(r.bits.edge_record) : "") << ','
        << (r.bits.line_buffer > 0 ? std::to_string(r.bits.line_buffer) : "") << ','
        << (ok && r.bits.edge_record > 0 ? std::to_string(r.active_edges * r.bits.edge_record) : "") << ',';
    if (ok && r.edge_order > 0)
      out << r.edge_order << ',' << r.regions << ',' << r.curve_edge_records << ',' << r.curve_active_edges << ',';
    else
      out << ",,,,";
    out << (ok && r.has_truth ? std::to_string(r.double_truth_coverage_differs) : "") << ',';
    out << (ok && r.has_truth ? fixed(r.truth_ssim, 5) + "," + fixed(r.double_truth_ssim, 5) + "," +
                                    std::to_string(r.truth.over_one) + "," + std::to_string(r.double_truth.over_one)
                              : std::string(",,,"))
        << ',' << fixed(r.seconds, 3)
        << ",\"";
    for (char c : r.error) out << (c == '"' ? '\'' : c == '\n' ? ' ' : c);
    out << "\"\n";
  }
  return out.str();
}

std::string markdown_text(const std::vector<Result>& rows) {
  std::ostringstream out;
  out << "| scene | shading | u×v | polygons | active edges | cycles | vs truth max / mean / coverage px | RMSE | "
         "PSNR dB | Mach | double vs truth max / mean | vs double max / mean | edge record / line buffer bits | "
         "frac x / depth / attr | int x / depth / attr |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Result& r : rows) {
    const std::string scene = std::filesystem::path(r.axis_values[0]).stem().string();
    out << "| " << scene << " | " << r.axis_values[1] << " | " << r.u << "×" << r.v << " | ";
    if (!r.error.empty() && r.polygons == 0) {
      out << r.error << " | | | | | | | | | | " << r.x_frac << " / " << r.depth_frac << " / " << r.attr_frac
          << " | |\n";
      continue;
    }
    // Whitted's points: regions instead of polygons, and the curved ones among the active edges.
    out << (r.regions > 0 ? std::to_string(r.regions) + " regions" : std::to_string(r.polygons)) << " | "
        << r.active_edges << (r.curve_active_edges > 0 ? " (" + std::to_string(r.curve_active_edges) + " curved)" : "")
        << " | "
        << (r.cycles < 0 ? std::string("—")
            : std::to_string(r.cycles) + (r.cycles_source.rfind("predicted", 0) == 0 ? " (predicted)" : ""))
        << " | ";
    if (r.has_truth)
      out << r.truth.max_abs << " / " << fixed(r.truth.mean_abs, 2) << " / " << r.truth_coverage_differs << " | "
          << fixed(r.truth.rmse, 2) << " | "
          << fixed(r.truth.psnr, 1) << " | " << fixed(r.truth_mach, 1) << " | " << r.double_truth.max_abs << " / "
          << fixed(r.double_truth.mean_abs, 2) << " | ";
    else
      out << "— | — | — | — | — | ";
    out << r.vs_double.max_abs << " / " << fixed(r.vs_double.mean_abs, 3) << " | " << r.bits.edge_record << " / "
        << r.bits.line_buffer << " | " << r.x_frac << " / " << r.depth_frac << " / " << r.attr_frac << " | "
        << r.x_int << " / " << r.depth_int << " / " << r.attr_int << " |\n";
  }
  return out.str();
}

// A progress bar on stderr, only when it is a terminal.
class Progress {
 public:
  Progress(long long total, bool on) : total_(total), on_(on && isatty(2)) {}
  void step(const std::string& what) {
    std::lock_guard<std::mutex> lock(m_);
    ++done_;
    if (!on_) return;
    const int width = 30, fill = static_cast<int>(width * done_ / std::max(1LL, total_));
    std::fprintf(stderr, "\r[%s%s] %lld/%lld %-40.40s", std::string(fill, '#').c_str(),
                 std::string(width - fill, '.').c_str(), done_, total_, what.c_str());
    if (done_ == total_) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  }

 private:
  long long total_, done_ = 0;
  bool on_;
  std::mutex m_;
};

}  // namespace

CLI::App* add_sweep_command(CLI::App& app, SweepArgs& a) {
  auto* s = app.add_subcommand(
      "sweep", "error against cost over scenes x shading x tessellation x fraction bits (CSV, markdown)");
  s->add_option("scenes", a.scenes, "scene files (JSON); default: scenes/sphere.json scenes/cone.json")
      ->check(cli::non_empty_name());
  cli::add_name_list(s, "--shadings", a.shadings,
                     "flat, gouraud-eq1 (Gouraud's eq. 1: the shade interpolated, depth 1/Z), gouraud-eq2 (his eq. 2: S*Z and Z "
                     "interpolated, divided per pixel), phong, whitted (patches by curved edges, "
                     "k_u = u, k_v = v subpatches, Phong)",
                     {"flat", "gouraud-eq1", "gouraud-eq2", "phong", "whitted"});
  CLI::Option* tess = cli::add_real_list(
      s, "--tess", a.tess, "factors on the first object's u and v (u >= 3, v >= 1; a vault's u rounded to even)", 0.01,
      64.0);
  CLI::Option* uv = cli::add_int_list(
      s, "--uv", a.uv, "instead of --tess: u = v = n on the first object (axis uv; a vault's u rounded to even)", 1, 1024);
  cli::exclusive({tess, uv});
  cli::add_int_list(s, "--frac-bits", a.attr_frac,
                    "fraction bits of the shading's attribute group: shade (flat, Gouraud) or normal (Phong)", 0, 64);
  cli::add_int_list(s, "--x-frac-bits", a.x_frac, "fraction bits of X (pixels)", 0, 64);
  cli::add_int_list(s, "--depth-frac-bits", a.depth_frac, "fraction bits of the depth channel", 0, 64);
  s->add_option("--rule", a.rule, "vertex rule of flat and Gouraud shading (phong: eq. 3, the truth's illumination)")
      ->check(CLI::IsMember({"gouraud", "lambert", "warnock", "romney", "phong"}))
      ->capture_default_str();
  cli::add_file(s, "--csv", a.csv, "CSV to write (one row per point)")->capture_default_str();
  cli::add_file(s, "--md", a.md, "markdown table to write");
  s->add_option("--jobs,-j", a.jobs, "points rendered at once (threads)")
      ->check(cli::integer_in(1, 256))
      ->capture_default_str();
  s->add_option("--shard", a.shard, "i/N: run only points k with k mod N == i (0-based; e.g. $SLURM_ARRAY_TASK_ID/N)")
      ->capture_default_str();
  s->add_option("--max-active-edges", a.max_active_edges, "the model's active-edge list capacity")
      ->check(cli::integer_in(1, 1 << 16))
      ->capture_default_str();
  s->add_flag("--rtl", a.rtl, "cycles per frame from the Verilated RTL (points within its active-edge list)");
  s->add_flag("--full-frame", a.full_frame, "with --rtl: full-frame output instead of sparse");
  s->add_flag("--compact", a.compact, "with --rtl --full-frame: the compact top (the default sizes, compact true, no "
                                      "smoother) at the flat and gouraud-eq1 points");
  s->add_flag("--quiet,-q", a.quiet, "no progress bar");
  cli::add_file(s, "--images", a.images,
                "folder for PNGs: SCENE_SHADING_UxV.png (the fixed-point image) per point, SCENE_truth.png per scene");
  return s;
}

void check_sweep(const SweepArgs& a) {
  if (a.full_frame && !a.rtl) throw UsageError("--full-frame needs --rtl");
  if (a.compact && !a.rtl) throw UsageError("--compact needs --rtl");
  if (a.compact && !a.full_frame) throw UsageError("--compact: the compact top emits full frames only; add --full-frame");
#ifndef WATKINS_HAVE_RTL
  if (a.rtl) throw UsageError("--rtl: this build has no RTL simulation (install Verilator and SystemC)");
#endif
  long long shard = 0, shards = 1;
  cli::parse_shard("--shard", a.shard, shard, shards);
}

int run_sweep(const SweepArgs& in) {
  check_sweep(in);
  SweepArgs a = in;
  if (a.scenes.empty()) {
    const std::string root = WATKINS_SOURCE_DIR;
    a.scenes = {root + "/scenes/sphere.json", root + "/scenes/cone.json"};
  }
  long long shard = 0, shards = 1;
  cli::parse_shard("--shard", a.shard, shard, shards);
  // Every scene is read, parsed and checked for a tessellated object before any point runs: a
  // scene that cannot be read fails the run (exit code 1) with nothing written, while a point the
  // model refuses (a format too narrow for its scene) keeps its message in its row.
  RunFiles files;
  for (const std::string& path : a.scenes) {
    const Scene parsed = parse_scene_file(path);
    files.input("the scene file " + path, path);
    files.scene_inputs(parsed);
    int u = 0, v = 0;
    (void)retessellate(read_scene_text(path), path, 1.0, false, u, v);
  }
  // The folder first: a table inside a folder the run makes is then declared as one of its files.
  if (!a.images.empty()) files.output_folder("--images", a.images);
  files.output("--csv", a.csv);
  if (!a.md.empty()) files.output("--md", a.md);
  const std::vector<Axis> axes = make_axes(a);
  std::vector<long long> points;
  for (long long k = shard; k < grid_size(axes); k += shards) points.push_back(k);

  std::vector<Result> rows(points.size());
  Progress progress(static_cast<long long>(points.size()), !a.quiet);
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i; (i = next++) < points.size();) {
      rows[i] = evaluate(a, axes, points[i]);
      progress.step(std::filesystem::path(rows[i].axis_values[0]).stem().string() + " " + rows[i].axis_values[1] +
                    " " + std::to_string(rows[i].u) + "x" + std::to_string(rows[i].v) + " frac " +
                    std::to_string(rows[i].attr_frac));
    }
  };
  std::vector<std::thread> threads;
  for (int j = 1; j < std::min<int>(a.jobs, static_cast<int>(points.size())); ++j) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();

  int failed = 0, rtl_bad = 0;
  for (const Result& r : rows) {
    if (!r.error.empty()) {
      ++failed;
      std::fprintf(stderr, "watkins sweep: point %lld (%s %s x%s, frac attr %d x %d depth %d): %s\n", r.point,
                   r.axis_values[0].c_str(), r.axis_values[1].c_str(), r.axis_values[2].c_str(), r.attr_frac,
                   r.x_frac, r.depth_frac, r.error.c_str());
    }
    if (r.rtl_mismatches > 0 || r.error.rfind("RTL run failed", 0) == 0) ++rtl_bad;
  }
  // As `render --rtl`: an RTL that disagrees with its model is a bug, and a run that finds one
  // writes nothing.
  if (!rtl_bad) {
    files.add(a.csv, csv_text(axes, rows));
    if (!a.md.empty()) files.add(a.md, markdown_text(rows));
    if (!a.images.empty()) {
      const bool one_format = a.attr_frac.size() == 1 && a.x_frac.size() == 1 && a.depth_frac.size() == 1;
      std::set<std::string> truths;
      for (Result& r : rows) {
        const std::string stem = std::filesystem::path(r.axis_values[0]).stem().string();
        std::string name = stem + "_" + r.axis_values[1] + "_" + std::to_string(r.u) + "x" + std::to_string(r.v);
        if (!one_format)
          name += "_f" + std::to_string(r.attr_frac) + "-" + std::to_string(r.x_frac) + "-" + std::to_string(r.depth_frac);
        if (!r.png.empty()) files.add_in(a.images, name + ".png", std::move(r.png));
        if (!r.truth_png.empty() && truths.insert(stem).second)
          files.add_in(a.images, stem + "_truth.png", std::move(r.truth_png));
      }
    }
    files.commit();
  }
  std::printf("sweep         %zu of %lld points (shard %lld/%lld), %d failed%s; %s%s%s%s\n", rows.size(),
              grid_size(axes), shard, shards, failed, rtl_bad ? ", RTL MISMATCH" : "",
              rtl_bad ? "nothing written" : "wrote ", rtl_bad ? "" : a.csv.c_str(), a.md.empty() || rtl_bad ? "" : ", ",
              rtl_bad ? "" : a.md.c_str());
  return rtl_bad ? 3 : 0;
}

}  // namespace watkins::sweep
