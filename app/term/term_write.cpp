#include "app/term/term_write.hpp"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>

namespace lattice::app {

std::size_t writeToPeer(int fd, std::span<const std::uint8_t> bytes) {
  using Clock = std::chrono::steady_clock;
  std::size_t done = 0;
  Clock::time_point lastProgress = Clock::now();
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      lastProgress = Clock::now();
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EINTR) break;  // the peer is gone
    if (Clock::now() - lastProgress > std::chrono::milliseconds(kPeerWaitMs)) break;
    pollfd p{fd, POLLOUT, 0};
    ::poll(&p, 1, 50);
  }
  return done;
}

}  // namespace lattice::app
