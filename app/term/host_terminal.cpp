#include "app/term/host_terminal.hpp"

#include <signal.h>
#include <unistd.h>

#include <array>

namespace lattice::app {
namespace {

constexpr std::array<int, 5> kCrashSignals = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};

// What the crash handler needs, in plain statics (a handler may read them).
int gFd = -1;
termios gOriginal{};
std::array<struct sigaction, kCrashSignals.size()> gPrevious{};

void restoreOnCrash(int signal) {
  if (gFd >= 0) ::tcsetattr(gFd, TCSANOW, &gOriginal);
  for (std::size_t i = 0; i < kCrashSignals.size(); ++i)
    if (kCrashSignals[i] == signal) ::sigaction(signal, &gPrevious[i], nullptr);
  ::raise(signal);
}

}  // namespace

HostTerminal::HostTerminal(int fd) : fd_(fd) {
  if (!::isatty(fd) || ::tcgetattr(fd, &original_) != 0) return;
  saved_ = true;
  gOriginal = original_;
  gFd = fd;
  struct sigaction action {};
  action.sa_handler = restoreOnCrash;
  sigemptyset(&action.sa_mask);
  for (std::size_t i = 0; i < kCrashSignals.size(); ++i) ::sigaction(kCrashSignals[i], &action, &gPrevious[i]);
  termios raw = original_;
  ::cfmakeraw(&raw);
  raw.c_cc[VMIN] = 1;
  raw.c_cc[VTIME] = 0;
  ::tcsetattr(fd, TCSANOW, &raw);
}

HostTerminal::~HostTerminal() {
  if (!saved_) return;
  ::tcsetattr(fd_, TCSANOW, &original_);
  for (std::size_t i = 0; i < kCrashSignals.size(); ++i) ::sigaction(kCrashSignals[i], &gPrevious[i], nullptr);
  gFd = -1;
}

}  // namespace lattice::app
