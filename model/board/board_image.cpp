// The board's scene bank image (board_image.hpp).
#include "board_image.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include "bit_field.hpp"
#include "fixed_point.hpp"
#include "formats.hpp"

namespace watkins::board {
namespace {

// {z, y, x} of a Q2.14 unit vector, as light_i / eye_i take it.
std::uint64_t pack_unit(const std::array<i64, 3>& v) {
  std::uint64_t w = 0;
  for (int c = 0; c < 3; ++c) w |= wrap_unsigned(v[c], fmt::UnitBits) << (c * fmt::UnitBits);
  return w;
}

std::uint64_t pack_rgb(int r, int g, int b) {
  return (std::uint64_t(r & 0xff) << 16) | (std::uint64_t(g & 0xff) << 8) | std::uint64_t(b & 0xff);
}

void check_fits(const char* what, long long v, int bits) {
  if (v < 0 || v >= (1LL << bits))
    throw std::invalid_argument(std::string("bank image: ") + what + " = " + std::to_string(v) + " does not fit " +
                                std::to_string(bits) + " bits");
}

tb::EdgeWords field_word(std::uint64_t v) {
  tb::EdgeWords w{};
  tb::set_bits(w, 0, 64, v);
  return w;
}

}  // namespace

BankImage bank_image(const Frame& frame, const Config& config, int bank_words) {
  const tb::EdgeLayout layout = tb::EdgeLayout::of(config, frame.shading);
  if (layout.bits < BankLayout::MinWordBits)
    throw std::invalid_argument("bank image: the edge record is " + std::to_string(layout.bits) +
                                " bits, narrower than the header's " + std::to_string(BankLayout::MinWordBits));
  const bool phong = frame.shading == ShadingMode::Phong;
  BankImage bank;
  bank.word_bits = layout.bits;
  bank.edges = static_cast<int>(frame.edges.size());
  bank.materials = phong ? static_cast<int>(frame.materials.size()) : 0;
  const long long total = BankLayout::HeaderWords + bank.materials + bank.edges;
  if (bank_words > 0 && total > bank_words)
    throw std::invalid_argument("bank image: the frame needs " + std::to_string(total) + " words (" +
                                std::to_string(bank.edges) + " edge records, " + std::to_string(bank.materials) +
                                " materials), more than the bank's " + std::to_string(bank_words));
  const int material_id_bits = id_bits(config.max_materials);
  if (bank.materials > (1 << material_id_bits))
    throw std::invalid_argument("bank image: " + std::to_string(bank.materials) + " materials, more than the " +
                                std::to_string(1 << material_id_bits) + " entries of the table");
  check_fits("width", frame.width, fmt::LineBits);
  check_fits("height", frame.height, fmt::LineBits);
  check_fits("smooth_w", frame.smooth_w, fmt::SmoothWBits);

  bank.words.reserve(static_cast<std::size_t>(total));
  bank.words.push_back(field_word(std::uint64_t(bank.edges)));
  bank.words.push_back(field_word(std::uint64_t(frame.width)));
  bank.words.push_back(field_word(std::uint64_t(frame.height)));
  bank.words.push_back(field_word(pack_rgb(frame.background[0], frame.background[1], frame.background[2])));
  const std::uint64_t flags = (std::uint64_t(frame.depth_tie == DepthTie::Submission) << BankLayout::FlagTieBit) |
                              (std::uint64_t(frame.eq2) << BankLayout::FlagEq2Bit) |
                              (std::uint64_t(frame.smooth_w) << BankLayout::FlagSmoothLsb);
  bank.words.push_back(field_word(flags));
  bank.words.push_back(field_word(phong ? pack_unit(frame.light) : 0));
  bank.words.push_back(field_word(phong ? pack_unit(frame.eye) : 0));
  bank.words.push_back(field_word(std::uint64_t(bank.materials)));
  for (int k = 0; k < bank.materials; ++k) {
    const QuantizedMaterial& m = frame.materials[k];
    check_fits("material d", m.d, fmt::MaterialBits);
    check_fits("material w", m.w, fmt::MaterialBits);
    check_fits("material n", m.shininess, fmt::ShininessBits);
    const std::uint64_t word = pack_rgb(m.cp[0], m.cp[1], m.cp[2]) |
                               (std::uint64_t(m.d) << BankLayout::MaterialDLsb) |
                               (std::uint64_t(m.w) << BankLayout::MaterialWLsb) |
                               (std::uint64_t(m.shininess) << BankLayout::MaterialNLsb);
    bank.words.push_back(field_word(word));
  }
  for (const EdgeRecord& e : frame.edges) bank.words.push_back(tb::pack_edge(layout, e));
  return bank;
}

void write_readmemh(std::ostream& out, const BankImage& bank) {
  static const char* hex = "0123456789abcdef";
  const int digits = (bank.word_bits + 3) / 4;
  std::string line(static_cast<std::size_t>(digits), '0');
  for (const tb::EdgeWords& w : bank.words) {
    for (int d = 0; d < digits; ++d) {
      const int lsb = 4 * (digits - 1 - d);
      const int width = std::min(4, bank.word_bits - lsb);
      line[static_cast<std::size_t>(d)] = hex[tb::get_bits(w, lsb, width)];
    }
    out << line << '\n';
  }
}

void write_readmemh_file(const std::string& path, const BankImage& bank) {
  std::ofstream out(path);
  if (out) write_readmemh(out, bank);
  out.flush();
  if (!out) throw std::runtime_error(path + ": cannot write the bank image");
}

Image pmod_levels(Image image) {
  for (std::uint8_t& level : image.rgb) level &= 0xF0;
  return image;
}

}  // namespace watkins::board
