#pragma once
// Where a terminal's bytes come from, and where its keys and answers go: a
// program on a pseudo-terminal, a serial line, or a recorded stream played at
// a line rate. The session (term_session.hpp) polls one of these beside the
// user's keyboard, so each source says which descriptor to wait on (or how
// long until it has more, for a played stream) and why it ended.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "app/term/term_options.hpp"

namespace lattice::app {

class TermSource {
 public:
  virtual ~TermSource() = default;
  // The descriptor to poll for input; -1 when there is none (a played stream).
  virtual int fd() const = 0;
  // Appends what has arrived to `out`; false once the source has ended (the
  // program exited, the line hung up, the stream is played out).
  virtual bool read(std::vector<std::uint8_t>& out) = 0;
  // Keys and answers toward the program or the line; a played stream has no
  // one to hear them and drops them.
  virtual void write(std::span<const std::uint8_t> bytes) = 0;
  // Milliseconds until read() has more without the descriptor waking the
  // poll (a paced stream), or -1: wait for the descriptor.
  virtual int timeoutMs() const { return -1; }
  // Ends the source early (the user quit): a program is hung up on.
  virtual void stop() {}
  // Once read() has returned false: why, in words ("the program exited with status 0").
  virtual std::string endReason() const = 0;
};

// Chosen by options.source; the device's profile gives a played stream its
// baud rate when none was given. Errors: Usage (a program that cannot be
// run), Serial (a port that cannot be opened), Input (a stream unreadable
// or over kMaxStreamBytes).
std::unique_ptr<TermSource> openTermSource(const TermOptions& options, int profileBaud);

}  // namespace lattice::app
