#include "foundation/system/temp_file_registry.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>
#include <mutex>

namespace lattice {
namespace {

// state: 0 free, 1 being filled, 2 live (the handler reads only live slots).
// constinit with a zeroed path: all zero bits, so the table is .bss that no
// start-up code writes (without it GCC stores each state at start-up, one
// per page: 256 KiB resident before main).
struct Slot {
  std::atomic<int> state{0};
  char path[TempFileRegistry::kPathBytes]{};
};
constinit Slot slots[TempFileRegistry::kSlots];
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

extern "C" void unlinkTemporariesAndReraise(int signal) {
  for (Slot& s : slots)
    if (s.state.load(std::memory_order_acquire) == 2) ::unlink(s.path);
  std::signal(signal, SIG_DFL);
  std::raise(signal);  // blocked until this handler returns, then the default action
}

void installHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int signal : kSignals) {
      struct sigaction current {};
      if (::sigaction(signal, nullptr, &current) != 0 || current.sa_handler != SIG_DFL) continue;
      struct sigaction action {};
      action.sa_handler = unlinkTemporariesAndReraise;
      sigemptyset(&action.sa_mask);
      for (int other : kSignals) sigaddset(&action.sa_mask, other);  // one handler run at a time
      ::sigaction(signal, &action, nullptr);
    }
  });
}

}  // namespace

int TempFileRegistry::add(const char* path) {
  installHandlers();
  const std::size_t length = std::strlen(path);
  if (length >= kPathBytes) return -1;
  for (std::size_t i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (!slots[i].state.compare_exchange_strong(expected, 1, std::memory_order_acq_rel)) continue;
    std::memcpy(slots[i].path, path, length + 1);
    slots[i].state.store(2, std::memory_order_release);
    return static_cast<int>(i);
  }
  return -1;
}

void TempFileRegistry::remove(int slot) {
  if (slot >= 0) slots[static_cast<std::size_t>(slot)].state.store(0, std::memory_order_release);
}

std::size_t TempFileRegistry::live() {
  std::size_t n = 0;
  for (const Slot& s : slots) n += s.state.load(std::memory_order_acquire) == 2;
  return n;
}

}  // namespace lattice
