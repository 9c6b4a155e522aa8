// The FuseSoC core must list every RTL source, or users of the core get an incomplete design.
#include <gtest/gtest.h>

#include <dirent.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "config.hpp"

TEST(CoreFile, ListsEveryRtlSource) {
  std::ifstream f(WATKINS_SOURCE_DIR "/watkins.core");
  ASSERT_TRUE(f) << "watkins.core missing";
  std::stringstream core;
  core << f.rdbuf();
  // The pipeline (rtl/) and the board tops (rtl/board/, with their constraint files).
  for (const std::string folder : {"rtl/", "rtl/board/"}) {
    DIR* d = opendir((WATKINS_SOURCE_DIR "/" + folder).c_str());
    ASSERT_NE(d, nullptr) << folder;
    int n = 0;
    while (dirent* e = readdir(d)) {
      const std::string name = e->d_name;
      const bool source = name.size() > 3 && name.substr(name.size() - 3) == ".sv";
      const bool pins = name.size() > 4 && name.substr(name.size() - 4) == ".lpf";
      if (!source && !pins) continue;
      ++n;
      EXPECT_NE(core.str().find("- " + folder + name + "\n"), std::string::npos) << folder << name << " is not in watkins.core";
    }
    closedir(d);
    EXPECT_GE(n, 8) << folder;
  }
}

// Users set the top's parameters through the core (`--XFracBits=15`): it must declare every one
// `watkins_gen_pkg --params` prints, and pass them to the toplevel.

TEST(CoreFile, DeclaresEveryTopParameter) {
  std::ifstream f(WATKINS_SOURCE_DIR "/watkins.core");
  std::stringstream core;
  core << f.rdbuf();
  const std::string text = core.str();
  const size_t targets = text.find("\ntargets:");
  ASSERT_NE(targets, std::string::npos);
  const size_t toplevel_params = text.find("parameters: [", targets);
  ASSERT_NE(toplevel_params, std::string::npos);
  const std::string passed = text.substr(toplevel_params, text.find(']', toplevel_params) - toplevel_params);
  // The default configuration's list, and the parameters listed only when not at the RTL's default.
  watkins::Config other;
  other.edge_order = 3;
  other.smoothing = false;
  std::vector<watkins::RtlParameter> params = watkins::rtl_parameters(watkins::Config{}, watkins::ShadingMode::Phong);
  for (const watkins::RtlParameter& p : watkins::rtl_parameters(other, watkins::ShadingMode::Phong)) params.push_back(p);
  for (const watkins::RtlParameter& p : params) {
    EXPECT_NE(text.find(std::string("\n  ") + p.name + ":\n"), std::string::npos) << p.name << " not declared";
    EXPECT_NE(passed.find(p.name), std::string::npos) << p.name << " not passed to watkins_top";
  }
}
