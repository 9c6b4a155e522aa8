// Edge record → watkins_pkg::edge_t of the RTL built for a configuration, bit-exact. The one place
// where the C++ record meets the RTL's packed struct; tests/cosim/test_edge_packing.cpp checks the
// default layout against rtl/watkins_pkg.sv and round-trips a narrow one.
//
// A packed struct puts its first field at the top: edge_t = {y0, n, poly, material, value, slope}.
// value and slope are *channel vectors* of VectorBits = XB + ZB + 3*AB bits (XB = XIntBits +
// XFracBits, ZB = DepthIntBits + DepthFracBits, AB = AttrIntBits + AttrFracBits of the top's
// parameters, rtl_parameters() in model/twins/config.hpp): slot 0 (X) at bit 0, slot 1 (Z) at XB,
// slot c in 2..4 at XB + ZB + (c-2)*AB, each signed two's complement. So, from bit 0 up: slope,
// value, material (MaterialIdBits), poly (PolyIdBits), n and y0 (LineBits each): EdgeRecordBits =
// Config::edge_record_bits(shading). At edge_order 3 the slope field is {d3, d2, d1}: d1 (the
// record's slope) at bit 0, d2 and d3 above it, one channel vector each, then value and the rest. For the default configuration that is the 466-bit record of
// rtl/watkins_pkg.sv (every slot 42 bits). Verilator stores a port or signal wider than 64 bits as
// little-endian 32-bit words (VlWide<N>); the fields are cut with the benches' one bit packer
// (bit_field.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "bit_field.hpp"
#include "config.hpp"
#include "edge_record.hpp"
#include "fixed_point.hpp"
#include "formats.hpp"

namespace watkins::tb {

// Where each channel slot sits in a channel vector (value, slope, the ae_value / sg_e / sg_f taps).
struct ChannelLayout {
  std::array<int, fmt::NumChannels> lsb{}, bits{};
  int vector_bits = 0;
  // Slot c at the sum of the slots below it (watkins_pkg::slot_lo), each bits[c] wide.
  static ChannelLayout of(const ChannelFormats& f) {
    ChannelLayout l;
    for (int c = 0; c < fmt::NumChannels; ++c) {
      l.lsb[c] = l.vector_bits;
      l.bits[c] = f.bits[c];
      l.vector_bits += f.bits[c];
    }
    return l;
  }
  ChannelVector read(const std::uint32_t* words, int base = 0) const {
    ChannelVector v{};
    for (int c = 0; c < fmt::NumChannels; ++c) v[c] = get_signed(words, base + lsb[c], bits[c]);
    return v;
  }
};

// The edge_t of watkins_top built for (config, shading).
struct EdgeLayout {
  ChannelLayout channels;
  int material_bits = 0, poly_bits = 0;
  int order = 1;  // Config::edge_order: forward differences carried (d1 = slope; d2, d3 at 3)
  int slope_lsb = 0, d2_lsb = 0, d3_lsb = 0, value_lsb = 0, material_lsb = 0, poly_lsb = 0, n_lsb = 0, y0_lsb = 0;
  int bits = 0;   // $bits(edge_t) == Config::edge_record_bits(shading)
  int words = 0;  // 32-bit words of the port

  static EdgeLayout of(const Config& config, ShadingMode shading) {
    EdgeLayout l;
    l.channels = ChannelLayout::of(config.channels(shading));
    l.material_bits = id_bits(config.max_materials);
    l.poly_bits = id_bits(config.max_polygons);
    l.order = config.edge_order;
    l.d2_lsb = l.slope_lsb + l.channels.vector_bits;
    l.d3_lsb = l.d2_lsb + l.channels.vector_bits;
    l.value_lsb = l.slope_lsb + l.order * l.channels.vector_bits;
    l.material_lsb = l.value_lsb + l.channels.vector_bits;
    l.poly_lsb = l.material_lsb + l.material_bits;
    l.n_lsb = l.poly_lsb + l.poly_bits;
    l.y0_lsb = l.n_lsb + fmt::LineBits;
    l.bits = l.y0_lsb + fmt::LineBits;
    l.words = (l.bits + 31) / 32;
    return l;
  }
};

// The widest edge record any valid configuration gives (Config::check(): every slot at most
// MaxWordBits, ids at most the default's widths, edge order 3): 2*13 + 16 + 4 + 4*5*62 = 1286
// bits, 41 words.
constexpr int MaxEdgeRecordBits =
    2 * fmt::LineBits + fmt::PolyIdBits + fmt::MaterialIdBits + 4 * fmt::NumChannels * Config::MaxWordBits;
constexpr int MaxEdgeWords = (MaxEdgeRecordBits + 31) / 32;
using EdgeWords = std::array<std::uint32_t, MaxEdgeWords>;  // words past layout.words stay 0

// The default configuration's layout (both shadings: shade and normal share the default format).
inline const EdgeLayout& default_edge_layout() {
  static const EdgeLayout l = EdgeLayout::of(Config{}, ShadingMode::Gouraud);
  return l;
}

// Throws std::invalid_argument when a field does not fit its width in `layout` (a preparation
// bug, or a frame prepared for another configuration: the RTL would silently see another record).
inline EdgeWords pack_edge(const EdgeLayout& layout, const EdgeRecord& e) {
  auto check_unsigned = [](const char* what, long long v, int bits) {
    if (v < 0 || v >= (1LL << bits))
      throw std::invalid_argument(std::string("pack_edge: ") + what + " = " + std::to_string(v) +
                                  " does not fit " + std::to_string(bits) + " unsigned bits");
  };
  check_unsigned("y0", e.y0, fmt::LineBits);
  check_unsigned("n", e.n, fmt::LineBits);
  check_unsigned("poly", e.poly, layout.poly_bits);
  check_unsigned("material", e.material, layout.material_bits);
  EdgeWords w{};
  set_bits(w, layout.y0_lsb, fmt::LineBits, static_cast<std::uint64_t>(e.y0));
  set_bits(w, layout.n_lsb, fmt::LineBits, static_cast<std::uint64_t>(e.n));
  set_bits(w, layout.poly_lsb, layout.poly_bits, static_cast<std::uint64_t>(e.poly));
  set_bits(w, layout.material_lsb, layout.material_bits, static_cast<std::uint64_t>(e.material));
  const ChannelLayout& ch = layout.channels;
  struct Field {
    const char* name;
    const ChannelVector& v;
    int lsb;
  };
  const Field fields[] = {{"value", e.value, layout.value_lsb},
                          {"slope", e.slope, layout.slope_lsb},
                          {"d2", e.d2, layout.d2_lsb},
                          {"d3", e.d3, layout.d3_lsb}};
  for (int c = 0; c < fmt::NumChannels; ++c) {
    for (const Field& f : fields) {
      const bool carried = &f.v == &e.value || &f.v == &e.slope || layout.order == 3;
      if (!carried) {
        // An order-1 record has no d2, d3: a curved edge cannot be sent to an order-1 top.
        if (f.v[c] != 0)
          throw std::invalid_argument(std::string("pack_edge: ") + f.name + "[" + std::to_string(c) + "] = " +
                                      std::to_string(f.v[c]) + " on an edge-order-1 record");
        continue;
      }
      if (!fits_signed(f.v[c], ch.bits[c]))
        throw std::invalid_argument(std::string("pack_edge: ") + f.name + "[" + std::to_string(c) + "] = " +
                                    std::to_string(f.v[c]) + " does not fit " + std::to_string(ch.bits[c]) +
                                    " signed bits");
      set_bits(w, f.lsb + ch.lsb[c], ch.bits[c], wrap_unsigned(f.v[c], ch.bits[c]));
    }
  }
  return w;
}

// Inverse of pack_edge (id is not carried and comes back 0).
inline EdgeRecord unpack_edge(const EdgeLayout& layout, const EdgeWords& w) {
  EdgeRecord e;
  e.y0 = static_cast<int>(get_bits(w, layout.y0_lsb, fmt::LineBits));
  e.n = static_cast<int>(get_bits(w, layout.n_lsb, fmt::LineBits));
  e.poly = static_cast<int>(get_bits(w, layout.poly_lsb, layout.poly_bits));
  e.material = static_cast<int>(get_bits(w, layout.material_lsb, layout.material_bits));
  e.value = layout.channels.read(w.data(), layout.value_lsb);
  e.slope = layout.channels.read(w.data(), layout.slope_lsb);
  if (layout.order == 3) {
    e.d2 = layout.channels.read(w.data(), layout.d2_lsb);
    e.d3 = layout.channels.read(w.data(), layout.d3_lsb);
  }
  return e;
}

// The word a source drives between beats: 0xDEADBEEF over the record's bits, 0 above them (the RTL
// must ignore edge_i while edge_valid_i is low).
inline EdgeWords poison_edge(const EdgeLayout& layout) {
  EdgeWords w{};
  for (int i = 0; i < layout.words; ++i) w[i] = 0xDEADBEEFu;
  if (layout.bits % 32) w[layout.words - 1] &= (1u << (layout.bits % 32)) - 1;
  return w;
}

// Writes a packed record to a Verilated edge_t port or signal: VlWide<N> (N = layout.words) when
// the record is wider than 64 bits, else QData / IData.
template <class Port>
void write_edge(Port& port, const EdgeWords& w) {
  if constexpr (std::is_integral_v<Port>) {
    port = static_cast<Port>(w[0] | (std::uint64_t{w[1]} << 32));
  } else {
    for (std::size_t i = 0; i < sizeof(Port) / sizeof(w[0]); ++i) port[i] = w[i];
  }
}

}  // namespace watkins::tb
