// The edge packer (model/twins/edge_packing.hpp): the default layout against the edge_t declaration
// in rtl/watkins_pkg.sv, and a narrow configuration's layout (per-slot widths) round trip.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <regex>
#include <sstream>

#include "config_file.hpp"
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

// Every field of the unpacked record equals the packed one's (the id is not carried).
void expect_same_fields(const EdgeRecord& d, const EdgeRecord& e, int k) {
  EXPECT_EQ(d.y0, e.y0) << "record " << k;
  EXPECT_EQ(d.n, e.n) << "record " << k;
  EXPECT_EQ(d.poly, e.poly) << "record " << k;
  EXPECT_EQ(d.material, e.material) << "record " << k;
  EXPECT_EQ(d.value, e.value) << "record " << k;
  EXPECT_EQ(d.slope, e.slope) << "record " << k;
  EXPECT_EQ(d.d2, e.d2) << "record " << k;
  EXPECT_EQ(d.d3, e.d3) << "record " << k;
}

}  // namespace

const EdgeLayout& def = default_edge_layout();

TEST(EdgePacking, FieldsSitWhereThePackedStructPutsThem) {
  const EdgeRecord e = sample_record();
  const EdgeWords w = pack_edge(def, e);
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
  for (int i = 15; i < MaxEdgeWords; ++i) EXPECT_EQ(w[i], 0u) << "word " << i;
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
    expect_same_fields(unpack_edge(def, pack_edge(def, e)), e, k);
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(EdgePacking, RejectsFieldsThatDoNotFit) {
  EdgeRecord e;
  e.n = 1;
  e.y0 = 1 << fmt::LineBits;
  EXPECT_THROW(pack_edge(def, e), std::invalid_argument);
  e.y0 = 0;
  e.poly = -1;
  EXPECT_THROW(pack_edge(def, e), std::invalid_argument);
  e.poly = 0;
  e.material = 1 << fmt::MaterialIdBits;
  EXPECT_THROW(pack_edge(def, e), std::invalid_argument);
  e.material = 0;
  e.value[2] = i64{1} << (fmt::ChannelBits - 1);
  EXPECT_THROW(pack_edge(def, e), std::invalid_argument);
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
  EXPECT_EQ(dims, (std::vector<std::string>{"[LineBits-1:0]", "[LineBits-1:0]", "[PolyIdBits-1:0]",
                                            "[MaterialIdBits-1:0]", "[VectorBits-1:0]", "[SlopeBits-1:0]"}));
  EXPECT_NE(ael.find("localparam int unsigned SlopeBits = EdgeOrder * VectorBits,"), std::string::npos)
      << "the slope field holds EdgeOrder channel vectors (d1, d2, d3)";
  EXPECT_NE(pkg.find("edge_bits = 2 * LineBits + pb + mb + (1 + ord) * vector_bits(xb, zb, ab);"), std::string::npos);
  EXPECT_NE(pkg.find("slot_lo = (c == 0) ? 0 : (c == 1) ? xb : xb + zb + (c - 2) * ab;"), std::string::npos);
  EXPECT_EQ(def.bits, fmt::EdgeRecordBits);
  EXPECT_EQ(def.bits, 2 * fmt::LineBits + fmt::PolyIdBits + fmt::MaterialIdBits + 2 * fmt::NumChannels * fmt::ChannelBits);
  EXPECT_EQ(EdgeLayout::of(Config{}, ShadingMode::Phong).bits, def.bits) << "shade and normal share the default";
}

// A narrow configuration (tests/configs/narrow.json): every slot its own width, the ids narrower.
// Fields sit where the RTL's layout puts them (slot 0 at bit 0, slot 1 at XB, slot c at
// XB + ZB + (c-2)*AB; slope, value, material, poly, n, y0 from bit 0), and records round-trip.
// At edge order 3 the slope field is three vectors, d1 (the slope) at bit 0, then d2 and d3.
TEST(EdgePacking, NarrowConfigurationLayoutRoundTrips) {
  Config cfg = load_config(WATKINS_SOURCE_DIR "/tests/configs/narrow.json");
  for (const int order : {1, 3})
  for (const ShadingMode shading : {ShadingMode::Gouraud, ShadingMode::Phong}) {
    cfg.edge_order = order;
    const EdgeLayout l = EdgeLayout::of(cfg, shading);
    const ChannelFormats f = cfg.channels(shading);
    const int xb = cfg.x.bits(), zb = cfg.depth.bits(), ab = f.bits[fmt::ChanR];
    const int vb = xb + zb + 3 * ab;
    ASSERT_EQ(l.bits, cfg.edge_record_bits(shading));
    ASSERT_LT(l.bits, fmt::EdgeRecordBits) << "the test configuration is meant to be narrow";
    EXPECT_EQ(l.channels.vector_bits, vb);
    EXPECT_EQ(l.channels.lsb, (std::array<int, 5>{0, xb, xb + zb, xb + zb + ab, xb + zb + 2 * ab}));
    EXPECT_EQ(l.value_lsb, order * vb);
    EXPECT_EQ(l.material_lsb, (1 + order) * vb);
    EXPECT_EQ(l.poly_lsb, (1 + order) * vb + id_bits(cfg.max_materials));
    if (order == 3) {
      EXPECT_EQ(l.d2_lsb, vb);
      EXPECT_EQ(l.d3_lsb, 2 * vb);
    }
    EXPECT_EQ(l.y0_lsb, l.bits - fmt::LineBits);

    std::mt19937_64 rng(11);
    for (int k = 0; k < 2000; ++k) {
      EdgeRecord e;
      e.y0 = static_cast<int>(rng() % (1u << fmt::LineBits));
      e.n = static_cast<int>(rng() % (1u << fmt::LineBits));
      e.poly = static_cast<int>(rng() % (1u << l.poly_bits));
      e.material = static_cast<int>(rng() % (1u << l.material_bits));
      for (int c = 0; c < fmt::NumChannels; ++c) {
        const i64 lim = i64{1} << (l.channels.bits[c] - 1);
        std::uniform_int_distribution<i64> ch(-lim, lim - 1);
        e.value[c] = k < 2 ? (k ? -lim : lim - 1) : ch(rng);
        e.slope[c] = k < 2 ? (k ? lim - 1 : -lim) : ch(rng);
        if (order == 3) {
          e.d2[c] = ch(rng);
          e.d3[c] = k < 2 ? (k ? -lim : lim - 1) : ch(rng);
        }
      }
      const EdgeWords w = pack_edge(l, e);
      ASSERT_EQ(get_bits(w, l.y0_lsb, fmt::LineBits), static_cast<std::uint64_t>(e.y0));
      ASSERT_EQ(get_signed(w, l.value_lsb + l.channels.lsb[fmt::ChanZ], zb), e.value[fmt::ChanZ]);
      ASSERT_EQ(get_signed(w, l.slope_lsb + l.channels.lsb[fmt::ChanB], ab), e.slope[fmt::ChanB]);
      if (order == 3) ASSERT_EQ(get_signed(w, l.d3_lsb + l.channels.lsb[fmt::ChanX], xb), e.d3[fmt::ChanX]);
      for (int i = l.words; i < MaxEdgeWords; ++i) ASSERT_EQ(w[i], 0u) << "above the record, word " << i;
      expect_same_fields(unpack_edge(l, w), e, k);
      if (::testing::Test::HasFailure()) return;
    }
    // A value one past its slot, or an id past its width, is refused.
    EdgeRecord e;
    e.value[fmt::ChanX] = i64{1} << (xb - 1);
    EXPECT_THROW(pack_edge(l, e), std::invalid_argument);
    e.value[fmt::ChanX] = 0;
    e.poly = 1 << l.poly_bits;
    EXPECT_THROW(pack_edge(l, e), std::invalid_argument);
    // A curved edge's d2 has no place in an order-1 record.
    e.poly = 0;
    e.d2[fmt::ChanZ] = 1;
    if (order == 1) EXPECT_THROW(pack_edge(l, e), std::invalid_argument);
    else EXPECT_NO_THROW(pack_edge(l, e));
  }
}

// The widest valid configuration fits EdgeWords.
TEST(EdgePacking, EdgeWordsHoldTheWidestConfiguration) {
  Config c;
  c.x = {Config::MaxWordBits - Config::MaxXFrac, Config::MaxXFrac};
  c.depth = c.shade = c.normal = {Config::MaxWordBits - 30, 30};
  c.depth_bits = 24;
  c.edge_order = 3;
  ASSERT_EQ(c.check(), "");
  for (const ShadingMode s : {ShadingMode::Gouraud, ShadingMode::Phong}) {
    EXPECT_EQ(EdgeLayout::of(c, s).bits, MaxEdgeRecordBits);
    EXPECT_EQ(EdgeLayout::of(c, s).words, MaxEdgeWords);
  }
}
