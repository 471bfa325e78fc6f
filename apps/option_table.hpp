// The option table every subcommand's options come from: one entry per option
// (its flag without "--", which is also its config-file key, its type, its
// --help group and text) drives the CLI11 registration, the command-line
// conversion and the merge of a TOML config file, so the flags and the keys
// cannot drift apart. The types are halfspace's own where CLI11 and toml++
// have none: START:STOP:COUNT ranges, NXxNY shapes, memory sizes.
#pragma once

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/problem.hpp"

namespace halfspace::app {

enum class OptionKind {
  number,      // double
  modulus,     // double; "inf" too (a rigid body's modulus)
  numbers,     // doubles: one number, a list "A,B,C" or a range "START:STOP:COUNT"; a TOML array too
  integer,     // long long
  text,        // string
  path,        // string; relative paths in a config file are relative to the file
  dimensions,  // string "N" or "AxB"; a config file may also give a bare number
  memory,      // string "8G", "512M" or bytes; a config file may also give a whole number of bytes
  flag,        // bool, no value
};

// What a subcommand's options record besides their values: where each came
// from and how it was written, for messages and for the provenance written
// into output files. A subcommand's options struct derives from it.
struct GivenOptions {
  std::optional<std::string> config;                     // path of the TOML file, if any
  std::string config_text;                               // its contents
  std::string command_line;                              // argv joined and shell-quoted
  std::set<std::string, std::less<>> from_config;        // keys whose value came from the file
  std::map<std::string, std::string, std::less<>> text;  // every given value as written

  // Whether the option was given, on the command line or in the file.
  bool given(std::string_view key) const { return text.contains(key); }
  // A given setting and its value as the user wrote it, for error messages:
  // "--force -1" from the command line, "force = -1 in run.toml" from a file.
  std::string describe(std::string_view key) const;
  // The option by itself: "--force", or "force (in run.toml)".
  std::string name(std::string_view key) const;
};

// Where one option's value is stored in a particular options object.
using OptionSlot = std::variant<std::optional<double>*, std::optional<long long>*, std::optional<std::string>*, bool*,
                                std::optional<std::vector<double>>*>;

// One option as the table lists it, for the options struct `Options`.
template <class Options>
struct OptionSpec {
  using Field = std::variant<std::optional<double> Options::*, std::optional<long long> Options::*,
                             std::optional<std::string> Options::*, bool Options::*,
                             std::optional<std::vector<double>> Options::*>;
  std::string_view key;  // the long flag without "--", and the config file key
  Field field;
  OptionKind kind;
  std::string_view group;
  std::string_view value_name;
  std::string_view help;
};

// The rows of `first`, then those of `second`.
template <class Spec, std::size_t N, std::size_t M>
std::array<Spec, N + M> joined(const std::array<Spec, N>& first, const std::array<Spec, M>& second) {
  std::array<Spec, N + M> rows{};
  std::ranges::copy(first, rows.begin());
  std::ranges::copy(second, rows.begin() + N);
  return rows;
}

// An option of the table bound to an options object.
struct BoundOption {
  std::string_view key;
  OptionKind kind;
  OptionSlot slot;
};

// Options that exclude each other. Choosing an alternative on the command
// line (by one of its selectors) makes the config file's keys of the *other*
// alternatives of its group be ignored, so that `--approach 1e-6` overrides a
// file that sets `force`.
struct Alternative {
  std::vector<std::string_view> selectors;  // keys that choose this alternative
  std::vector<std::string_view> keys;       // every key that belongs to it
};
using AlternativeGroup = std::vector<Alternative>;

// The program's spelling of a library's options (OptionSpelling,
// problem.hpp): an option's flag is the table key that is its name with '-'
// for '_', case aside ("e_star" is --E-star, "layer_E" --layer-E); its value
// the one the user wrote, if given, or with `library_values` the one the
// library shows ("-1 Pa s", "2 m/s (y component)").
class GivenSpelling : public OptionSpelling {
 public:
  template <class Options>
  GivenSpelling(const GivenOptions& given, std::span<const OptionSpec<Options>> table, bool library_values = false)
      : given_(given), library_values_(library_values) {
    for (const OptionSpec<Options>& spec : table) keys_.push_back(spec.key);
  }
  std::string name(std::string_view option) const override { return given_.name(key(option)); }
  std::string describe(std::string_view option, std::string_view value) const override;

 protected:
  // The table's key of `option`; its name with '-' for '_' if none matches.
  virtual std::string key(std::string_view option) const;

 private:
  const GivenOptions& given_;
  bool library_values_;
  std::vector<std::string_view> keys_;
};

// Registers one option with CLI11 (the non-template part of add_options).
void add_option(CLI::App& command, std::string_view key, OptionKind kind, std::string_view group,
                std::string_view value_name, std::string_view help);

// Registers --config FILE (a TOML file of the command's options; `example`
// one of its lines, for the help).
void add_config_option(CLI::App& command, std::string_view example);

// Registers every option of `table` with CLI11.
template <class Options>
void add_options(CLI::App& command, std::span<const OptionSpec<Options>> table) {
  for (const OptionSpec<Options>& spec : table) {
    add_option(command, spec.key, spec.kind, spec.group, spec.value_name, spec.help);
  }
}

// The table's options bound to the fields of `options`.
template <class Options>
std::vector<BoundOption> bind_options(std::span<const OptionSpec<Options>> table, Options& options) {
  std::vector<BoundOption> bound;
  bound.reserve(table.size());
  for (const OptionSpec<Options>& spec : table) {
    bound.push_back(
        {spec.key, spec.kind, std::visit([&](auto member) -> OptionSlot { return &(options.*member); }, spec.field)});
  }
  return bound;
}

// Reads the options given on the command line after CLI11 parsed it, and
// --config if `command` has it; records argv as options.command_line.
// Throws InputError naming the flag when a value is not of its type.
void read_command_line(const CLI::App& command, const std::vector<std::string>& argv,
                       std::span<const BoundOption> options, GivenOptions& given);

// If given.config is set, reads that TOML file and fills every option the
// command line left unset. A command-line option also discards the file's
// keys of the alternatives it excludes. Throws FileError if the file cannot
// be read and InputError for a TOML syntax error, an unknown key or a value
// of the wrong type, naming the key and the file.
void merge_config_file(std::span<const BoundOption> options, std::span<const AlternativeGroup> alternatives,
                       std::string_view command_name, GivenOptions& given);

// The run of a command whose options are `table` alone (no alternatives),
// registered here with --config (`example` as add_config_option's): reads
// the command line, then the file, into Options and returns run(options).
template <class Options, class Run>
std::function<int(const std::vector<std::string>&)> table_command(CLI::App& command,
                                                                  std::span<const OptionSpec<Options>> table,
                                                                  std::string_view example, Run run) {
  add_config_option(command, example);
  add_options(command, table);
  return [&command, table, run](const std::vector<std::string>& argv) {
    Options options;
    const std::vector<BoundOption> bound = bind_options(table, options);
    read_command_line(command, argv, bound, options);
    merge_config_file(bound, {}, command.get_name(), options);
    return run(options);
  };
}

}  // namespace halfspace::app
