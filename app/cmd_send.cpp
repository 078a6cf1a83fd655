// `lattice send STREAM --port ...`: play a stored command stream to a
// terminal over a serial line, resumably. See docs/serial.md.
#include <fmt/format.h>

#include <cstdio>
#include <memory>
#include <string>

#include "app/commands.hpp"
#include "app/serial_args.hpp"
#include "devices/work_budget.hpp"
#include "foundation/atomic_file.hpp"
#include "io/serial_sink.hpp"
#include "io/stream_sender.hpp"
#include "foundation/error.hpp"
#include "foundation/progress.hpp"

namespace {

struct SendArgs {
  std::string stream;
  lattice::io::SerialOptions serial;
  std::uint64_t resume = 0;
};

void runSend(const SendArgs& args) {
  // A stream the emulators would refuse as too long is no terminal stream.
  auto bytes = lattice::readFileUpTo(args.stream, lattice::kMaxStreamBytes, "a stream to send");
  // Checked before the port is opened, so a typo does not touch the line.
  if (args.resume > bytes.size())
    throw lattice::Error(lattice::ErrorKind::Usage,
                         fmt::format("--resume {}: past the end of {} ({} bytes)", args.resume, args.stream, bytes.size()));
  auto sink = lattice::io::openSerialSink(args.serial);
  lattice::Progress progress("send", bytes.size() > args.resume ? bytes.size() - args.resume : 0, "B");
  try {
    auto result = lattice::io::sendStream(bytes, args.resume, *sink,
                                      [&](std::uint64_t offset) { progress.set(offset - args.resume); });
    progress.finish();
    fmt::print(stderr, "sent {} bytes to {} in {:.1f} s ({:.0f} B/s)\n", result.bytesSent, sink->path(),
               result.seconds, result.seconds > 0 ? static_cast<double>(result.bytesSent) / result.seconds : 0.0);
  } catch (const lattice::io::SerialFault& fault) {
    // Leave the bar where it stopped; the message follows on a line of its own.
    bool drawing = progress.enabled();
    progress.setEnabled(false);
    if (drawing) std::fputc('\n', stderr);
    fmt::print(stderr, "lattice: {} of {} bytes went out; to continue from there run:\n  {}\n",
               fault.resumeOffset(), bytes.size(), lattice::io::resumeCommand(args.stream, args.serial, fault.resumeOffset()));
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
  lattice::app::addSerialOptions(cmd, args->serial);
  cmd->add_option("--resume", args->resume, "Start at this byte offset, as printed by a failed send")
      ->check(CLI::NonNegativeNumber);
  cmd->callback([args] { runSend(*args); });
}

}  // namespace lattice::app
