#include "app/cli/cli_errors.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdlib>
#include <optional>

#include "app/cli/did_you_mean.hpp"

namespace lattice::app {
namespace {

// "--widht=100" -> "--widht"; "-o" stays.
std::string flagPart(const std::string& argument) { return argument.substr(0, argument.find('=')); }

bool looksLikeNumber(const std::string& argument) {
  char* end = nullptr;
  std::strtod(argument.c_str(), &end);
  return end != argument.c_str() && *end == '\0';
}

bool isFlag(const std::string& argument) {
  return argument.size() > 1 && argument[0] == '-' && !looksLikeNumber(argument);
}

// Flags that were removed, and what to write instead (docs/cli.md, "Removed flags and formats").
struct RemovedFlag {
  const char* flag;
  const char* instead;
};
constexpr RemovedFlag kRemovedFlags[] = {
    {"--apollo-profile", "--set profile=P (with --device apollo)"},
    {"--split", "`lattice quantize --split` to compare palettes (render uses the median cut)"},
    {"--refine", "`lattice quantize --refine` to compare palettes (render refines nothing)"},
};

std::string suggestion(const std::string& typed, const std::vector<std::string>& names) {
  const std::optional<std::string> nearest = nearestName(typed, names);
  return nearest ? fmt::format("did you mean '{}'? ", *nearest) : std::string();
}

// CLI11 messages start with a capital and name the option loosely; keep
// their content but in our lower-case, one-line form.
std::string tidy(std::string message) {
  for (char& c : message)
    if (c == '\n') c = ' ';
  while (!message.empty() && (message.back() == ' ' || message.back() == '.')) message.pop_back();
  if (!message.empty() && message[0] >= 'A' && message[0] <= 'Z' && (message.size() < 2 || message[1] < 'A' || message[1] > 'Z'))
    message[0] = static_cast<char>(message[0] - 'A' + 'a');
  return message;
}

}  // namespace

std::vector<std::string> commandNames(const CLI::App& root) {
  std::vector<std::string> names;
  for (const CLI::App* sub : root.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
  return names;
}

std::vector<std::string> flagNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
  }
  return names;
}

std::string describeParseError(const CLI::App& root, const CLI::ParseError& error,
                               const std::vector<std::string>& arguments) {
  const std::vector<std::string> commands = commandNames(root);
  const std::string commandList = fmt::format("{}", fmt::join(commands, ", "));
  // The command is the first word that is not a flag (the root has no
  // options taking values besides --help and --version).
  std::size_t at = 0;
  while (at < arguments.size() && isFlag(arguments[at])) ++at;
  if (at == arguments.size()) {
    for (const std::string& argument : arguments)
      if (root.get_option_no_throw(flagPart(argument)) == nullptr)
        return fmt::format("unknown flag '{}'; {}give a command first: {} (`lattice --help` describes them)",
                           argument, suggestion(flagPart(argument), flagNames(root)), commandList);
    return fmt::format("give a command: {} (`lattice --help` describes them, `lattice COMMAND --help` their flags)",
                       commandList);
  }
  const std::string& word = arguments[at];
  const CLI::App* command = nullptr;
  for (const CLI::App* sub : root.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->check_name(word)) command = sub;
  if (command == nullptr)
    return fmt::format("unknown command '{}'; {}the commands are {} (`lattice --help` describes them)", word,
                       suggestion(word, commands), commandList);
  // A nested command (`export pov`) owns the flags after its name.
  std::string path = command->get_name();
  for (bool deeper = true; deeper && at + 1 < arguments.size() && !isFlag(arguments[at + 1]);) {
    deeper = false;
    for (const CLI::App* sub : command->get_subcommands([](const CLI::App*) { return true; }))
      if (sub->check_name(arguments[at + 1])) {
        command = sub;
        path += " " + sub->get_name();
        ++at;
        deeper = true;
        break;
      }
  }
  const std::string help = fmt::format("`lattice {} --help` lists its flags", path);
  const std::vector<std::string> flags = flagNames(*command);
  bool flagsEnded = false;
  for (std::size_t i = at + 1; i < arguments.size(); ++i) {
    const std::string& argument = arguments[i];
    if (argument == "--") flagsEnded = true;
    if (flagsEnded || !isFlag(argument)) continue;
    const std::string flag = flagPart(argument);
    // Short flags may be bundled (-qk 16); only whole unknown names are judged.
    if (flag.rfind("--", 0) != 0 && flag.size() > 2) continue;
    if (command->get_option_no_throw(flag) != nullptr) continue;
    for (const RemovedFlag& removed : kRemovedFlags)
      if (flag == removed.flag) return fmt::format("{}: {} was removed; write {} instead", path, flag, removed.instead);
    return fmt::format("{}: unknown flag '{}'; {}{}", path, flag, suggestion(flag, flags), help);
  }
  return fmt::format("{}: {}; {}", path, tidy(error.what()), help);
}

}  // namespace lattice::app
