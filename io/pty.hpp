#pragma once
// A pseudo-terminal pair: the slave side is a real tty with a line
// discipline (termios, IXON, TIOCEXCL) that SerialPort opens by path like
// any serial port, the master side is the "terminal" at the other end.
// Tests use it as a peer that reads, sends XOFF/XON or hangs up; it can also
// connect `lattice send` to an emulator without hardware.
#include <string>

namespace lattice::io {

class PtyPair {
 public:
  // Error(Serial) if the system has no ptys left.
  PtyPair();
  ~PtyPair();
  PtyPair(const PtyPair&) = delete;
  PtyPair& operator=(const PtyPair&) = delete;

  // The path to open as a serial port, e.g. /dev/pts/3.
  const std::string& slavePath() const { return slavePath_; }
  int masterFd() const { return master_; }
  // The pair keeps its own slave fd open until released so that the master
  // does not see a hang-up between openpty() and the port's open().
  void releaseSlave();
  // Closing the master is the peer hanging up: the slave's writes fail with EIO.
  void closeMaster();

 private:
  int master_ = -1;
  int slave_ = -1;
  std::string slavePath_;
};

}  // namespace lattice::io
