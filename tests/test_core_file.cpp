// The FuseSoC core must list every RTL source, or users of the core get an incomplete design.
#include <gtest/gtest.h>

#include <dirent.h>

#include <fstream>
#include <sstream>
#include <string>

TEST(CoreFile, ListsEveryRtlSource) {
  std::ifstream f(WATKINS_SOURCE_DIR "/watkins.core");
  ASSERT_TRUE(f) << "watkins.core missing";
  std::stringstream core;
  core << f.rdbuf();
  DIR* d = opendir(WATKINS_SOURCE_DIR "/rtl");
  ASSERT_NE(d, nullptr);
  int n = 0;
  while (dirent* e = readdir(d)) {
    const std::string name = e->d_name;
    if (name.size() < 3 || name.substr(name.size() - 3) != ".sv") continue;
    ++n;
    EXPECT_NE(core.str().find("- rtl/" + name + "\n"), std::string::npos) << "rtl/" << name << " is not in watkins.core";
  }
  closedir(d);
  EXPECT_GE(n, 8);
}
