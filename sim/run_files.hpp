// The files one run of `watkins` reads and writes, and the only way any subcommand writes a file.
//
// A subcommand tells RunFiles every file it reads (the scene, the files the scene names, a
// configuration, ...) and every file it will write, before it does any work. An output that is
// one of the inputs, or another output, is refused at once (UsageError: exit code 2), judged by
// file identity (device and inode; for an output that does not exist yet, its folder's identity
// and its name), so a hard link, a symbolic link or a `..` path to an input is caught as surely as
// its own name. An output whose folder does not exist is refused at once too (exit code 1), not
// after the run.
//
// Outputs are written all or nothing: add() keeps a file's bytes, stage() hands out a temporary
// for a file another writer streams (the simulator's waveform); commit() writes every kept file to
// a temporary beside its name, checks every write, flush and close, and renames each temporary
// over its name only when all were written. A run that fails anywhere leaves no output and no
// temporary behind. A name that exists and is not a regular file (/dev/null, a FIFO) is written
// in place. Write errors are std::runtime_error (exit code 1), naming the output.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace watkins {

struct Scene;

class RunFiles {
 public:
  // A file the run reads; `what` names it in messages ("the scene", "--config", "objects[2].file
  // of scene.json"). A path that does not exist is skipped: the reader reports it.
  void input(const std::string& what, const std::string& path);
  // The files a parsed scene names (meshes, raw volumes), as inputs.
  void scene_inputs(const Scene& parsed);
  // A file the run will write, named by `option` ("--out"); refused now if empty, an input or
  // another output (UsageError), or if its folder does not exist (std::runtime_error).
  void output(const std::string& option, const std::string& path);
  // A folder the run writes files into (created at commit); its files are added with add_in().
  void output_folder(const std::string& option, const std::string& path);
  // Keeps `bytes` for the output `path`, declared before by output(). A file of an output folder
  // (`folder/name`) is declared and checked here, so before anything is written.
  void add(const std::string& path, std::vector<unsigned char> bytes);
  void add(const std::string& path, const std::string& text) {
    add(path, std::vector<unsigned char>(text.begin(), text.end()));
  }
  void add_in(const std::string& folder, const std::string& name, std::vector<unsigned char> bytes);
  // The name another writer streams the declared output `path` under: a temporary beside it that
  // commit() renames over it and a failed run removes (for a device, a private temporary whose
  // bytes commit() writes into it: a streaming writer never gets a device's name).
  std::string stage(const std::string& path);
  // Writes every kept file and renames every temporary over its name. May be called again after
  // more add()s (`watkins synth` rewrites its tables after every run): each call replaces the
  // files it writes whole.
  void commit();
  ~RunFiles();

 private:
  struct Identity {
    bool exists = false;
    dev_t dev = 0;
    ino_t ino = 0;      // of the file, or of its folder when it does not exist
    std::string name;   // the file name, when it does not exist
    bool operator==(const Identity& o) const;
  };
  struct Input {
    std::string what, path;
    Identity id;
  };
  struct Output {
    std::string option, path;
    Identity id;
    bool folder = false;
  };
  struct Pending {
    std::string path, temp;
    std::vector<unsigned char> bytes;
    bool staged = false;  // written by someone else under temp: only renamed here
    bool copy_to_device = false;  // staged for a device: temp is private, its bytes copied at commit
  };
  static Identity identity(const std::string& path);
  static std::string through_links(const std::string& path);
  void check_output(const Output& o) const;
  const Output* declared(const std::string& path) const;
  static std::string temporary_for(const std::string& path);

  std::vector<Input> inputs_;
  std::vector<Output> outputs_;
  std::vector<Pending> pending_;
};

}  // namespace watkins
