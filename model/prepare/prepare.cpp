// Scene preparation: quantization, edge setup with sub-pixel prestep, y-sort, capacity checks.
#include "prepare.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "curved_edges.hpp"
#include "signed_bits.hpp"

namespace watkins {
namespace {

constexpr i64 kSub = 1 << fmt::SubPixelBits;               // 16 sub-pixel steps per pixel
constexpr i64 kHalfPixelSub = kSub / 2;                     // pixel centre offset in 1/16 pixel
constexpr double kVertexLimit = fmt::VertexLimit;  // 8192 pixels
constexpr double kUnitSlack = 1e-6;  // |unit vector component| <= 1 up to double rounding

i64 quantize(double v, int frac_bits) { return std::llround(std::ldexp(v, frac_bits)); }

// ceil(a / kSub) for any sign of a.
i64 ceil_sub(i64 a) { return static_cast<i64>(floor_shift(a + kSub - 1, fmt::SubPixelBits)); }

// A component of a unit vector, checked and rounded to `frac_bits` fraction bits.
i64 quantize_unit(double c, int frac_bits, const std::string& what) {
  if (!(std::isfinite(c) && std::fabs(c) <= 1 + kUnitSlack))
    throw SceneError(what + " component " + number_text(c) + " is outside [-1, 1] (expected a unit vector)");
  return quantize(c, frac_bits);
}

// Light and eye directions: Q2.14 (UnitBits), the phong_shader's frame constants.
std::array<i64, 3> quantize_direction(const double (&v)[3], const std::string& what) {
  return {quantize_unit(v[0], fmt::UnitFracBits, what), quantize_unit(v[1], fmt::UnitFracBits, what),
          quantize_unit(v[2], fmt::UnitFracBits, what)};
}

std::string where(int poly, int vertex) {
  std::ostringstream s;
  s << "polygon " << poly << " vertex " << vertex;
  return s.str();
}

}  // namespace

QuantizedVertex quantize_vertex(const ScreenVertex& v, ShadingMode shading, const Config& cfg, bool eq2) {
  QuantizedVertex q;
  auto in_range = [](double c) { return std::isfinite(c) && c >= -kVertexLimit && c < kVertexLimit; };
  if (!in_range(v.x) || !in_range(v.y))
    throw SceneError("vertex (" + std::to_string(v.x) + ", " + std::to_string(v.y) +
                     ") is outside the representable range [-8192, 8192) pixels");
  if (!(v.depth >= 0.0 && v.depth < 1.0))
    throw SceneError("vertex depth " + std::to_string(v.depth) + " is outside [0, 1)");
  q.x16 = quantize(v.x, fmt::SubPixelBits);
  q.y16 = quantize(v.y, fmt::SubPixelBits);
  if (q.x16 >= static_cast<i64>(kVertexLimit) * kSub || q.y16 >= static_cast<i64>(kVertexLimit) * kSub)
    throw SceneError("vertex rounds to the edge of the representable range [-8192, 8192) pixels");
  // Vertex channels are exact integers here, never held by the hardware: whether the X word (or
  // any other) is wide enough is decided by the values the pipeline holds, which prepare()
  // checks on every edge and span (an off-screen vertex may lie outside the X word).
  q.ch[fmt::ChanX] = q.x16 * (i64{1} << (cfg.x.frac_bits - fmt::SubPixelBits));
  const int fz = cfg.depth.frac_bits;
  const i64 depth_max = (i64{1} << cfg.depth_bits) - 1;
  q.ch[fmt::ChanZ] = std::min<i64>(quantize(v.depth, cfg.depth_bits + fz), (depth_max << fz) | ((i64{1} << fz) - 1));
  if (shading == ShadingMode::Phong) {
    for (int c = 0; c < 3; ++c)
      q.ch[fmt::ChanNx + c] = quantize_unit(v.normal[c], cfg.normal.frac_bits, "vertex normal");
    return q;
  }
  // Eq. (2)'s numerator: the shade times the depth the divider will see at the vertex.
  const double z = eq2 ? std::ldexp(static_cast<double>(q.ch[fmt::ChanZ]), -(cfg.depth_bits + fz)) : 1.0;
  for (int c = 0; c < fmt::ShadeChannels; ++c) {
    if (!(v.rgb[c] >= 0.0 && v.rgb[c] <= fmt::ShadeMax))
      throw SceneError("vertex shade " + std::to_string(v.rgb[c]) + " is outside [0, 255]");
    q.ch[fmt::ChanR + c] = quantize(v.rgb[c] * z, cfg.shade.frac_bits);
  }
  return q;
}

int quantize_smooth_weight(double W) {
  return static_cast<int>(std::clamp<long>(std::lround(W * (1 << fmt::SmoothWFracBits)), 0, (1 << fmt::SmoothWBits) - 1));
}

QuantizedMaterial quantize_material(const PhongMaterial& m) {
  auto in = [](double x, double lo, double hi) { return std::isfinite(x) && x >= lo && x <= hi; };
  const double w_max = double((1 << fmt::MaterialBits) - 1) / (1 << fmt::MaterialFracBits);
  QuantizedMaterial q;
  for (int c = 0; c < 3; ++c) {
    if (!in(m.cp[c], 0, 1)) throw SceneError("colour " + number_text(m.cp[c]) + " is outside [0, 1]");
    q.cp[c] = static_cast<int>(std::lround(m.cp[c] * fmt::ShadeMax));
  }
  if (!in(m.d, 0, 1)) throw SceneError("d = " + number_text(m.d) + " is outside [0, 1]");
  if (!in(m.W, 0, w_max)) throw SceneError("W = " + number_text(m.W) + " is outside [0, " + number_text(w_max) + "]");
  if (m.n < 0 || m.n >= (1 << fmt::ShininessBits))
    throw SceneError("n = " + std::to_string(m.n) + " is outside [0, " +
                     std::to_string((1 << fmt::ShininessBits) - 1) + "]");
  const int one = 1 << fmt::MaterialFracBits;
  q.d = std::clamp(static_cast<int>(quantize(m.d, fmt::MaterialFracBits)), 0, one);
  q.w = std::clamp(static_cast<int>(quantize(m.W, fmt::MaterialFracBits)), 0, (1 << fmt::MaterialBits) - 1);
  q.shininess = m.n;
  return q;
}

namespace {

// make_edge_record, also reporting the signed bits each channel's values need on the edge's
// first and last scan line, before any wrap (values step linearly: the ends are the extremes).
bool edge_setup(const QuantizedVertex& a, const QuantizedVertex& b, int poly, int height,
                const ChannelFormats& formats, EdgeRecord& out, std::array<int, fmt::NumChannels>* bits) {
  if (a.y16 == b.y16) return false;  // horizontal: its polygon's other edges bound the span
  // Canonical order, top vertex first, so two polygons sharing the edge step identical X.
  const QuantizedVertex& top = a.y16 < b.y16 ? a : b;
  const QuantizedVertex& bot = a.y16 < b.y16 ? b : a;
  // Scan line y is crossed when top <= y + 1/2 < bottom (half-open: no double hits).
  i64 y_first = ceil_sub(top.y16 - kHalfPixelSub);
  const i64 y_end = std::min<i64>(ceil_sub(bot.y16 - kHalfPixelSub), height);
  y_first = std::max<i64>(y_first, 0);
  if (y_end <= y_first) return false;

  const i64 dy = bot.y16 - top.y16;
  const i64 y_centre = y_first * kSub + kHalfPixelSub;  // first scan line's centre, 1/16 pixel
  out.y0 = static_cast<int>(y_first);
  out.n = static_cast<int>(y_end - y_first);
  out.poly = poly;
  for (int c = 0; c < fmt::NumChannels; ++c) {
    const i128 delta = static_cast<i128>(bot.ch[c]) - top.ch[c];
    // ΔS = (S2 − S1)/n per scan line (Gouraud), here per unit of y so sub-pixel vertices step
    // exactly; rounded once. The prestep to the first centre is computed exactly, rounded once.
    const i128 slope = round_div(delta * kSub, dy);
    const i128 first = top.ch[c] + round_div(delta * (y_centre - top.y16), dy);
    out.slope[c] = wrap_signed(slope, formats.bits[c]);
    out.value[c] = wrap_signed(first, formats.bits[c]);
    if (bits) (*bits)[c] = std::max(signed_bits(first), signed_bits(first + (out.n - 1) * slope));
  }
  return true;
}

}  // namespace

bool make_edge_record(const QuantizedVertex& a, const QuantizedVertex& b, int poly, int height,
                      const ChannelFormats& formats, EdgeRecord& out) {
  return edge_setup(a, b, poly, height, formats, out, nullptr);
}

bool make_edge_record(const QuantizedVertex& a, const QuantizedVertex& b, int poly, int height,
                      EdgeRecord& out) {
  return make_edge_record(a, b, poly, height, Config{}.channels(ShadingMode::Gouraud), out);
}

static PreparedScene prepare_unnamed(const BuiltScene& scene, const Config& cfg);

// Phong's frame constants: the materials (at most 2^MaterialIdBits), light and eye in Q2.14.
static void prepare_phong_constants(const BuiltScene& scene, const Config& cfg, PreparedScene& out) {
  const std::size_t max_materials = cfg.max_materials;
  if (scene.materials.size() > max_materials)
    throw SceneError("scene needs " + std::to_string(scene.materials.size()) + " materials; the material id is " +
                     std::to_string(id_bits(cfg.max_materials)) + " bits and holds " + std::to_string(max_materials) +
                     (cfg.max_materials == fmt::MaxMaterials
                          ? " (merge materials, or raise MaterialIdBits in model/twins/formats.hpp and the RTL to match)"
                          : " (max_materials of the configuration)"));
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    try {
      out.materials.push_back(quantize_material(scene.materials[m]));
    } catch (const SceneError& e) {
      throw SceneError("material " + std::to_string(m) + ": " + e.what());
    }
  }
  out.light = quantize_direction(scene.light, "light direction");
  out.eye = quantize_direction(scene.eye, "eye direction");
}

PreparedScene prepare(const BuiltScene& scene, const PrepareOptions& opt) {
  Config cfg;
  cfg.max_active_edges = opt.max_active_edges;
  return prepare(scene, cfg);
}

Config with_scene_edge_order(const BuiltScene& scene, Config base) {
  if (!scene.curves.empty()) base.edge_order = 3;
  if (scene.shading == ShadingMode::Gouraud && scene.interpolation == Interpolation::Eq2) base.eq2 = true;
  return base;
}

Config fit_int_bits(const BuiltScene& scene, const Config& base_in, PreparedScene* probe) {
  const Config base = with_scene_edge_order(scene, base_in);
  Config wide = base;
  ChannelFormat& attr = scene.shading == ShadingMode::Phong ? wide.normal : wide.shade;
  for (ChannelFormat* f : {&wide.x, &wide.depth, &attr})
    f->int_bits = std::max(Config::MinIntBits, Config::MaxWordBits - f->frac_bits);
  wide.max_active_edges = 1 << 30;
  if (const std::string e = wide.check(); !e.empty()) throw SceneError("configuration: " + e);
  PreparedScene p = prepare(scene, wide);
  const ChannelFormats f = wide.channels(scene.shading);
  Config c = base;
  ChannelFormat* group[fmt::NumChannels] = {&c.x, &c.depth, nullptr, nullptr, nullptr};
  for (int ch = fmt::ChanR; ch < fmt::NumChannels; ++ch)
    group[ch] = scene.shading == ShadingMode::Phong ? &c.normal : &c.shade;
  for (ChannelFormat* g : {&c.x, &c.depth, group[fmt::ChanR]}) g->int_bits = Config::MinIntBits;
  for (int ch = 0; ch < fmt::NumChannels; ++ch)
    group[ch]->int_bits = std::max(group[ch]->int_bits, p.needs.int_bits_needed(ch, f.frac[ch]));
  if (probe) *probe = std::move(p);
  return c;
}

PreparedScene prepare(const BuiltScene& scene, const Config& cfg) {
  if (const std::string e = cfg.check(scene.shading); !e.empty()) throw SceneError("configuration: " + e);
  try {
    return prepare_unnamed(scene, cfg);
  } catch (const SceneError& e) {
    throw SceneError(scene.name + ": " + e.what());  // every message names the scene
  }
}

// Refuses a frame whose channel values need more bits than their words hold.
static void check_channel_bits(const std::array<int, fmt::NumChannels>& need, const ChannelFormats& formats,
                               ShadingMode shading, const char* where) {
  for (int c = 0; c < fmt::NumChannels; ++c)
    if (need[c] > formats.bits[c]) {
      const char* group = channel_group_name(c, shading);
      throw SceneError(std::string(where) + " values of channel " + channel_name(c, shading) + " need " +
                       std::to_string(need[c]) + " signed bits; the configuration's " + group + " word is " +
                       std::to_string(formats.bits[c]) + " (" + group + ".int_bits " +
                       std::to_string(formats.bits[c] - formats.frac[c]) + ", needs " +
                       std::to_string(need[c] - formats.frac[c]) + ")");
    }
}

// Whitted's curved edges (curved_edges.hpp): each curve's forward-difference records, region r
// paired as polygon polygons.size() + r, after the polygons' edges (the y-sort keeps them there
// on equal first lines). They need the cubic incrementer: an order-1 configuration is refused.
static void prepare_curves(const BuiltScene& scene, const Config& cfg, PreparedScene& out,
                           std::array<int, fmt::NumChannels>& edge_bits) {
  if (scene.curves.empty()) return;
  if (out.eq2)
    throw SceneError("interpolation: the scene has " + std::to_string(scene.curves.size()) +
                     " curved edges; eq2 divides the shade of polygons only (draw the patches as polygons)");
  if (cfg.edge_order != 3)
    throw SceneError("edge_order: the scene has " + std::to_string(scene.curves.size()) +
                     " curved edges, which need edge_order 3 (cubic forward differences); the configuration's is " +
                     std::to_string(cfg.edge_order));
  const std::size_t ids = scene.polygons.size() + static_cast<std::size_t>(std::max(0, scene.curve_regions));
  if (ids > static_cast<std::size_t>(cfg.max_polygons))
    throw SceneError("scene has " + std::to_string(scene.polygons.size()) + " polygons and " +
                     std::to_string(scene.curve_regions) + " curved regions; the polygon id is " +
                     std::to_string(id_bits(cfg.max_polygons)) + " bits (at most " + std::to_string(cfg.max_polygons) + ")");
  const bool phong = scene.shading == ShadingMode::Phong;
  for (std::size_t i = 0; i < scene.curves.size(); ++i) {
    const ScreenCurve& curve = scene.curves[i];
    const std::string name = "curve " + std::to_string(i);
    if (curve.region < 0 || curve.region >= scene.curve_regions)
      throw SceneError(name + ": region " + std::to_string(curve.region) + " is not one of the scene's " +
                       std::to_string(scene.curve_regions));
    if (phong && (curve.material < 0 || curve.material >= static_cast<int>(out.materials.size())))
      throw SceneError(name + ": material " + std::to_string(curve.material) + " is not one of the scene's " +
                       std::to_string(out.materials.size()) + " materials");
    CurveEdges fit;
    try {
      fit = fit_curve(curve, scene.height, scene.shading, cfg);
    } catch (const SceneError& e) {
      throw SceneError(name + ": " + e.what());
    }
    for (EdgeRecord r : fit.records) {
      r.poly = static_cast<int>(scene.polygons.size()) + curve.region;
      r.material = phong ? curve.material : 0;
      out.edges.push_back(r);
    }
    for (int c = 0; c < fmt::NumChannels; ++c) edge_bits[c] = std::max(edge_bits[c], fit.value_bits[c]);
  }
}

static PreparedScene prepare_unnamed(const BuiltScene& scene, const Config& cfg) {
  if (scene.width < 1 || scene.width > cfg.max_width || scene.height < 1 ||
      scene.height > fmt::MaxScreen)
    throw SceneError("screen " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                     " exceeds the pipeline's limit of " + std::to_string(cfg.max_width) + "x" +
                     std::to_string(fmt::MaxScreen) +
                     (cfg.max_width == fmt::MaxScreen ? "" : " (max_width of the configuration)"));
  const std::size_t max_polys = cfg.max_polygons;
  if (scene.polygons.size() > max_polys)
    throw SceneError("scene has " + std::to_string(scene.polygons.size()) +
                     " polygons; the polygon id is " + std::to_string(id_bits(cfg.max_polygons)) +
                     " bits (at most " + std::to_string(max_polys) + ")");

  PreparedScene out;
  out.config = cfg;
  out.width = scene.width;
  out.height = scene.height;
  for (int c = 0; c < 3; ++c)
    out.background[c] = static_cast<std::uint8_t>(
        std::clamp<long>(std::lround(scene.background[c]), 0, fmt::ShadeMax));
  out.polygons = static_cast<int>(scene.polygons.size());
  out.shading = scene.shading;
  out.depth_tie = scene.depth_tie;
  out.smooth_w = quantize_smooth_weight(scene.smooth);
  if (out.smoothed() && !cfg.smoothing)
    throw SceneError("smoothing: the scene smooths (W = " + std::to_string(out.smooth_w) + "/" +
                     std::to_string(1 << fmt::SmoothWFracBits) +
                     ", shading.smooth or --smooth); the configuration has smoothing false (no smoother)");
  const bool phong = scene.shading == ShadingMode::Phong;
  out.eq2 = !phong && scene.interpolation == Interpolation::Eq2;
  if (out.eq2 && !cfg.eq2)
    throw SceneError("interpolation: the scene uses eq2 (Gouraud's eq. (2), a division per pixel); the "
                     "configuration has eq2 false (no shade divider)");
  if (phong) prepare_phong_constants(scene, cfg, out);
  const ChannelFormats formats = cfg.channels(scene.shading);
  std::array<int, fmt::NumChannels> edge_bits{};  // bits the edge values need, before any wrap

  for (std::size_t p = 0; p < scene.polygons.size(); ++p) {
    const auto& poly = scene.polygons[p];
    if (phong && (poly.material < 0 || poly.material >= static_cast<int>(out.materials.size())))
      throw SceneError("polygon " + std::to_string(p) + ": material " + std::to_string(poly.material) +
                       " is not one of the scene's " + std::to_string(out.materials.size()) + " materials");
    std::vector<QuantizedVertex> q;
    for (std::size_t i = 0; i < poly.v.size(); ++i) {
      try {
        q.push_back(quantize_vertex(poly.v[i], scene.shading, cfg, out.eq2));
      } catch (const SceneError& e) {
        throw SceneError(where(static_cast<int>(p), static_cast<int>(i)) + ": " + e.what());
      }
    }
    for (std::size_t i = 0; i < q.size(); ++i) {
      EdgeRecord e;
      std::array<int, fmt::NumChannels> bits{};
      if (edge_setup(q[i], q[(i + 1) % q.size()], static_cast<int>(p), scene.height, formats, e, &bits)) {
        e.material = phong ? poly.material : 0;
        out.edges.push_back(e);
        for (int c = 0; c < fmt::NumChannels; ++c) edge_bits[c] = std::max(edge_bits[c], bits[c]);
      }
    }
  }
  prepare_curves(scene, cfg, out, edge_bits);
  // The hardware reads edges in order of their first scan line; polygon order breaks ties.
  std::stable_sort(out.edges.begin(), out.edges.end(),
                   [](const EdgeRecord& a, const EdgeRecord& b) { return a.y0 < b.y0; });
  for (std::size_t i = 0; i < out.edges.size(); ++i) out.edges[i].id = static_cast<int>(i);
  // The RTL numbers records with id_bits(max_edges) bits; a wrapped id would break X ties wrong.
  if (out.edges.size() > static_cast<std::size_t>(cfg.max_edges))
    throw SceneError("scene has " + std::to_string(out.edges.size()) + " edge records; the edge id is " +
                     std::to_string(id_bits(cfg.max_edges)) + " bits (at most " + std::to_string(cfg.max_edges) +
                     (cfg.max_edges == fmt::MaxEdges ? ")" : ", max_edges of the configuration)"));

  // Edge values wrapped on some scan line would step (and sort) wrong: refuse before the walk.
  check_channel_bits(edge_bits, formats, scene.shading, "edge");
  out.needs = measure_needs(out, out.polygons, formats);
  for (int c = 0; c < fmt::NumChannels; ++c) out.needs.value_bits[c] = std::max(out.needs.value_bits[c], edge_bits[c]);
  const SceneNeeds& needs = out.needs;
  check_channel_bits(needs.value_bits, formats, scene.shading, "span");
  if (needs.max_active_edges > cfg.max_active_edges)
    throw SceneError("scene needs " + std::to_string(needs.max_active_edges) +
                     " active edges on scan line " + std::to_string(needs.max_active_line) +
                     "; the active-edge list holds " + std::to_string(cfg.max_active_edges) +
                     " (raise --max-active-edges, and the RTL's MaxActiveEdges, to match)");
  return out;
}

}  // namespace watkins
