// libFuzzer target: the option parsers of every `watkins` subcommand. The input split at its NUL
// bytes is the command line after argv[0] ("watkins"); it is parsed by the CLI11 app with every
// subcommand registered (sim/commands.hpp) and the chosen subcommand's option checks run -- what
// `watkins` does before it reads, renders or writes anything (nothing is run here). Success,
// CLI::ParseError (help requests included) and watkins::UsageError are the expected outcomes; any
// other exception, a crash or a sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "fuzz_util.hpp"
#include "usage_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input = watkins::fuzz::bytes_of(data, size);
  std::vector<std::string> args{"watkins"};
  if (!input.empty()) {
    std::size_t from = 0;
    for (;;) {
      const std::size_t nul = input.find('\0', from);
      args.push_back(input.substr(from, nul == std::string::npos ? std::string::npos : nul - from));
      if (nul == std::string::npos) break;
      from = nul + 1;
    }
  }
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  CLI::App app{"watkins"};
  const watkins::cli::Commands commands(app);
  try {
    app.parse(static_cast<int>(args.size()), argv.data());
    commands.check();
  } catch (const CLI::ParseError&) {
  } catch (const watkins::UsageError&) {
  }
  return 0;
}
