#pragma once
// The body of `lattice send`: a stored command stream out of a serial sink
// from a resume offset, with progress, and on a fault the exact command that
// continues it.
#include <cstdint>
#include <functional>
#include <span>
#include <string>

#include "io/serial_options.hpp"
#include "io/serial_sink.hpp"

namespace lattice::io {

struct SendResult {
  std::uint64_t bytesSent = 0;  // this run, after the resume offset
  double seconds = 0.0;
};

// Called with the offset in the whole stream after each chunk.
using SendProgress = std::function<void(std::uint64_t offset)>;

// Sends stream[resumeOffset..] and closes (drains) the sink. Error(Usage) if
// the offset is past the end; SerialFault (offsets in the whole stream) on a
// stall or hang-up.
SendResult sendStream(std::span<const std::uint8_t> stream, std::uint64_t resumeOffset, SerialSink& sink,
                      const SendProgress& progress = {});

// "lattice send FILE --port ... --resume N", quoting FILE for a POSIX shell.
std::string resumeCommand(const std::string& file, const SerialOptions& options, std::uint64_t offset);

}  // namespace lattice::io
