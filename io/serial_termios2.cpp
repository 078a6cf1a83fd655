// Deliberately no <termios.h> here: <asm/termbits.h> defines its own struct termios.
#include "io/serial_termios2.hpp"

#include <asm/termbits.h>
#include <sys/ioctl.h>

#include <cerrno>

namespace lattice::detail {

int setBaudTermios2(int fd, int baud) {
  struct termios2 settings {};
  if (::ioctl(fd, TCGETS2, &settings) != 0) return errno;
  // Both the output (CBAUD) and input (CBAUD << IBSHIFT) fields say "other".
  settings.c_cflag &= ~static_cast<tcflag_t>(CBAUD | (CBAUD << IBSHIFT));
  settings.c_cflag |= BOTHER | (BOTHER << IBSHIFT);
  settings.c_ospeed = static_cast<speed_t>(baud);
  settings.c_ispeed = static_cast<speed_t>(baud);
  if (::ioctl(fd, TCSETS2, &settings) != 0) return errno;
  return 0;
}

long readBaudTermios2(int fd) {
  struct termios2 settings {};
  if (::ioctl(fd, TCGETS2, &settings) != 0) return -1;
  return static_cast<long>(settings.c_ospeed);
}

}  // namespace lattice::detail
