// Every numeric flag of every command, read from the command table itself,
// declares its range and refuses NaN, infinities and overflow through the
// one number parser (app/cli/number_flags.hpp): a flag added later is
// covered without being listed here.
#include <catch2/catch.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/cli/number_flags.hpp"
#include "app/commands/run_lattice.hpp"
#include "tests/support/run_lattice.hpp"

namespace {

struct NumericFlag {
  std::vector<std::string> command;  // "export", "pov"
  std::string flag;                  // "--width"
};

// The flags whose type name is one of `types` ("INT", "SIZE"), below `app`.
void collectTyped(CLI::App& app, std::vector<std::string> path, std::vector<NumericFlag>& out,
                  const std::vector<std::string>& types) {
  for (CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    std::vector<std::string> here = path;
    here.push_back(sub->get_name());
    collectTyped(*sub, here, out, types);
    for (const CLI::Option* option : sub->get_options()) {
      const std::string type = option->get_type_name();
      const std::string base = type.substr(0, type.find(':'));
      if (std::find(types.begin(), types.end(), base) != types.end() && !option->get_lnames().empty())
        out.push_back({here, "--" + option->get_lnames().front()});
    }
  }
}

void collect(CLI::App& app, std::vector<std::string> path, std::vector<NumericFlag>& out) {
  collectTyped(app, std::move(path), out, {"INT", "UINT", "FLOAT"});
}

// What parsing `flag value` under `command` says (empty: taken).
std::string refusalOf(const NumericFlag& f, const std::string& value) {
  std::vector<std::string> argv = {"lattice"};
  argv.insert(argv.end(), f.command.begin(), f.command.end());
  argv.push_back(f.flag);
  argv.push_back(value);
  std::vector<char*> raw;
  for (std::string& a : argv) raw.push_back(a.data());
  CLI::App tree;
  lattice::app::buildCommandTree(tree);
  try {
    tree.parse(static_cast<int>(raw.size()), raw.data());
  } catch (const CLI::ValidationError& e) {
    return e.what();
  } catch (const CLI::RequiredError&) {
    return {};  // the value was taken; the command's positionals were not given
  } catch (const CLI::ParseError& e) {
    return e.get_exit_code() == 0 ? std::string() : std::string("other parse error: ") + e.what();
  } catch (const std::exception& e) {
    return std::string("other error: ") + e.what();
  }
  return {};
}

}  // namespace

TEST_CASE("every numeric flag declares its range", "[cli][numbers]") {
  CLI::App root;
  lattice::app::buildCommandTree(root);
  // guardNumbers gives a flag without one its type's range as a backstop;
  // each flag should say its own, which its --help then shows.
  for (const std::string& name : lattice::app::numericOptionsWithoutRange(root)) FAIL_CHECK(name << " has no range");
}

TEST_CASE("every numeric flag refuses NaN, infinities and overflow with its name, exit 2", "[cli][numbers]") {
  CLI::App root;
  lattice::app::buildCommandTree(root);
  std::vector<NumericFlag> flags;
  collect(root, {}, flags);
  REQUIRE(flags.size() >= 20);  // the table has about thirty; an empty walk would prove nothing
  for (const NumericFlag& f : flags) {
    for (const char* value : {"nan", "inf", "-inf", "1e999"}) {
      const std::string message = refusalOf(f, value);
      INFO(f.command.back() << " " << f.flag << " " << value << ": " << message);
      CHECK_THAT(message, Catch::StartsWith(f.flag) && Catch::Contains("not a") && Catch::Contains(value));
    }
  }
}

TEST_CASE("every size flag refuses NaN, zero, negatives and unknown units with its name, and takes sizes",
          "[cli][numbers]") {
  CLI::App root;
  lattice::app::buildCommandTree(root);
  std::vector<NumericFlag> flags;
  collectTyped(root, {}, flags, {"SIZE"});
  REQUIRE(flags.size() >= 2);  // render --lht-cache and --wire-bytes at least
  for (const NumericFlag& f : flags) {
    for (const char* value : {"nan", "inf", "0", "-1", "12Q", "1e999"}) {
      const std::string message = refusalOf(f, value);
      INFO(f.command.back() << " " << f.flag << " " << value << ": " << message);
      CHECK_THAT(message, Catch::StartsWith(f.flag) && Catch::Contains("give a size in bytes"));
    }
    for (const char* value : {"57600", "56K", "8MiB"}) {
      INFO(f.command.back() << " " << f.flag << " " << value);
      CHECK(refusalOf(f, value).empty());
    }
  }
}

TEST_CASE("the refusal reaches the user as one lattice: error line and exit 2", "[cli][numbers]") {
  const auto run = lattice::testing::runLattice("render scenes/torus-floor.toml --device tek4125 --wire-seconds nan");
  CHECK(run.exitCode == 2);
  CHECK_THAT(run.stderrText, Catch::StartsWith("lattice: error: render: --wire-seconds: 'nan' is not a finite number; "
                                                "give a number from 0.001 to 1000000000"));
  const auto set = lattice::testing::runLattice("render scenes/torus-floor.toml --device tek4125 --set width=nan");
  CHECK(set.exitCode == 2);
  CHECK_THAT(set.stderrText, Catch::Contains("width: 'nan' is not a finite number"));
  // An integer flag takes digits: 1e1 is refused by the number parser with the range, not by CLI11's conversion.
  const auto whole = lattice::testing::runLattice("render scenes/torus-floor.toml --width 1e1");
  CHECK(whole.exitCode == 2);
  CHECK_THAT(whole.stderrText, Catch::Contains("--width: '1e1' is not a whole number in digits; give a whole number from 1 to 16384"));
}
