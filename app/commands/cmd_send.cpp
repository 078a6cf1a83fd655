// `lattice send STREAM --port ...`: play a stored command stream to a
// terminal over a serial line, resumably. See docs/serial.md.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
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
#include "app/stream_check.hpp"
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
  bool raw = false;    // send even what does not look like a terminal stream
};

constexpr std::string_view kVirtualPrefix = "virtual:";

// The flags a resumed send must repeat besides the line's: the device and
// its settings; for a virtual terminal (whose port names the device) the
// settings and the screen's path, if one was given; --raw.
std::vector<std::string> resumeFlags(const SendArgs& args, bool virtualPort, bool screenGiven) {
  std::vector<std::string> flags;
  if (!args.device.empty()) {
    if (!virtualPort) flags = {"--device", args.device};
    for (const std::string& setting : args.settings) {
      flags.push_back("--set");
      flags.push_back(setting);
    }
    if (virtualPort && screenGiven) {
      flags.push_back("-o");
      flags.push_back(args.screen);
    }
  }
  if (args.raw) flags.push_back("--raw");
  return flags;
}

// The 4027's answer is awaited in slices of this many seconds, so that a
// Ctrl-C is seen while the terminal is silent.
constexpr double kAwaitSliceSeconds = 0.05;

// Sends the stream; returns the signal that stopped it (Ctrl-C...), after
// saying where, or 0 when none did.
int sendFile(SendArgs args, const CLI::App& cmd) {
  // `--port virtual:DEVICE`: the device's emulator on the far side of a pty.
  std::unique_ptr<lattice::app::VirtualTerminal> terminal;
  const bool virtualPort = args.serial.port.rfind(kVirtualPrefix, 0) == 0;
  if (!virtualPort && cmd.count("--output") > 0)
    throw lattice::Error(lattice::ErrorKind::Usage,
                         "-o writes the screen of a virtual terminal, and a real terminal's screen cannot be read "
                         "back: use --port virtual:DEVICE, or drop -o");
  const std::string name = virtualPort ? args.serial.port.substr(kVirtualPrefix.size()) : std::string();
  // The line as the user named it, for the --resume command: a virtual
  // terminal's pty is gone by the time it is run.
  lattice::io::SerialOptions named = args.serial;
  if (virtualPort) {
    if (!args.device.empty() && args.device != name)
      throw lattice::Error(lattice::ErrorKind::Usage,
                           fmt::format("--device {} and --port {} name two terminals; drop --device", args.device,
                                       args.serial.port));
    args.device = name;  // an unknown name fails in makeDevice, listing the devices
    if (args.screen.empty()) args.screen = fmt::format("virtual-{}.png", name);
    lattice::app::checkOutputPath(args.screen, "-o", cmd.count("--force") > 0);
  }
  // Recognised before anything is opened, from the file's first bytes only:
  // a PNG, a scene or noise is refused before a byte goes on the line, however
  // long the file (sent, it would hold the line for as long as it takes to
  // pace out, and leave the terminal in whatever mode its bytes selected).
  if (!args.raw) {
    const std::vector<std::uint8_t> head = lattice::app::readStreamHead(args.stream);
    if (!args.device.empty())
      lattice::app::requireStream(head, lattice::devices::makeDevice(args.device, args.settings), args.stream,
                                  virtualPort ? lattice::app::StreamUse::SendVirtual : lattice::app::StreamUse::Send);
    else
      lattice::app::requireAnyStream(head, args.stream, lattice::app::StreamUse::Send);
  }
  if (virtualPort) {
    lattice::io::SerialOptions line = args.serial;
    if (cmd.count("--baud") == 0) {
      const lattice::devices::Device profile = lattice::devices::makeDevice(name, args.settings);
      if (profile.line) line.baud = args.serial.baud = named.baud = profile.line->baud;
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
  // From here a Ctrl-C (SIGTERM, SIGHUP) stops the send where it is and says
  // how to resume, as a stall does; then the process ends by the signal.
  std::optional<lattice::io::SendSignals> signals(std::in_place);
  sink->setStopCheck([&signals] { return signals->caught() != 0; });
  if (gated) {
    const int fd = sink->fd();
    const double timeout = args.serial.stallTimeoutSeconds;
    gate.await = [await = device->replies->await, fd, timeout, &signals] {
      using Clock = std::chrono::steady_clock;
      const Clock::time_point deadline =
          Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout));
      for (;;) {
        // Stopped: return as if answered; the sink's next write or close
        // sees the same signal and stops the send, counting what went out.
        if (signals->caught() != 0) return;
        const double left = std::chrono::duration<double>(deadline - Clock::now()).count();
        try {
          await(fd, std::clamp(left, 0.0, kAwaitSliceSeconds));
          return;
        } catch (const lattice::Error& e) {
          if (e.kind() != lattice::ErrorKind::Stalled || left <= kAwaitSliceSeconds) throw;
        }
      }
    };
    fmt::print(stderr, "lattice send: waiting for the {}'s answer after each of {} records\n", device->title,
               gate.points.size());
  }
  lattice::Progress progress("send", bytes.size() > args.resume ? bytes.size() - args.resume : 0, "B");
  // Where the stream stopped and the command that continues it, after the bar.
  const auto sayWhereItStopped = [&](std::uint64_t resumeOffset) {
    const bool drawing = progress.enabled();
    progress.setEnabled(false);  // leave the bar where it stopped
    if (drawing) std::fputc('\n', stderr);
    fmt::print(stderr, "lattice: {} of {} bytes went out; to continue from there run:\n  {}\n", resumeOffset,
               bytes.size(),
               lattice::io::resumeCommand(args.stream, virtualPort ? named : args.serial, resumeOffset,
                                          resumeFlags(args, virtualPort, cmd.count("--output") > 0)));
  };
  lattice::io::SendResult result;
  try {
    result = lattice::io::sendStream(bytes, args.resume, *sink,
                                     [&](std::uint64_t offset) { progress.set(offset - args.resume); },
                                     gated ? &gate : nullptr);
  } catch (const lattice::io::SerialFault& fault) {
    sayWhereItStopped(fault.resumeOffset());
    throw;
  } catch (const lattice::io::SendStopped& stop) {
    sayWhereItStopped(stop.resumeOffset());
    fmt::print(stderr, "lattice: stopped by {}\n", lattice::io::signalName(signals->caught()));
    return signals->caught();
  }
  // The whole stream went out; a signal now still ends the command (no screen is drawn).
  const int late = signals->caught();
  signals.reset();
  progress.finish();
  fmt::print(stderr, "sent {} bytes to {} in {:.1f} s ({:.0f} B/s)\n", result.bytesSent, sink->path(),
             result.seconds, result.seconds > 0 ? static_cast<double>(result.bytesSent) / result.seconds : 0.0);
  if (late != 0) {
    fmt::print(stderr, "lattice: stopped by {} after the whole stream went out\n", lattice::io::signalName(late));
    return late;
  }
  if (terminal) {
    sink.reset();  // closing the line ends the terminal's stream
    lattice::StreamDecoder& screen = terminal->finish(args.serial.stallTimeoutSeconds);
    lattice::checkPixelWork(screen.report(), args.stream);
    lattice::io::writePng(args.screen, screen.image());
    fmt::print(stderr, "lattice send: the virtual terminal drew {} bytes ({} commands, {} unknown, {} malformed): {}\n",
               screen.report().bytes, screen.report().commands, screen.report().unknownCommands,
               screen.report().malformed, args.screen);
  }
  return 0;
}

void runSend(const SendArgs& args, const CLI::App& cmd) {
  // Ended by the signal only now, with the line, the virtual terminal and
  // the handlers put away (SendSignals says why it is the signal, not an exit).
  if (const int signal = sendFile(args, cmd); signal != 0) lattice::io::dieOf(signal);
}

}  // namespace

namespace lattice::app {

void addSend(CLI::App& root) {
  auto args = std::make_shared<SendArgs>();
  auto* cmd = root.add_subcommand(
      "send",
      "Send a stored device command stream (e.g. a Tektronix 4125/4027 stream file) to a terminal over a serial line, through "
      "flow control, with a progress bar. A file that is not a terminal's stream (a PNG, a scene, noise) is "
      "refused with exit 3 before a byte goes out (--raw sends it anyway). If the line stalls (exit 6) or hangs up "
      "(exit 7), or the send is interrupted (Ctrl-C: status 130), it prints how many bytes went out and the "
      "`--resume` command that continues exactly there.");
  // Read (and refused with exit 3, naming the file) by readStreamHead and readFileUpTo, not by a CLI check.
  cmd->add_option("STREAM", args->stream, "The command stream file to send")->required();
  lattice::app::addSerialOptions(cmd, args->serial, /*portRequired=*/true,
                                 "9600; for virtual:DEVICE, the device profile's rate");
  cmd->get_option("--port")->description(
      "Serial port: a device such as /dev/ttyUSB0, `auto` for the only USB-serial adapter (`lattice ports` lists "
      "them), or virtual:tek4125 / virtual:tek4027 for our emulator on a pseudo-terminal (docs/serial.md)");
  cmd->add_option("--device", args->device,
                  "The terminal the stream is for (the stream must look like its stream, unless --raw), and how "
                  "it paces the stream by answering requests: with tek4027, "
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
  cmd->add_flag("--raw", args->raw,
                "Send the file even if it does not look like a terminal's command stream (without it, a PNG, a "
                "scene, an empty file, noise or another terminal's stream is refused with exit 3 before a byte "
                "goes out)");
  cmd->callback([args, cmd] { runSend(*args, *cmd); });
}

}  // namespace lattice::app
