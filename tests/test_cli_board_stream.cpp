// `watkins board stream` as users run it, into a file (how the board bench's packets are made;
// a serial port gets the same bytes): a turntable's packets back to back, each the magic, B, W,
// the words and the CRC; a frame too large for the board's bank refused in one line before
// anything is written; frames that do not fit the configuration, and options that cannot apply,
// refused.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "frame_packet.hpp"

using namespace watkins::test;

namespace {

const std::string kCone = WATKINS_SOURCE_DIR "/scenes/cone.json";
const std::string kDefault = WATKINS_SOURCE_DIR "/scenes/default.json";

// A scratch folder whose files' names are known before they exist.
struct Scratch : ScratchDir {
  std::string path(const std::string& name) const { return dir_ + "/" + name; }
};

std::vector<std::uint8_t> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {});
}

TEST(CliBoardStream, TurntablePacketsToAFile) {
  Scratch dir;
  const std::string out = dir.path("frames.bin");
  const CliRun r = run_cli("board stream " + kCone + " --turntable 4 --port " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("frames        4 at 320x240 (doubling 2)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bank 512 words"), std::string::npos) << r.output;
  const std::vector<std::uint8_t> bytes = read_bytes(out);
  std::size_t at = 0;
  int packets = 0;
  while (at < bytes.size()) {
    ASSERT_LE(at + 11, bytes.size());
    EXPECT_EQ(std::string(bytes.begin() + at, bytes.begin() + at + 4), "WKFR") << "packet " << packets;
    const std::size_t b = bytes[at + 4], w = bytes[at + 5] | (bytes[at + 6] << 8);
    EXPECT_GE(w, 8u);
    const std::size_t size = 11 + w * b;
    ASSERT_LE(at + size, bytes.size());
    std::uint32_t crc = 0;
    for (int j = 0; j < 4; ++j) crc |= std::uint32_t(bytes[at + size - 4 + j]) << (8 * j);
    EXPECT_EQ(crc, watkins::board::crc32(bytes.data() + at + 4, size - 8)) << "packet " << packets;
    at += size;
    ++packets;
  }
  EXPECT_EQ(packets, 4);
}

TEST(CliBoardStream, FrameTooLargeForTheBankRefused) {
  Scratch dir;
  const std::string out = dir.path("frames.bin");
  // The default scene's frame is 286 words: more than a 256-word bank.
  CliRun r = run_cli("board stream " + kCone + " " + kDefault + " --config " WATKINS_SOURCE_DIR
                     "/scenes/sized/default.gouraud.json --bank-words 256 --port " + out);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(kDefault + ": the frame needs 286 bank words"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("more than the board's 256; nothing sent"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("packets"), std::string::npos) << r.output;  // refused before the summary
  EXPECT_FALSE(std::filesystem::exists(out));
  // The same frames fit the 512 words `board build` gives the cone.
  r = run_cli("board stream " + kCone + " " + kDefault + " --config " WATKINS_SOURCE_DIR
              "/scenes/sized/default.gouraud.json --port " + out);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(out));
}

TEST(CliBoardStream, RefusesFramesAndOptionsThatCannotApply) {
  Scratch dir;
  const std::string out = dir.path("frames.bin");
  // The default scene at the cone's sized configuration: more polygons than its ids hold.
  CliRun r = run_cli("board stream " + kCone + " " + kDefault + " --port " + out);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(kDefault + ": does not fit the board's configuration"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  r = run_cli("board stream " + kCone + " " + kCone + " --turntable 2 --port " + out);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--turntable"), std::string::npos) << r.output;
  r = run_cli("board stream " + kCone + " --loop --port " + out);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--loop"), std::string::npos) << r.output;
  for (const char* bad : {"--bank-words 300", "--fps 0", "--turntable 0"}) {
    r = run_cli("board stream " + kCone + " --port " + out + " " + bad);
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.output;
  }
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
