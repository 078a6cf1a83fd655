#include "app/virtual_terminal.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <deque>

#include "foundation/error.hpp"
#include "foundation/line_timing.hpp"

namespace lattice::app {
namespace {

constexpr std::uint8_t kXon = 0x11;   // DC1
constexpr std::uint8_t kXoff = 0x13;  // DC3

void writeByte(int fd, std::uint8_t byte) {
  // The master takes a byte unless the sender's input side is full, which a
  // sender that reads its answers never lets happen; retry briefly anyway.
  for (int tries = 0; tries < 1000; ++tries) {
    if (::write(fd, &byte, 1) == 1) return;
    if (errno != EAGAIN && errno != EINTR) return;
    ::usleep(1000);
  }
}

}  // namespace

VirtualTerminal::VirtualTerminal(devices::Device device, const io::SerialOptions& line)
    : device_(std::move(device)), line_(line), emulator_(device_.makeEmulator()) {
  ::fcntl(pty_.masterFd(), F_SETFL, ::fcntl(pty_.masterFd(), F_GETFL) | O_NONBLOCK);
  thread_ = std::thread([this] { run(); });
}

VirtualTerminal::~VirtualTerminal() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

void VirtualTerminal::run() {
  using Clock = std::chrono::steady_clock;
  const double charactersPerSecond = 1.0 / transmitSeconds(1, line_.lineFormat());
  const bool flagging = line_.flow == io::FlowControl::XonXoff;
  const int fd = pty_.masterFd();
  std::deque<std::uint8_t> buffer;
  bool held = false;  // we sent XOFF
  bool hungUp = false;
  double owed = 0;    // characters the line rate allows us to draw now
  Clock::time_point last = Clock::now();
  std::vector<std::uint8_t> chunk(kInputBufferBytes);
  while (!stop_) {
    // Take what arrived: everything with flagging (the XOFF will hold the
    // sender), else only what fits (a full pty holds the sender).
    if (!hungUp) {
      const std::size_t room = flagging ? chunk.size() : kInputBufferBytes - buffer.size();
      if (room > 0) {
        const ssize_t n = ::read(fd, chunk.data(), room);
        if (n > 0) {
          buffer.insert(buffer.end(), chunk.begin(), chunk.begin() + n);
        } else if (n < 0 && errno == EIO) {
          hungUp = true;  // every slave descriptor closed: the sender is done
        }
      }
    }
    if (flagging && !held && buffer.size() > kInputBufferBytes * 3 / 4) {
      writeByte(fd, kXoff);
      held = true;
    }
    // Draw at the line rate; after the hang-up, what is left at once.
    const Clock::time_point now = Clock::now();
    owed = std::min(owed + std::chrono::duration<double>(now - last).count() * charactersPerSecond,
                    static_cast<double>(kInputBufferBytes));
    last = now;
    std::size_t draw = hungUp ? buffer.size() : std::min(buffer.size(), static_cast<std::size_t>(owed));
    if (draw > 0) {
      const std::size_t from = drawn_.size();
      drawn_.insert(drawn_.end(), buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(draw));
      buffer.erase(buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(draw));
      owed -= static_cast<double>(draw);
      emulator_->feed(std::span<const std::uint8_t>(drawn_).subspan(from));
      if (device_.replies && !hungUp) {
        // Requests in what was drawn since the last one answered (a record
        // starts in the parser's ground state, so the scan may start there).
        const std::vector<std::size_t> points =
            device_.replies->points(std::span<const std::uint8_t>(drawn_).subspan(answeredUpTo_));
        for (std::size_t i = 0; i < points.size(); ++i) writeByte(fd, '\r');
        if (!points.empty()) answeredUpTo_ += points.back();
      }
    }
    if (held && buffer.size() <= kInputBufferBytes / 4) {
      writeByte(fd, kXon);
      held = false;
    }
    if (hungUp && buffer.empty()) break;
    if (draw == 0) {
      pollfd p{fd, POLLIN, 0};
      ::poll(&p, 1, 5);
    }
  }
  closed_ = true;
}

StreamDecoder& VirtualTerminal::finish(double timeoutSeconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
  while (!closed_) {
    if (std::chrono::steady_clock::now() > deadline)
      throw Error(ErrorKind::Stalled, fmt::format("the virtual {} did not see the line close within {} s",
                                                  device_.title, timeoutSeconds));
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  thread_.join();
  emulator_->finish();
  return *emulator_;
}

}  // namespace lattice::app
