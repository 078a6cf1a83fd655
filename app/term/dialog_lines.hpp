#pragma once
// The last lines of a terminal's dialog area, as a text terminal shows them:
// LF starts a new line, a CR alone returns to the line's start (the next
// characters overwrite it, as a typewriter's carriage would), a line longer
// than the width wraps. `lattice term` shows these under the picture.
#include <string>
#include <vector>

namespace lattice::app {

// At most `count` lines of at most `width` characters, oldest first.
std::vector<std::string> lastDialogLines(const std::string& text, std::size_t count, std::size_t width);

}  // namespace lattice::app
