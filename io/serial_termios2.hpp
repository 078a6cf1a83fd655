#pragma once
// Linux's termios2 interface (ioctl TCSETS2 with BOTHER) sets any baud rate,
// not only the Bnnn constants. Its header <asm/termbits.h> clashes with
// <termios.h>, so it lives alone in serial_termios2.cpp behind this interface.

namespace lattice::detail {

// Sets input and output speed to `baud` exactly (BOTHER). Returns 0, or the
// errno of the refused ioctl.
int setBaudTermios2(int fd, int baud);
// The output speed the driver actually set, or -1 if it cannot be read.
long readBaudTermios2(int fd);

}  // namespace lattice::detail
