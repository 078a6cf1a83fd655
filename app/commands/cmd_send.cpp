// `lattice send STREAM --port ...`: play a stored command stream to a
// terminal over a serial line, resumably. See docs/serial.md.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/commands/commands.hpp"
#include "app/cli/number_flags.hpp"
#include "app/output_check.hpp"
#include "app/cli/serial_args.hpp"
#include "app/virtual_terminal.hpp"
#include "devices/device_table.hpp"
#include "devices/work_budget.hpp"
#include "foundation/system/atomic_file.hpp"
#include "io/png.hpp"
#include "io/serial_sink.hpp"
#include "io/stream_sender.hpp"
#include "foundation/error.hpp"
#include "foundation/progress.hpp"

namespace {

struct SendArgs {
  std::string stream;
  std::string device;                 // empty: send without waiting for answers
  std::vector<std::string> settings;  // the device profile's --set overrides
  lattice::io::SerialOptions serial;
  std::uint64_t resume = 0;
  std::string screen;  // with a virtual terminal: the PNG of what it drew
};

constexpr std::string_view kVirtualPrefix = "virtual:";

// The flags a resumed send must repeat besides the line's.
std::vector<std::string> deviceFlags(const SendArgs& args) {
  std::vector<std::string> flags;
  if (args.device.empty()) return flags;
  flags = {"--device", args.device};
  for (const std::string& setting : args.settings) {
    flags.push_back("--set");
    flags.push_back(setting);
  }
  return flags;
}

void runSend(SendArgs args, const CLI::App& cmd) {
  // `--port virtual:DEVICE`: the device's emulator on the far side of a pty.
  std::unique_ptr<lattice::app::VirtualTerminal> terminal;
  const bool virtualPort = args.serial.port.rfind(kVirtualPrefix, 0) == 0;
  if (!virtualPort && cmd.count("--output") > 0)
    throw lattice::Error(lattice::ErrorKind::Usage,
                         "-o writes the screen of a virtual terminal, and a real terminal's screen cannot be read "
                         "back: use --port virtual:DEVICE, or drop -o");
  if (virtualPort) {
    const std::string name = args.serial.port.substr(kVirtualPrefix.size());
    if (!args.device.empty() && args.device != name)
      throw lattice::Error(lattice::ErrorKind::Usage,
                           fmt::format("--device {} and --port {} name two terminals; drop --device", args.device,
                                       args.serial.port));
    args.device = name;  // an unknown name fails in makeDevice, listing the devices
    if (args.screen.empty()) args.screen = fmt::format("virtual-{}.png", name);
    lattice::app::checkOutputPath(args.screen, "-o", cmd.count("--force") > 0);
    lattice::io::SerialOptions line = args.serial;
    if (cmd.count("--baud") == 0) {
      const lattice::devices::Device profile = lattice::devices::makeDevice(name, args.settings);
      if (profile.line) line.baud = args.serial.baud = profile.line->baud;
    }
    terminal = std::make_unique<lattice::app::VirtualTerminal>(lattice::devices::makeDevice(name, args.settings), line);
    args.serial.port = terminal->portPath();
    // A pty takes bytes as fast as they come: hold them to the line rate.
    args.serial.pace = true;
    fmt::print(stderr, "lattice send: a virtual {} at {} baud, flow {}, on {}\n",
               lattice::devices::makeDevice(name, args.settings).title, args.serial.baud,
               lattice::io::toString(args.serial.flow), terminal->portPath());
  }
  // A stream the emulators would refuse as too long is no terminal stream.
  auto bytes = lattice::readFileUpTo(args.stream, lattice::kMaxStreamBytes, "a stream to send");
  // Checked before the port is opened, so a typo does not touch the line.
  if (args.resume > bytes.size())
    throw lattice::Error(lattice::ErrorKind::Usage,
                         fmt::format("--resume {}: past the end of {} ({} bytes)", args.resume, args.stream, bytes.size()));
  // A terminal that answers requests (the 4027's `!REP`) is sent one record
  // at a time; without --device a paced stream would overrun its buffer, so
  // say so (found by asking every device that paces where this stream asks).
  std::optional<lattice::devices::Device> device;
  lattice::io::ReplyGate gate;
  if (!args.device.empty()) {
    device = lattice::devices::makeDevice(args.device, args.settings);
    if (device->replies) gate.points = device->replies->points(bytes);
  } else {
    for (const auto& entry : lattice::devices::deviceTable()) {
      const lattice::devices::Device candidate = entry.make({});
      if (!candidate.replies) continue;
      const std::size_t requests = candidate.replies->points(bytes).size();
      if (requests > 0)
        fmt::print(stderr,
                   "lattice send: note: {} holds {} report requests; a {} overruns its buffer unless each is "
                   "answered before the next record: add --device {} to wait for the answers\n",
                   args.stream, requests, candidate.title, candidate.name);
    }
  }
  const bool gated = !gate.points.empty();
  auto sink = lattice::io::openSerialSink(args.serial);
  if (terminal) terminal->senderConnected();
  if (gated) {
    const int fd = sink->fd();
    const double timeout = args.serial.stallTimeoutSeconds;
    gate.await = [await = device->replies->await, fd, timeout] { await(fd, timeout); };
    fmt::print(stderr, "lattice send: waiting for the {}'s answer after each of {} records\n", device->title,
               gate.points.size());
  }
  lattice::Progress progress("send", bytes.size() > args.resume ? bytes.size() - args.resume : 0, "B");
  try {
    auto result = lattice::io::sendStream(bytes, args.resume, *sink,
                                      [&](std::uint64_t offset) { progress.set(offset - args.resume); },
                                          gated ? &gate : nullptr);
    progress.finish();
    fmt::print(stderr, "sent {} bytes to {} in {:.1f} s ({:.0f} B/s)\n", result.bytesSent, sink->path(),
               result.seconds, result.seconds > 0 ? static_cast<double>(result.bytesSent) / result.seconds : 0.0);
    if (terminal) {
      sink.reset();  // closing the line ends the terminal's stream
      lattice::StreamDecoder& screen = terminal->finish(args.serial.stallTimeoutSeconds);
      lattice::checkPixelWork(screen.report(), args.stream);
      lattice::io::writePng(args.screen, screen.image());
      fmt::print(stderr, "lattice send: the virtual terminal drew {} bytes ({} commands, {} unknown, {} malformed): {}\n",
                 screen.report().bytes, screen.report().commands, screen.report().unknownCommands,
                 screen.report().malformed, args.screen);
    }
  } catch (const lattice::io::SerialFault& fault) {
    // Leave the bar where it stopped; the message follows on a line of its own.
    bool drawing = progress.enabled();
    progress.setEnabled(false);
    if (drawing) std::fputc('\n', stderr);
    fmt::print(stderr, "lattice: {} of {} bytes went out; to continue from there run:\n  {}\n",
               fault.resumeOffset(), bytes.size(), lattice::io::resumeCommand(args.stream, args.serial, fault.resumeOffset(), deviceFlags(args)));
    throw;
  }
}

}  // namespace

namespace lattice::app {

void addSend(CLI::App& root) {
  auto args = std::make_shared<SendArgs>();
  auto* cmd = root.add_subcommand(
      "send",
      "Send a stored device command stream (e.g. a Tektronix 4125/4027 stream file) to a terminal over a serial line, through "
      "flow control, with a progress bar. If the line stalls (exit 6) or hangs up (exit 7) it prints how many "
      "bytes went out and the `--resume` command that continues exactly there.");
  // Read (and refused with exit 3, naming the file) by readFileUpTo, not by a CLI check.
  cmd->add_option("STREAM", args->stream, "The command stream file to send")->required();
  lattice::app::addSerialOptions(cmd, args->serial, /*portRequired=*/true,
                                 "9600; for virtual:DEVICE, the device profile's rate");
  cmd->get_option("--port")->description(
      "Serial port: a device such as /dev/ttyUSB0, `auto` for the only USB-serial adapter (`lattice ports` lists "
      "them), or virtual:tek4125 / virtual:tek4027 for our emulator on a pseudo-terminal (docs/serial.md)");
  cmd->add_option("--device", args->device,
                  "The terminal the stream is for, when it paces the stream by answering requests: with tek4027, "
                  "a stream paced with `!REP 00` (pacing=report or auto) is sent one record at a time, each after "
                  "the terminal's answer to the one before (--stall-timeout bounds each wait)")
      ->check(CLI::IsMember(lattice::devices::deviceNames()));
  cmd->add_option("--set", args->settings,
                  "With --device: override a profile assumption, key=value (repeatable), as for render");
  cmd->add_option("--resume", args->resume, "Start at this byte offset, as printed by a failed send")
      ->check(lattice::app::numberIn({0, 9.0e15, true}));
  cmd->add_option("-o,--output", args->screen,
                  "With --port virtual:DEVICE: the PNG of the screen the virtual terminal drew (default "
                  "virtual-DEVICE.png)");
  cmd->callback([args, cmd] { runSend(*args, *cmd); });
}

}  // namespace lattice::app
