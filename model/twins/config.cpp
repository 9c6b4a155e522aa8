#include "config.hpp"

#include <cstring>

namespace watkins {

const char* channel_name(int c, ShadingMode shading) {
  static const char* gouraud[fmt::NumChannels] = {"X", "Z", "R", "G", "B"};
  static const char* phong[fmt::NumChannels] = {"X", "Z", "Nx", "Ny", "Nz"};
  return (shading == ShadingMode::Phong ? phong : gouraud)[c];
}

const char* channel_group_name(int c, ShadingMode shading) {
  if (c == fmt::ChanX) return "x";
  if (c == fmt::ChanZ) return "depth";
  return shading == ShadingMode::Phong ? "normal" : "shade";
}

const char* phong_format_name(PhongFormat f) { return f == PhongFormat::Narrow ? "narrow" : "model"; }

int id_bits(int n) {
  int b = 1;
  while ((1LL << b) < n) ++b;
  return b;
}

int Config::edge_record_bits(ShadingMode shading) const {
  const ChannelFormats f = channels(shading);
  int words = 0;
  for (int c = 0; c < fmt::NumChannels; ++c) words += f.bits[c];
  return 2 * fmt::LineBits + id_bits(max_polygons) + id_bits(max_materials) + (1 + edge_order) * words;
}

bool RtlParameter::operator==(const RtlParameter& o) const {
  return value == o.value && std::strcmp(name, o.name) == 0;
}

std::vector<RtlParameter> rtl_parameters(const Config& c, ShadingMode shading) {
  const bool phong = shading == ShadingMode::Phong;
  const ChannelFormat& attr = phong ? c.normal : c.shade;
  std::vector<RtlParameter> p{{"Phong", phong ? 1 : 0},
          {"MaxActiveEdges", c.max_active_edges},
          {"MaxWidth", c.max_width},
          {"XIntBits", c.x.int_bits},
          {"XFracBits", c.x.frac_bits},
          {"DepthIntBits", c.depth.int_bits},
          {"DepthFracBits", c.depth.frac_bits},
          {"AttrIntBits", attr.int_bits},
          {"AttrFracBits", attr.frac_bits},
          {"DepthBits", c.depth_bits},
          {"PolyIdBits", id_bits(c.max_polygons)},
          {"MaterialIdBits", id_bits(c.max_materials)},
          {"EdgeIdBits", id_bits(c.max_edges)}};
  // The RTL's default is 1; leaving it out then keeps every order-1 list (and the tops built
  // for it, keyed by the list) exactly as before the parameter existed.
  if (c.edge_order != 1) p.push_back({"EdgeOrder", c.edge_order});
  // Likewise Smoothing (RTL default 1): only a top without the smoother lists it.
  if (!c.smoothing) p.push_back({"Smoothing", 0});
  // Likewise the eq. (2) divider (RTL default HasEq2 = 0), a block of the Gouraud top only.
  if (c.eq2 && !phong) {
    p.push_back({"HasEq2", 1});
    p.push_back({"Eq2RecipBits", c.eq2_recip_bits});
  }
  // Likewise Compact (RTL default 0).
  if (c.compact) p.push_back({"Compact", 1});
  // Likewise Lanes (RTL default 1).
  if (c.lanes != 1) p.push_back({"Lanes", c.lanes});
  // Likewise PhongNarrow (RTL default 0), a parameter of the Phong blocks only.
  if (phong && c.phong == PhongFormat::Narrow) p.push_back({"PhongNarrow", 1});
  return p;
}

std::string Config::check() const {
  auto range = [](const std::string& field, int v, int lo, int hi) -> std::string {
    if (v >= lo && v <= hi) return "";
    return field + ": " + std::to_string(v) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  };
  struct Group {
    const char* name;
    const ChannelFormat& f;
    int min_frac;
    int natural_int;  // signed integer bits of the group's largest quantity, before any scene
  };
  const Group groups[] = {{"x", x, MinXFrac, fmt::VertexIntBits},
                          {"depth", depth, 0, depth_bits + 1},
                          {"shade", shade, 0, fmt::ShadeBits + 1},
                          {"normal", normal, 0, 2}};
  if (std::string e = range("depth_bits", depth_bits, 1, MaxDepthBits); !e.empty()) return e;
  for (const Group& g : groups) {
    const std::string n = g.name;
    if (g.f.int_bits < MinIntBits)
      return n + ".int_bits: " + std::to_string(g.f.int_bits) + " is below " + std::to_string(MinIntBits) +
             " (the sign bit)";
    if (g.f.frac_bits < g.min_frac)
      return n + ".frac_bits: " + std::to_string(g.f.frac_bits) + " is below " + std::to_string(g.min_frac) +
             (n == "x" ? " (X holds the vertices' 1/16 pixel exactly)" : "");
    if (n == "x" && g.f.frac_bits > MaxXFrac)
      return "x.frac_bits: " + std::to_string(g.f.frac_bits) + " is above " + std::to_string(MaxXFrac) +
             " (the span step shifts by p + RecipBits - x.frac_bits >= 1)";
    if (g.f.frac_bits + g.natural_int > MaxWordBits)
      return n + ".frac_bits: " + std::to_string(g.f.frac_bits) + " is above " +
             std::to_string(MaxWordBits - g.natural_int) + " (the model quantizes in " +
             std::to_string(MaxWordBits) + "-bit words)";
    if (g.f.bits() > MaxWordBits)
      return n + ": int_bits + frac_bits = " + std::to_string(g.f.bits()) + " exceeds the model's " +
             std::to_string(MaxWordBits) + "-bit words";
  }
  if (std::string e = range("max_active_edges", max_active_edges, 1, 1 << 30); !e.empty()) return e;
  if (std::string e = range("max_width", max_width, 1, fmt::MaxScreen); !e.empty()) return e;
  if (std::string e = range("max_materials", max_materials, 1, fmt::MaxMaterials); !e.empty()) return e;
  if (std::string e = range("max_polygons", max_polygons, 1, fmt::MaxPolygons); !e.empty()) return e;
  if (std::string e = range("max_edges", max_edges, 1, fmt::MaxEdges); !e.empty()) return e;
  if (std::string e = range("eq2_recip_bits", eq2_recip_bits, MinEq2RecipBits, MaxEq2RecipBits); !e.empty())
    return e;
  if (edge_order != 1 && edge_order != 3)
    return "edge_order: " + std::to_string(edge_order) + " is neither 1 (straight edges) nor 3 (cubic forward differences)";
  if (lanes != 1 && lanes != 2)
    return "lanes: " + std::to_string(lanes) + " is neither 1 nor 2 (fragments per clock of the compact top)";
  if (lanes != 1 && !compact) return "lanes: 2 needs compact true (the pipelined top takes one fragment per clock)";
  if (phong == PhongFormat::Narrow && !compact)
    return "phong.formats: narrow needs compact true (the pipelined Phong blocks take the model's formats)";
  return "";
}

std::string Config::check(ShadingMode shading) const {
  if (std::string e = check(); !e.empty()) return e;
  if (lanes != 1 && shading == ShadingMode::Phong)
    return "lanes: 2 is Gouraud only (the compact Phong blocks shade one fragment a beat)";
  return "";
}

}  // namespace watkins
