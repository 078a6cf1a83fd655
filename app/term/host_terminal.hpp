#pragma once
// The terminal the user runs `lattice term` in, put in raw mode for as long
// as the session lasts: every key goes to the program as typed (Ctrl-C
// included, as on a real terminal's line), nothing is echoed by the host.
//
// Method: the modes found at the start are saved and put back by the
// destructor, which every way out of the session passes through (the end of
// the program or line, the quit key, an error, SIGINT/SIGTERM/SIGHUP, which
// the session catches and turns into an ordinary end). For the signals that
// cannot be caught that way (a crash: SIGSEGV, SIGBUS, SIGFPE, SIGILL,
// SIGABRT) a handler puts the saved modes back with tcsetattr, which is
// async-signal-safe, and then lets the signal take its default course.
// SIGKILL cannot be handled by anyone; `stty sane` is the remedy, said in docs/term.md.
#include <termios.h>

namespace lattice::app {

class HostTerminal {
 public:
  // `fd`: the user's terminal (standard input). Not a terminal: nothing is changed.
  explicit HostTerminal(int fd);
  ~HostTerminal();
  HostTerminal(const HostTerminal&) = delete;
  HostTerminal& operator=(const HostTerminal&) = delete;
  bool isTerminal() const { return saved_; }

 private:
  int fd_;
  bool saved_ = false;
  termios original_{};
};

}  // namespace lattice::app
