// rtl/board/host_link.sv (uart_rx and scene_loader) at 78.75 MHz and 3 Mbaud, BankWords 64 and a
// 67-bit word (9 bytes, 5 pad bits), driven by the bit-level line model
// (testbench/board/uart_line.hpp) with the packets of model/board/frame_packet.hpp. The bench
// keeps the two banks as the scene bank's write port would and checks, packet by packet: the
// words written equal the packet's, in order, to the bank not shown; a good packet counts and
// swaps the banks at the next begin_i, not before; a packet with a bad CRC, a wrong word size, a
// word count past the bank or under the header, a framing error, or a pause of 2^TimeoutBits
// clocks is dropped and counted and the shown bank stays; noise between packets is ignored; a
// newer good packet replaces one that waits for its swap. Each case at 0 and +-2 % rate error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "Vhost_link.h"
#include "board/uart_line.hpp"
#include "frame_packet.hpp"
#include "rtl_harness.hpp"

using namespace watkins::rtl;
using watkins::board::BankImage;
using watkins::board::frame_packet;
using watkins::board_tb::UartLine;

namespace {

constexpr double ClockHz = 78.75e6, Baud = 3e6;
constexpr int BankWords = WATKINS_RTL_PARAM_BankWords;
constexpr int WordBits = WATKINS_RTL_PARAM_WordBits;
constexpr int TimeoutBits = WATKINS_RTL_PARAM_TimeoutBits;
using Word = watkins::tb::EdgeWords;

BankImage random_bank(std::mt19937_64& rng, int words) {
  BankImage b;
  b.word_bits = WordBits;
  for (int k = 0; k < words; ++k) {
    Word w{};
    for (int lsb = 0; lsb < WordBits; lsb += 32) set_bits(w, lsb, std::min(32, WordBits - lsb), rng());
    b.words.push_back(w);
  }
  return b;
}

class LinkBench {
 public:
  explicit LinkBench(double rate_error, std::uint64_t seed)
      : line_(Baud * (1 + rate_error)), rng_(seed), banks_(2, std::vector<Word>(BankWords, Word{})) {
    h_.dut.rx_i = 1;
    h_.dut.begin_i = 0;
    h_.reset();
    phase_ = std::uniform_real_distribution<double>(0, 1 / ClockHz)(rng_);
  }
  UartLine& line() { return line_; }
  std::mt19937_64& rng() { return rng_; }
  // Sends `bytes` from the line's end plus a few bits and clocks until they are taken.
  void send(const std::vector<std::uint8_t>& bytes, double gap_bits = 3) {
    line_.send(bytes, next_start(gap_bits));
    run_until(line_.end_s() + 3 * line_.bit_s());
  }
  // gap_bits of idle line after the line's last byte or now, whichever is later.
  double next_start(double gap_bits = 3) const { return std::max(line_.end_s(), now()) + gap_bits * line_.bit_s(); }
  void run_until(double t) {
    while (now() < t) clock(false);
  }
  void clock(bool begin) {
    h_.dut.rx_i = line_.level(now());
    h_.dut.begin_i = begin;
    h_.tick();
    ++n_;
    if (h_.dut.wr_en_o) {
      const int bank = h_.dut.wr_bank_o, addr = h_.dut.wr_addr_o;
      if (bank == static_cast<int>(h_.dut.bank_active_o)) ++writes_to_shown;
      Word w{};
      for (int lsb = 0; lsb < WordBits; lsb += 32)
        set_bits(w, lsb, std::min(32, WordBits - lsb), get_bits(h_.dut.wr_data_o, lsb, std::min(32, WordBits - lsb)));
      banks_[bank][addr] = w;
      writes.push_back(addr);
    }
  }
  // One clock with begin_i, then a few without.
  void begin_frame() {
    clock(true);
    for (int i = 0; i < 4; ++i) clock(false);
  }
  int shown() const { return h_.dut.bank_active_o; }
  int frames() const { return h_.dut.frame_count_o; }
  int errors() const { return h_.dut.error_count_o; }
  bool bank_holds(int bank, const BankImage& b) const {
    for (std::size_t k = 0; k < b.words.size(); ++k)
      if (banks_[bank][k] != b.words[k]) return false;
    return true;
  }
  double now() const { return phase_ + static_cast<double>(n_) / ClockHz; }

  std::vector<int> writes;  // addresses written, in order
  int writes_to_shown = 0;

 private:
  Harness<Vhost_link> h_;
  UartLine line_;
  std::mt19937_64 rng_;
  std::vector<std::vector<Word>> banks_;
  double phase_ = 0;
  std::uint64_t n_ = 0;
};

std::vector<int> ascending(int n) {
  std::vector<int> v(n);
  for (int k = 0; k < n; ++k) v[k] = k;
  return v;
}

class RtlHostLink : public ::testing::TestWithParam<double> {};

TEST_P(RtlHostLink, GoodPacketsSwapAtTheNextBegin) {
  LinkBench b(GetParam(), 1);
  const BankImage a = random_bank(b.rng(), 40), c = random_bank(b.rng(), BankWords);
  b.send(frame_packet(a));
  EXPECT_EQ(b.writes, ascending(40));
  EXPECT_TRUE(b.bank_holds(1, a));
  EXPECT_EQ(b.frames(), 1);
  EXPECT_EQ(b.errors(), 0);
  EXPECT_EQ(b.shown(), 0);  // no swap before the frame player begins a frame
  b.begin_frame();
  EXPECT_EQ(b.shown(), 1);
  b.begin_frame();
  EXPECT_EQ(b.shown(), 1);  // one swap per good packet
  b.writes.clear();
  b.send(frame_packet(c));  // a full bank, into bank 0
  EXPECT_EQ(b.writes, ascending(BankWords));
  EXPECT_TRUE(b.bank_holds(0, c));
  EXPECT_TRUE(b.bank_holds(1, a));
  b.begin_frame();
  EXPECT_EQ(b.shown(), 0);
  EXPECT_EQ(b.frames(), 2);
  EXPECT_EQ(b.errors(), 0);
  EXPECT_EQ(b.writes_to_shown, 0);
}

TEST_P(RtlHostLink, BadPacketsAreDroppedAndCounted) {
  LinkBench b(GetParam(), 2);
  const BankImage a = random_bank(b.rng(), 24);
  b.send(frame_packet(a));
  b.begin_frame();
  ASSERT_EQ(b.shown(), 1);
  int errors = 0;
  auto dropped = [&](const std::vector<std::uint8_t>& p, bool writes_words, const char* what) {
    b.writes.clear();
    b.send(p);
    b.begin_frame();
    EXPECT_EQ(b.errors(), ++errors) << what;
    EXPECT_EQ(b.frames(), 1) << what;
    EXPECT_EQ(b.shown(), 1) << what;
    EXPECT_EQ(!b.writes.empty(), writes_words) << what;
    EXPECT_TRUE(b.bank_holds(1, a)) << what;
  };
  const BankImage d = random_bank(b.rng(), 30);
  const std::vector<std::uint8_t> good = frame_packet(d);

  std::vector<std::uint8_t> p = good;
  p[7 + 9 * 11 + 3] ^= 0x10;  // a payload bit: the CRC fails
  dropped(p, true, "payload bit flipped");
  p = good;
  p[p.size() - 1] ^= 0x80;  // the CRC's own bit
  dropped(p, true, "CRC bit flipped");
  BankImage narrow = d;
  narrow.word_bits = WordBits - 8;  // B one byte less
  dropped(frame_packet(narrow), false, "word size");
  dropped(frame_packet(random_bank(b.rng(), BankWords + 1)), false, "more words than the bank");
  dropped(frame_packet(random_bank(b.rng(), 7)), false, "fewer words than the header");
  // A framing error inside the words.
  b.writes.clear();
  b.line().send(std::vector<std::uint8_t>(good.begin(), good.begin() + 100), b.next_start());
  b.line().break_last_stop_bit();
  b.line().send(std::vector<std::uint8_t>(good.begin() + 100, good.end()), b.line().end_s() + 2 * b.line().bit_s());
  b.run_until(b.line().end_s() + 3 * b.line().bit_s());
  b.begin_frame();
  EXPECT_EQ(b.errors(), ++errors) << "framing error";
  EXPECT_EQ(b.shown(), 1);
  // A pause of 2^TimeoutBits clocks after 50 bytes.
  b.line().send(std::vector<std::uint8_t>(good.begin(), good.begin() + 50), b.next_start());
  const double pause = (1 << TimeoutBits) / ClockHz + 5 * b.line().bit_s();
  b.line().send(std::vector<std::uint8_t>(good.begin() + 50, good.end()), b.line().end_s() + pause);
  b.run_until(b.line().end_s() + 3 * b.line().bit_s());
  b.begin_frame();
  EXPECT_EQ(b.errors(), ++errors) << "pause";
  EXPECT_EQ(b.shown(), 1);
  EXPECT_EQ(b.frames(), 1);

  // Noise without the magic, then the good packet: taken, no error.
  std::vector<std::uint8_t> noise(200);
  for (auto& x : noise) x = static_cast<std::uint8_t>(b.rng()() % 0x50);  // never 0x57 (the magic's first byte)
  b.send(noise);
  b.writes.clear();
  b.send(good);
  EXPECT_EQ(b.writes, ascending(30));
  EXPECT_TRUE(b.bank_holds(0, d));
  b.begin_frame();
  EXPECT_EQ(b.shown(), 0);
  EXPECT_EQ(b.frames(), 2);
  EXPECT_EQ(b.errors(), errors);
  EXPECT_EQ(b.writes_to_shown, 0);
}

TEST_P(RtlHostLink, NewerPacketReplacesOneWaitingForItsSwap) {
  LinkBench b(GetParam(), 3);
  const BankImage a = random_bank(b.rng(), 20), c = random_bank(b.rng(), 33);
  b.send(frame_packet(a));
  b.send(frame_packet(c));  // no begin between: c goes to the same bank
  EXPECT_TRUE(b.bank_holds(1, c));
  EXPECT_EQ(b.frames(), 2);
  b.begin_frame();
  EXPECT_EQ(b.shown(), 1);
  b.begin_frame();
  EXPECT_EQ(b.shown(), 1);
  // A begin while a packet arrives does not swap (nothing waits); the packet lands in bank 0.
  const BankImage d = random_bank(b.rng(), 12);
  const std::vector<std::uint8_t> p = frame_packet(d);
  b.line().send(p, b.next_start());
  b.run_until(b.line().end_s() - 40 * b.line().bit_s());
  b.begin_frame();
  EXPECT_EQ(b.shown(), 1);
  b.run_until(b.line().end_s() + 3 * b.line().bit_s());
  EXPECT_TRUE(b.bank_holds(0, d));
  b.begin_frame();
  EXPECT_EQ(b.shown(), 0);
  EXPECT_EQ(b.errors(), 0);
  EXPECT_EQ(b.writes_to_shown, 0);
}

INSTANTIATE_TEST_SUITE_P(RateError, RtlHostLink, ::testing::Values(0.0, 0.02, -0.02),
                         [](const ::testing::TestParamInfo<double>& i) {
                           return i.param == 0 ? std::string("Exact") : i.param > 0 ? std::string("Fast2pct")
                                                                                   : std::string("Slow2pct");
                         });

}  // namespace
