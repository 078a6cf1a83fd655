#pragma once
// The user's terminal, played by a test: `lattice` runs with a real
// pseudo-terminal as its controlling terminal and its standard input,
// output and error, as it does in a person's xterm. The test reads what it
// draws, types keys, sends it signals, and reads the terminal's modes
// (termios) before, during and after, so "raw while running, restored on
// every way out" is checked on a real tty. Optionally it answers the
// device-attributes request as a sixel terminal (xterm -ti vt340) does.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "io/pty.hpp"
#include "tests/support/run_lattice.hpp"

namespace lattice::testing {

class PtyHost {
 public:
  // rows x columns of text, the text area's pixels; `sixel`: answer DA1
  // with attribute 4 and XTSMGRAPHICS with 256 registers.
  PtyHost(int rows, int columns, int pixelWidth, int pixelHeight, bool sixel) : sixel_(sixel) {
    winsize size{};
    size.ws_row = static_cast<unsigned short>(rows);
    size.ws_col = static_cast<unsigned short>(columns);
    size.ws_xpixel = static_cast<unsigned short>(pixelWidth);
    size.ws_ypixel = static_cast<unsigned short>(pixelHeight);
    slave_ = ::open(pty_.slavePath().c_str(), O_RDWR | O_NOCTTY);
    ::ioctl(slave_, TIOCSWINSZ, &size);
    // A shell's modes, as a person's terminal has them (PtyPair leaves its pty raw).
    ::tcgetattr(slave_, &before_);
    before_.c_lflag |= ICANON | ECHO | ECHOE | ISIG | IEXTEN;
    before_.c_iflag |= ICRNL | IXON;
    before_.c_oflag |= OPOST | ONLCR;
    ::tcsetattr(slave_, TCSANOW, &before_);
    ::tcgetattr(slave_, &before_);
    ::fcntl(pty_.masterFd(), F_SETFL, ::fcntl(pty_.masterFd(), F_GETFL) | O_NONBLOCK);
  }
  ~PtyHost() {
    if (child_ > 0 && !done_) {
      ::kill(child_, SIGKILL);
      ::waitpid(child_, nullptr, 0);
    }
    if (slave_ >= 0) ::close(slave_);
  }

  // Starts `lattice ARGS` (no shell) on the terminal.
  void start(const std::vector<std::string>& args) {
    std::vector<std::string> argv = {latticeBinary().string()};
    argv.insert(argv.end(), args.begin(), args.end());
    const std::string path = pty_.slavePath();
    child_ = ::fork();
    if (child_ == 0) {
      ::setsid();
      const int tty = ::open(path.c_str(), O_RDWR);
      ::ioctl(tty, TIOCSCTTY, 0);
      ::dup2(tty, 0);
      ::dup2(tty, 1);
      ::dup2(tty, 2);
      std::vector<char*> raw;
      for (std::string& a : argv) raw.push_back(a.data());
      raw.push_back(nullptr);
      ::execv(raw[0], raw.data());
      ::_exit(127);
    }
  }

  // Reads what the program drew for up to `seconds`, answering its
  // questions; returns early once it has exited. Notes raw mode when seen.
  void pump(double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
      termios now{};
      if (::tcgetattr(slave_, &now) == 0 && !(now.c_lflag & ICANON) && !(now.c_lflag & ECHO)) sawRaw_ = true;
      pollfd p{pty_.masterFd(), POLLIN, 0};
      ::poll(&p, 1, 20);
      char buffer[65536];
      ssize_t n;
      while ((n = ::read(pty_.masterFd(), buffer, sizeof buffer)) > 0) output_.append(buffer, static_cast<std::size_t>(n));
      if (sixel_ && !answered_ && output_.find("\x1b[c") != std::string::npos) {
        const std::string answer = "\x1b[?1;0;256S\x1b[?63;1;2;4;6;9;15;22c";
        (void)!::write(pty_.masterFd(), answer.data(), answer.size());
        answered_ = true;
      }
      if (!done_ && ::waitpid(child_, &status_, WNOHANG) == child_) done_ = true;
      if (done_ && n <= 0) return;
    }
  }
  // The window changes size: the kernel sends SIGWINCH to the program.
  void resize(int rows, int columns, int pixelWidth, int pixelHeight) {
    winsize size{};
    size.ws_row = static_cast<unsigned short>(rows);
    size.ws_col = static_cast<unsigned short>(columns);
    size.ws_xpixel = static_cast<unsigned short>(pixelWidth);
    size.ws_ypixel = static_cast<unsigned short>(pixelHeight);
    ::ioctl(slave_, TIOCSWINSZ, &size);
  }
  void type(const std::string& keys) { (void)!::write(pty_.masterFd(), keys.data(), keys.size()); }
  void signal(int s) { ::kill(child_, s); }
  // Pumps until the program exits (at most `seconds`); its exit code, or -1.
  int wait(double seconds) {
    pump(seconds);
    return done_ && WIFEXITED(status_) ? WEXITSTATUS(status_) : -1;
  }
  const std::string& output() const { return output_; }
  bool sawRaw() const { return sawRaw_; }
  // The terminal's modes now equal those it had before the program ran.
  bool restored() const {
    termios now{};
    ::tcgetattr(slave_, &now);
    return now.c_lflag == before_.c_lflag && now.c_iflag == before_.c_iflag && now.c_oflag == before_.c_oflag &&
           now.c_cflag == before_.c_cflag;
  }

 private:
  io::PtyPair pty_;
  int slave_ = -1;  // kept open so the terminal outlives the program and can be inspected
  bool sixel_;
  bool answered_ = false;
  bool sawRaw_ = false;
  bool done_ = false;
  int status_ = 0;
  pid_t child_ = -1;
  termios before_{};
  std::string output_;
};

}  // namespace lattice::testing
