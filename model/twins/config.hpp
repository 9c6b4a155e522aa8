// A hardware configuration chosen at run time: the fixed-point format of each channel group
// (X, depth, shade R G B, normal Nx Ny Nz) and the capacities of the pipeline. The twins and
// scene preparation take their widths from it, so one binary models any configuration; the
// default is exactly the compile-time formats (formats.hpp, rtl/watkins_pkg.sv), bit for bit.
//
// A channel group's word is signed two's complement, int_bits + frac_bits wide; int_bits
// counts the sign bit. Values are in the group's own unit scaled by 2^frac_bits: X in pixels,
// depth in 2^-depth_bits of [0, 1), shade in 8-bit levels, the normal in units of 1.0.
// The edge record's channel slots 2..4 carry the shade (Gouraud) or the normal (Phong), so a
// configuration resolves to five slot formats per shading mode (ChannelFormats).
//
// What the RTL takes from it: watkins_top's parameters (rtl_parameters(), printed by
// `watkins_gen_pkg --params F --shading S` as a Verilator -G file):
//   slot formats     X: XIntBits, XFracBits; Z: DepthIntBits, DepthFracBits; slots 2..4: AttrIntBits,
//                    AttrFracBits (the shade group in a Gouraud top, the normal group in a Phong top)
//   depth_bits       DepthBits (fragment depth, scan-line buffer depth word)
//   max_active_edges MaxActiveEdges; max_width MaxWidth (line buffer);
//   max_materials    MaterialIdBits = clog2(max_materials); max_polygons PolyIdBits = clog2(max_polygons)
//   max_edges        EdgeIdBits = clog2(max_edges) (the active-edge list's record numbers)
//   edge_order       EdgeOrder: 1 steps value += slope (straight edges), 3 steps a cubic by forward
//                    differences (Whitted's curved edges, model/prepare/curved_edges.hpp); listed
//                    only when not 1, so an order-1 configuration's list is that of one without it
//   smoothing        Smoothing: false builds the top without Herman & Liu's smoother (a frame
//                    that smooths is refused, prepare() and the RTL benches); listed only when
//                    false, so a smoothing configuration's list is that of one without it
//   eq2, eq2_recip_bits  HasEq2, Eq2RecipBits (Gouraud top only): the shade divider of Gouraud's
//                    eq. (2) after the interpolator (shade_divider.hpp), its reciprocal's mantissa
//                    bits; listed only when eq2, so every other list is unchanged
//   compact          Compact: the compact micro-architecture (docs/reference/compact.md: the
//                    compact_* blocks in place of their pipelined counterparts; the same values,
//                    other cycles); listed only when true
//   lanes            Lanes: fragments per clock of the compact top's fragment path (interpolator's
//                    stepper, line buffer's writer): 1, or 2 for a scene whose lines hold more
//                    fragments than a line's clocks (compact only); listed only when not 1
//   phong.formats    PhongNarrow (Phong top only): the normalizer's and shader's internal formats,
//                    the model's or the narrow set (phong_format.hpp; compact only); listed only
//                    when narrow
// Each twin's header lists which of its registers takes which of these.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "formats.hpp"
#include "phong_format.hpp"
#include "shading_mode.hpp"

namespace watkins {

// One channel group's format: a signed word of int_bits + frac_bits bits.
struct ChannelFormat {
  int int_bits = fmt::ChannelBits - fmt::FracBits;  // includes the sign bit
  int frac_bits = fmt::FracBits;
  constexpr int bits() const { return int_bits + frac_bits; }
  constexpr bool operator==(const ChannelFormat& o) const {
    return int_bits == o.int_bits && frac_bits == o.frac_bits;
  }
  constexpr bool operator!=(const ChannelFormat& o) const { return !(*this == o); }
};

// The five channel slots of the edge record (X, Z, then R G B or Nx Ny Nz) for one shading
// mode: what the twins read. bits[c] is slot c's register width, frac[c] its fraction bits.
struct ChannelFormats {
  std::array<int, fmt::NumChannels> bits{};
  std::array<int, fmt::NumChannels> frac{};
  int depth_bits = fmt::DepthBits;  // fragment depth: clamp(round(Z), 0, 2^depth_bits - 1)
  int edge_order = 1;  // 1: value += slope; 3: value += d1, d1 += d2, d2 += d3 (edge_incrementer)
  int eq2_recip_bits = fmt::Eq2RecipBits;  // the shade divider's 1/depth mantissa (shade_divider.hpp)
  PhongFormat phong = PhongFormat::Model;  // the Phong blocks' internal formats (phong_format.hpp)
  int x_frac() const { return frac[fmt::ChanX]; }
};

struct Config {
  ChannelFormat x;       // X, pixels
  ChannelFormat depth;   // Z (1/Z or Z), 2^-depth_bits units
  ChannelFormat shade;   // R, G, B, 8-bit levels (Gouraud)
  ChannelFormat normal;  // Nx, Ny, Nz, units of 1.0 (Phong)
  int depth_bits = fmt::DepthBits;               // depth resolution: [0, 1) -> [0, 2^depth_bits)
  int max_active_edges = fmt::MaxActiveEdges;    // active-edge list entries
  int max_width = fmt::DefaultMaxWidth;          // scan-line buffer pixels (screen width limit), as the RTL's default
  int max_materials = fmt::MaxMaterials;         // Phong material table entries
  int max_polygons = fmt::MaxPolygons;           // polygons per frame (polygon ids)
  int max_edges = fmt::MaxEdges;                 // edge records per frame (edge ids: the X tie order)
  // Forward differences per edge record: 1 (the slope: straight edges, the default hardware) or 3
  // (d1, d2, d3: a cubic in the scan-line index, for Whitted's curved edges; the record carries
  // three channel vectors of differences instead of one).
  int edge_order = 1;
  // Whether the hardware has Herman & Liu's 3x3 smoother after the scanline buffer (Frame::smooth_w
  // != 0 needs it). A scene that never smooths is built without it: a top's largest optional block.
  bool smoothing = true;
  // Whether the Gouraud hardware has the shade divider of Gouraud's eq. (2) (shade_divider.hpp,
  // the top's HasEq2): a frame with Frame::eq2 needs it. Off by default: the top without it is
  // today's. eq2_recip_bits: the mantissa bits of its reciprocal of the depth.
  bool eq2 = false;
  int eq2_recip_bits = fmt::Eq2RecipBits;
  // Which micro-architecture the top is built as: false the pipelined blocks (one fragment per
  // clock at 100+ MHz), true the compact ones for small parts (docs/reference/compact.md). The
  // values are the same either way; only the cycle model's timing differs.
  bool compact = false;
  // Fragments per clock of the compact fragment path: 1, or 2 (two consecutive pixels of a span a
  // beat; the line buffer's RAMs split by x parity). The values are the same either way.
  int lanes = 1;
  // The Phong blocks' internal formats: the model's (formats.hpp) or the narrow set, every product
  // one 16 x 16 product and 1/sqrt and cos(s)^n from tables (phong_format.hpp; compact only). The
  // values differ between the two; each is bit-exact with the RTL built for it.
  PhongFormat phong = PhongFormat::Model;

  // Limits a configuration must respect (validate() checks them).
  static constexpr int MaxWordBits = 62;      // the model keeps every word in 64 bits, products in 128
  static constexpr int MinXFrac = fmt::SubPixelBits;   // X holds the vertices' 1/16 pixel exactly
  // The per-pixel step is round_shift(delta * recip, p + RecipBits - x.frac_bits) with p >= 0:
  // the shift stays a right shift of at least one bit (the RTL adds half of it).
  static constexpr int MaxXFrac = fmt::RecipBits - 1;
  // Integer bits have no minimum beyond the sign: whether the values fit is the scene's
  // question, answered by prepare() (vertices, edge values on every line, span values).
  static constexpr int MinIntBits = 1;
  static constexpr int MaxDepthBits = 32;     // the fragment's depth word
  // The divider's mantissa: at least 9 bits, so a quotient whose shift is not positive is above
  // 255 (shade_divider.hpp); at most 30, so its products fit the model's 128-bit words.
  static constexpr int MinEq2RecipBits = 9, MaxEq2RecipBits = 30;

  // The slot formats of the edge record for `shading`.
  ChannelFormats channels(ShadingMode shading) const {
    ChannelFormats f;
    const ChannelFormat& attr = shading == ShadingMode::Phong ? normal : shade;
    const ChannelFormat slot[fmt::NumChannels] = {x, depth, attr, attr, attr};
    for (int c = 0; c < fmt::NumChannels; ++c) {
      f.bits[c] = slot[c].bits();
      f.frac[c] = slot[c].frac_bits;
    }
    f.depth_bits = depth_bits;
    f.edge_order = edge_order;
    f.eq2_recip_bits = eq2_recip_bits;
    f.phong = phong;
    return f;
  }
  // Bits of one edge record ($bits(edge_t) of the RTL built for this configuration).
  int edge_record_bits(ShadingMode shading) const;
  // "" when valid, else the first problem as "field: message" (e.g. "x.frac_bits: ...").
  std::string check() const;
  // check(), then what the `shading` top cannot build: lanes 2 in Phong (the compact Phong blocks
  // shade one fragment a beat).
  std::string check(ShadingMode shading) const;

  bool operator==(const Config& o) const {
    return x == o.x && depth == o.depth && shade == o.shade && normal == o.normal &&
           depth_bits == o.depth_bits && max_active_edges == o.max_active_edges &&
           max_width == o.max_width && max_materials == o.max_materials && max_polygons == o.max_polygons &&
           max_edges == o.max_edges && edge_order == o.edge_order && smoothing == o.smoothing && eq2 == o.eq2 &&
           eq2_recip_bits == o.eq2_recip_bits && compact == o.compact && lanes == o.lanes && phong == o.phong;
  }
  bool operator!=(const Config& o) const { return !(*this == o); }
};

// One parameter of watkins_top, named as the RTL names it.
struct RtlParameter {
  const char* name;
  long long value;
  bool operator==(const RtlParameter& o) const;
};
// watkins_top's parameters for `config` and `shading`, in a fixed order (Phong first): the RTL
// built with them is bit-exact with WatkinsTop(config) on frames of that shading. Two
// configurations with equal lists build the same hardware (a Gouraud top ignores the normal
// group, a Phong top the shade group).
std::vector<RtlParameter> rtl_parameters(const Config& config, ShadingMode shading);

// Names of channel slot c for messages: X, Z, R, G, B or X, Z, Nx, Ny, Nz; and of its group
// (the configuration's field): x, depth, shade or normal.
const char* channel_name(int c, ShadingMode shading);
const char* channel_group_name(int c, ShadingMode shading);

// The config file's names of the Phong formats: "model", "narrow".
const char* phong_format_name(PhongFormat f);

// ceil(log2(n)) for n >= 1: the id width that numbers n things (at least 1 bit).
int id_bits(int n);

}  // namespace watkins
