// The body of `lattice send`, shared with `lattice render --port` (which
// records the stream first and sends the file, so an interrupted send
// resumes as one of `lattice send`'s does). See app/commands/send_file.hpp.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/commands/send_file.hpp"
#include "app/output_check.hpp"
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

using lattice::app::SendArgs;

constexpr std::string_view kVirtualPrefix = "virtual:";

// The flags a resumed send must repeat besides the line's: the device and
// its settings; for a virtual terminal (whose port names the device) the
// settings and the screen's path, if one was given; --raw.
std::vector<std::string> resumeFlags(const SendArgs& args, bool virtualPort) {
  std::vector<std::string> flags;
  if (!args.device.empty()) {
    if (!virtualPort) flags = {"--device", args.device};
    for (const std::string& setting : args.settings) {
      flags.push_back("--set");
      flags.push_back(setting);
    }
    if (virtualPort && args.screenGiven) {
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
int sendFile(SendArgs args) {
  // `--port virtual:DEVICE`: the device's emulator on the far side of a pty.
  std::unique_ptr<lattice::app::VirtualTerminal> terminal;
  const bool virtualPort = args.serial.port.rfind(kVirtualPrefix, 0) == 0;
  if (!virtualPort && args.screenGiven)
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
    lattice::app::checkOutputPath(args.screen, "-o", args.force);
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
    if (!args.baudGiven) {
      const lattice::devices::Device profile = lattice::devices::makeDevice(name, args.settings);
      if (profile.line) line.baud = args.serial.baud = named.baud = profile.line->baud;
    }
    terminal = std::make_unique<lattice::app::VirtualTerminal>(lattice::devices::makeDevice(name, args.settings), line);
    args.serial.port = terminal->portPath();
    // A pty takes bytes as fast as they come: hold them to the line rate.
    args.serial.pace = true;
    fmt::print(stderr, "{}: a virtual {} at {} baud, flow {}, on {}\n", args.who,
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
    fmt::print(stderr, "{}: waiting for the {}'s answer after each of {} records\n", args.who, device->title,
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
                                          resumeFlags(args, virtualPort)));
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
    fmt::print(stderr, "{}: the virtual terminal drew {} bytes ({} commands, {} unknown, {} malformed): {}\n",
               args.who, screen.report().bytes, screen.report().commands, screen.report().unknownCommands,
               screen.report().malformed, args.screen);
  }
  return 0;
}

}  // namespace

namespace lattice::app {

void runSend(const SendArgs& args) {
  // Ended by the signal only now, with the line, the virtual terminal and
  // the handlers put away (SendSignals says why it is the signal, not an exit).
  if (const int signal = sendFile(args); signal != 0) lattice::io::dieOf(signal);
}

}  // namespace lattice::app
