#pragma once
// Temporary files that must not outlive the process, even when it is killed.
//
// Method: a fixed table of live temporary paths (kSlots entries, no
// allocation) and handlers for SIGINT, SIGTERM and SIGHUP that unlink every
// live one (unlink is async-signal-safe), restore the default action and
// re-raise the signal, so the process still dies of it with the usual status.
// Handlers are installed on first use, and only for signals whose action is
// still the default: an ignored SIGHUP (nohup) stays ignored, and a handler
// someone else installed is left alone. SIGKILL cannot be caught: a temporary
// can survive only that (or a power cut), and its name says what it is.
//
// A path is registered before the file is created and released after it is
// renamed or unlinked, so the handler may unlink a name that does not exist
// yet or any more (harmless), but never misses a file that does.
#include <cstddef>

namespace lattice {

class TempFileRegistry {
 public:
  static constexpr std::size_t kSlots = 64;  // live temporaries at once; more are not signal-protected
  static constexpr std::size_t kPathBytes = 4096;

  // The slot holding `path`, or -1 when the table is full or the path too long.
  static int add(const char* path);
  static void remove(int slot);  // no-op for -1
  static std::size_t live();     // registered now (for tests)
};

}  // namespace lattice
