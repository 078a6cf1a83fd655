// The command-line fuzzing entry (entries.hpp: commandLine): `lattice` run
// in-process, as main() runs it (app/commands/run_lattice.hpp), on an argv
// built from the fuzz input and the command table itself.
//
// Method and tunables:
// * The command tree is built once (buildCommandTree) and read for every
//   command, nested ones too, and each command's flags; the devices' --set
//   keys and their choices are read from the device table's settings tables
//   (foundation/settings_schema.hpp). Nothing here lists a command, a flag or
//   a key, so one added later is fuzzed the day it lands.
// * Input bytes are a program: byte 0 picks the command; then each byte
//   picks a flag of it, and the flag's value comes from the next bytes: a
//   number from the number pool for numeric flags (in-range values kept
//   small so a legal render or rasterization stays cheap, and every kind of
//   number the parser must refuse), one of the names a flag's check lists
//   (its settings table's choices and unset word), or for others a pool word, a scratch
//   file, a `--set` key=value, or up to 12 raw bytes of the input. A 0xFF
//   byte ends the argv; the bytes after it are the input file (@in).
// * Files: a scratch directory per process holds @in (the input's tail), a
//   small valid scene and small 4125 and 4014 streams; each run has it as
//   its working directory, so outputs named by a bare word go there too, and
//   everything but the inputs is removed after each run.
// * Work that is legitimately long is kept out, so a timeout means a hang:
//   a scene argument is always the small scene (a scene of the input's bytes
//   could ask for a 16384-pixel side or a fine lattice; the scene reader is
//   fuzzed by its own target), table1 runs its short form, and a render
//   with a wire budget is given the scene's size (no size search).
// * Flags that wait on the outside world are not given: `ports --wait`
//   (waits for a person to plug in an adapter), and a --port other than the
//   virtual terminals or a missing path; --baud is left at its default so
//   pacing a few hundred bytes takes milliseconds (`term --stream` plays the
//   input at the device's rate: 512 bytes in well under a second).
// * The answer is an exit code; Error and CLI11's errors are the expected
//   answers to bad input. A crash, a sanitizer report, an uncaught exception
//   or a hang (libFuzzer's -timeout) is a finding.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/cli/help_export.hpp"
#include "app/commands/run_lattice.hpp"
#include "devices/device_table.hpp"
#include "foundation/error.hpp"
#include "foundation/settings_schema.hpp"
#include "fuzz/entries.hpp"

namespace lattice::fuzz {
namespace {

struct Command {
  std::vector<std::string> words;  // "export", "pov"
  struct Flag {
    std::string name;  // "--width"
    bool numeric = false;
    bool takesValue = true;
    std::vector<std::string> values;  // the names it takes, where its check lists them
  };
  std::vector<Flag> flags;
  std::vector<std::string> positionals;  // how many positional words it takes, named
};

struct Table {
  std::vector<Command> commands;
  std::vector<std::string> setItems;  // "planes=4", "width=nan", ...
  std::filesystem::path dir;
};

const char* const kNumbers[] = {"0", "1", "2", "3", "0.5", "-1", "-0", "nan", "NaN", "inf", "-inf", "1e999",
                                "1e300", "-1e300", "99999999999", "1e3", "1.5", "", "x", "0x10", "+1", "50%"};
const char* const kWords[] = {"-", "", "auto", "virtual:tek4125", "virtual:tek4014", "/nonexistent/port",
                              "8MiB", "1G", "1.5M", "nan", "0", "10%,50%", "0%,100%", "4096,2", "nan%", "1e300",
                              "thesis", "compact", "on-demand", "compressed", "fs", "bayer", "median", "variance",
                              "sample", "frame", "passes", "small", "full", "double", "float", "fixed", "tek4125",
                              "tek4027", "tek4014", "sixel", "apollo", "png", "sphere", "capsule", "16x16", "0x0"};

void collect(CLI::App& app, std::vector<std::string> path, std::vector<Command>& out) {
  for (CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    std::vector<std::string> here = path;
    here.push_back(sub->get_name());
    Command command{here, {}, {}};
    for (const CLI::Option* option : sub->get_options()) {
      if (option->get_lnames().empty() && option->get_snames().empty()) {
        command.positionals.push_back(option->get_name());
        continue;
      }
      const std::string name = option->get_lnames().empty() ? "-" + option->get_snames().front()
                                                            : "--" + option->get_lnames().front();
      if (name == "--help" || name == "--wait" || name == "--baud") continue;
      const std::string type = option->get_type_name();
      const std::string base = type.substr(0, type.find(':'));
      command.flags.push_back({name, base == "INT" || base == "UINT" || base == "FLOAT", option->get_expected_max() > 0,
                               app::flagValueNames(*option)});
    }
    if (sub->get_subcommands([](const CLI::App*) { return true; }).empty()) out.push_back(command);
    collect(*sub, here, out);
  }
}

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

Table buildTable() {
  Table t;
  CLI::App root;
  app::buildCommandTree(root);
  collect(root, {}, t.commands);
  // Each device's keys from its settings table: its choices, its range's
  // ends and the values every number must refuse.
  for (const devices::DeviceEntry& entry : devices::deviceTable())
    for (const SettingInfo& setting : entry.settings()) {
      const std::string key(setting.key);
      for (const std::string_view choice : setting.choices) t.setItems.push_back(key + "=" + std::string(choice));
      for (const char* value : {"0", "1", "4", "nan", "inf", "-1", "99999999999", "on", "x"})
        t.setItems.push_back(key + "=" + value);
    }
  t.setItems.push_back("no-equals");
  t.dir = std::filesystem::temp_directory_path() / ("lattice-fuzz-cli-" + std::to_string(::getpid()));
  std::filesystem::create_directories(t.dir);
  write(t.dir / "scene.toml",
        "[options]\nwidth = 12\nheight = 10\n"
        "[camera]\ntype = \"look_at\"\neye = [0.0, 2.6, -5.0]\ntarget = [0.0, 0.0, 0.0]\nfov = 38\n"
        "[[lights]]\nposition = [3.0, 6.0, -3.0]\nintensity = 7.5\n"
        "[[objects]]\ntype = \"torus\"\nmajor = 1.0\nminor = 0.35\n"
        "[[objects]]\ntype = \"half_space\"\nnormal = [0.0, 1.0, 0.0]\noffset = -0.6\n");
  // Full-screen 4125 fill, a 4014 vector: one command each.
  write(t.dir / "fill.tek", std::string("\x1bRR") + "  `  " + std::string("\x3f\x7f\x7f\x3f\x7f") + "1");
  write(t.dir / "vec.t14", std::string("\x1d") + "  `  " + "?\x7f?\x7f?" + "\x1f");
  return t;
}

// Bytes as the program the header describes.
class Reader {
 public:
  explicit Reader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  bool done() const { return at_ >= end_; }
  std::uint8_t next() { return done() ? 0 : bytes_[at_++]; }
  void setEnd(std::size_t end) { end_ = end; }
  std::string raw() {
    const std::size_t length = std::min<std::size_t>(next() % 13, end_ - std::min(at_, end_));
    std::string text(reinterpret_cast<const char*>(bytes_.data() + at_), length);
    at_ += length;
    text.erase(std::remove(text.begin(), text.end(), '\0'), text.end());
    return text;
  }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t at_ = 0, end_ = 0;
};

}  // namespace

void commandLine(std::span<const std::uint8_t> bytes) {
  static const Table table = buildTable();
  if (bytes.empty() || table.commands.empty()) return;
  const auto marker = std::find(bytes.begin(), bytes.end(), std::uint8_t{0xFF});
  const std::size_t programEnd = static_cast<std::size_t>(marker - bytes.begin());
  write(table.dir / "in", std::string(marker == bytes.end() ? marker : marker + 1, bytes.end()));
  const std::string files[] = {(table.dir / "in").string(), (table.dir / "scene.toml").string(),
                               (table.dir / "fill.tek").string(), (table.dir / "vec.t14").string(),
                               (table.dir / "out.png").string(), (table.dir / "out.tek").string(),
                               table.dir.string()};
  Reader in(bytes);
  in.setEnd(programEnd);
  const Command& command = table.commands[in.next() % table.commands.size()];
  std::vector<std::string> argv = {"lattice"};
  argv.insert(argv.end(), command.words.begin(), command.words.end());
  // Positionals first (most commands need one to do anything): scratch files.
  // A scene is always the small one: a scene from the input bytes could ask
  // for legitimately hours of work (a 16384-pixel side, a fine lattice), which
  // libFuzzer would report as a hang; the scene reader has its own target.
  // term's program is a scratch file, never executable: a fuzzer must not run
  // what its bytes name, and exec's refusal is the answer checked.
  for (const std::string& positional : command.positionals)
    argv.push_back(positional == "scene" ? files[1] : files[in.next() % std::size(files)]);
  while (!in.done() && !command.flags.empty() && argv.size() < 48) {
    const Command::Flag& flag = command.flags[in.next() % command.flags.size()];
    argv.push_back(flag.name);
    if (!flag.takesValue) continue;
    const std::uint8_t how = in.next();
    if (flag.numeric) argv.push_back(kNumbers[how % std::size(kNumbers)]);
    else if (flag.name == "--set") argv.push_back(table.setItems[(how * 256u + in.next()) % table.setItems.size()]);
    else if (flag.name == "--port") argv.push_back(how % 2 ? "virtual:tek4125" : "/nonexistent/port");
    else if (flag.name == "--scene") argv.push_back(files[1]);
    else if (!flag.values.empty() && how < 64) argv.push_back(flag.values[how % flag.values.size()]);
    else if (how < 96) argv.push_back(kWords[how % std::size(kWords)]);
    else if (how < 160) argv.push_back(files[how % std::size(files)]);
    else argv.push_back(in.raw());
  }
  // table1 recomputes the thesis's Table 1, seconds of fixed work whatever
  // the input: its short form keeps a run well inside libFuzzer's timeout.
  if (command.words.front() == "table1" && std::find(argv.begin(), argv.end(), "--quick") == argv.end())
    argv.push_back("--quick");
  // A wire budget with no size searches picture sizes up to the device's
  // whole screen, each rendered and searched: seconds of legitimate work
  // under the sanitizers. Given the small scene's own size, the search is
  // the fixed-size one.
  const auto given = [&](const char* flag) { return std::find(argv.begin(), argv.end(), flag) != argv.end(); };
  if (command.words.front() == "render" && (given("--wire-seconds") || given("--wire-bytes")) && !given("--width") &&
      !given("--height"))
    argv.insert(argv.end(), {"--width", "12", "--height", "10"});
  // `term --stream` plays at the device's rate, which a `--set baud=1` makes
  // hours for a few hundred bytes: played unpaced, it decodes the same bytes.
  if (command.words.front() == "term" && std::find(argv.begin(), argv.end(), "--stream") != argv.end())
    argv.push_back("--unpaced");
  std::vector<char*> raw;
  for (std::string& word : argv) raw.push_back(word.data());
  // LATTICE_FUZZ_SHOW_ARGV=1 prints the command line an input becomes: how a
  // finding is turned into a command a person can run.
  if (std::getenv("LATTICE_FUZZ_SHOW_ARGV") != nullptr) {
    for (const std::string& word : argv) std::fprintf(stderr, "'%s' ", word.c_str());
    std::fprintf(stderr, "\n");
  }
  // A pool word given as an output path ("auto", "-o variance") is a file
  // in the working directory: run in the scratch directory so it goes there.
  std::error_code ignored;
  const std::filesystem::path before = std::filesystem::current_path(ignored);
  std::filesystem::current_path(table.dir, ignored);
  (void)app::runLattice(static_cast<int>(raw.size()), raw.data());
  std::filesystem::current_path(before, ignored);
  // Outputs of this run go; the fixed inputs stay.
  for (const auto& entry : std::filesystem::directory_iterator(table.dir, ignored)) {
    const std::string name = entry.path().filename().string();
    if (name != "in" && name != "scene.toml" && name != "fill.tek" && name != "vec.t14")
      std::filesystem::remove_all(entry.path(), ignored);
  }
}

}  // namespace lattice::fuzz
