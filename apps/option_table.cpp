// The option table's machinery: CLI11 registration, command-line conversion
// and the TOML merge, for every subcommand's table (option_table.hpp).
#include "option_table.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <limits>

#include "halfspace/error.hpp"
#include "value_parsing.hpp"

namespace halfspace::app {
namespace {

bool is_set(const BoundOption& spec) {
  return std::visit(
      [](auto slot) -> bool {
        if constexpr (std::is_same_v<decltype(slot), bool*>) {
          return *slot;
        } else {
          return slot->has_value();
        }
      },
      spec.slot);
}

bool excluded_by(std::string_view key, const std::set<std::string, std::less<>>& given,
                 std::span<const AlternativeGroup> alternatives) {
  for (const AlternativeGroup& group : alternatives) {
    for (const Alternative& own : group) {
      if (std::find(own.keys.begin(), own.keys.end(), key) == own.keys.end()) continue;
      for (const Alternative& other : group) {
        if (&other == &own) continue;
        for (std::string_view selector : other.selectors) {
          if (given.contains(selector)) return true;
        }
      }
    }
  }
  return false;
}

// Stores a command-line value after converting it to the option's type.
void set_from_text(GivenOptions& options, const BoundOption& spec, const std::string& text) {
  options.text.insert_or_assign(std::string(spec.key), text);
  const std::string what = options.describe(spec.key);
  switch (spec.kind) {
    case OptionKind::number:
      *std::get<std::optional<double>*>(spec.slot) = parse_number(text, what);
      break;
    case OptionKind::modulus:
      *std::get<std::optional<double>*>(spec.slot) =
          text == "inf" || text == "+inf" ? std::numeric_limits<double>::infinity() : parse_number(text, what);
      break;
    case OptionKind::numbers:
      *std::get<std::optional<std::vector<double>>*>(spec.slot) = parse_number_list(text, what);
      break;
    case OptionKind::integer:
      *std::get<std::optional<long long>*>(spec.slot) = parse_integer(text, what);
      break;
    case OptionKind::text:
    case OptionKind::path:
    case OptionKind::dimensions:
    case OptionKind::memory:
      *std::get<std::optional<std::string>*>(spec.slot) = text;
      break;
    case OptionKind::flag:
      *std::get<bool*>(spec.slot) = true;
      break;
  }
}

std::string_view toml_type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a float";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    default:
      return "a date or time";
  }
}

// A config value as it would be written in the file, for error messages.
std::string toml_text(const toml::node& node) {
  if (const toml::array* array = node.as_array()) {
    std::string text = "[";
    for (std::size_t k = 0; k < array->size(); ++k) text += (k == 0 ? "" : ", ") + toml_text(*array->get(k));
    return text + "]";
  }
  if (node.is_string()) return fmt::format("\"{}\"", *node.value<std::string>());
  if (node.is_integer()) return fmt::format("{}", *node.value<long long>());
  if (node.is_floating_point()) return fmt::format("{}", *node.value<double>());
  if (node.is_boolean()) return *node.value<bool>() ? "true" : "false";
  return std::string(toml_type_name(node));
}

// Stores a config file value after checking its TOML type.
void set_from_toml(const BoundOption& spec, const toml::node& node, const std::filesystem::path& file) {
  const auto wrong_type = [&](std::string_view expected) {
    return InputError(fmt::format("key '{}' in config file {} must be {} (got {})", spec.key, file.string(), expected,
                                  toml_type_name(node)));
  };
  switch (spec.kind) {
    case OptionKind::number:
    case OptionKind::modulus: {
      // TOML's inf is a float: a modulus may be it (a rigid body).
      if (!node.is_number()) throw wrong_type("a number");
      *std::get<std::optional<double>*>(spec.slot) = *node.value<double>();
      break;
    }
    case OptionKind::numbers: {
      const std::string what = fmt::format("{} = {} in {}", spec.key, toml_text(node), file.string());
      std::vector<double> values;
      if (node.is_number()) {
        values.push_back(*node.value<double>());
      } else if (node.is_string()) {
        values = parse_number_list(*node.value<std::string>(), what);
      } else if (const toml::array* array = node.as_array(); array != nullptr && !array->empty()) {
        for (const toml::node& element : *array) {
          if (!element.is_number())
            throw wrong_type("a number, an array of numbers or a string such as \"1e5:1e7:10\"");
          values.push_back(*element.value<double>());
        }
      } else {
        throw wrong_type("a number, an array of numbers or a string such as \"1e5:1e7:10\"");
      }
      *std::get<std::optional<std::vector<double>>*>(spec.slot) = values;
      break;
    }
    case OptionKind::integer: {
      if (!node.is_integer()) throw wrong_type("an integer");
      *std::get<std::optional<long long>*>(spec.slot) = *node.value<long long>();
      break;
    }
    case OptionKind::text:
    case OptionKind::path: {
      if (!node.is_string()) throw wrong_type("a string");
      std::string text = *node.value<std::string>();
      const std::filesystem::path relative_to = file.parent_path();
      if (spec.kind == OptionKind::path && !text.empty() && std::filesystem::path(text).is_relative() &&
          !relative_to.empty()) {
        text = (relative_to / text).string();
      }
      *std::get<std::optional<std::string>*>(spec.slot) = text;
      break;
    }
    case OptionKind::dimensions:
    case OptionKind::memory: {
      // Read as text, as on the command line; a memory size is whole bytes.
      const bool memory = spec.kind == OptionKind::memory;
      std::string text;
      if (node.is_string()) {
        text = *node.value<std::string>();
      } else if (node.is_integer()) {
        text = fmt::format("{}", *node.value<long long>());
      } else if (node.is_floating_point() && !memory) {
        text = fmt::format("{}", *node.value<double>());  // shortest form that reads back exactly
      } else {
        throw wrong_type(memory ? "a string such as \"8G\" or a whole number of bytes"
                                : "a number or a string such as \"256x256\"");
      }
      *std::get<std::optional<std::string>*>(spec.slot) = text;
      break;
    }
    case OptionKind::flag: {
      if (!node.is_boolean()) throw wrong_type("true or false");
      *std::get<bool*>(spec.slot) = *node.value<bool>();
      break;
    }
  }
}

// "E_star" -> "E-star": the spellings people try first for a key that exists.
std::string unknown_key_message(std::string_view key, const std::filesystem::path& file,
                                std::span<const BoundOption> options, std::string_view command_name) {
  std::string message = fmt::format("unknown key '{}' in config file {}", key, file.string());
  if (key == "config") {
    return message + " (a config file cannot name another one)";
  }
  for (const BoundOption& spec : options) {
    if (spec.key.size() != key.size()) continue;
    bool similar = true;
    for (std::size_t k = 0; k < key.size() && similar; ++k) {
      const auto fold = [](char c) {
        c = c == '_' ? '-' : c;
        return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
      };
      similar = fold(key[k]) == fold(spec.key[k]);
    }
    if (similar) return message + fmt::format(" (did you mean '{}'?)", spec.key);
  }
  return message + fmt::format(" (the keys are the long option names of 'halfspace {}' without '--')", command_name);
}

constexpr std::size_t kMaxConfigBytes = std::size_t{1} << 20;

std::string read_text_file(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    throw FileError(fmt::format("config file {} does not exist", path.string()));
  }
  if (std::filesystem::is_directory(path, error)) {
    throw FileError(fmt::format("config file {} is a directory", path.string()));
  }
  // A config file holds a few options: read at most kMaxConfigBytes (plus
  // one to tell), so that /dev/zero or a huge file cannot exhaust memory.
  std::ifstream in(path, std::ios::binary);
  std::string text;
  std::array<char, 1 << 16> piece{};
  while (in && text.size() <= kMaxConfigBytes) {
    in.read(piece.data(), static_cast<std::streamsize>(piece.size()));
    text.append(piece.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad() || (!in.eof() && text.size() <= kMaxConfigBytes)) {
    throw FileError(fmt::format("config file {} cannot be read", path.string()));
  }
  if (text.size() > kMaxConfigBytes) {
    throw FileError(fmt::format("config file {} is larger than {} bytes (1 MiB); a config file holds a few options",
                                path.string(), kMaxConfigBytes));
  }
  return text;
}

}  // namespace

std::string GivenOptions::describe(std::string_view key) const {
  const auto found = text.find(key);
  const std::string_view value = found == text.end() ? std::string_view() : std::string_view(found->second);
  if (from_config.contains(key)) {
    return fmt::format("{} = {} in {}", key, value, config.value_or(""));
  }
  return fmt::format("--{} {}", key, value);
}

std::string GivenOptions::name(std::string_view key) const {
  if (from_config.contains(key)) {
    return fmt::format("{} (in {})", key, config.value_or(""));
  }
  return fmt::format("--{}", key);
}

std::string GivenSpelling::describe(std::string_view option, std::string_view value) const {
  const std::string flag = key(option);
  if (library_values_ && given_.from_config.contains(flag)) {
    return fmt::format("{} = {} in {}", flag, value, given_.config.value_or(""));
  }
  if (library_values_ || !given_.given(flag)) return fmt::format("--{} {}", flag, value);
  std::string written = given_.describe(flag);
  if (written.ends_with(' ')) written.pop_back();  // a flag, which has no value
  return written;
}

std::string GivenSpelling::key(std::string_view option) const {
  for (const std::string_view key : keys_) {
    const bool same = std::ranges::equal(key, option, [](char a, char b) {
      return std::tolower(static_cast<unsigned char>(a)) ==
             std::tolower(static_cast<unsigned char>(b == '_' ? '-' : b));
    });
    if (same) return std::string(key);
  }
  std::string flag(option);
  std::ranges::replace(flag, '_', '-');
  return flag;
}

void add_option(CLI::App& command, std::string_view key, OptionKind kind, std::string_view group,
                std::string_view value_name, std::string_view help) {
  const std::string flag = fmt::format("--{}", key);
  CLI::Option* option = kind == OptionKind::flag ? command.add_flag(flag) : command.add_option(flag);
  option->description(std::string(help));
  option->group(std::string(group));
  if (kind != OptionKind::flag) option->type_name(std::string(value_name));
}

void add_config_option(CLI::App& command, std::string_view example) {
  command.add_option("--config")
      ->type_name("FILE")
      ->description(fmt::format("TOML file of options: keys are the long option names without '--' (e.g. {}); options "
                                "given on the command line override it",
                                example));
}

void read_command_line(const CLI::App& command, const std::vector<std::string>& argv,
                       std::span<const BoundOption> options, GivenOptions& given) {
  given.command_line = join_command_line(argv);
  if (const CLI::Option* config = command.get_option_no_throw("--config"); config != nullptr && config->count() > 0) {
    given.config = config->as<std::string>();
  }
  for (const BoundOption& spec : options) {
    const CLI::Option* option = command.get_option(fmt::format("--{}", spec.key));
    if (option->count() == 0) continue;
    set_from_text(given, spec, spec.kind == OptionKind::flag ? std::string() : option->as<std::string>());
  }
}

void merge_config_file(std::span<const BoundOption> options, std::span<const AlternativeGroup> alternatives,
                       std::string_view command_name, GivenOptions& given) {
  if (!given.config) return;
  const std::filesystem::path file = *given.config;
  given.config_text = read_text_file(file);

  toml::table table;
  try {
    table = toml::parse(given.config_text, file.string());
  } catch (const toml::parse_error& error) {
    throw InputError(fmt::format("config file {} is not valid TOML: {} (line {}, column {})", file.string(),
                                 error.description(), error.source().begin.line, error.source().begin.column));
  }

  std::set<std::string, std::less<>> set_keys;
  for (const BoundOption& spec : options) {
    if (is_set(spec)) set_keys.emplace(spec.key);
  }
  for (auto&& [key, node] : table) {
    // A named copy: clang 14 (the fuzz build) cannot capture a structured binding.
    const std::string_view name = key.str();
    const auto spec =
        std::find_if(options.begin(), options.end(), [&](const BoundOption& option) { return option.key == name; });
    if (spec == options.end()) throw InputError(unknown_key_message(name, file, options, command_name));
    if (set_keys.contains(spec->key) || excluded_by(spec->key, set_keys, alternatives)) continue;
    set_from_toml(*spec, node, file);
    given.from_config.emplace(spec->key);
    given.text.insert_or_assign(std::string(spec->key), toml_text(node));
  }
}

}  // namespace halfspace::app
