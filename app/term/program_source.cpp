#include "app/term/program_source.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

#include "app/term/term_write.hpp"
#include "foundation/error.hpp"
#include "io/stream_sender.hpp"

namespace lattice::app {
namespace {

// The child's side, between fork and exec: only async-signal-safe calls.
[[noreturn]] void runChild(const std::string& slavePath, char* const* argv, const char* term, int errorPipe) {
  ::setsid();
  const int slave = ::open(slavePath.c_str(), O_RDWR);  // a session leader's first tty becomes its terminal
  if (slave < 0) {
    const int error = errno;
    (void)!::write(errorPipe, &error, sizeof error);
    ::_exit(127);
  }
  ::ioctl(slave, TIOCSCTTY, 0);
  termios mode{};
  if (::tcgetattr(slave, &mode) == 0) {
    mode.c_oflag &= ~static_cast<tcflag_t>(OPOST);  // graphics bytes arrive as written
    ::tcsetattr(slave, TCSANOW, &mode);
  }
  winsize size{};
  size.ws_row = 24;  // a dialog area's text lines and columns, for programs that ask
  size.ws_col = 80;
  ::ioctl(slave, TIOCSWINSZ, &size);
  ::dup2(slave, 0);
  ::dup2(slave, 1);
  ::dup2(slave, 2);
  if (slave > 2) ::close(slave);
  ::setenv("TERM", term, 1);
  // The parent's signal dispositions are not the program's business.
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGCHLD}) ::signal(s, SIG_DFL);
  ::execvp(argv[0], argv);
  const int error = errno;
  (void)!::write(errorPipe, &error, sizeof error);
  ::_exit(127);
}

}  // namespace

std::string termNameFor(const std::string& device) {
  if (device == "tek4027" || device == "tek4014") return device;
  return "tek4125";
}

ProgramSource::ProgramSource(const std::vector<std::string>& argv, const std::string& termName) {
  if (argv.empty())
    throw Error(ErrorKind::Usage, "term: name the program to run after --, e.g. lattice term -- gnuplot plot.gp");
  name_ = argv.front();
  std::vector<std::string> args = argv;
  std::vector<char*> pointers;
  for (std::string& arg : args) pointers.push_back(arg.data());
  pointers.push_back(nullptr);
  int pipeFds[2];
  if (::pipe2(pipeFds, O_CLOEXEC) != 0)
    throw Error(ErrorKind::Internal, fmt::format("term: cannot make a pipe: {}", std::strerror(errno)));
  const std::string slavePath = pty_.slavePath();
  child_ = ::fork();
  if (child_ < 0) {
    ::close(pipeFds[0]);
    ::close(pipeFds[1]);
    throw Error(ErrorKind::Usage, fmt::format("term: cannot start {}: {}", name_, std::strerror(errno)));
  }
  if (child_ == 0) runChild(slavePath, pointers.data(), termName.c_str(), pipeFds[1]);
  ::close(pipeFds[1]);
  int childError = 0;
  ssize_t got;
  do got = ::read(pipeFds[0], &childError, sizeof childError);
  while (got < 0 && errno == EINTR);
  ::close(pipeFds[0]);
  // The child has the slave open (or failed to): ours would keep the master from seeing its end.
  pty_.releaseSlave();
  if (got == static_cast<ssize_t>(sizeof childError)) {
    reap(true);
    throw Error(ErrorKind::Usage, fmt::format("term: cannot run {}: {} (check the name and PATH)", name_,
                                              std::strerror(childError)));
  }
  ::fcntl(pty_.masterFd(), F_SETFL, ::fcntl(pty_.masterFd(), F_GETFL) | O_NONBLOCK);
}

ProgramSource::~ProgramSource() {
  if (!reaped_) stop();
}

bool ProgramSource::read(std::vector<std::uint8_t>& out) {
  std::uint8_t buffer[65536];
  for (;;) {
    const ssize_t n = ::read(pty_.masterFd(), buffer, sizeof buffer);
    if (n > 0) {
      out.insert(out.end(), buffer, buffer + n);
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) return true;
    // EIO (or end of file): every slave descriptor is closed, the program is gone.
    reap(true);
    return false;
  }
}

void ProgramSource::write(std::span<const std::uint8_t> bytes) { writeToPeer(pty_.masterFd(), bytes); }

void ProgramSource::stop() {
  if (reaped_ || child_ <= 0) return;
  ::kill(-child_, SIGHUP);  // the terminal hangs up on the program's session
  ::kill(child_, SIGHUP);
  for (int i = 0; i < 50 && !reaped_; ++i) {
    reap(false);
    if (!reaped_) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (!reaped_) {
    ::kill(-child_, SIGKILL);
    ::kill(child_, SIGKILL);
    reap(true);
  }
}

void ProgramSource::reap(bool wait) {
  if (reaped_ || child_ <= 0) return;
  pid_t done;
  do done = ::waitpid(child_, &status_, wait ? 0 : WNOHANG);
  while (done < 0 && errno == EINTR);
  if (done == child_ || (done < 0 && errno == ECHILD)) reaped_ = true;
}

std::string ProgramSource::endReason() const {
  if (!reaped_) return fmt::format("{} closed the terminal", name_);
  if (WIFSIGNALED(status_)) return fmt::format("{} was killed by {}", name_, io::signalName(WTERMSIG(status_)));
  return fmt::format("{} exited with status {}", name_, WEXITSTATUS(status_));
}

}  // namespace lattice::app
