#include "io/stdout_sink.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "foundation/error.hpp"

namespace lattice::io {

void StdoutSink::write(std::span<const std::uint8_t> bytes) {
  const std::uint8_t* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    ssize_t n = ::write(STDOUT_FILENO, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw Error(ErrorKind::Output, std::string("standard output: write failed after ") +
                                         std::to_string(written_) + " bytes: " + std::strerror(errno));
    }
    p += n;
    left -= static_cast<std::size_t>(n);
    written_ += static_cast<std::uint64_t>(n);
  }
}

void StdoutSink::flush() {}

}  // namespace lattice::io
