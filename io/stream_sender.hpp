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
// unanswered request: its bytes went out).
SendResult sendStream(std::span<const std::uint8_t> stream, std::uint64_t resumeOffset, SerialSink& sink,
                      const SendProgress& progress = {}, const ReplyGate* gate = nullptr);

// "lattice send FILE --port ... [EXTRA...] --resume N", quoting FILE and each
// of `extra` (the send's other flags, e.g. --device tek4027) for a POSIX shell.
std::string resumeCommand(const std::string& file, const SerialOptions& options, std::uint64_t offset,
                          const std::vector<std::string>& extra = {});

}  // namespace lattice::io
