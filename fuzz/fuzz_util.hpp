// Shared pieces of the libFuzzer targets (scripts/fuzz): a private scratch folder per process for
// inputs that must reach the readers as files, and the input's bytes as a string.
#pragma once

#include <stdlib.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

namespace watkins::fuzz {

// A folder made once per process with mkdtemp (mode 0700, a fresh name), removed with its files
// when the process ends normally; the fuzzer writes its scratch files only here.
class ScratchDir {
 public:
  ScratchDir() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "watkins-fuzz-XXXXXX").string();
    if (::mkdtemp(tmpl.data()) == nullptr) {
      std::perror("watkins fuzz: mkdtemp");
      std::abort();  // nothing else can run without it: stop loudly, not as a finding-free pass
    }
    path_ = tmpl;
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::string& path() const { return path_; }

  // `bytes` written to `name` inside the folder; the file's full path.
  std::string write(const std::string& name, const std::string& bytes) const {
    const std::string p = path_ + "/" + name;
    std::FILE* f = std::fopen(p.c_str(), "wb");
    if (f == nullptr) {
      std::perror("watkins fuzz: scratch file");
      std::abort();
    }
    const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    if (std::fclose(f) != 0 || !ok) {
      std::perror("watkins fuzz: scratch file");
      std::abort();
    }
    return p;
  }

  // The process's folder (made on first use).
  static const ScratchDir& instance() {
    static const ScratchDir dir;
    return dir;
  }

 private:
  std::string path_;
};

inline std::string bytes_of(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

}  // namespace watkins::fuzz
