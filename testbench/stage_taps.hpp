// Where the stage checker reads the four internal valid/ready streams of watkins_top
// (active_edge_list -> segment_former -> segment_interpolator -> shading -> scanline_buffer):
// pointers to the /*verilator public_flat_rd*/ ae_*, sg_*, fr_*, sh_* signals of
// rtl/watkins_top.sv in a Verilated model. stage_taps() is the only template of the check: one
// binding per Verilated root class; the checker itself (stage_checker.hpp) reads the pointers.
#pragma once

#include <cstdint>
#include <type_traits>

namespace watkins::tb::detail {

// An unsigned signal whose C type depends on the top's parameters: Verilator stores a signal of
// up to 8 / 16 / 32 / 64 bits as CData / SData / IData / QData, and ae_poly (PolyIdBits), the
// material ids (MaterialIdBits) and the depths (DepthBits) change width with the configuration.
class TapField {
 public:
  TapField() = default;
  template <class T>
  explicit TapField(const T& signal) : p_(&signal), bytes_(sizeof(T)) {
    static_assert(std::is_integral_v<T> && std::is_unsigned_v<T>, "a tap is an unsigned Verilated signal");
  }
  std::uint64_t operator*() const {
    switch (bytes_) {
      case 1: return *static_cast<const std::uint8_t*>(p_);
      case 2: return *static_cast<const std::uint16_t*>(p_);
      case 4: return *static_cast<const std::uint32_t*>(p_);
      default: return *static_cast<const std::uint64_t*>(p_);
    }
  }
  int as_int() const { return static_cast<int>(**this); }

 private:
  const void* p_ = nullptr;
  int bytes_ = 0;
};

// A channel vector's words: VlWide<N> when wider than 64 bits, else QData or IData, read as
// little-endian 32-bit words (x86, as Verilator's own VlWide) by the bit packer.
template <class W>
const std::uint32_t* tap_words(const W& w) {
  if constexpr (std::is_integral_v<W>) {
    static_assert(sizeof(W) >= sizeof(std::uint32_t), "channel vectors of 16 bits or fewer are not supported");
    return reinterpret_cast<const std::uint32_t*>(&w);
  } else {
    return w.data();
  }
}

// valid/ready/eol are CData; the channel vectors are read per slot with the top's ChannelLayout
// (edge_packing.hpp).
struct StageTaps {
  const std::uint8_t *ae_valid = nullptr, *ae_ready = nullptr, *ae_eol = nullptr;
  TapField ae_poly, ae_material;
  const std::uint32_t* ae_value = nullptr;
  const std::uint8_t *sg_valid = nullptr, *sg_ready = nullptr, *sg_eol = nullptr;
  TapField sg_poly, sg_material;
  const std::uint32_t *sg_e = nullptr, *sg_f = nullptr;
  const std::uint8_t *fr_valid = nullptr, *fr_ready = nullptr, *fr_eol = nullptr;
  const std::uint16_t* fr_x = nullptr;
  TapField fr_material, fr_depth;
  const std::uint64_t* fr_normal = nullptr;  // {Nz, Ny, Nx}, NormalInBits each (54 bits)
  // Lane 1 of a beat (Lanes = 2: the fragment at x + 1, after lane 0); fr_pair is 0 otherwise.
  const std::uint8_t* fr_pair = nullptr;
  TapField fr_depth1;
  const std::uint8_t *sh_valid = nullptr, *sh_ready = nullptr, *sh_eol = nullptr;
  const std::uint16_t* sh_x = nullptr;
  TapField sh_depth, sh_poly;
  const std::uint32_t* sh_rgb = nullptr;
  const std::uint8_t* sh_pair = nullptr;
  TapField sh_depth1;
  const std::uint32_t* sh_rgb1 = nullptr;
};

// `root` is the Verilated model's root (model.rootp, e.g. Vwatkins_top___024root).
template <class Root>
StageTaps stage_taps(const Root& root) {
  StageTaps t;
  t.ae_valid = &root.watkins_top__DOT__ae_valid;
  t.ae_ready = &root.watkins_top__DOT__ae_ready;
  t.ae_eol = &root.watkins_top__DOT__ae_eol;
  t.ae_poly = TapField(root.watkins_top__DOT__ae_poly);
  t.ae_material = TapField(root.watkins_top__DOT__ae_material);
  t.ae_value = tap_words(root.watkins_top__DOT__ae_value);
  t.sg_valid = &root.watkins_top__DOT__sg_valid;
  t.sg_ready = &root.watkins_top__DOT__sg_ready;
  t.sg_eol = &root.watkins_top__DOT__sg_eol;
  t.sg_poly = TapField(root.watkins_top__DOT__sg_poly);
  t.sg_material = TapField(root.watkins_top__DOT__sg_material);
  t.sg_e = tap_words(root.watkins_top__DOT__sg_e);
  t.sg_f = tap_words(root.watkins_top__DOT__sg_f);
  t.fr_valid = &root.watkins_top__DOT__fr_valid;
  t.fr_ready = &root.watkins_top__DOT__fr_ready;
  t.fr_eol = &root.watkins_top__DOT__fr_eol;
  t.fr_x = &root.watkins_top__DOT__fr_x;
  t.fr_depth = TapField(root.watkins_top__DOT__fr_depth);
  t.fr_material = TapField(root.watkins_top__DOT__fr_material);
  t.fr_normal = &root.watkins_top__DOT__fr_normal;
  t.fr_pair = &root.watkins_top__DOT__fr_pair;
  t.fr_depth1 = TapField(root.watkins_top__DOT__fr_depth1);
  t.sh_valid = &root.watkins_top__DOT__sh_valid;
  t.sh_ready = &root.watkins_top__DOT__sh_ready;
  t.sh_eol = &root.watkins_top__DOT__sh_eol;
  t.sh_x = &root.watkins_top__DOT__sh_x;
  t.sh_depth = TapField(root.watkins_top__DOT__sh_depth);
  t.sh_poly = TapField(root.watkins_top__DOT__sh_poly);
  t.sh_rgb = &root.watkins_top__DOT__sh_rgb;
  t.sh_pair = &root.watkins_top__DOT__sh_pair;
  t.sh_depth1 = TapField(root.watkins_top__DOT__sh_depth1);
  t.sh_rgb1 = &root.watkins_top__DOT__sh_rgb1;
  return t;
}

}  // namespace watkins::tb::detail
