#pragma once
// A program run on a pseudo-terminal, with Lattice as its terminal: what a
// person at a Tektronix terminal on a Unix host had. The program's side is a
// real tty (it may ask for its size, set modes, be sent SIGHUP), so the
// program cannot tell it from a serial terminal.
//
// Method: openpty, then fork; the child starts a session, opens the slave
// (which makes it the controlling terminal), turns output processing off
// (OPOST: a graphics stream must arrive byte for byte, not with LF turned
// into CR LF), sets TERM to the device's terminfo name and execs the
// program. An exec that fails is reported through a close-on-exec pipe, so
// a misspelt program is an error of the command line, not a blank screen.
// The program's end is the master's EIO once every slave descriptor is
// closed; its status comes from waitpid. stop() hangs up the way a terminal
// does (SIGHUP to the process group), then SIGKILL if it is still there.
#include <sys/types.h>

#include <string>
#include <vector>

#include "app/term/term_source.hpp"
#include "io/pty.hpp"

namespace lattice::app {

class ProgramSource final : public TermSource {
 public:
  // Error(Usage) when `argv` is empty or its program cannot be run.
  ProgramSource(const std::vector<std::string>& argv, const std::string& termName);
  ~ProgramSource() override;
  int fd() const override { return pty_.masterFd(); }
  bool read(std::vector<std::uint8_t>& out) override;
  void write(std::span<const std::uint8_t> bytes) override;
  void stop() override;
  std::string endReason() const override;

 private:
  void reap(bool wait);

  io::PtyPair pty_;
  std::string name_;
  pid_t child_ = -1;
  int status_ = 0;
  bool reaped_ = false;
};

// The TERM a program is given for a device: its terminfo entry's name
// (ncurses' terminfo.src has tek4125, tek4027 and tek4014).
std::string termNameFor(const std::string& device);

}  // namespace lattice::app
