#include "app/cli/number_flags.hpp"

#include <CLI/CLI.hpp>

#include <limits>

namespace lattice::app {
namespace {

constexpr const char* kCheckName = "lattice-number";
constexpr const char* kBackstopName = "lattice-number-by-type";  // what guardNumbers adds

// CLI11's name of the option's C++ type ("INT", "UINT", "FLOAT"), before any
// validator's description it appends after a ':'.
std::string baseType(const CLI::Option& option) {
  const std::string full = option.get_type_name();
  return full.substr(0, full.find(':'));
}

bool hasCheck(CLI::Option& option, const char* name) {
  try {
    return option.get_validator(name) != nullptr;
  } catch (const CLI::OptionNotFound&) {
    return false;
  }
}

template <class Visit>
void forEachNumericOption(CLI::App& app, const std::string& path, Visit&& visit) {
  for (CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
    const std::string name = path.empty() ? command->get_name() : path + " " + command->get_name();
    forEachNumericOption(*command, name, visit);
    for (CLI::Option* option : command->get_options()) {
      const std::string type = baseType(*option);
      if (type == "INT" || type == "UINT" || type == "FLOAT") visit(name, *option, type);
    }
  }
}

}  // namespace

CLI::Validator numberIn(NumberRange range) {
  // The description is what --help shows after the type: "INT in 1 to 16384".
  return CLI::Validator([range](std::string& text) { return numberTextProblem(text, range); }, describeRange(range),
                        kCheckName);
}

CLI::Validator numberIn(NumberRange range, const std::string& word) {
  return CLI::Validator(
      [range, word](std::string& text) { return text == word ? std::string() : numberTextProblem(text, range); },
      describeRange(range) + ", or " + word, kCheckName);
}

void guardNumbers(CLI::App& root) {
  forEachNumericOption(root, "", [](const std::string&, CLI::Option& option, const std::string& type) {
    if (hasCheck(option, kCheckName)) return;
    // 2^63 and 2^64 are the widest integers an option holds; CLI11's own
    // conversion refuses what overflows a narrower one.
    const NumberRange range = type == "INT" ? NumberRange{-9.2e18, 9.2e18, true}
                              : type == "UINT" ? NumberRange{0, 1.8e19, true}
                                               : NumberRange{};
    option.check(numberIn(range).name(kBackstopName));
  });
}

std::vector<std::string> numericOptionsWithoutRange(CLI::App& root) {
  std::vector<std::string> missing;
  forEachNumericOption(root, "", [&](const std::string& command, CLI::Option& option, const std::string&) {
    if (!hasCheck(option, kCheckName)) missing.push_back(command + " " + option.get_name());
  });
  return missing;
}

}  // namespace lattice::app
