// The SystemVerilog package must be exactly what the generator prints from model/twins/formats.hpp.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

namespace {

std::string run(const std::string& cmd) {
  std::unique_ptr<FILE, int (*)(FILE*)> p(popen(cmd.c_str(), "r"), pclose);
  std::string out;
  std::array<char, 4096> buf;
  while (p && fgets(buf.data(), buf.size(), p.get())) out += buf.data();
  return out;
}

TEST(Formats, SvPackageIsGeneratedFromTheHeader) {
  std::ifstream f(WATKINS_SOURCE_DIR "/rtl/watkins_pkg.sv");
  ASSERT_TRUE(f) << "rtl/watkins_pkg.sv missing";
  std::stringstream committed;
  committed << f.rdbuf();
  const std::string generated = run(WATKINS_GEN_PKG);
  ASSERT_FALSE(generated.empty());
  EXPECT_EQ(committed.str(), generated) << "rtl/watkins_pkg.sv is stale: run scripts/lib/gen_pkg.sh";
}

}  // namespace
