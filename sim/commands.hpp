// Every `watkins` subcommand on one CLI11 app: registration, the option checks that need no file
// (so a malformed command line is exit code 2 before anything is read, rendered or written), and
// the run. main() (watkins.cpp) and the option fuzzer (fuzz/) share it.
#pragma once

#include <memory>

namespace CLI {
class App;
}

namespace watkins::cli {

class Commands {
 public:
  explicit Commands(CLI::App& app);  // registers every subcommand and its options on `app`
  ~Commands();
  // After app.parse(): the chosen subcommand's checks of its options (UsageError naming one).
  void check() const;
  // After check(): runs the chosen subcommand; returns its exit code. Throws as the subcommand does.
  int run() const;

 private:
  struct Args;
  std::unique_ptr<Args> args_;
};

// main(): parses argv, checks and runs, and maps every outcome to the exit code and one line on
// stderr (docs/guide/cli.md, "Exit codes").
int main_entry(int argc, char** argv);

}  // namespace watkins::cli
