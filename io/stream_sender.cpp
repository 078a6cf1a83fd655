#include "io/stream_sender.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>

#include "foundation/error.hpp"

namespace lattice::io {
namespace {

// Small enough that progress moves often at 9600 baud (~1 s per KB), large
// enough that a fast line is not held up by per-chunk work.
constexpr std::size_t kChunk = 512;

std::string shellQuote(const std::string& text) {
  bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '/' || c == '.' ||
           c == '_' || c == '-' || c == '+' || c == ',' || c == ':' || c == '=' || c == '@';
  });
  if (plain) return text;
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};
constexpr std::size_t kStopCount = std::size(kStopSignals);
// A lock-free atomic: safe to store from a handler (on whichever thread it
// runs, the virtual terminal's too) and to read from the sending thread.
std::atomic<int> caughtSignal{0};
static_assert(std::atomic<int>::is_always_lock_free);
// Written before the handlers are installed, read by them.
struct sigaction previousAction[kStopCount];
bool installed[kStopCount] = {};

extern "C" void recordStopSignal(int signal) {
  int none = 0;
  if (caughtSignal.compare_exchange_strong(none, signal)) return;
  // A second one: end now, by the action there was before. The signal is
  // blocked while this handler runs, so the raise takes effect on return.
  for (std::size_t i = 0; i < kStopCount; ++i)
    if (kStopSignals[i] == signal) ::sigaction(signal, &previousAction[i], nullptr);
  std::raise(signal);
}

}  // namespace

SendSignals::SendSignals() {
  caughtSignal.store(0);
  for (std::size_t i = 0; i < kStopCount; ++i) {
    installed[i] = false;
    if (::sigaction(kStopSignals[i], nullptr, &previousAction[i]) != 0) continue;
    if (!(previousAction[i].sa_flags & SA_SIGINFO) && previousAction[i].sa_handler == SIG_IGN) continue;
    struct sigaction action {};
    action.sa_handler = recordStopSignal;
    sigemptyset(&action.sa_mask);
    for (int other : kStopSignals) sigaddset(&action.sa_mask, other);  // one handler run at a time
    // No SA_RESTART: a blocking call returns EINTR; the sink's loops check again anyway.
    installed[i] = ::sigaction(kStopSignals[i], &action, nullptr) == 0;
  }
}

SendSignals::~SendSignals() {
  for (std::size_t i = 0; i < kStopCount; ++i)
    if (installed[i]) ::sigaction(kStopSignals[i], &previousAction[i], nullptr);
}

int SendSignals::caught() const { return caughtSignal.load(); }

void dieOf(int signal) {
  std::fflush(nullptr);  // what stdio holds would be lost with the process
  std::raise(signal);
  std::_Exit(128 + signal);
}

std::string signalName(int signal) {
  switch (signal) {
    case SIGINT: return "SIGINT (Ctrl-C)";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return fmt::format("signal {}", signal);
  }
}

SendResult sendStream(std::span<const std::uint8_t> stream, std::uint64_t resumeOffset, SerialSink& sink,
                      const SendProgress& progress, const ReplyGate* gate) {
  if (resumeOffset > stream.size())
    throw Error(ErrorKind::Usage, fmt::format("--resume {}: past the end of the stream ({} bytes); use an offset "
                                              "from 0 to {}, as printed by the failed send",
                                              resumeOffset, stream.size(), stream.size()));
  auto start = std::chrono::steady_clock::now();
  sink.setStreamOffset(resumeOffset);
  std::uint64_t offset = resumeOffset;
  // Points at or before the resume offset were answered by the earlier run.
  const std::vector<std::size_t> none;
  const std::vector<std::size_t>& points = gate != nullptr ? gate->points : none;
  auto next = std::upper_bound(points.begin(), points.end(), resumeOffset);
  const std::size_t total = points.size();
  while (offset < stream.size()) {
    const std::uint64_t stop = next != points.end() ? std::min<std::uint64_t>(*next, stream.size()) : stream.size();
    auto chunk = stream.subspan(static_cast<std::size_t>(offset),
                                static_cast<std::size_t>(std::min<std::uint64_t>(kChunk, stop - offset)));
    sink.write(chunk);
    offset += chunk.size();
    if (progress) progress(offset);
    if (next != points.end() && offset == *next) {
      const std::size_t ordinal = static_cast<std::size_t>(next - points.begin()) + 1;
      try {
        gate->await();
      } catch (const SerialFault&) {
        throw;
      } catch (const Error& e) {
        const bool stalled = e.kind() == ErrorKind::Stalled;
        throw SerialFault(stalled ? ErrorKind::Stalled : ErrorKind::HangUp,
                          stalled ? fmt::format("the terminal did not answer request {} of {} (ending at byte {}); is it "
                                                "on line and set to answer reports? (leave out --device to send "
                                                "without waiting)",
                                                ordinal, total, offset)
                                  : fmt::format("the line went away while waiting for the answer to request {} of {} "
                                                "(ending at byte {})",
                                                ordinal, total, offset),
                          offset, offset);
      }
      ++next;
    }
  }
  sink.close();
  return {offset - resumeOffset, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
}

std::string resumeCommand(const std::string& file, const SerialOptions& options, std::uint64_t offset,
                          const std::vector<std::string>& extra) {
  SerialOptions quoted = options;
  quoted.port = shellQuote(options.port);
  std::string more;
  for (const std::string& arg : extra) {
    more += ' ';
    more += shellQuote(arg);  // appended apart: gcc 12 misreads `" " + string` (-Wrestrict)
  }
  return fmt::format("lattice send {} {}{} --resume {}", shellQuote(file), serialFlags(quoted), more, offset);
}

}  // namespace lattice::io
