// The option layer every `watkins` subcommand declares its options through, so one rule holds
// everywhere: a number is finite and in range, a value has exactly its format (an integer is
// digits, `i/N` is two integers and a slash), a list has no empty item, a file name is not empty,
// and options that exclude each other are refused together. A value that breaks a rule is a
// usage error (exit code 2) with one line naming the option: CLI11 reports a failed check as
// "--option: message".
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "scene.hpp"

namespace watkins::cli {

// A real number, finite, in [lo, hi] (CLI::Range alone lets NaN through).
CLI::Validator finite_in(double lo, double hi);
// A decimal integer in [lo, hi], digits only (no "12abc", no "1e3", no " 7").
CLI::Validator integer_in(long long lo, long long hi);
// A seed: a decimal integer in [0, 2^64 - 1]; "-1" and 2^64 are refused, not wrapped.
CLI::Validator seed64();
// A file or folder name: not empty.
CLI::Validator non_empty_name();

// A file option: a name that is not empty.
CLI::Option* add_file(CLI::App* app, const std::string& name, std::string& target, const std::string& help);

// Comma-separated lists, each occurrence possibly holding several items ("--tess 1,2 --tess 4");
// an empty item ("1,,2", "1,") is refused, and every item is checked as its scalar would be.
CLI::Option* add_real_list(CLI::App* app, const std::string& name, std::vector<double>& target,
                           const std::string& help, double lo, double hi);
CLI::Option* add_int_list(CLI::App* app, const std::string& name, std::vector<int>& target, const std::string& help,
                          int lo, int hi);
CLI::Option* add_name_list(CLI::App* app, const std::string& name, std::vector<std::string>& target,
                           const std::string& help, const std::vector<std::string>& allowed);

// --shading: a pipeline's name, "gouraud" or "phong" (parse_shading_mode's); anything else is
// "--shading: unknown shading mode "x" (gouraud, phong)". Not given: the scene's shading.mode.
CLI::Option* add_shading(CLI::App* app, std::string& target, const std::string& help);
// The scene's build options that --shading `name` sets (none when `name` is empty).
BuildOptions shading_options(const std::string& name);

// `i/N`: two decimal integers, 0 <= i < N; anything else (extra fields, signs, spaces) is refused
// (UsageError naming `option`).
void parse_shard(const std::string& option, const std::string& text, long long& i, long long& n);

// Every pair of `options` excludes each other: giving two is "--a excludes --b" (exit code 2).
void exclusive(const std::vector<CLI::Option*>& options);

}  // namespace watkins::cli
