// The host link on the Verilated board top (testbench/board/board_bench.hpp): frames of a
// turntable (model/board/turntable.hpp) of the faceted cone (scenes/cone.json, 12 facets) at 0, 10
// and 20 degrees, prepared at the default scene's sized configuration (the top's), packed as the host packs them (model/board/frame_packet.hpp) and driven into
// ulx3s_top's ftdi_txd pin by the bit-level line model (testbench/board/uart_line.hpp) at
// 3 Mbaud. Bank 0 holds the default scene; frame A arrives during video frame 0 and is shown
// from video frame 1, frame B during frame 1 and is shown from frame 2, each equal to the
// model's image of that frame bit for bit; a corrupted packet of a third frame arrives during
// frame 2: dropped (link-error count 1, led[2]'s source), and video frame 3 still shows B.
#include <cstdio>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "board_bench.hpp"
#include "board_image.hpp"
#include "config_file.hpp"
#include "frame_packet.hpp"
#include "prepare.hpp"
#include "scene.hpp"
#include "turntable.hpp"
#include "uart_line.hpp"
#include "watkins_top.hpp"

namespace watkins::board_tb {
namespace {

constexpr int Doubling = WATKINS_BOARD_DOUBLING;
constexpr int BankWords = WATKINS_BOARD_BANK_WORDS;
constexpr double Baud = 3e6;
constexpr double FrameSeconds = double(FrameClocks) / 25.2e6;  // 16.67 ms

long long pixel_mismatches(const Image& got, const Image& want) {
  long long bad = 0;
  for (std::size_t i = 0; i < want.rgb.size(); ++i) bad += got.rgb[i] != want.rgb[i];
  return bad;
}

TEST(BoardStream, TwoFramesShownACorruptedOneDropped) {
  const Config config = load_config(WATKINS_SOURCE_DIR "/scenes/sized/default.gouraud.json");
  const Scene still_scene = parse_scene_file(WATKINS_SOURCE_DIR "/scenes/default.json");
  const Scene scene = parse_scene_file(WATKINS_SOURCE_DIR "/scenes/cone.json");
  WatkinsTop top(config);
  auto frame_at = [&](double degrees) { return prepare(build_scene(board::turntable(scene, degrees)), config); };
  const PreparedScene still = prepare(build_scene(still_scene), config), a = frame_at(0), b = frame_at(10),
                      c = frame_at(20);

  // Bank 0: the default scene, the file the top was built to read.
  const std::string tmp = std::string(WATKINS_BOARD_BANK_FILE) + ".tmp" + std::to_string(::getpid());
  board::write_readmemh_file(tmp, board::bank_image(still, config, BankWords));
  ASSERT_EQ(std::rename(tmp.c_str(), WATKINS_BOARD_BANK_FILE), 0);

  const std::vector<std::uint8_t> pa = board::frame_packet(board::bank_image(a, config, BankWords)),
                                   pb = board::frame_packet(board::bank_image(b, config, BankWords));
  std::vector<std::uint8_t> pc = board::frame_packet(board::bank_image(c, config, BankWords));
  pc[pc.size() / 2] ^= 0x04;  // one payload bit
  // Each packet arrives within its video frame, before the frame's request (its last visible
  // pixel, 480 of 525 lines in).
  for (const std::vector<std::uint8_t>* p : std::vector<const std::vector<std::uint8_t>*>{&pa, &pb, &pc})
    ASSERT_LT(board::packet_seconds(p->size(), Baud), FrameSeconds * 480 / 525 - 1e-3) << p->size() << " bytes";
  UartLine line(Baud);
  line.send(pa, 0.5e-3);
  line.send(pb, FrameSeconds + 0.5e-3);
  line.send(pc, 2 * FrameSeconds + 0.5e-3);

  BoardBench bench;
  BoardOptions opt;
  opt.video_frames = 4;
  opt.tmds_clock = false;  // the encoders' inputs are captured; the serializers are tested alone
  opt.ftdi_txd = [&line](double t) { return line.level(t); };
  const BoardRun r = bench.run(opt);
  std::printf("board stream: packets of %zu, %zu, %zu bytes; %lld pixel clocks in %.2f s\n", pa.size(), pb.size(),
              pc.size(), r.pixel_clocks, r.wall_seconds);

  ASSERT_EQ(r.frames.size(), 4u);
  EXPECT_EQ(r.link_frames, 2);
  EXPECT_EQ(r.link_errors, 1);
  ASSERT_GE(r.begin_banks.size(), 3u);
  EXPECT_EQ(r.begin_banks[0], 1);  // A, written to bank 1
  EXPECT_EQ(r.begin_banks[1], 0);  // B, written to bank 0
  EXPECT_EQ(r.begin_banks[2], 0);  // B stays
  const Image want_a = doubled(top.render(a), Doubling), want_b = doubled(top.render(b), Doubling);
  ASSERT_NE(want_a.rgb, want_b.rgb);
  ASSERT_NE(doubled(top.render(c), Doubling).rgb, want_b.rgb);  // a frame shown from C would show
  EXPECT_EQ(pixel_mismatches(r.frames[1], want_a), 0) << "video frame 1 against the model's image of A";
  EXPECT_EQ(pixel_mismatches(r.frames[2], want_b), 0) << "video frame 2 against the model's image of B";
  EXPECT_EQ(pixel_mismatches(r.frames[3], want_b), 0) << "video frame 3 (the corrupted frame dropped)";
  EXPECT_EQ(r.missed_count, 0);
  EXPECT_FALSE(r.overflow);
}

}  // namespace
}  // namespace watkins::board_tb
