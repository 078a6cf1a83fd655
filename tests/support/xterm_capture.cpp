#include "tests/support/xterm_capture.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <thread>

#include "foundation/error.hpp"
#include "tests/support/temp_dir.hpp"

namespace lattice::testing {
namespace {

using Clock = std::chrono::steady_clock;

bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::string dirs = path;
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const std::string file = dirs.substr(start, end - start) + "/" + program;
    if (::access(file.c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

// A child process, killed and reaped when this goes out of scope.
class Child {
 public:
  // `keepFd` stays open in the child (Xvfb's -displayfd); output goes to /dev/null.
  Child(const std::vector<std::string>& argv, const std::string& display, int keepFd = -1) {
    pid_ = ::fork();
    if (pid_ != 0) return;
    const int devNull = ::open("/dev/null", O_RDWR);
    if (devNull >= 0) {
      ::dup2(devNull, 0);
      ::dup2(devNull, 1);
      ::dup2(devNull, 2);
    }
    if (keepFd >= 0) ::fcntl(keepFd, F_SETFD, 0);
    if (!display.empty()) ::setenv("DISPLAY", display.c_str(), 1);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execvp(args[0], args.data());
    ::_exit(127);
  }
  ~Child() { stop(); }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  bool started() const { return pid_ > 0; }
  // True when the child has exited (and is reaped); its status in `status`.
  bool exited(int& status) {
    if (pid_ <= 0) return true;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      return true;
    }
    return false;
  }
  void stop() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGTERM);
    int status = 0;
    for (int i = 0; i < 40; ++i) {  // two seconds to go quietly, then SIGKILL
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
  }

 private:
  pid_t pid_ = -1;
};

// Runs a program to its end; its exit status, or -1.
int runToEnd(const std::vector<std::string>& argv, const std::string& display) {
  Child child(argv, display);
  if (!child.started()) return -1;
  int status = 0;
  const auto deadline = Clock::now() + std::chrono::seconds(20);
  while (!child.exited(status)) {
    if (Clock::now() > deadline) return -1;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::vector<std::uint8_t> readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::uint32_t field(const std::vector<std::uint8_t>& b, std::size_t index) {
  const std::size_t at = index * 4;
  return std::uint32_t(b[at]) << 24 | std::uint32_t(b[at + 1]) << 16 | std::uint32_t(b[at + 2]) << 8 | b[at + 3];
}

int shiftOf(std::uint32_t mask) {
  int shift = 0;
  while (mask != 0 && (mask & 1u) == 0) {
    mask >>= 1;
    ++shift;
  }
  return shift;
}

}  // namespace

std::string missingXtermPeers() {
  std::string missing;
  for (const char* program : {"Xvfb", "xterm", "xwd"})
    if (!onPath(program)) missing += std::string(missing.empty() ? "" : ", ") + program;
  return missing;
}

RgbImage decodeXwd(const std::vector<std::uint8_t>& b) {
  const auto bad = [](const std::string& what) { return Error(ErrorKind::Input, "xwd capture: " + what); };
  if (b.size() < 100) throw bad("shorter than its 100-byte header");
  const std::uint32_t headerSize = field(b, 0), version = field(b, 1), format = field(b, 2);
  const std::uint32_t width = field(b, 4), height = field(b, 5), byteOrder = field(b, 7);
  const std::uint32_t bitsPerPixel = field(b, 11), bytesPerLine = field(b, 12);
  const std::uint32_t redMask = field(b, 14), greenMask = field(b, 15), blueMask = field(b, 16);
  const std::uint32_t colours = field(b, 19);
  if (version != 7 || format != 2) throw bad("not a version 7 ZPixmap dump");
  if (bitsPerPixel != 24 && bitsPerPixel != 32) throw bad("not 24 or 32 bits a pixel");
  if (width == 0 || height == 0 || width > 16384 || height > 16384) throw bad("implausible size");
  const std::uint64_t start = std::uint64_t(headerSize) + std::uint64_t(colours) * 12;
  if (bytesPerLine < width * (bitsPerPixel / 8) || start + std::uint64_t(bytesPerLine) * height > b.size())
    throw bad("pixel data cut short");
  RgbImage image(static_cast<int>(width), static_cast<int>(height));
  const std::uint32_t step = bitsPerPixel / 8;
  for (std::uint32_t y = 0; y < height; ++y)
    for (std::uint32_t x = 0; x < width; ++x) {
      const std::uint8_t* p = &b[start + std::uint64_t(y) * bytesPerLine + std::uint64_t(x) * step];
      std::uint32_t v = 0;
      for (std::uint32_t i = 0; i < step; ++i)  // byte_order 0: least significant byte first
        v |= std::uint32_t(p[i]) << (8 * (byteOrder == 0 ? i : step - 1 - i));
      std::uint8_t* out = image.pixel(static_cast<int>(x), static_cast<int>(y));
      out[0] = static_cast<std::uint8_t>((v & redMask) >> shiftOf(redMask));
      out[1] = static_cast<std::uint8_t>((v & greenMask) >> shiftOf(greenMask));
      out[2] = static_cast<std::uint8_t>((v & blueMask) >> shiftOf(blueMask));
    }
  return image;
}

XtermCapture captureXterm(const XtermCaptureOptions& o) {
  XtermCapture result;
  if (const std::string missing = missingXtermPeers(); !missing.empty()) {
    result.skipReason = "not on PATH: " + missing + " (scripts/setup.sh installs xvfb, xterm and x11-apps)";
    return result;
  }
  const auto deadline = Clock::now() + std::chrono::milliseconds(static_cast<long>(o.timeoutSeconds * 1000));
  TempDir scratch("xterm-capture");

  // Xvfb picks a free display itself and writes its number once it listens.
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    result.skipReason = "cannot make a pipe for Xvfb";
    return result;
  }
  Child xvfb({"Xvfb", "-displayfd", std::to_string(fds[1]), "-screen", "0",
              std::to_string(o.screenWidth) + "x" + std::to_string(o.screenHeight) + "x24", "-nolisten", "tcp"},
             "", fds[1]);
  ::close(fds[1]);
  std::string number;
  while (Clock::now() < deadline) {
    pollfd p{fds[0], POLLIN, 0};
    if (::poll(&p, 1, 100) <= 0) continue;
    char c = 0;
    if (::read(fds[0], &c, 1) != 1 || c == '\n') break;
    number += c;
  }
  ::close(fds[0]);
  if (number.empty()) {
    result.skipReason = "Xvfb did not start (no display number within the time-out)";
    return result;
  }
  const std::string display = ":" + number;

  const std::string marker = scratch / "window-id";
  std::vector<std::string> xtermArgs = {"xterm", "-b", "0", "-bw", "0"};
  xtermArgs.insert(xtermArgs.end(), o.xtermArguments.begin(), o.xtermArguments.end());
  const std::vector<std::string> shell = {
      "-e", "sh", "-c",
      "s=\"$1\"; m=\"$2\"; shift 2; printf '\\033[?25l'; if [ $# -gt 0 ]; then \"$@\"; else cat \"$s\"; fi; "
      "printf %s \"$WINDOWID\" > \"$m.part\"; mv \"$m.part\" \"$m\"; exec sleep 600",
      "sh", o.streamFile, marker};
  xtermArgs.insert(xtermArgs.end(), shell.begin(), shell.end());
  xtermArgs.insert(xtermArgs.end(), o.command.begin(), o.command.end());
  Child xterm(xtermArgs, display);

  std::string windowId;
  int status = 0;
  while (Clock::now() < deadline && windowId.empty()) {
    if (xterm.exited(status)) {
      result.skipReason = "xterm exited before the stream was shown (status " + std::to_string(status) + ")";
      return result;
    }
    const auto bytes = readAll(marker);
    windowId.assign(bytes.begin(), bytes.end());
    if (windowId.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  if (windowId.empty()) {
    result.skipReason = "xterm did not finish showing the stream within the time-out";
    return result;
  }

  const std::string dump = scratch / "window.xwd";
  std::vector<std::uint8_t> previous;
  while (true) {
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    const std::vector<std::string> which =
        o.windowName.empty() ? std::vector<std::string>{"-id", windowId} : std::vector<std::string>{"-name", o.windowName};
    if (runToEnd({"xwd", "-silent", "-nobdrs", which[0], which[1], "-out", dump}, display) != 0) {
      result.skipReason = "xwd could not capture xterm's window " + which[1];
      return result;
    }
    std::vector<std::uint8_t> bytes = readAll(dump);
    const bool settled = bytes == previous;
    previous = std::move(bytes);
    if (settled || Clock::now() > deadline) break;
  }
  result.window = decodeXwd(previous);
  return result;
}

}  // namespace lattice::testing
