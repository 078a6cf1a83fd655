// Help as docs/cli.md groups it, defaults that say what happens, the
// program's name in usage lines, and the man page and bash completion
// generated from the same command table.
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "tests/support/run_lattice.hpp"

namespace {

// Standard output of a shell command.
std::string capture(const std::string& command) {
  std::string out;
  if (std::FILE* pipe = ::popen(command.c_str(), "r")) {
    char buffer[4096];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
    ::pclose(pipe);
  }
  return out;
}

std::string help(const std::string& arguments) {
  return capture(fmt::format("'{}' {} --help", lattice::testing::latticeBinary().string(), arguments));
}

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The commands `lattice --help` lists (CLI11: "Subcommands:" then "  name  description").
std::vector<std::string> commands() {
  const std::string text = help("");
  std::vector<std::string> names;
  const std::size_t at = text.find("Subcommands:");
  std::istringstream lines(text.substr(at == std::string::npos ? text.size() : at));
  std::string line;
  std::getline(lines, line);
  while (std::getline(lines, line)) {
    std::smatch m;
    if (std::regex_search(line, m, std::regex("^  ([a-z0-9-]+)( |$)"))) names.push_back(m[1]);
  }
  return names;
}

// Long flags at the start of option lines (descriptions mention others).
std::set<std::string> flagsIn(const std::string& text, const std::regex& line) {
  std::set<std::string> flags;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), line); it != std::sregex_iterator(); ++it) {
    const std::string names = (*it)[1];
    const std::regex flag("--[a-z0-9][a-z0-9-]*");
    for (auto f = std::sregex_iterator(names.begin(), names.end(), flag); f != std::sregex_iterator(); ++f)
      flags.insert(f->str());
  }
  return flags;
}

// CLI11's option lines: indented, starting with the names ("-k,--colors", "--width").
const std::regex kHelpOptionLine(R"(\n\s+(-[^\s]+))");

}  // namespace

TEST_CASE("render --help is grouped as docs/cli.md groups it, with the program's name", "[cli]") {
  const std::string text = help("render");
  INFO(text);
  CHECK_THAT(text, Catch::Contains("lattice render [OPTIONS]"));
  CHECK_FALSE(Catch::Contains("/app/lattice").match(text));
  for (const char* group : {"Output:", "Picture:", "Lattices:", "Quantizer (devices):", "Memory:", "Serial line:", "Wire budget:",
                            "Report:"})
    CHECK_THAT(text, Catch::Contains(group));
  // --baud's default is the device profile's rate, as the render uses.
  CHECK_THAT(text, Catch::Contains("=the device profile's rate: tek4125 38400"));
  CHECK_THAT(help("send"), Catch::Contains("virtual:"));
}

TEST_CASE("the man page lists every command and flag --help does, and no other", "[cli]") {
  const std::filesystem::path page = std::filesystem::path(LATTICE_BINARY_DIR) / "app" / "lattice.1";
  REQUIRE(std::filesystem::exists(page));  // built with `lattice` (target lattice_man)
  std::string man = readFile(page);
  man = std::regex_replace(man, std::regex(R"(\\-)"), "-");
  std::set<std::string> fromHelp;
  const std::vector<std::string> names = commands();
  REQUIRE(names.size() >= 10);
  for (const std::string& name : names) {
    CHECK_THAT(man, Catch::Contains(fmt::format(".SS \"lattice {}\"", name)));
    std::string text = help(name);
    for (const std::string& flag : flagsIn(text, kHelpOptionLine)) fromHelp.insert(flag);
  }
  for (const std::string& flag : flagsIn(help("export pov"), kHelpOptionLine)) fromHelp.insert(flag);
  const std::set<std::string> fromMan = flagsIn(man, std::regex(R"(\n\.TP\n\\fB([^\n]*?)\\fR)"));
  CHECK(fromMan == fromHelp);
}

TEST_CASE("bash completion offers the commands, a command's flags and a flag's values", "[cli]") {
  const std::filesystem::path script = std::filesystem::path(LATTICE_BINARY_DIR) / "app" / "lattice.bash";
  REQUIRE(std::filesystem::exists(script));
  const auto complete = [&](const std::string& words, int current) {
    return capture(fmt::format("bash -c 'source \"{}\"; COMP_WORDS=({}); COMP_CWORD={}; _lattice; echo \"${{COMPREPLY[*]}}\"'",
                               script.string(), words, current));
  };
  CHECK(complete("lattice rend", 1) == "render\n");
  CHECK(complete("lattice render --wid", 2) == "--width\n");
  CHECK(complete("lattice emulate --ra", 2) == "--raw\n");
  // A flag's values, where its settings table names them.
  CHECK(complete("lattice render --lht-form c", 3) == "compressed\n");
  CHECK(complete("lattice render --dither ''", 3) == "none fs bayer\n");
  CHECK(complete("lattice send --parity o", 3) == "odd\n");
}
