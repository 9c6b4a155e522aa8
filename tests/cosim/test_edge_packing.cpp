// The edge packer (testbench/edge_packing.hpp) against the edge_t declaration in rtl/watkins_pkg.sv.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <regex>
#include <sstream>

#include "edge_packing.hpp"

using namespace watkins;
using namespace watkins::tb;

namespace {

EdgeRecord sample_record() {
  EdgeRecord e;
  e.y0 = 0x1ABC;  // 13 bits: 1 1010 1011 1100
  e.n = 0x0123;
  e.poly = 0xBEEF;
  e.material = 0xA;
  for (int c = 0; c < fmt::NumChannels; ++c) {
    e.value[c] = (c % 2 ? -1 : 1) * ((i64{1} << (fmt::ChannelBits - 2)) + 0x1234567 * (c + 1));
    e.slope[c] = (c % 2 ? 1 : -1) * (i64{0x5A5A5A} * (c + 3));
  }
  return e;
}

}  // namespace

TEST(EdgePacking, FieldsSitWhereThePackedStructPutsThem) {
  const EdgeRecord e = sample_record();
  const EdgeWords w = pack_edge(e);
  // y0 is the top field: bits 465..453.
  EXPECT_EQ(get_bits(w, 453, 13), 0x1ABCu);
  EXPECT_EQ(w[14] >> 5, 0x1ABCu) << "y0 occupies bits [465:453] = word 14 bits [17:5]";
  EXPECT_EQ(get_bits(w, 440, 13), 0x0123u);
  EXPECT_EQ(get_bits(w, 424, 16), 0xBEEFu);
  EXPECT_EQ(get_bits(w, 420, 4), 0xAu);
  // value[4] (B) at the top of the value field, slope[0] (X) at bit 0.
  const std::uint64_t mask = (std::uint64_t{1} << fmt::ChannelBits) - 1;
  for (int c = 0; c < fmt::NumChannels; ++c) {
    EXPECT_EQ(get_bits(w, 210 + 42 * c, 42), static_cast<std::uint64_t>(e.value[c]) & mask) << "value " << c;
    EXPECT_EQ(get_bits(w, 42 * c, 42), static_cast<std::uint64_t>(e.slope[c]) & mask) << "slope " << c;
  }
  // slope[0] low word by hand: -(0x5A5A5A * 3) in two's complement.
  EXPECT_EQ(w[0], static_cast<std::uint32_t>(-(0x5A5A5A * 3)));
  // Nothing above bit 465.
  EXPECT_EQ(w[14] >> 18, 0u);
}

TEST(EdgePacking, RoundTripsRandomRecords) {
  std::mt19937_64 rng(7);
  const i64 lim = i64{1} << (fmt::ChannelBits - 1);
  std::uniform_int_distribution<i64> ch(-lim, lim - 1);
  for (int k = 0; k < 2000; ++k) {
    EdgeRecord e;
    e.y0 = static_cast<int>(rng() % (1u << fmt::LineBits));
    e.n = static_cast<int>(rng() % (1u << fmt::LineBits));
    e.poly = static_cast<int>(rng() % (1u << fmt::PolyIdBits));
    e.material = static_cast<int>(rng() % (1u << fmt::MaterialIdBits));
    for (int c = 0; c < fmt::NumChannels; ++c) {
      e.value[c] = k < 8 ? (k % 2 ? -lim : lim - 1) : ch(rng);  // extremes first
      e.slope[c] = k < 8 ? (k % 4 < 2 ? -1 : 0) : ch(rng);
    }
    const EdgeRecord d = unpack_edge(pack_edge(e));
    ASSERT_EQ(d.y0, e.y0);
    ASSERT_EQ(d.n, e.n);
    ASSERT_EQ(d.poly, e.poly);
    ASSERT_EQ(d.material, e.material);
    ASSERT_EQ(d.value, e.value) << "record " << k;
    ASSERT_EQ(d.slope, e.slope) << "record " << k;
  }
}

TEST(EdgePacking, RejectsFieldsThatDoNotFit) {
  EdgeRecord e;
  e.n = 1;
  e.y0 = 1 << fmt::LineBits;
  EXPECT_THROW(pack_edge(e), std::invalid_argument);
  e.y0 = 0;
  e.poly = -1;
  EXPECT_THROW(pack_edge(e), std::invalid_argument);
  e.poly = 0;
  e.material = 1 << fmt::MaterialIdBits;
  EXPECT_THROW(pack_edge(e), std::invalid_argument);
  e.material = 0;
  e.value[2] = i64{1} << (fmt::ChannelBits - 1);
  EXPECT_THROW(pack_edge(e), std::invalid_argument);
}

// The layout above is what the RTL declares: the active-edge list's record_t (the one place the
// record's fields are named) has the same fields in the same order, the channel vectors
// watkins_pkg::vector_bits wide with X at the bottom, and watkins_pkg::edge_bits adds them up.
TEST(EdgePacking, MatchesTheRecordInTheRtl) {
  auto read = [](const char* path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
  const std::string ael = read(WATKINS_SOURCE_DIR "/rtl/active_edge_list.sv");
  const std::string pkg = read(WATKINS_SOURCE_DIR "/rtl/watkins_pkg.sv");
  ASSERT_FALSE(ael.empty() || pkg.empty()) << "cannot read rtl/active_edge_list.sv or rtl/watkins_pkg.sv";
  const auto e = ael.find("} record_t;");
  ASSERT_NE(e, std::string::npos);
  const auto b = ael.rfind("typedef struct packed", e);
  ASSERT_NE(b, std::string::npos);
  const std::string body = ael.substr(b, e - b);
  const std::regex field(R"(logic\s+((?:\[[^\]]+\])+)\s*(\w+)\s*;)");
  std::vector<std::string> names, dims;
  for (std::sregex_iterator it(body.begin(), body.end(), field), end; it != end; ++it) {
    dims.push_back(std::regex_replace((*it)[1].str(), std::regex(R"(\s+)"), ""));
    names.push_back((*it)[2].str());
  }
  EXPECT_EQ(names, (std::vector<std::string>{"y0", "n", "poly", "material", "value", "slope"}));
  EXPECT_EQ(dims, (std::vector<std::string>{"[LB-1:0]", "[LB-1:0]", "[PolyIdBits-1:0]", "[MaterialIdBits-1:0]",
                                            "[VB-1:0]", "[VB-1:0]"}));
  EXPECT_NE(pkg.find("edge_bits = 2 * LineBits + pb + mb + 2 * vector_bits(xb, zb, ab);"), std::string::npos);
  EXPECT_NE(pkg.find("slot_lo = (c == 0) ? 0 : (c == 1) ? xb : xb + zb + (c - 2) * ab;"), std::string::npos);
  EXPECT_EQ(edge_layout::Bits, 2 * fmt::LineBits + fmt::PolyIdBits + fmt::MaterialIdBits +
                                   2 * fmt::NumChannels * fmt::ChannelBits);
}
