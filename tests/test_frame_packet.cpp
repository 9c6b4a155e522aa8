// The host link's packet (model/board/frame_packet.hpp): the CRC-32/ISO-HDLC check value and its
// residue, and a scene's bank image packed as the board's scene_loader reads it -- the magic, the
// word's bytes, the word count, every word little-endian, the CRC over everything after the magic.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "bit_field.hpp"
#include "board_image.hpp"
#include "frame_packet.hpp"
#include "prepare.hpp"
#include "scene_builder.hpp"

using namespace watkins;
using namespace watkins::board;
using namespace watkins::test;

namespace {

TEST(FramePacket, Crc32CheckValueAndResidue) {
  const std::string s = "123456789";
  const auto* d = reinterpret_cast<const std::uint8_t*>(s.data());
  EXPECT_EQ(crc32(d, s.size()), 0xcbf43926u);
  EXPECT_EQ(crc32(d + 4, 5, crc32(d, 4)), 0xcbf43926u);  // continued
  // The data followed by its CRC, little-endian: the register (before the final XOR) holds
  // 0xDEBB20E3, the residue scene_loader compares.
  std::vector<std::uint8_t> v(s.begin(), s.end());
  for (int j = 0; j < 4; ++j) v.push_back(static_cast<std::uint8_t>(0xcbf43926u >> (8 * j)));
  EXPECT_EQ(~crc32(v.data(), v.size()), 0xdebb20e3u);
}

TEST(FramePacket, BankWordsLittleEndianAfterTheHeader) {
  const PreparedScene p = prepare(screen(320, 240, {poly({vtx(100, 50, 0.3, 200, 10, 10), vtx(220, 60, 0.5, 10, 200, 10),
                                                          vtx(150, 180, 0.7, 10, 10, 200)})}, "triangle"));
  const Config cfg;
  const BankImage bank = bank_image(p, cfg);
  const int b = word_bytes(bank.word_bits);
  ASSERT_EQ(b, (cfg.edge_record_bits(ShadingMode::Gouraud) + 7) / 8);
  const std::vector<std::uint8_t> pk = frame_packet(bank);
  const std::size_t w = bank.words.size();
  ASSERT_EQ(w, 8 + p.edges.size());
  ASSERT_EQ(pk.size(), 7 + w * b + 4);
  EXPECT_EQ(std::string(pk.begin(), pk.begin() + 4), "WKFR");
  EXPECT_EQ(pk[4], b);
  EXPECT_EQ(pk[5] | (pk[6] << 8), static_cast<int>(w));
  for (std::size_t k = 0; k < w; ++k)
    for (int j = 0; j < b; ++j)
      ASSERT_EQ(pk[7 + k * b + j], tb::get_bits(bank.words[k], 8 * j, std::min(8, bank.word_bits - 8 * j)))
          << "word " << k << " byte " << j;
  std::uint32_t crc = 0;
  for (int j = 0; j < 4; ++j) crc |= std::uint32_t(pk[pk.size() - 4 + j]) << (8 * j);
  EXPECT_EQ(crc, crc32(pk.data() + 4, pk.size() - 8));
  EXPECT_DOUBLE_EQ(packet_seconds(pk.size(), 3e6), pk.size() * 10 / 3e6);
}

}  // namespace
