#pragma once
// Errors that reach the user. Every failure a user can cause (bad scene, bad
// LHT file, bad stream, serial fault, bad flag) is thrown as lattice::Error
// with a message that names the file (and line:column where there is one),
// what was expected, and how to fix it. The CLI maps the category to the
// process exit code documented in docs/cli.md, so scripts can tell a bad
// input from a dead serial line.
#include <stdexcept>
#include <string>

namespace lattice {

enum class ErrorKind : int {
  Usage = 2,        // wrong flags or arguments
  Input = 3,        // a scene, LHT, PNG or stream file that cannot be used
  Output = 4,       // cannot write an output file
  Serial = 5,       // serial port cannot be opened or configured
  Stalled = 6,      // flow control held the line past --stall-timeout (resumable)
  HangUp = 7,       // the peer went away mid-stream
  Budget = 8,       // --memory-budget cannot be met
  Internal = 70,    // a bug: an invariant of ours failed
};

// Whether a command's outputs land when it fails with this error
// (foundation/system/output_transaction.hpp): almost never; Keep is for a
// failure found after complete outputs were made, which the user still wants
// (a render whose measured peak broke --memory-budget; the smallest stream
// when nothing fits a wire budget).
enum class Outputs { Discard, Keep };

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message, Outputs outputs = Outputs::Discard)
      : std::runtime_error(message), kind_(kind), outputs_(outputs) {}
  ErrorKind kind() const noexcept { return kind_; }
  int exitCode() const noexcept { return static_cast<int>(kind_); }
  bool keepsOutputs() const noexcept { return outputs_ == Outputs::Keep; }

 private:
  ErrorKind kind_;
  Outputs outputs_;
};

// "path:line:col: message", the form editors and compilers use, so a user can
// jump to the place.
std::string locate(const std::string& path, long line, long column, const std::string& message);

}  // namespace lattice
