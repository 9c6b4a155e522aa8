#include "config_file.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "scene_error.hpp"
#include "strict_json.hpp"

namespace watkins {
namespace {

using nlohmann::json;

std::string show(const json& j) { return show_json(j); }

class ConfigReader {
 public:
  explicit ConfigReader(std::string name) : name_(std::move(name)) {}
  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw SceneError(name_ + ": " + (field.empty() ? "" : field + ": ") + what);
  }
  void keys(const json& j, const std::string& field, std::initializer_list<const char*> allowed) const {
    if (!j.is_object()) fail(field, "expected an object, got " + show(j));
    for (auto it = j.begin(); it != j.end(); ++it) {
      bool ok = false;
      for (const char* a : allowed) ok = ok || it.key() == a;
      if (!ok) fail(field, "unknown key " + quote_input(it.key()));
    }
  }
  // An integer at j[key] when present (kept otherwise).
  void integer(const json& j, const std::string& field, const char* key, int& out) const {
    auto it = j.find(key);
    if (it == j.end()) return;
    const std::string f = field.empty() ? key : field + "." + key;
    if (!it->is_number()) fail(f, "expected an integer, got " + show(*it));
    const double x = it->get<double>();
    if (!(std::isfinite(x) && x == std::floor(x) && std::fabs(x) < 1e9)) fail(f, "expected an integer, got " + show(*it));
    out = static_cast<int>(x);
  }
  // A boolean at j[key] when present (kept otherwise).
  void boolean(const json& j, const char* key, bool& out) const {
    auto it = j.find(key);
    if (it == j.end()) return;
    if (!it->is_boolean()) fail(key, "expected true or false, got " + show(*it));
    out = it->get<bool>();
  }
  void group(const json& j, const char* key, ChannelFormat& out) const {
    auto it = j.find(key);
    if (it == j.end()) return;
    keys(*it, key, {"int_bits", "frac_bits"});
    integer(*it, key, "int_bits", out.int_bits);
    integer(*it, key, "frac_bits", out.frac_bits);
  }
  // "phong": {"formats": "model" | "narrow"} when present (kept otherwise).
  void phong(const json& j, PhongFormat& out) const {
    auto it = j.find("phong");
    if (it == j.end()) return;
    keys(*it, "phong", {"formats"});
    auto f = it->find("formats");
    if (f == it->end()) return;
    if (f->is_string() && f->get<std::string>() == "model") {
      out = PhongFormat::Model;
    } else if (f->is_string() && f->get<std::string>() == "narrow") {
      out = PhongFormat::Narrow;
    } else {
      fail("phong.formats", "expected \"model\" or \"narrow\", got " + show(*f));
    }
  }

 private:
  std::string name_;
};

}  // namespace

Config parse_config(const std::string& text, const std::string& name) {
  const json root = parse_strict_json(text, name, /*comments=*/false);
  const ConfigReader r(name);
  r.keys(root, "", {"x", "depth", "shade", "normal", "depth_bits", "max_active_edges", "max_width",
                    "max_materials", "max_polygons", "max_edges", "edge_order", "smoothing", "eq2", "eq2_recip_bits",
                    "compact", "lanes", "phong"});
  Config c;
  r.group(root, "x", c.x);
  r.group(root, "depth", c.depth);
  r.group(root, "shade", c.shade);
  r.group(root, "normal", c.normal);
  r.integer(root, "", "depth_bits", c.depth_bits);
  r.integer(root, "", "max_active_edges", c.max_active_edges);
  r.integer(root, "", "max_width", c.max_width);
  r.integer(root, "", "max_materials", c.max_materials);
  r.integer(root, "", "max_polygons", c.max_polygons);
  r.integer(root, "", "max_edges", c.max_edges);
  r.integer(root, "", "edge_order", c.edge_order);
  r.boolean(root, "smoothing", c.smoothing);
  r.boolean(root, "eq2", c.eq2);
  r.integer(root, "", "eq2_recip_bits", c.eq2_recip_bits);
  r.boolean(root, "compact", c.compact);
  r.integer(root, "", "lanes", c.lanes);
  r.phong(root, c.phong);
  if (const std::string e = c.check(); !e.empty()) throw SceneError(name + ": " + e);
  return c;
}

Config load_config(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw SceneError(path + ": cannot open configuration file");
  // At most 1 MiB (a configuration is a few hundred bytes; /dev/zero is refused, not read whole).
  constexpr std::streamsize kMaxBytes = 1 << 20;
  std::string text(static_cast<size_t>(kMaxBytes) + 1, '\0');
  in.read(text.data(), kMaxBytes + 1);
  text.resize(static_cast<size_t>(in.gcount()));
  if (in.bad()) throw SceneError(path + ": cannot read configuration file");
  if (text.size() > static_cast<size_t>(kMaxBytes)) throw SceneError(path + ": configuration file is larger than 1 MiB");
  return parse_config(text, path);
}

std::string config_json(const Config& c) {
  auto group = [](const ChannelFormat& f) {
    return "{\"int_bits\": " + std::to_string(f.int_bits) + ", \"frac_bits\": " + std::to_string(f.frac_bits) + "}";
  };
  std::ostringstream o;
  o << "{\n"
    << "  \"x\": " << group(c.x) << ",\n"
    << "  \"depth\": " << group(c.depth) << ",\n"
    << "  \"shade\": " << group(c.shade) << ",\n"
    << "  \"normal\": " << group(c.normal) << ",\n"
    << "  \"depth_bits\": " << c.depth_bits << ",\n"
    << "  \"max_active_edges\": " << c.max_active_edges << ",\n"
    << "  \"max_width\": " << c.max_width << ",\n"
    << "  \"max_materials\": " << c.max_materials << ",\n"
    << "  \"max_polygons\": " << c.max_polygons << ",\n"
    << "  \"max_edges\": " << c.max_edges;
  // Written only when not the default, so an order-1 file reads as it always did.
  if (c.edge_order != 1) o << ",\n  \"edge_order\": " << c.edge_order;
  // Likewise: absent means the smoother is there.
  if (!c.smoothing) o << ",\n  \"smoothing\": false";
  // Likewise: absent means no eq. (2) divider (and its default mantissa).
  if (c.eq2) o << ",\n  \"eq2\": true,\n  \"eq2_recip_bits\": " << c.eq2_recip_bits;
  // Likewise: absent means the pipelined micro-architecture.
  if (c.compact) o << ",\n  \"compact\": true";
  // Likewise: absent means one fragment a clock.
  if (c.lanes != 1) o << ",\n  \"lanes\": " << c.lanes;
  // Likewise: absent means the model's Phong formats.
  if (c.phong != PhongFormat::Model) o << ",\n  \"phong\": {\"formats\": \"" << phong_format_name(c.phong) << "\"}";
  o << "\n}\n";
  return o.str();
}

}  // namespace watkins
