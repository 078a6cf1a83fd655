#include "io/pty.hpp"

#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>

#include "foundation/error.hpp"

namespace lattice::io {

PtyPair::PtyPair() {
  std::array<char, 128> name{};
  // openpty does not bound the name buffer; 128 is far above "/dev/pts/NNNN".
  if (::openpty(&master_, &slave_, name.data(), nullptr, nullptr) != 0)
    throw Error(ErrorKind::Serial, std::string("cannot create a pseudo-terminal: ") + std::strerror(errno));
  slavePath_ = name.data();
  ::fcntl(master_, F_SETFD, FD_CLOEXEC);
  ::fcntl(slave_, F_SETFD, FD_CLOEXEC);
  // The master end carries raw bytes; its own line discipline must not echo
  // or translate what the peer writes back to the slave.
  termios raw{};
  if (::tcgetattr(master_, &raw) == 0) {
    ::cfmakeraw(&raw);
    ::tcsetattr(master_, TCSANOW, &raw);
  }
}

PtyPair::~PtyPair() {
  releaseSlave();
  closeMaster();
}

void PtyPair::releaseSlave() {
  if (slave_ >= 0) ::close(slave_);
  slave_ = -1;
}

void PtyPair::closeMaster() {
  if (master_ >= 0) ::close(master_);
  master_ = -1;
}

}  // namespace lattice::io
