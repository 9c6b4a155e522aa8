// rtl/board/tmds_encoder.sv against TmdsEncoder (model/board/tmds.hpp), symbol for symbol: every
// data byte from every reachable running disparity, then 4,194,304 symbols of random and
// structured streams (video lines with their blanking, runs that push the disparity to its bounds,
// random bytes and random blanking with every control pair). Every symbol the RTL sends decodes
// (tmds_decode) to the byte or control pair it was given, and the disparity of the symbols sent
// since the last blanking stays within DVI's [-8, 8] and equals the twin's.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <vector>

#include "Vtmds_encoder.h"
#include "rtl_harness.hpp"
#include "tmds.hpp"

using namespace watkins;
using namespace watkins::rtl;

namespace {

struct Input {
  std::uint8_t data = 0;
  bool de = false, c0 = false, c1 = false;
};

int ones_minus_zeros(std::uint16_t symbol) { return 2 * __builtin_popcount(symbol & 0x3ffu) - 10; }

// The RTL and the twin clocked together; every symbol compared, decoded and its disparity kept.
struct Bench {
  Harness<Vtmds_encoder> h;
  TmdsEncoder twin;
  int disparity = 0;  // of the RTL's symbols since the last blanking
  std::uint64_t symbols = 0, mismatches = 0, bad_decodes = 0, out_of_bounds = 0;
  std::map<int, std::uint64_t> disparity_seen;

  Bench() {
    h.dut.data_i = 0;
    h.dut.de_i = 0;
    h.dut.c0_i = 0;
    h.dut.c1_i = 0;
    h.reset();
  }
  std::uint16_t send(const Input& in) {
    h.dut.data_i = in.data;
    h.dut.de_i = in.de;
    h.dut.c0_i = in.c0;
    h.dut.c1_i = in.c1;
    h.tick();
    const std::uint16_t got = h.dut.symbol_o;
    const std::uint16_t want = twin.encode(in.data, in.de, in.c0, in.c1);
    ++symbols;
    if (got != want && ++mismatches <= 5)
      ADD_FAILURE() << "symbol " << symbols << ": data " << int(in.data) << " de " << in.de << " c " << in.c1
                    << in.c0 << ": RTL " << got << ", twin " << want;
    const TmdsDecoded d = tmds_decode(got);
    const bool decoded = in.de ? d.kind == TmdsDecoded::Kind::Data && d.data == in.data
                               : d.kind == TmdsDecoded::Kind::Control && d.c0 == in.c0 && d.c1 == in.c1;
    if (!decoded && ++bad_decodes <= 5) ADD_FAILURE() << "symbol " << symbols << " " << got << " does not decode back";
    disparity = in.de ? disparity + ones_minus_zeros(got) : 0;
    ++disparity_seen[disparity];
    if (disparity != twin.disparity() || disparity < -TmdsDisparityMax || disparity > TmdsDisparityMax) {
      if (++out_of_bounds <= 5)
        ADD_FAILURE() << "symbol " << symbols << ": disparity " << disparity << ", twin " << twin.disparity();
    }
    return got;
  }
  void expect_clean() const {
    EXPECT_EQ(mismatches, 0u);
    EXPECT_EQ(bad_decodes, 0u);
    EXPECT_EQ(out_of_bounds, 0u);
  }
};

Input data(std::uint8_t d) { return Input{d, true, false, false}; }
Input blank(int c = 0) { return Input{0, false, (c & 1) != 0, (c & 2) != 0}; }

// The disparities the encoder reaches from 0 (a blanking), each with a shortest byte sequence that
// reaches it: a search over the twin.
std::map<int, std::vector<std::uint8_t>> reachable_disparities() {
  std::map<int, std::vector<std::uint8_t>> path{{0, {}}};
  std::vector<int> todo{0};
  while (!todo.empty()) {
    const int c = todo.front();
    todo.erase(todo.begin());
    for (int d = 0; d < 256; ++d) {
      TmdsEncoder e;
      for (const std::uint8_t b : path[c]) e.encode(b, true, false, false);
      e.encode(static_cast<std::uint8_t>(d), true, false, false);
      if (path.count(e.disparity()) == 0) {
        path[e.disparity()] = path[c];
        path[e.disparity()].push_back(static_cast<std::uint8_t>(d));
        todo.push_back(e.disparity());
      }
    }
  }
  return path;
}

TEST(RtlTmdsEncoder, ResetSendsTheBlankToken) {
  Bench b;
  EXPECT_EQ(b.h.dut.symbol_o, TmdsControl[0]);
  // The disparity starts at 0: the first data symbols equal a fresh twin's (black from 0 goes
  // 0x100, -8, then 0x3ff, +2: the DC balance inverts it).
  EXPECT_EQ(b.send(data(0x00)), 0x100);
  EXPECT_EQ(b.send(data(0x00)), 0x3ff);
  EXPECT_EQ(b.twin.disparity(), 2);
  b.expect_clean();
}

// The DVI 1.0 equations worked by hand on a few bytes from a zero disparity.
TEST(RtlTmdsEncoder, HandWorkedSymbols) {
  // 0xff: eight ones -> XNOR, q_m = 0 1111 1111 (q_m[8] clear), balanced no, cnt 0 -> bit 9 set,
  // bits 7:0 inverted: 10 0000 0000; the disparity -8.
  // 0x55 (0101 0101): four ones, bit 0 set -> XOR: q_m[i] = q_m[i-1] ^ d[i] = 1,1,0,0,1,1,0,0 from
  // bit 0 -> 0011 0011 with q_m[8] set: balanced -> bit 9 clear, sent as is: 01 0011 0011.
  // 0x10 (0001 0000): one one -> XOR: bits 0..3 clear, 4..7 set: 1111 0000, q_m[8] set: balanced:
  // 01 1111 0000.
  const std::array<std::pair<std::uint8_t, std::uint16_t>, 3> cases{
      {{0xff, 0b10'0000'0000}, {0x55, 0b01'0011'0011}, {0x10, 0b01'1111'0000}}};
  for (const auto& [byte, symbol] : cases) {
    Bench b;
    EXPECT_EQ(b.send(data(byte)), symbol) << "byte " << int(byte);
    b.expect_clean();
  }
  // The control tokens, DVI 1.0's q_out[0:9] read from bit 0.
  Bench b;
  for (int c = 0; c < 4; ++c) EXPECT_EQ(b.send(blank(c)), TmdsControl[c]);
  EXPECT_EQ(TmdsControl[0], 0b11'0101'0100);  // q_out[0:9] = 0010101011
  EXPECT_EQ(TmdsControl[3], 0b10'1010'1011);  // q_out[0:9] = 1101010101
  b.expect_clean();
}

// Every data byte from every disparity the encoder can be in: the RTL is driven there from a
// blanking along the twin's shortest path, then sends the byte, then blanking clears it again.
TEST(RtlTmdsEncoder, EveryByteFromEveryDisparity) {
  const auto paths = reachable_disparities();
  std::set<int> states;
  for (const auto& [c, p] : paths) states.insert(c);
  EXPECT_EQ(states, (std::set<int>{-8, -6, -4, -2, 0, 2, 4, 6, 8}));
  Bench b;
  std::uint64_t pairs = 0;
  for (const auto& [c, p] : paths) {
    for (int d = 0; d < 256; ++d) {
      b.send(blank(d & 3));
      for (const std::uint8_t x : p) b.send(data(x));
      ASSERT_EQ(b.disparity, c);
      b.send(data(static_cast<std::uint8_t>(d)));
      // Two more bytes from the resulting disparity show the state the byte left.
      b.send(data(0x00));
      b.send(data(0xff));
      ++pairs;
    }
  }
  EXPECT_EQ(pairs, 9u * 256u);
  b.expect_clean();
}

// Every 10-bit word: data words are exactly the ones some disparity sends (two per byte whose
// q_m is unbalanced, one per balanced byte), the four tokens are control, the rest invalid.
TEST(RtlTmdsEncoder, DecoderKnowsEveryWord) {
  std::set<std::uint16_t> sent;
  for (const auto& [c, p] : reachable_disparities()) {
    for (int d = 0; d < 256; ++d) {
      TmdsEncoder e;
      for (const std::uint8_t x : p) e.encode(x, true, false, false);
      const std::uint16_t s = e.encode(static_cast<std::uint8_t>(d), true, false, false);
      sent.insert(s);
      const TmdsDecoded r = tmds_decode(s);
      ASSERT_EQ(r.kind, TmdsDecoded::Kind::Data);
      ASSERT_EQ(r.data, d);
    }
  }
  int balanced = 0;
  for (int d = 0; d < 256; ++d)
    balanced += __builtin_popcount(tmds_transition_minimized(static_cast<std::uint8_t>(d)) & 0xffu) == 4;
  EXPECT_EQ(sent.size(), static_cast<std::size_t>(balanced + 2 * (256 - balanced)));
  int data_words = 0, control_words = 0;
  for (unsigned w = 0; w < 1024; ++w) {
    const TmdsDecoded r = tmds_decode(static_cast<std::uint16_t>(w));
    data_words += r.kind == TmdsDecoded::Kind::Data;
    control_words += r.kind == TmdsDecoded::Kind::Control;
    EXPECT_EQ(r.kind == TmdsDecoded::Kind::Data, sent.count(static_cast<std::uint16_t>(w)) == 1) << "word " << w;
  }
  EXPECT_EQ(data_words, static_cast<int>(sent.size()));
  EXPECT_EQ(control_words, 4);
}

// 2^22 symbols of streams a display link carries and some it never would.
TEST(RtlTmdsEncoder, RandomAndStructuredStreams) {
  constexpr std::uint64_t Symbols = std::uint64_t{1} << 22;
  std::mt19937_64 rng(0x7d5);
  Bench b;
  while (b.symbols < Symbols) {
    switch (rng() % 5) {
      case 0: {  // a video line: 640 pixels of a gradient or noise, then 160 clocks of blanking
        const bool noise = rng() % 2;
        const std::uint8_t base = static_cast<std::uint8_t>(rng());
        for (int x = 0; x < 640; ++x) b.send(data(noise ? static_cast<std::uint8_t>(rng()) : static_cast<std::uint8_t>(base + x / 3)));
        const int sync = static_cast<int>(rng() % 4);
        for (int x = 0; x < 160; ++x) b.send(blank(x >= 16 && x < 112 ? sync : 0));
        break;
      }
      case 1: {  // runs of one byte: the disparity swings to its bounds
        const std::uint8_t v = static_cast<std::uint8_t>(rng());
        const int n = 1 + static_cast<int>(rng() % 64);
        for (int i = 0; i < n; ++i) b.send(data(v));
        break;
      }
      case 2: {  // alternating two bytes
        const std::uint8_t u = static_cast<std::uint8_t>(rng()), v = static_cast<std::uint8_t>(rng());
        const int n = 2 + static_cast<int>(rng() % 64);
        for (int i = 0; i < n; ++i) b.send(data(i % 2 ? u : v));
        break;
      }
      case 3: {  // random bytes
        const int n = 1 + static_cast<int>(rng() % 256);
        for (int i = 0; i < n; ++i) b.send(data(static_cast<std::uint8_t>(rng())));
        break;
      }
      default: {  // a short blanking with random control pairs, mid-stream
        const int n = 1 + static_cast<int>(rng() % 8);
        for (int i = 0; i < n; ++i) b.send(blank(static_cast<int>(rng() % 4)));
        break;
      }
    }
  }
  b.expect_clean();
  for (int c = -TmdsDisparityMax; c <= TmdsDisparityMax; c += 2)
    EXPECT_GT(b.disparity_seen[c], 0u) << "disparity " << c << " never reached";
  EXPECT_EQ(b.disparity_seen.size(), 9u);
  std::printf("tmds_encoder: %llu symbols, RTL = twin, every one decoded back\n",
              static_cast<unsigned long long>(b.symbols));
}

}  // namespace
