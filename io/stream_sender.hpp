#pragma once
// The body of `lattice send`: a stored command stream out of a serial sink
// from a resume offset, with progress, and on a fault the exact command that
// continues it.
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "io/serial_options.hpp"
#include "io/serial_sink.hpp"

namespace lattice::io {

struct SendResult {
  std::uint64_t bytesSent = 0;  // this run, after the resume offset
  double seconds = 0.0;
};

// Called with the offset in the whole stream after each chunk.
using SendProgress = std::function<void(std::uint64_t offset)>;

// Where the sender stops until the terminal answers (a device's reply
// pacing, devices/device.hpp): offsets in the whole stream, ascending, each
// just past a request; `await` blocks until one answer has come and throws
// lattice::Error (Stalled or HangUp) when none does.
struct ReplyGate {
  std::vector<std::size_t> points;
  std::function<void()> await;
};

// Sends stream[resumeOffset..] and closes (drains) the sink, stopping at each
// of `gate`'s points past the resume offset for an answer. Error(Usage) if
// the offset is past the end; SerialFault (offsets in the whole stream) on a
// stall or hang-up, or on an answer that does not come (resume just past the
// unanswered request: its bytes went out); SendStopped when the sink's stop
// check says so (SendSignals below).
SendResult sendStream(std::span<const std::uint8_t> stream, std::uint64_t resumeOffset, SerialSink& sink,
                      const SendProgress& progress = {}, const ReplyGate* gate = nullptr);

// "lattice send FILE --port ... [EXTRA...] --resume N", quoting FILE and each
// of `extra` (the send's other flags, e.g. --device tek4027) for a POSIX shell.
std::string resumeCommand(const std::string& file, const SerialOptions& options, std::uint64_t offset,
                          const std::vector<std::string>& extra = {});

// Ctrl-C (SIGINT), SIGTERM and SIGHUP while a stream goes out. Their default
// action kills the sender where it stands: the user learns neither how far
// the stream got nor how to resume it, and the bytes the kernel still queues
// go out after the end. While a SendSignals lives, these signals only record
// themselves (a store to a lock-free atomic: all a handler may safely do); a stop
// check made of caught() (SerialSink::setStopCheck) sees it within one slice
// of the sink's loop and stops the send as a stall would, counting what went
// out. The caller then says where it stopped, lets this go and calls dieOf,
// so the process still ends by the signal: the shell sees 128 + the signal
// (130 for Ctrl-C) and a script's loop stops as it would have.
//
// A second signal before that ends the process at once (the way out should
// anything fail to check). A signal that was ignored when this was made
// (nohup's SIGHUP, SIGINT for a shell's background job) stays ignored. The
// actions there were, the default or a handler such as the temporary-file
// registry's (foundation/system/temp_file_registry.hpp), come back when this
// is destroyed. One at a time.
class SendSignals {
 public:
  SendSignals();
  ~SendSignals();
  SendSignals(const SendSignals&) = delete;
  SendSignals& operator=(const SendSignals&) = delete;
  // The first of the signals received, or 0.
  int caught() const;
};

// Ends the process by `signal` through its action, as if it had come now
// (after a SendSignals is gone: the action there was before it); if that
// action returns, exits with 128 + signal, the shell's status for it.
[[noreturn]] void dieOf(int signal);

// "SIGINT (Ctrl-C)", "SIGTERM", "SIGHUP", else "signal N".
std::string signalName(int signal);

}  // namespace lattice::io
