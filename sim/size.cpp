// watkins size SCENE [--bound L] [--shading S] [--interpolation eq1|eq2] [--patches curves|polygons]
// [--out F]: the smallest
// configuration whose fixed-point image stays within L levels of the double reference.
//
// The criterion, per pixel, against the double reference of the same algorithm:
//  * where the image and the reference show the same polygon, |Δ| ≤ max(L, Δ_default): the default
//    (widest) configuration's own error at that pixel is allowed where it already exceeds L (the
//    1/16-pixel vertex grid moves sub-pixel slivers' shades: sphere 23 levels at 64 pixels);
//  * coverage and visibility may differ from the reference only at pixels where the default
//    configuration's differ too (a subset of the default's pixel set, not just its count).
// The search: start at the default, lower x.frac_bits, the attribute group's frac_bits (shade in a
// Gouraud frame, normal in a Phong frame), depth_bits and depth.frac_bits one bit at a time while
// the criterion holds (and, for a scene interpolating by Gouraud's eq. (2), eq2_recip_bits, the
// shade divider's mantissa), coordinate descent until no width can drop a bit; in four orders of the
// widths, keeping the smallest edge record (then line buffer). Integer bits are exactly
// what SceneNeeds reports at the chosen fractions; capacities are the scene's needs; the smoother
// (smoothing) only when the scene's shading.smooth turns it on. With --compact the configuration is
// the compact top's: "compact" true and, for a Phong scene, the narrow Phong formats
// (phong.formats, docs/reference/compact-phong.md), every point judged at them; the normal group's
// fraction starts at the narrow normalizer's 15 bits, which its input rounds to.
#include "size.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "config_file.hpp"
#include "options.hpp"
#include "run_files.hpp"
#include "float_reference.hpp"
#include "hardware_cost.hpp"
#include "image_io.hpp"
#include "prepare.hpp"
#include "scene.hpp"
#include "scene_types.hpp"
#include "scene_error.hpp"
#include "usage_error.hpp"
#include "watkins_top.hpp"

namespace watkins::size {
namespace {

// The widths the search lowers; a point of the search.
enum Dim { DimX, DimAttr, DimDepthBits, DimDepth, DimRecip, NumDims };
using Widths = std::array<int, NumDims>;

const char* dim_name(int d, ShadingMode shading) {
  switch (d) {
    case DimX: return "x.frac_bits";
    case DimAttr: return shading == ShadingMode::Phong ? "normal.frac_bits" : "shade.frac_bits";
    case DimDepthBits: return "depth_bits";
    case DimRecip: return "eq2_recip_bits";
    default: return "depth.frac_bits";
  }
}

// Where the search starts: the default configuration's widths; for the narrow Phong formats the
// normal's fraction at most the narrow normalizer's input fraction (more bits are rounded away).
Widths default_widths(bool narrow_phong = false) {
  const Config d;
  const int attr = narrow_phong ? std::min(d.normal.frac_bits, narrow::InFracBits) : d.shade.frac_bits;
  return {d.x.frac_bits, attr, d.depth_bits, d.depth.frac_bits, d.eq2_recip_bits};
}

// One rendered point of the search.
struct Point {
  Widths w{};
  Config cfg;            // the sized configuration (exact integer bits and capacities)
  std::string refused;   // non-empty: the configuration is invalid or prepare() refused the scene
  ImageError err;        // against the double reference
  int over_bound = 0;    // same-polygon pixels above their allowance
  int worst_excess = 0;  // largest |Δ| − allowance, and where
  int worst_x = -1, worst_y = -1, worst_abs = 0;
  int extra_flips = 0;   // coverage or visibility differences at pixels where the default has none
  bool passes() const { return refused.empty() && over_bound == 0 && extra_flips == 0; }
};

// The scene, its reference and the default configuration's image: what every point is judged by.
class Judge {
 public:
  Judge(const BuiltScene& scene, int bound, bool compact)
      : scene_(scene), bound_(bound), compact_(compact),
        phong_format_(compact && scene.shading == ShadingMode::Phong ? PhongFormat::Narrow : PhongFormat::Model) {
    reference_ = render_float_reference(scene_);
    // The default formats (at edge_order 3 when the scene has curves; the compact top's Phong
    // formats with --compact); the list need not limit the baseline.
    Config def = with_scene_edge_order(scene_, Config{});
    def.compact = compact_;
    def.phong = phong_format_;
    def.max_active_edges = 1 << 30;
    const PreparedScene prepared = prepare(scene_, def);
    WatkinsTop top(def);
    const Image img = top.render(prepared);
    baseline_ = compare_images(img, reference_);
    const std::size_t n = std::size_t(img.width) * img.height;
    allowance_.assign(n, bound_);
    grid_flip_.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      if (geometry_differs(img, reference_, i)) {
        grid_flip_[i] = 1;
        ++default_flips_;
        continue;
      }
      if (!img.covered[i]) continue;
      const int e = pixel_max_abs(img, reference_, i);
      if (e > bound_) {
        allowance_[i] = e;
        ++default_over_;
      }
    }
  }

  // Renders the configuration of widths `w` with exact integer bits and capacities (once per
  // distinct `w`: the search orders share points).
  const Point& evaluate(const Widths& w) {
    auto it = memo_.find(w);
    if (it == memo_.end()) it = memo_.emplace(w, render_point(w)).first;
    return it->second;
  }

  Point render_point(const Widths& w) {
    ++evaluations_;
    Point p;
    p.w = w;
    PreparedScene prepared;
    try {
      p.cfg = sized_config(w);
      prepared = prepare(scene_, p.cfg);
    } catch (const SceneError& e) {
      p.refused = e.what();
      return p;
    }
    WatkinsTop top(p.cfg);
    const Image img = top.render(prepared);
    p.err = compare_images(img, reference_);
    const std::size_t n = allowance_.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (geometry_differs(img, reference_, i)) {
        if (!grid_flip_[i]) ++p.extra_flips;
        continue;
      }
      if (!img.covered[i] || grid_flip_[i]) continue;  // the default's geometry differs here: no shade bound
      const int e = pixel_max_abs(img, reference_, i);
      if (e > allowance_[i]) {
        ++p.over_bound;
        if (e - allowance_[i] > p.worst_excess) {
          p.worst_excess = e - allowance_[i];
          p.worst_abs = e;
          p.worst_x = int(i % img.width);
          p.worst_y = int(i / img.width);
        }
      }
    }
    return p;
  }

  // The configuration for widths `w`: the fractions given, every group's integer bits exactly
  // what the scene's values need at them (SceneNeeds), capacities the scene's. The group the
  // frame does not use (normal in Gouraud, shade in Phong) keeps the default format. Throws
  // SceneError when the widths are not a valid configuration.
  Config sized_config(const Widths& w) const {
    Config c;
    // The smoother only when the scene smooths (shading.smooth): a top without it is much smaller.
    c.smoothing = quantize_smooth_weight(scene_.smooth) != 0;
    c.x.frac_bits = w[DimX];
    attr(c).frac_bits = w[DimAttr];
    c.depth_bits = w[DimDepthBits];
    c.depth.frac_bits = w[DimDepth];
    c.eq2_recip_bits = w[DimRecip];  // read by the divider only (fit_int_bits adds it for an eq2 scene)
    c.compact = compact_;
    c.phong = phong_format_;
    PreparedScene probe;
    c = fit_int_bits(scene_, c, &probe);  // the integer bits, as the sweep derives them
    const SceneNeeds& needs = probe.needs;
    c.max_active_edges = std::max(1, needs.max_active_edges);
    // The scanline_buffer addresses bank * MaxWidth + x (no power-of-two concatenation), so any
    // MaxWidth >= the screen width serves: the screen width itself, not rounded.
    c.max_width = scene_.width;
    // Gouraud frames carry material id 0 on every edge: one table entry (the id's 1-bit minimum).
    c.max_materials = scene_.shading == ShadingMode::Phong ? std::max<int>(1, scene_.materials.size()) : 1;
    // Polygon ids: the polygons', then one per region of Whitted's curves (prepare_curves).
    c.max_polygons = std::max<int>(1, scene_.polygons.size() + std::max(0, scene_.curve_regions));
    c.max_edges = std::max<int>(1, probe.edges.size());
    if (const std::string e = c.check(); !e.empty()) throw SceneError(e);
    return c;
  }

  const ImageError& baseline() const { return baseline_; }
  int default_over() const { return default_over_; }
  int default_flips() const { return default_flips_; }
  int evaluations() const { return evaluations_; }
  // The search's start: default_widths() at this judge's Phong formats.
  Widths start() const { return default_widths(phong_format_ == PhongFormat::Narrow); }

 private:
  ChannelFormat& attr(Config& c) const { return scene_.shading == ShadingMode::Phong ? c.normal : c.shade; }

  const BuiltScene& scene_;
  int bound_;
  bool compact_;
  PhongFormat phong_format_;
  Image reference_;
  ImageError baseline_;
  std::vector<int> allowance_;          // per pixel: max(L, the default's |Δ|)
  std::vector<std::uint8_t> grid_flip_; // per pixel: the default's coverage or polygon differs
  int default_over_ = 0, default_flips_ = 0, evaluations_ = 0;
  std::map<Widths, Point> memo_;
};

// What broke at a point that fails, in one phrase.
std::string broke(const Point& p, int bound) {
  if (!p.refused.empty()) return "refused: " + p.refused;
  std::string s;
  if (p.over_bound) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "bound: %d pixel(s) over, worst %d levels at (%d, %d) where %d %s allowed",
                  p.over_bound, p.worst_abs, p.worst_x, p.worst_y, p.worst_abs - p.worst_excess,
                  p.worst_abs - p.worst_excess > bound ? "(the default's) is" : "is");
    s = buf;
  }
  if (p.extra_flips) {
    if (!s.empty()) s += "; ";
    s += "visibility: " + std::to_string(p.extra_flips) + " pixel(s) change coverage or polygon where the default does not";
  }
  return s.empty() ? "nothing (passes)" : s;
}

int parse_bound(const std::string& s) {
  const bool digits = !s.empty() && s.size() <= 3 && s.find_first_not_of("0123456789") == std::string::npos;
  const int v = digits ? std::stoi(s) : -1;
  if (v < 0 || v > fmt::ShadeMax)
    throw UsageError("--bound: expected a whole number of levels in 0..255, got \"" + s + "\"");
  return v;
}

std::string default_out(const std::string& scene) {
  if (scene.empty()) return "default.config.json";
  std::string stem = scene.substr(scene.find_last_of('/') == std::string::npos ? 0 : scene.find_last_of('/') + 1);
  if (const auto dot = stem.rfind('.'); dot != std::string::npos && dot > 0) stem.resize(dot);
  return stem + ".config.json";
}

std::string format(const ChannelFormat& f) {
  return std::to_string(f.int_bits) + "." + std::to_string(f.frac_bits);
}

// The search's result: the chosen widths, the edge records each order reached, its rounds.
struct Descent {
  std::vector<int> dims;  // the widths searched, in the first order
  std::size_t orders = 0;
  bool eq2 = false;       // the shade divider's mantissa searched too
  Widths widths{};
  std::string tried;
  int rounds = 0;
};

Descent descend(Judge& judge, const BuiltScene& scene, int bound) {
  const ShadingMode shading = scene.shading;
  // Coordinate descent: each width lowered while the criterion holds, rounds until none moves.
  // Where it ends depends on the order the widths are lowered in — depth resolution can sit in
  // depth_bits (line buffer and edge record) or in depth.frac_bits (edge record only) — so the
  // descent runs in a few orders and keeps the smallest edge record (then line buffer, then the
  // sum of the widths). Every result is a local minimum: no width can drop one bit.
  std::vector<std::vector<int>> orders{{DimX, DimAttr, DimDepthBits, DimDepth},
                                       {DimX, DimAttr, DimDepth, DimDepthBits},
                                       {DimDepthBits, DimDepth, DimAttr, DimX},
                                       {DimDepth, DimDepthBits, DimAttr, DimX}};
  // The shade divider's mantissa, last, when the frame divides (eq2): other frames never read it.
  const bool eq2 = shading == ShadingMode::Gouraud && scene.interpolation == Interpolation::Eq2;
  if (eq2)
    for (std::vector<int>& order : orders) order.push_back(DimRecip);
  Descent out;
  out.dims = orders[0];
  out.orders = orders.size();
  out.eq2 = eq2;
  if (!judge.evaluate(judge.start()).passes())  // the default passes by construction
    throw std::runtime_error("the default configuration fails its own criterion: " +
                             broke(judge.evaluate(judge.start()), bound));
  auto cost = [&](const Point& p) {
    const Widths& w = p.w;
    return std::make_tuple(p.cfg.edge_record_bits(shading), line_buffer_bits(p.cfg), w[0] + w[1] + w[2] + w[3] + w[4]);
  };
  Widths& cur = out.widths;
  for (std::size_t o = 0; o < orders.size(); ++o) {
    Widths w = judge.start();
    int r = 0;
    for (bool moved = true; moved; ++r) {
      moved = false;
      for (int d : orders[o])
        for (;;) {
          Widths lower = w;
          --lower[d];
          if (!judge.evaluate(lower).passes()) break;
          w = lower;
          moved = true;
        }
    }
    out.tried += (o ? ", " : "") + std::to_string(judge.evaluate(w).cfg.edge_record_bits(shading));
    if (o == 0 || cost(judge.evaluate(w)) < cost(judge.evaluate(cur))) {
      cur = w;
      out.rounds = r;
    }
  }
  return out;
}

}  // namespace

CLI::App* add_size_command(CLI::App& app, SizeArgs& a) {
  auto* s = app.add_subcommand("size", "the smallest configuration whose image stays within --bound levels of the "
                                       "double reference (writes a configuration file)");
  cli::add_file(s, "scene", a.scene, "scene file (JSON); default: the embedded default scene");
  s->add_option("--bound", a.bound, "levels: the largest |fixed - double| allowed at a pixel showing the same polygon")
      ->capture_default_str();
  s->add_option("--shading", a.shading, "gouraud or phong; overrides the scene's shading.mode");
  s->add_option("--interpolation", a.interpolation,
                "gouraud: eq1 or eq2 (Gouraud's eq. 2, sizing the shade divider's eq2_recip_bits too); overrides "
                "shading.interpolation");
  cli::add_file(s, "--out,-o", a.out, "configuration file to write (default: <scene>.config.json)");
  s->add_flag("--compact", a.compact, "size the compact top: writes compact true and, for a Phong scene, the narrow "
                                      "Phong formats (phong.formats), every width judged at them");
  s->add_option("--patches", a.patches, "patch objects drawn as curves (Whitted's edges; sized at edge_order 3) or "
                                        "polygons; overrides each object's \"draw\"")
      ->check(CLI::IsMember({"curves", "polygons"}));
  return s;
}

// The command line's names parsed into the scene's build options (UsageError naming the option).
BuildOptions build_options(const SizeArgs& a) {
  BuildOptions opt;
  if (!a.shading.empty()) {
    opt.shading = parse_shading_mode(a.shading);
    if (!opt.shading) throw UsageError("--shading: unknown shading mode \"" + a.shading + "\" (gouraud, phong)");
  }
  if (!a.interpolation.empty()) {
    opt.interpolation = parse_interpolation(a.interpolation);
    if (!opt.interpolation)
      throw UsageError("--interpolation: unknown interpolation \"" + a.interpolation + "\" (eq1, eq2)");
  }
  if (!a.patches.empty()) opt.patches_as_curves = a.patches == "curves";
  return opt;
}

void check_size(const SizeArgs& a) {
  (void)parse_bound(a.bound);
  (void)build_options(a);
}

Config sized_config(const BuiltScene& scene, int bound, bool compact) {
  Judge judge(scene, bound, compact);
  return judge.evaluate(descend(judge, scene, bound).widths).cfg;
}

int run_size(const SizeArgs& a) {
  const int bound = parse_bound(a.bound);
  const BuildOptions opt = build_options(a);
  const auto t0 = std::chrono::steady_clock::now();
  RunFiles file;  // complete or not at all (run_files.hpp), never over the scene or a file it reads
  const Scene parsed = parse_scene_file(a.scene);
  if (!a.scene.empty()) file.input("the scene file", a.scene);
  file.scene_inputs(parsed);
  const std::string out = a.out.empty() ? default_out(a.scene) : a.out;
  file.output(a.out.empty() ? "the default output (--out)" : "--out", out);
  const BuiltScene scene = build_scene(parsed, opt);
  const ShadingMode shading = scene.shading;

  Judge judge(scene, bound, a.compact);
  const Descent found = descend(judge, scene, bound);
  const std::vector<int>& dims = found.dims;
  const Widths& cur = found.widths;
  const std::string& tried = found.tried;
  const int rounds = found.rounds;
  const Point chosen = judge.evaluate(cur);
  // One bit below the chosen point, per width: the error there and which limit broke.
  std::array<Point, NumDims> below;
  for (int d : dims) {
    Widths w = cur;
    --w[d];
    below[d] = judge.evaluate(w);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const Config& c = chosen.cfg;
  const Config def = with_scene_edge_order(scene, Config{});
  const ImageError& b = judge.baseline();
  std::printf("scene         %s  %dx%d  shading %s, %zu polygons\n", scene.name.c_str(), scene.width, scene.height,
              to_string(shading), scene.polygons.size());
  std::printf("bound         %d level(s) from the double reference at every pixel showing the same polygon; where the "
              "default configuration is already worse (%d pixels, max %d), no worse than it; coverage and visibility "
              "may differ only where the default's do (%d pixels)\n",
              bound, judge.default_over(), b.max_abs, judge.default_flips());
  std::printf("search        %d configurations rendered, coordinate descent in %zu orders of the widths (edge records "
              "%s bits), the smallest kept (%d rounds), %.2f s\n",
              judge.evaluations(), found.orders, tried.c_str(), rounds, seconds);
  std::printf("chosen        group   int.frac  bits   (default int.frac bits)\n");
  auto group = [&](const char* name, const ChannelFormat& f, const ChannelFormat& d, const char* note) {
    std::printf("              %-7s %-9s %-6d (%s %d)%s\n", name, format(f).c_str(), f.bits(), format(d).c_str(), d.bits(),
                note);
  };
  const bool phong = shading == ShadingMode::Phong;
  group("x", c.x, def.x, "");
  group("depth", c.depth, def.depth, "");
  group("shade", c.shade, def.shade, phong ? "  unused by a Phong frame: default kept" : "");
  group("normal", c.normal, def.normal, phong ? "" : "  unused by a Gouraud frame: default kept");
  std::printf("              depth_bits %d (default %d)\n", c.depth_bits, def.depth_bits);
  if (found.eq2)
    std::printf("eq2           the shade divider (Gouraud's eq. 2): eq2_recip_bits %d (default %d)\n", c.eq2_recip_bits,
                def.eq2_recip_bits);
  std::printf("capacities    max_active_edges %d, max_width %d (the screen width; the line buffer takes any width), "
              "max_materials %d (%d-bit id%s), max_polygons %d (%d-bit id), max_edges %d (%d-bit id)\n",
              c.max_active_edges, c.max_width, c.max_materials, id_bits(c.max_materials),
              phong ? "" : ": Gouraud edges carry material 0", c.max_polygons, id_bits(c.max_polygons),
              c.max_edges, id_bits(c.max_edges));
  if (c.compact)
    std::printf("compact       true (the compact top)%s\n",
                c.phong == PhongFormat::Narrow ? "; phong.formats narrow (the compact Phong blocks' 16 x 16 products)" : "");
  std::printf("smoothing     %s\n", c.smoothing ? "true (the scene smooths: the top has the smoother)"
                                                 : "false (the scene never smooths: the top has no smoother)");
  std::printf("edge record   %d bits (default %d)\n", c.edge_record_bits(shading), def.edge_record_bits(shading));
  Config def_rtl = def;
  def_rtl.max_width = fmt::DefaultMaxWidth;
  std::printf("line buffer   %lld bits: 2 x %d x (%d depth + 24 RGB) (the default RTL: %lld, MaxWidth %d)\n",
              line_buffer_bits(c), c.max_width, c.depth_bits, line_buffer_bits(def_rtl), fmt::DefaultMaxWidth);
  std::printf("active list   %lld bits: %d x %d\n", (long long)c.max_active_edges * c.edge_record_bits(shading),
              c.max_active_edges, c.edge_record_bits(shading));
  auto error = [&](const Point& p) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "max |d| %d, mean |d| %.4f levels, %d pixels > 1 level; %d change polygon, %d coverage",
                  p.err.max_abs, p.err.mean_abs, p.err.over_one, p.err.visibility_differs, p.err.coverage_differs);
    return std::string(buf);
  };
  std::printf("error default %s\n", error(judge.evaluate(judge.start())).c_str());
  std::printf("error chosen  %s\n", error(chosen).c_str());
  std::printf("one bit below\n");
  for (int d : dims) {
    const Point& p = below[d];
    std::printf("  %-17s %2d: %s\n", dim_name(d, shading), p.w[d],
                p.refused.empty() ? (error(p) + "\n                       broke " + broke(p, bound)).c_str()
                                  : broke(p, bound).c_str());
  }
  file.add(out, config_json(c));
  file.commit();
  std::printf("wrote         %s\n", out.c_str());
  return 0;
}

}  // namespace watkins::size
