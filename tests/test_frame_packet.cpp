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

// The turntable of the host link's animations (model/board/turntable.hpp).
#include "camera.hpp"
#include "scene.hpp"
#include "turntable.hpp"

namespace {

TEST(Turntable, EulerDegreesRoundTrip) {
  for (const glm::dvec3 d : {glm::dvec3(-15, 0, 0), glm::dvec3(10, 20, 30), glm::dvec3(-170, 80, 45),
                             glm::dvec3(30, 90, 0), glm::dvec3(0, -90, 20)}) {
    const glm::dmat3 m = rotation(d), back = rotation(board::euler_degrees(m));
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) EXPECT_NEAR(back[c][r], m[c][r], 1e-12) << d.x << " " << d.y << " " << d.z;
  }
}

TEST(Turntable, DefaultSceneTurnsAboutItsCentre) {
  const Scene s = parse_scene_file("");
  const glm::dvec3 c = board::turntable_centre(s);
  // The sphere's centre (-0.55, -0.25, 3.8) and the cone's base (0.75, -1.55, 4.4), which the
  // cone's rotation (-15 degrees about X) moves with the rest of it.
  const glm::dvec3 cone = rotation(glm::dvec3(-15, 0, 0)) * glm::dvec3(0.75, -1.55, 4.4);
  EXPECT_NEAR(c.x, 0.1, 1e-12);
  EXPECT_NEAR(c.z, (3.8 + cone.z) / 2, 1e-12);
  const Scene q = board::turntable(s, 90);
  // A quarter turn about +y takes (dx, dz) to (dz, -dx) about the centre.
  const SceneObject& sphere = q.objects[0];
  const glm::dvec3 p = sphere.transform.translate + rotation(sphere.transform.rotate_deg) * sphere.center;
  EXPECT_NEAR(p.x, c.x + (3.8 - c.z), 1e-9);
  EXPECT_NEAR(p.z, c.z - (-0.55 - c.x), 1e-9);
  EXPECT_NEAR(p.y, -0.25, 1e-9);
  // A whole turn is the scene again.
  const Scene w = board::turntable(s, 360);
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    const glm::dmat3 a = rotation(s.objects[i].transform.rotate_deg), b = rotation(w.objects[i].transform.rotate_deg);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(w.objects[i].transform.translate[k], s.objects[i].transform.translate[k], 1e-9);
      for (int r = 0; r < 3; ++r) EXPECT_NEAR(b[k][r], a[k][r], 1e-12);
    }
  }
}

}  // namespace
