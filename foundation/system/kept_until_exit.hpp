#pragma once
// Objects a command is done with just before the process exits, kept instead
// of destroyed: the operating system takes back their memory at exit at once,
// where their destructors would walk and free every node (a scene's thousands
// of leaves and unions) on one thread after the outputs are written.
//
// Method: ownership moves into a list that is itself never destroyed; the
// list stays reachable from a static pointer, so LeakSanitizer (which reports
// only unreachable blocks) says nothing. Only for what needs no destructor to
// run: nothing flushed, unlocked or removed on destruction (outputs are
// committed before, through AtomicFile / OutputTransaction).
#include <memory>
#include <utility>
#include <vector>

namespace lattice {

// The objects kept so far (for tests); the list lives until the process ends.
inline std::vector<std::shared_ptr<void>>& keptUntilExit() {
  static auto* kept = new std::vector<std::shared_ptr<void>>();  // never deleted: nothing runs at exit
  return *kept;
}

template <typename T>
void keepUntilExit(std::unique_ptr<T> owned) {
  keptUntilExit().push_back(std::shared_ptr<T>(std::move(owned)));
}

}  // namespace lattice
