#include "app/cli/help_export.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <map>
#include <vector>

#include "app/cli/cli_errors.hpp"

namespace lattice::app {
namespace {

// roff: a backslash starts an escape, a line starting with . or ' is a request.
std::string roff(const std::string& text) {
  std::string out;
  bool lineStart = true;
  for (char c : text) {
    if (c == '\\') {
      out += "\\e";
    } else if (c == '-') {
      out += "\\-";
    } else if (lineStart && (c == '.' || c == '\'')) {
      out += "\\&";
      out += c;
    } else {
      out += c;
    }
    lineStart = c == '\n';
  }
  return out;
}

std::vector<const CLI::App*> subcommandsOf(const CLI::App& app) {
  std::vector<const CLI::App*> subs;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) subs.push_back(sub);
  return subs;
}

std::string optionNames(const CLI::Option& option) {
  std::vector<std::string> names;
  for (const std::string& s : option.get_snames()) names.push_back("-" + s);
  for (const std::string& l : option.get_lnames()) names.push_back("--" + l);
  return fmt::format("{}", fmt::join(names, ", "));
}

void describeCommand(std::string& page, const CLI::App& command, const std::string& path) {
  std::vector<std::string> positionals;
  for (const CLI::Option* option : command.get_options())
    if (option->get_positional()) positionals.push_back(option->get_name());
  page += fmt::format(".SS \"{}\"\n", roff(path));
  page += fmt::format(".B {}\n[\\fIOPTIONS\\fR] {}\n.PP\n", roff(path), roff(fmt::format("{}", fmt::join(positionals, " "))));
  page += roff(command.get_description()) + "\n";
  // Options by help group, in the order the groups first appear (as --help lists them).
  std::vector<std::string> groups;
  std::map<std::string, std::vector<const CLI::Option*>> byGroup;
  for (const CLI::Option* option : command.get_options()) {
    if (option->get_positional() || option->get_group().empty()) continue;
    if (byGroup.find(option->get_group()) == byGroup.end()) groups.push_back(option->get_group());
    byGroup[option->get_group()].push_back(option);
  }
  for (const std::string& group : groups) {
    page += fmt::format(".PP\n\\fI{}:\\fR\n", roff(group));
    for (const CLI::Option* option : byGroup[group]) {
      std::string head = "\\fB" + roff(optionNames(*option)) + "\\fR";
      if (option->get_type_size() != 0 && !option->get_type_name().empty()) head += " \\fI" + roff(option->get_type_name()) + "\\fR";
      page += ".TP\n" + head + "\n" + roff(option->get_description());
      if (!option->get_default_str().empty()) page += " [default: " + roff(option->get_default_str()) + "]";
      page += "\n";
    }
  }
  if (!command.get_footer().empty()) page += ".PP\n.nf\n" + roff(command.get_footer()) + "\n.fi\n";
  for (const CLI::App* sub : subcommandsOf(command)) describeCommand(page, *sub, path + " " + sub->get_name());
}

// `case "$prev" in` arms completing the values of `command`'s flags that name them.
std::string valueArms(const CLI::App& command) {
  std::string arms;
  for (const CLI::Option* option : command.get_options()) {
    const std::vector<std::string> names = flagValueNames(*option);
    if (names.empty() || option->get_lnames().empty()) continue;
    arms += fmt::format("        --{}) values=\"{}\" ;;\n", option->get_lnames().front(), fmt::join(names, " "));
  }
  return arms;
}

}  // namespace

std::vector<std::string> flagValueNames(const CLI::Option& option) {
  const std::string type = option.get_type_name();
  const std::size_t open = type.find('{'), close = type.find('}', open);
  std::vector<std::string> names;
  if (open == std::string::npos || close == std::string::npos) return names;
  std::string name;
  for (char c : type.substr(open + 1, close - open - 1)) {
    if (c == ',') {
      names.push_back(name);
      name.clear();
    } else {
      name += c;
    }
  }
  names.push_back(name);
  return names;
}

std::string manPage(const CLI::App& root, const std::string& version) {
  std::string page = fmt::format(".TH LATTICE 1 \"\" \"lattice {}\" \"User Commands\"\n", roff(version));
  page += ".SH NAME\nlattice \\- three\\-dimensional texturing using lattices, rendered for PNG and Tektronix terminals\n";
  page += ".SH SYNOPSIS\n.B lattice\n\\fICOMMAND\\fR [\\fIOPTIONS\\fR]\n.br\n.B lattice\n\\fICOMMAND\\fR \\-\\-help\n";
  page += ".SH DESCRIPTION\n" + roff(root.get_description()) + "\n";
  page += ".SH COMMANDS\n";
  for (const CLI::App* sub : subcommandsOf(root)) describeCommand(page, *sub, "lattice " + sub->get_name());
  page +=
      ".SH EXIT STATUS\n"
      ".TP\n0\nsuccess\n.TP\n2\nusage: a bad flag, value or combination\n"
      ".TP\n3\ninput: a file that cannot be used\n.TP\n4\noutput: a file that cannot be written\n"
      ".TP\n5\nserial: the port cannot be opened or configured\n.TP\n6\nstalled (the message gives the \\-\\-resume offset)\n"
      ".TP\n7\nhang\\-up (the message gives the \\-\\-resume offset)\n.TP\n8\n\\-\\-memory\\-budget cannot be met\n"
      ".TP\n70\ninternal error\n"
      ".SH SEE ALSO\nThe project's docs/cli.md and the documents it links.\n";
  return page;
}

std::string bashCompletion(const CLI::App& root) {
  std::string script =
      "# bash completion for lattice, generated from its command table (lattice --generate-bash-completion)\n"
      "_lattice() {\n"
      "  local cur=\"${COMP_WORDS[COMP_CWORD]}\" prev=\"${COMP_WORDS[COMP_CWORD - 1]}\" command=\"\" i\n"
      "  for ((i = 1; i < COMP_CWORD; i++)); do\n"
      "    case \"${COMP_WORDS[i]}\" in -*) ;; *) command=\"${command:+$command }${COMP_WORDS[i]}\"; break ;; esac\n"
      "  done\n"
      "  local words values=\"\"\n"
      "  case \"$command\" in\n";
  std::vector<std::string> rootWords = commandNames(root);
  for (const std::string& flag : flagNames(root)) rootWords.push_back(flag);
  script += fmt::format("    \"\") words=\"{}\" ;;\n", fmt::join(rootWords, " "));
  for (const CLI::App* sub : subcommandsOf(root)) {
    std::vector<std::string> words = commandNames(*sub);
    for (const std::string& flag : flagNames(*sub)) words.push_back(flag);
    const std::string arms = valueArms(*sub);
    script += fmt::format("    {}) words=\"{}\"\n", sub->get_name(), fmt::join(words, " "));
    if (!arms.empty()) script += "      case \"$prev\" in\n" + arms + "      esac\n";
    script += "      ;;\n";
  }
  script +=
      "  esac\n"
      "  if [[ -n \"$values\" ]]; then\n"
      "    COMPREPLY=($(compgen -W \"$values\" -- \"$cur\"))\n"
      "  elif [[ -z \"$command\" || \"$cur\" == -* ]]; then\n"
      "    COMPREPLY=($(compgen -W \"$words\" -- \"$cur\"))\n"
      "  else\n"
      "    COMPREPLY=($(compgen -f -- \"$cur\"))\n"
      "  fi\n"
      "}\n"
      "complete -o filenames -F _lattice lattice\n";
  return script;
}

}  // namespace lattice::app
