// The `watkins` command line as a test runs it (WATKINS_CLI: the binary's path, a compile
// definition of the test target): exit code and everything it printed.
#pragma once

#include <sys/wait.h>

#include <stdlib.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace watkins::test {

struct CliRun {
  int exit_code;
  std::string output;  // stdout and stderr
};

// Runs `watkins ARGS` (in folder `cwd` when given).
inline CliRun run_cli(const std::string& args, const std::string& cwd = "") {
  const std::string cmd =
      (cwd.empty() ? "" : "cd " + cwd + " && ") + std::string(WATKINS_CLI) + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  while (p && fgets(buf.data(), buf.size(), p)) out += buf.data();
  const int status = p ? pclose(p) : -1;
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

// A fresh folder under /tmp for a test's files, removed with everything in it at the end.
class ScratchDir {
 public:
  ScratchDir() {
    char tmpl[] = "/tmp/watkins_test_XXXXXX";
    if (!mkdtemp(tmpl)) throw std::runtime_error("mkdtemp failed");
    dir_ = tmpl;
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  // Writes `text` to dir/name; returns the path.
  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = dir_ + "/" + name;
    std::ofstream(path) << text;
    return path;
  }
  // Whether dir/name exists, and its bytes ("" when it does not).
  bool has(const std::string& name) const { return std::filesystem::exists(dir_ + "/" + name); }
  std::string contents(const std::string& name) const {
    std::ifstream in(dir_ + "/" + name, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }

 protected:
  std::string dir_;
};

}  // namespace watkins::test
