#include "io/serial_sink.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <thread>

namespace lattice::io {
namespace {

using Clock = std::chrono::steady_clock;

// Poll in short slices so the stall clock and the pacer are checked often
// without spinning.
constexpr int kPollSliceMs = 50;

}  // namespace

SerialSink::SerialSink(SerialPort port, const SerialOptions& options) : port_(std::move(port)), options_(options) {
  // Stale bytes from before we opened the line (a half-typed command, a
  // status report) mean nothing to this stream. Flushed before configuring,
  // so an XOFF arriving once the line is set up is never thrown away.
  port_.discardInput();
  port_.configure(options_);
  if (options_.pace) {
    double bytesPerSecond = static_cast<double>(options_.baud) / options_.lineFormat().bitsPerCharacter();
    // A burst of ~20 ms of line time keeps writes coarse without letting the
    // rate run ahead measurably.
    pacer_.emplace(bytesPerSecond, std::max(1.0, bytesPerSecond / 50.0), now());
  }
}

SerialSink::~SerialSink() {
  // Destroyed without close(): the caller is unwinding from an error. Do not
  // wait for the queue (it may be stalled); drop it so nothing trickles out.
  if (port_.isOpen()) port_.discardOutput();
}

double SerialSink::now() const { return std::chrono::duration<double>(Clock::now() - epoch_).count(); }

std::uint64_t SerialSink::abandon() {
  // Read the queue before discarding it: what was queued never went out.
  std::size_t queued = std::min<std::uint64_t>(port_.outputQueued(), accepted_);
  port_.discardOutput();
  port_.close();
  closed_ = true;
  return base_ + accepted_ - queued;
}

void SerialSink::checkStop() {
  if (!stop_ || !stop_()) return;
  const std::uint64_t resume = abandon();
  throw SendStopped(base_ + accepted_, resume);
}

void SerialSink::fail(ErrorKind kind, const std::string& why) {
  std::uint64_t sent = abandon() - base_;
  throw SerialFault(kind,
                    fmt::format("{}: {}; {} bytes of the stream went out (offset {} onward did not), resume from "
                                "offset {}",
                                port_.path(), why, base_ + sent, base_ + sent, base_ + sent),
                    base_ + accepted_, base_ + sent);
}

void SerialSink::stallCheck(Clock::time_point lastProgress, const char* where) {
  double stalled = std::chrono::duration<double>(Clock::now() - lastProgress).count();
  if (stalled < options_.stallTimeoutSeconds) return;
  fail(ErrorKind::Stalled,
       fmt::format("no byte could be {} for {:.1f} s (--stall-timeout): {}", where, stalled,
                   options_.flow == FlowControl::XonXoff ? "the terminal sent XOFF (DC3) and no XON (DC1); is it "
                                                           "paused, out of paper or in a setup menu?"
                   : options_.flow == FlowControl::RtsCts ? "the terminal holds CTS low; is it paused, or the "
                                                            "cable missing the RTS/CTS wires?"
                                                          : "the driver takes no more bytes"));
}

void SerialSink::write(std::span<const std::uint8_t> bytes) {
  if (closed_) throw Error(ErrorKind::Internal, fmt::format("{}: write after close", port_.path()));
  auto lastProgress = Clock::now();
  while (!bytes.empty()) {
    checkStop();
    std::size_t chunk = bytes.size();
    if (pacer_) {
      std::size_t allowed = pacer_->available(now());
      if (allowed == 0) {
        double wait = pacer_->secondsUntil(std::min<std::size_t>(bytes.size(), 64), now());
        std::this_thread::sleep_for(std::chrono::duration<double>(std::max(wait, 0.0005)));
        // Pacing is our own choice, not a stall of the line.
        lastProgress = Clock::now();
        continue;
      }
      chunk = std::min(chunk, allowed);
    }
    auto result = port_.writeSome(bytes.first(chunk));
    if (result.status == SerialPort::Status::HangUp)
      fail(ErrorKind::HangUp, "the line hung up (the terminal or adapter went away)");
    if (result.written > 0) {
      accepted_ += result.written;
      if (pacer_) pacer_->consume(result.written);
      bytes = bytes.subspan(result.written);
      lastProgress = Clock::now();
      continue;
    }
    // The kernel's queue is full: draining at line speed, or stopped by flow control.
    switch (port_.waitWritable(kPollSliceMs)) {
      case SerialPort::Wait::HangUp:
        fail(ErrorKind::HangUp, "the line hung up (the terminal or adapter went away)");
      case SerialPort::Wait::Timeout:
      case SerialPort::Wait::Writable:
        break;
    }
    stallCheck(lastProgress, "written");
  }
}

void SerialSink::close() {
  if (closed_) return;
  checkStop();
  // The queue must empty before tcdrain, which has no timeout: watch it
  // shrink, and call it a stall if it stops moving. A pty reports 0 at once.
  auto lastProgress = Clock::now();
  std::size_t queued = port_.outputQueued();
  while (queued > 0) {
    checkStop();
    if (port_.waitWritable(kPollSliceMs) == SerialPort::Wait::HangUp)
      fail(ErrorKind::HangUp, "the line hung up while the last bytes were going out");
    std::size_t nowQueued = port_.outputQueued();
    if (nowQueued < queued) lastProgress = Clock::now();
    queued = nowQueued;
    if (queued > 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(kPollSliceMs));
      stallCheck(lastProgress, "sent from the output queue");
    }
  }
  port_.drainQueued();
  port_.close();
  closed_ = true;
}

}  // namespace lattice::io
