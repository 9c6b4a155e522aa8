// Edge record → watkins_pkg::edge_t, bit-exact. The one place where the C++ record meets the RTL's
// packed struct; tests/cosim/test_edge_packing.cpp checks it against rtl/watkins_pkg.sv.
//
// A packed struct puts its first field at the top: edge_t = {y0, n, poly, material, value, slope},
// and `logic [NumChannels-1:0][ChannelBits-1:0] value` puts value[NumChannels-1] at the top of its
// field and value[0] (X) at the bottom. So, from bit 0 up: slope[0..4] at 0 + 42c, value[0..4] at
// 210 + 42c, material at 420, poly at 424, n at 440, y0 at 453; fmt::EdgeRecordBits (466) bits.
// Verilator stores the port as 15 little-endian 32-bit words (VlWide<15> / sc_bv<466>); the
// fields are cut with the benches' one bit packer (bit_field.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "bit_field.hpp"
#include "edge_record.hpp"
#include "fixed_point.hpp"
#include "formats.hpp"

namespace watkins::tb {

namespace edge_layout {
constexpr int SlopeLsb = 0;
constexpr int ValueLsb = SlopeLsb + fmt::NumChannels * fmt::ChannelBits;
constexpr int MaterialLsb = ValueLsb + fmt::NumChannels * fmt::ChannelBits;
constexpr int PolyLsb = MaterialLsb + fmt::MaterialIdBits;
constexpr int NLsb = PolyLsb + fmt::PolyIdBits;
constexpr int Y0Lsb = NLsb + fmt::LineBits;
constexpr int Bits = Y0Lsb + fmt::LineBits;  // $bits(watkins_pkg::edge_t)
constexpr int Words = (Bits + 31) / 32;
static_assert(Bits == fmt::EdgeRecordBits, "edge_t layout changed: update edge_packing.hpp and its test");
}  // namespace edge_layout

using EdgeWords = std::array<std::uint32_t, edge_layout::Words>;

// Throws std::invalid_argument when a field does not fit its width (a preparation bug: the RTL
// would silently see a different record).
inline EdgeWords pack_edge(const EdgeRecord& e) {
  using namespace edge_layout;
  auto check_unsigned = [](const char* what, long long v, int bits) {
    if (v < 0 || v >= (1LL << bits))
      throw std::invalid_argument(std::string("pack_edge: ") + what + " = " + std::to_string(v) +
                                  " does not fit " + std::to_string(bits) + " unsigned bits");
  };
  check_unsigned("y0", e.y0, fmt::LineBits);
  check_unsigned("n", e.n, fmt::LineBits);
  check_unsigned("poly", e.poly, fmt::PolyIdBits);
  check_unsigned("material", e.material, fmt::MaterialIdBits);
  EdgeWords w{};
  set_bits(w, Y0Lsb, fmt::LineBits, static_cast<std::uint64_t>(e.y0));
  set_bits(w, NLsb, fmt::LineBits, static_cast<std::uint64_t>(e.n));
  set_bits(w, PolyLsb, fmt::PolyIdBits, static_cast<std::uint64_t>(e.poly));
  set_bits(w, MaterialLsb, fmt::MaterialIdBits, static_cast<std::uint64_t>(e.material));
  for (int c = 0; c < fmt::NumChannels; ++c) {
    for (const bool is_slope : {false, true}) {
      const i64 v = is_slope ? e.slope[c] : e.value[c];
      if (!fits_signed(v, fmt::ChannelBits))
        throw std::invalid_argument(std::string("pack_edge: ") + (is_slope ? "slope[" : "value[") +
                                    std::to_string(c) + "] = " + std::to_string(v) + " does not fit " +
                                    std::to_string(fmt::ChannelBits) + " signed bits");
      set_bits(w, (is_slope ? SlopeLsb : ValueLsb) + c * fmt::ChannelBits, fmt::ChannelBits,
               wrap_unsigned(v, fmt::ChannelBits));
    }
  }
  return w;
}

// Inverse of pack_edge (id is not carried and comes back 0).
inline EdgeRecord unpack_edge(const EdgeWords& w) {
  using namespace edge_layout;
  EdgeRecord e;
  e.y0 = static_cast<int>(get_bits(w, Y0Lsb, fmt::LineBits));
  e.n = static_cast<int>(get_bits(w, NLsb, fmt::LineBits));
  e.poly = static_cast<int>(get_bits(w, PolyLsb, fmt::PolyIdBits));
  e.material = static_cast<int>(get_bits(w, MaterialLsb, fmt::MaterialIdBits));
  for (int c = 0; c < fmt::NumChannels; ++c) {
    e.value[c] = get_signed(w, ValueLsb + c * fmt::ChannelBits, fmt::ChannelBits);
    e.slope[c] = get_signed(w, SlopeLsb + c * fmt::ChannelBits, fmt::ChannelBits);
  }
  return e;
}

// Writes a packed record to a Verilated edge_t port or signal (VlWide<edge_layout::Words>).
template <class Port>
void write_edge(Port& port, const EdgeWords& w) {
  for (int i = 0; i < edge_layout::Words; ++i) port[i] = w[i];
}

}  // namespace watkins::tb
