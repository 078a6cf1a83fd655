#include "app/term/dialog_lines.hpp"

namespace lattice::app {

std::vector<std::string> lastDialogLines(const std::string& text, std::size_t count, std::size_t width) {
  std::vector<std::string> lines(1);
  std::size_t column = 0;
  for (char c : text) {
    if (c == '\n') {
      lines.emplace_back();
      column = 0;
    } else if (c == '\r') {
      column = 0;
    } else {
      if (width > 0 && column >= width) {
        lines.emplace_back();
        column = 0;
      }
      std::string& line = lines.back();
      if (column < line.size()) line[column] = c;
      else line.push_back(c);
      ++column;
    }
  }
  // A text that ends with LF leaves the cursor on an empty line: not shown.
  if (lines.size() > 1 && lines.back().empty()) lines.pop_back();
  if (lines.size() > count) lines.erase(lines.begin(), lines.end() - static_cast<std::ptrdiff_t>(count));
  return lines;
}

}  // namespace lattice::app
