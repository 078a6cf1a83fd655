#pragma once
// A ByteSink on a serial line: every byte, in order, through flow control,
// or an error that says exactly where the stream stopped.
//
// Counting. "Accepted" bytes were taken by the kernel; "sent" bytes have
// left the kernel's output queue (accepted minus TIOCOUTQ). When the line
// stalls or hangs up, the sink reads the queue, then discards it (TCOFLUSH):
// from then on exactly `sent` bytes have gone out and none will follow late,
// so resending the stream from offset `sent` repeats nothing and skips
// nothing. (A USB adapter's own FIFO, a few hundred bytes at most, is
// invisible to the kernel and counted as sent; see docs/serial.md.)
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>

#include "foundation/byte_sink.hpp"
#include "io/rate_limiter.hpp"
#include "io/serial_options.hpp"
#include "io/serial_port.hpp"
#include "foundation/error.hpp"

namespace lattice::io {

// ErrorKind::Stalled or HangUp, with the counts a caller needs to resume.
// Offsets include the sink's base offset (the --resume the stream started at).
class SerialFault : public Error {
 public:
  SerialFault(ErrorKind kind, const std::string& message, std::uint64_t acceptedOffset, std::uint64_t resumeOffset)
      : Error(kind, message), accepted_(acceptedOffset), resume_(resumeOffset) {}
  std::uint64_t acceptedOffset() const noexcept { return accepted_; }
  // The offset of the first byte that did not go out: resend from here.
  std::uint64_t resumeOffset() const noexcept { return resume_; }

 private:
  std::uint64_t accepted_;
  std::uint64_t resume_;
};

// The send was stopped from outside (SerialSink::setStopCheck: Ctrl-C), not
// by the line. As on a fault, the queue was read and then discarded and the
// port closed first, so exactly resumeOffset() bytes of the stream went out.
class SendStopped : public std::runtime_error {
 public:
  SendStopped(std::uint64_t acceptedOffset, std::uint64_t resumeOffset)
      : std::runtime_error("the send was stopped"), accepted_(acceptedOffset), resume_(resumeOffset) {}
  std::uint64_t acceptedOffset() const noexcept { return accepted_; }
  std::uint64_t resumeOffset() const noexcept { return resume_; }

 private:
  std::uint64_t accepted_;
  std::uint64_t resume_;
};

class SerialSink final : public ByteSink {
 public:
  // Takes an open port and configures it with `options`.
  SerialSink(SerialPort port, const SerialOptions& options);
  ~SerialSink() override;

  using ByteSink::write;
  // Blocks until the kernel has accepted every byte. Throws SerialFault
  // (Stalled) after options.stallTimeoutSeconds without progress, or
  // (HangUp) when the peer goes away.
  void write(std::span<const std::uint8_t> bytes) override;
  // Waits (with the same stall timeout) until the output queue is empty and
  // the last byte has left, then closes the port.
  void close() override;
  std::uint64_t bytesWritten() const override { return accepted_; }

  // Where this sink's first byte sits in the whole stream (a resumed send
  // starts at --resume N); errors report offsets in the whole stream.
  void setStreamOffset(std::uint64_t offset) { base_ = offset; }
  // Asked before every slice of write() and of close()'s wait for the queue
  // (at least every 50 ms while the line is held, and between the pacer's
  // bursts of about 20 ms): true stops the send there, with SendStopped.
  void setStopCheck(std::function<bool()> stop) { stop_ = std::move(stop); }
  const std::string& path() const { return port_.path(); }
  // The line's descriptor, for a driver that reads the terminal's answers
  // (the 4027's report pacing); the sink itself only writes.
  int fd() const { return port_.fd(); }

 private:
  // Counts what went out (accepted minus queued), discards the rest and
  // closes: the offset in the whole stream to resend from.
  std::uint64_t abandon();
  [[noreturn]] void fail(ErrorKind kind, const std::string& why);
  void checkStop();
  void stallCheck(std::chrono::steady_clock::time_point lastProgress, const char* where);
  double now() const;

  SerialPort port_;
  SerialOptions options_;
  std::optional<RateLimiter> pacer_;
  std::function<bool()> stop_;
  std::uint64_t accepted_ = 0;
  std::uint64_t base_ = 0;
  bool closed_ = false;
  std::chrono::steady_clock::time_point epoch_ = std::chrono::steady_clock::now();
};

}  // namespace lattice::io
