// Where the stage checker reads the four internal valid/ready streams of watkins_top
// (active_edge_list -> segment_former -> segment_interpolator -> shading -> scanline_buffer):
// pointers to the /*verilator public_flat_rd*/ ae_*, sg_*, fr_*, sh_* signals of
// rtl/watkins_top.sv in a Verilated model. stage_taps() is the only template of the check: one
// binding per Verilated root class; the checker itself (stage_checker.hpp) reads the pointers.
#pragma once

#include <cstdint>

namespace watkins::tb::detail {

// valid/ready/eol are CData; the channel vectors are VlWide<7> words, channel c at bits
// [c*ChannelBits +: ChannelBits].
struct StageTaps {
  const std::uint8_t *ae_valid = nullptr, *ae_ready = nullptr, *ae_eol = nullptr;
  const std::uint16_t* ae_poly = nullptr;
  const std::uint8_t* ae_material = nullptr;
  const std::uint32_t* ae_value = nullptr;
  const std::uint8_t *sg_valid = nullptr, *sg_ready = nullptr, *sg_eol = nullptr;
  const std::uint16_t* sg_poly = nullptr;
  const std::uint8_t* sg_material = nullptr;
  const std::uint32_t *sg_e = nullptr, *sg_f = nullptr;
  const std::uint8_t *fr_valid = nullptr, *fr_ready = nullptr, *fr_eol = nullptr;
  const std::uint16_t* fr_x = nullptr;
  const std::uint8_t* fr_material = nullptr;
  const std::uint32_t* fr_depth = nullptr;
  const std::uint64_t* fr_normal = nullptr;  // {Nz, Ny, Nx}, NormalInBits each (54 bits)
  const std::uint8_t *sh_valid = nullptr, *sh_ready = nullptr, *sh_eol = nullptr;
  const std::uint16_t* sh_x = nullptr;
  const std::uint32_t *sh_depth = nullptr, *sh_rgb = nullptr;
};

// `root` is the Verilated model's root (model.rootp, e.g. Vwatkins_top___024root).
template <class Root>
StageTaps stage_taps(const Root& root) {
  StageTaps t;
  t.ae_valid = &root.watkins_top__DOT__ae_valid;
  t.ae_ready = &root.watkins_top__DOT__ae_ready;
  t.ae_eol = &root.watkins_top__DOT__ae_eol;
  t.ae_poly = &root.watkins_top__DOT__ae_poly;
  t.ae_material = &root.watkins_top__DOT__ae_material;
  t.ae_value = root.watkins_top__DOT__ae_value.data();
  t.sg_valid = &root.watkins_top__DOT__sg_valid;
  t.sg_ready = &root.watkins_top__DOT__sg_ready;
  t.sg_eol = &root.watkins_top__DOT__sg_eol;
  t.sg_poly = &root.watkins_top__DOT__sg_poly;
  t.sg_material = &root.watkins_top__DOT__sg_material;
  t.sg_e = root.watkins_top__DOT__sg_e.data();
  t.sg_f = root.watkins_top__DOT__sg_f.data();
  t.fr_valid = &root.watkins_top__DOT__fr_valid;
  t.fr_ready = &root.watkins_top__DOT__fr_ready;
  t.fr_eol = &root.watkins_top__DOT__fr_eol;
  t.fr_x = &root.watkins_top__DOT__fr_x;
  t.fr_depth = &root.watkins_top__DOT__fr_depth;
  t.fr_material = &root.watkins_top__DOT__fr_material;
  t.fr_normal = &root.watkins_top__DOT__fr_normal;
  t.sh_valid = &root.watkins_top__DOT__sh_valid;
  t.sh_ready = &root.watkins_top__DOT__sh_ready;
  t.sh_eol = &root.watkins_top__DOT__sh_eol;
  t.sh_x = &root.watkins_top__DOT__sh_x;
  t.sh_depth = &root.watkins_top__DOT__sh_depth;
  t.sh_rgb = &root.watkins_top__DOT__sh_rgb;
  return t;
}

}  // namespace watkins::tb::detail
