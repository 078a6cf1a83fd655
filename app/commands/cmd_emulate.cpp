// `lattice emulate --device tek4125 IN.tek -o OUT.png`: decodes a command
// stream the way the terminal would draw it and writes the screen as PNG.
// Streams from other programs (gnuplot's tek410x terminal, PGPLOT) work too;
// whatever the emulator does not know is skipped and counted (--report).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "app/commands/commands.hpp"
#include "app/stream_check.hpp"
#include "app/stream_points.hpp"
#include "devices/device_table.hpp"
#include "devices/work_budget.hpp"
#include "io/png.hpp"
#include "foundation/error.hpp"

namespace {

struct EmulateOptions {
  std::string device;
  std::string input;
  std::string output;
  std::vector<std::string> settings;
  bool report = false;
  bool strict = false;
  bool raw = false;
  std::string at;  // --at: screens part-way (app/stream_points.hpp)
};

void runEmulate(const EmulateOptions& o, bool force) {
  using lattice::Error;
  using lattice::ErrorKind;
  // The --at items and the files they name are checked before anything is read.
  if (!o.at.empty()) lattice::app::checkStreamPointOutputs(o.at, o.output, force);
  const lattice::devices::Device device = lattice::devices::makeDevice(o.device, o.settings);
  std::unique_ptr<lattice::StreamDecoder> decoder = device.makeEmulator();
  // Refuses a PNG, a scene, an empty file... before it becomes a picture of noise.
  if (!o.raw) decoder = std::make_unique<lattice::app::CheckedDecoder>(std::move(decoder), device, o.input);
  // Read in pieces (a stream may be large, and the decoder takes any
  // chunking), within the stream-size limit and the drawing budget.
  std::FILE* in = o.input == "-" ? stdin : std::fopen(o.input.c_str(), "rb");
  if (!in) throw Error(ErrorKind::Input, fmt::format("{}: cannot open the stream: {}", o.input, std::strerror(errno)));
  try {
    if (o.at.empty()) lattice::decodeStream(*decoder, in, o.input);
    else
      for (const std::string& path : lattice::app::decodeWithSnapshots(*decoder, in, o.input, o.at, o.output))
        fmt::print(stderr, "lattice emulate: wrote {}\n", path);
  } catch (...) {
    if (in != stdin) std::fclose(in);
    throw;
  }
  if (in != stdin) std::fclose(in);
  lattice::io::writePng(o.output, decoder->image());
  const lattice::DecodeReport& report = decoder->report();
  if (o.report) fmt::print("{}", report.summary());
  if (report.unknownCommands + report.malformed > 0) {
    fmt::print(stderr, "lattice emulate: {}: skipped {} unknown and {} malformed commands{}\n", o.input,
               report.unknownCommands, report.malformed, o.report ? "" : " (--report lists them)");
    if (o.strict)
      throw Error(ErrorKind::Input,
                  fmt::format("{}: the stream is not clean {} input (--strict)", o.input, device.title));
  }
}

}  // namespace

namespace lattice::app {

void addEmulate(CLI::App& root) {
  auto o = std::make_shared<EmulateOptions>();
  auto* cmd = root.add_subcommand("emulate", "Decode a device's command stream into the PNG its screen would show");
  cmd->add_option("--device", o->device, "The device whose stream it is: tek4125 (4100-series commands), tek4027 (!-commands), tek4014 (4010/4014 graphics) or apollo (GPR journal)")
      ->required()
      ->check(CLI::IsMember(lattice::devices::deviceNames()));
  cmd->add_option("stream", o->input, "Command stream file, or - for standard input")->required();
  cmd->add_option("-o,--output", o->output, "PNG of the screen to write (atomically)")->required();
  cmd->add_option("--set", o->settings, "Override a profile assumption, key=value (repeatable), e.g. --set planes=4");
  cmd->add_flag("--report", o->report, "Print what was decoded: bytes, commands, unknown commands by name");
  cmd->add_flag("--strict", o->strict, "Exit 3 if the stream holds unknown or malformed commands");
  cmd->add_flag("--raw", o->raw,
                "Decode the bytes even if they do not look like the device's stream (without it, a PNG, a scene, "
                "an empty file or another device's stream is refused with exit 3)");
  cmd->add_option("--at", o->at,
                  "Also write the screen part-way, at percentages of the stream or byte offsets (10%,25%,50% or "
                  "4096,20000), at most 32: OUT-at25pct.png, OUT-at4096B.png beside OUT.png, written with OUT.png "
                  "only if the whole command succeeds");
  cmd->footer(
      "The stream is checked first: a file that does not look like the device's stream (a PNG, a scene, an\n"
      "empty file, another device's stream) is refused with exit 3 saying what it is; --raw decodes it anyway.\n"
      "The emulator never stops on bad bytes: unknown commands and garbage are skipped (resynchronising at the\n"
      "next command) and counted. Streams over 256 MiB, or asking for more than 2^30 pixels of drawing, are\n"
      "refused with exit 3 (docs/limits.md). Example:\n"
      "  lattice emulate --device tek4125 fuzzy.tek -o fuzzy.png --report");
  // --force is added to every command with outputs (app/output_check.hpp) after this runs.
  cmd->callback([o, cmd] { runEmulate(*o, cmd->count("--force") > 0); });
}

}  // namespace lattice::app
