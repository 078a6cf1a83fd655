#include "app/term/host_graphics.hpp"

#include <poll.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <chrono>
#include <regex>
#include <string_view>

#include "app/term/term_write.hpp"

namespace lattice::app {
namespace {

std::vector<int> numbersIn(const std::string& text) {
  std::vector<int> numbers;
  int value = 0;
  bool any = false;
  for (char c : text) {
    if (c >= '0' && c <= '9') {
      value = value * 10 + (c - '0');
      any = true;
      if (value > 1000000) value = 1000000;  // an answer is a handful of small numbers
    } else {
      if (any) numbers.push_back(value);
      value = 0;
      any = false;
    }
  }
  if (any) numbers.push_back(value);
  return numbers;
}

}  // namespace

bool readHostAnswers(const std::string& text, HostGraphics& host) {
  static const std::regex graphics("\x1b\\[\\?1;([0-9]+);([0-9]+)S");
  static const std::regex pixels("\x1b\\[4;([0-9]+);([0-9]+)t");
  static const std::regex attributes("\x1b\\[\\?([0-9;]*)c");
  std::smatch m;
  if (std::regex_search(text, m, graphics) && m[1] == "0") host.registers = std::stoi(m[2].str().substr(0, 6));
  if (std::regex_search(text, m, pixels) && host.pixelWidth == 0) {
    host.pixelHeight = std::stoi(m[1].str().substr(0, 6));
    host.pixelWidth = std::stoi(m[2].str().substr(0, 6));
  }
  if (!std::regex_search(text, m, attributes)) return false;
  const std::vector<int> list = numbersIn(m[1].str());
  host.sixel = false;
  for (std::size_t i = 1; i < list.size(); ++i)  // the first is the terminal's class
    if (list[i] == 4) host.sixel = true;
  if (!host.sixel) host.why = "the terminal's device attributes (" + m[1].str() + ") do not list sixel graphics (4)";
  return true;
}

bool readWindowSize(int fd, HostGraphics& host) {
  winsize size{};
  if (::ioctl(fd, TIOCGWINSZ, &size) != 0 || size.ws_col == 0 || size.ws_row == 0) return false;
  const int cellWidth = host.cellWidth(), cellHeight = host.cellHeight();
  host.columns = size.ws_col;
  host.rows = size.ws_row;
  host.pixelWidth = size.ws_xpixel > 0 ? size.ws_xpixel : cellWidth * host.columns;
  host.pixelHeight = size.ws_ypixel > 0 ? size.ws_ypixel : cellHeight * host.rows;
  return true;
}

HostGraphics askHost(int in, int out) {
  HostGraphics host;
  winsize size{};
  if (::ioctl(out, TIOCGWINSZ, &size) == 0 && size.ws_col > 0 && size.ws_row > 0) {
    host.columns = size.ws_col;
    host.rows = size.ws_row;
    host.pixelWidth = size.ws_xpixel;
    host.pixelHeight = size.ws_ypixel;
  }
  const std::string_view ask = host.pixelWidth > 0 ? "\x1b[?1;1;0S\x1b[c" : "\x1b[?1;1;0S\x1b[14t\x1b[c";
  writeToPeer(out, std::span(reinterpret_cast<const std::uint8_t*>(ask.data()), ask.size()));
  std::string answers;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(kAskSeconds);
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      host.sixel = false;
      host.why = "the terminal did not answer a device-attributes request (DA1) within a second";
      return host;
    }
    pollfd p{in, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
    char buffer[256];
    const ssize_t n = ::read(in, buffer, sizeof buffer);
    if (n <= 0) continue;
    answers.append(buffer, static_cast<std::size_t>(n));
    if (answers.size() > 4096) answers.erase(0, answers.size() - 4096);  // a terminal that chatters
    if (readHostAnswers(answers, host)) return host;
  }
}

}  // namespace lattice::app
