#include "run_files.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "scene.hpp"
#include "scene_types.hpp"
#include "usage_error.hpp"

namespace watkins {

namespace fs = std::filesystem;

namespace {

// A character device (/dev/null, /dev/full) holds no data a run could destroy: it may be an input
// and any number of outputs at once.
bool is_device(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

std::string folder_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// Writes all of `bytes` to `path` (created or truncated); every call checked. Messages name
// `shown` (the output the user asked for, when `path` is its temporary).
void write_bytes(const std::string& path, const std::vector<unsigned char>& bytes, const std::string& shown = "") {
  const std::string name = shown.empty() ? path : shown + " (temporary " + path + ")";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw std::runtime_error(name + ": cannot write: " + std::strerror(errno));
  const size_t n = bytes.empty() ? 0 : std::fwrite(bytes.data(), 1, bytes.size(), f);
  int err = n == bytes.size() ? 0 : errno;
  if (std::fflush(f) != 0 && !err) err = errno;
  if (std::fclose(f) != 0 && !err) err = errno;
  if (n != bytes.size() || err) throw std::runtime_error(name + ": cannot write: " + std::strerror(err ? err : EIO));
}

}  // namespace

bool RunFiles::Identity::operator==(const Identity& o) const {
  return exists == o.exists && dev == o.dev && ino == o.ino && name == o.name;
}

// The file a name leads to through symbolic links (the name itself when it is no link): an output
// named by a link is written where the link points, as a shell's redirection writes it, and the
// link stays.
std::string RunFiles::through_links(const std::string& path) {
  std::string named = path;
  for (int hops = 0; hops < 40; ++hops) {  // as many as the kernel follows
    std::error_code ec;
    if (!fs::is_symlink(named, ec)) break;
    const fs::path target = fs::read_symlink(named, ec);
    if (ec) break;
    named = target.is_absolute() ? target.string() : (fs::path(named).parent_path() / target).string();
  }
  return named;
}

// The file's device and inode (stat follows links: a link to an input is that input); for a name
// that does not exist, its folder's device and inode and the name in it (a dangling symbolic link
// names its target's, so it clashes with an output of that name); for a name whose folder does
// not exist either, the normalized path (it can only clash with another such output).
RunFiles::Identity RunFiles::identity(const std::string& path) {
  Identity id;
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    id.exists = true;
    id.dev = st.st_dev;
    id.ino = st.st_ino;
    return id;
  }
  const std::string named = through_links(path);
  id.name = fs::path(named).filename().string();
  if (::stat(folder_of(named).c_str(), &st) == 0) {
    id.dev = st.st_dev;
    id.ino = st.st_ino;
  } else {
    std::error_code ec;
    id.name = fs::weakly_canonical(fs::absolute(named, ec), ec).string();
  }
  return id;
}

void RunFiles::input(const std::string& what, const std::string& path) {
  if (path.empty() || is_device(path)) return;
  const Identity id = identity(path);
  if (!id.exists) return;  // the reader says it is missing
  for (const Output& o : outputs_)  // an input named after its outputs (a scene a run writes first)
    if (!o.folder && o.id == id)
      throw UsageError(o.option + " " + o.path + " is " + what + "; refusing to overwrite it");
  inputs_.push_back({what, path, id});
}

void RunFiles::scene_inputs(const Scene& parsed) {
  for (const SceneFile& f : files_read(parsed)) input("the " + f.kind + " of " + f.field + " in " + parsed.name, f.path);
}

void RunFiles::check_output(const Output& o) const {
  if (o.path.empty()) throw UsageError(o.option + ": the file name is empty");
  const bool device = is_device(o.path);
  if (!device)
    for (const Input& in : inputs_)
      if (in.id == o.id)
        throw UsageError(o.option + " " + o.path + " is " + in.what + "; refusing to overwrite it");
  for (const Output& other : outputs_)
    if (!device && !other.folder && !o.folder && other.id == o.id)
      throw UsageError(o.option + " and " + other.option + " name the same file " + o.path);
  if (o.folder) return;
  // A folder is not a file to replace, and a missing folder fails now rather than after the run
  // (a file of an output folder gets its folder at commit).
  std::error_code ec;
  if (fs::is_directory(o.path, ec))
    throw std::runtime_error(o.option + " " + o.path + ": cannot write: it is a folder");
  for (const Output& f : outputs_)
    if (f.folder && fs::path(o.path).parent_path() == fs::path(f.path)) return;
  const std::string folder = folder_of(o.path);
  if (!fs::is_directory(folder, ec))
    throw std::runtime_error(o.option + " " + o.path + ": cannot write: its folder " + folder + ": " +
                             std::strerror(fs::exists(folder, ec) ? ENOTDIR : ENOENT));
}

void RunFiles::output(const std::string& option, const std::string& path) {
  Output o{option, path, identity(path), false};
  check_output(o);
  outputs_.push_back(std::move(o));
}

void RunFiles::output_folder(const std::string& option, const std::string& path) {
  if (path.empty()) throw UsageError(option + ": the folder name is empty");
  std::error_code ec;
  if (fs::exists(path, ec) && !fs::is_directory(path, ec))
    throw std::runtime_error(option + " " + path + ": cannot write into it: it is not a folder");
  Output o{option, path, identity(path), true};
  check_output(o);
  outputs_.push_back(std::move(o));
}

const RunFiles::Output* RunFiles::declared(const std::string& path) const {
  for (const Output& o : outputs_)
    if (!o.folder && o.path == path) return &o;
  return nullptr;
}

void RunFiles::add(const std::string& path, std::vector<unsigned char> bytes) {
  if (!declared(path)) throw std::logic_error("RunFiles::add: " + path + " was not declared as an output");
  for (Pending& p : pending_)  // rewritten (synth's tables): the newest bytes
    if (p.path == path && !p.staged) {
      p.bytes = std::move(bytes);
      return;
    }
  pending_.push_back({path, "", std::move(bytes)});
}

void RunFiles::add_in(const std::string& folder, const std::string& name, std::vector<unsigned char> bytes) {
  const std::string path = (fs::path(folder) / name).string();
  const Output* f = nullptr;
  for (const Output& o : outputs_)
    if (o.folder && o.path == folder) f = &o;
  if (!f) throw std::logic_error("RunFiles::add_in: " + folder + " was not declared as an output folder");
  // A file of the folder that another output names, or that the run already put there, is
  // refused like any two outputs of one file, never replaced: the name alike (declared() matches
  // names) or not (output() matches identities).
  if (const Output* o = declared(path)) {
    if (o->option == f->option + " file") throw UsageError(f->option + ": two files of the run are named " + path);
    throw UsageError(f->option + " file and " + o->option + " name the same file " + path);
  }
  output(f->option + " file", path);
  add(path, std::move(bytes));
}

// The temporary beside `path`, or "" when path names an existing non-regular file (/dev/null, a
// FIFO), which is written in place.
std::string RunFiles::temporary_for(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) return "";
  const fs::path p(through_links(path));
  return (p.parent_path() / ("." + p.filename().string() + ".tmp" + std::to_string(::getpid()))).string();
}

std::string RunFiles::stage(const std::string& path) {
  if (!declared(path)) throw std::logic_error("RunFiles::stage: " + path + " was not declared as an output");
  std::string temp = temporary_for(path);
  bool copy = false;
  if (temp.empty()) {
    // A streaming writer may unlink and rename its file when it closes (an FST writer repacks):
    // it never gets a device's name. It writes a private temporary, copied into the device at
    // commit.
    const char* dir = std::getenv("TMPDIR");
    temp = (fs::path(dir && *dir ? dir : "/tmp") / ("watkins-" + std::to_string(::getpid()) + "-" +
                                                     std::to_string(pending_.size()) + ".stream"))
               .string();
    copy = true;
  }
  pending_.push_back({path, temp, {}, true, copy});
  return temp;
}

void RunFiles::commit() {
  for (const Output& o : outputs_)
    if (o.folder) {
      std::error_code ec;
      fs::create_directories(o.path, ec);
      if (ec) throw std::runtime_error(o.option + " " + o.path + ": cannot create the folder: " + ec.message());
    }
  for (Pending& p : pending_) {
    if (p.staged) continue;
    p.temp = temporary_for(p.path);  // set first: the destructor removes it if the write fails half-way
    if (!p.temp.empty()) write_bytes(p.temp, p.bytes, p.path);
  }
  for (Pending& p : pending_) {
    if (p.copy_to_device) {  // a streamed file meant for a device: its bytes, written in place
      std::ifstream in(p.temp, std::ios::binary);
      const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      if (!in.eof() && in.fail()) throw std::runtime_error(p.path + ": cannot read back " + p.temp);
      write_bytes(p.path, bytes);
    } else if (p.temp.empty() && !p.staged) {
      write_bytes(p.path, p.bytes);
    }
  }
  for (Pending& p : pending_) {
    if (p.temp.empty() || p.copy_to_device) continue;
    // Only a regular file (or nothing) is replaced: a device or FIFO that appeared meanwhile keeps
    // its place.
    const std::string dest = through_links(p.path);
    struct stat st {};
    if (::lstat(dest.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
      throw std::runtime_error(p.path + ": cannot write: it is no longer a regular file");
    if (std::rename(p.temp.c_str(), dest.c_str()) != 0)
      throw std::runtime_error(p.path + ": cannot write (rename from " + p.temp + "): " + std::strerror(errno));
    p.temp.clear();
  }
  for (Pending& p : pending_)
    if (p.copy_to_device) std::remove(p.temp.c_str());
  pending_.clear();
}

RunFiles::~RunFiles() {
  for (const Pending& p : pending_)
    if (!p.temp.empty()) std::remove(p.temp.c_str());
}

}  // namespace watkins
