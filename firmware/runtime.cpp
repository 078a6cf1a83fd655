// What newlib and libgcc ask of the platform, for a program with no
// operating system, no files and one thread (docs/firmware.md):
// - _sbrk: the heap grows from the end of .bss towards the stack and no
//   further (the linker script's budget); running out makes malloc fail, so
//   operator new throws std::bad_alloc like on the host.
// - _write etc.: there are no files (and no clock: _gettimeofday); anything newlib would print goes to the
//   host's stderr through semihosting, never to the UART (the Tek stream).
// - the 64-bit atomics GCC calls out to on a core with only 32-bit
//   exclusive loads (libatomic's __atomic_*_8): one core, no interrupt
//   touches them, so a plain load and store with interrupts masked is exact.
#include <sys/stat.h>
#include <sys/time.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>

#include "firmware/memory_marks.hpp"
#include "firmware/semihosting.hpp"

extern "C" {
extern char __heap_start, __heap_end;

void* _sbrk(std::ptrdiff_t increment) {
  static char* brk = &__heap_start;
  if (increment > &__heap_end - brk || increment < &__heap_start - brk) {
    errno = ENOMEM;
    return reinterpret_cast<void*>(-1);
  }
  char* old = brk;
  brk += increment;
  lattice::firmware::noteHeapBreak(static_cast<std::size_t>(brk - &__heap_start));
  return old;
}

int _write(int, const char* text, int length) {
  lattice::firmware::hostReport(std::string_view(text, static_cast<std::size_t>(length)));
  return length;
}
int _read(int, char*, int) { return 0; }
int _close(int) { return -1; }
int _lseek(int, int, int) { return 0; }
int _isatty(int) { return 1; }
int _fstat(int, struct stat* st) {
  st->st_mode = S_IFCHR;
  return 0;
}
int _getpid() { return 1; }
int _kill(int, int) {
  errno = EINVAL;
  return -1;
}
void _exit(int status) { lattice::firmware::hostExit(status); }
// The clocks (std::chrono, used for progress and line timing) read a time of
// day the board does not keep: always the epoch. No output depends on it.
int _gettimeofday(struct timeval* tv, void*) {
  if (tv) *tv = {};
  return 0;
}
// libstdc++'s std::random_device asks for it; the firmware has no entropy.
int getentropy(void*, std::size_t) {
  errno = ENOSYS;
  return -1;
}

namespace {
std::uint32_t maskInterrupts() {
  std::uint32_t primask;
  __asm__ volatile("mrs %0, primask\n cpsid i" : "=r"(primask)::"memory");
  return primask;
}
void restoreInterrupts(std::uint32_t primask) { __asm__ volatile("msr primask, %0" ::"r"(primask) : "memory"); }
}  // namespace

std::uint64_t __atomic_load_8(const volatile void* p, int) {
  const std::uint32_t m = maskInterrupts();
  const std::uint64_t v = *static_cast<const volatile std::uint64_t*>(p);
  restoreInterrupts(m);
  return v;
}
void __atomic_store_8(volatile void* p, std::uint64_t v, int) {
  const std::uint32_t m = maskInterrupts();
  *static_cast<volatile std::uint64_t*>(p) = v;
  restoreInterrupts(m);
}
std::uint64_t __atomic_fetch_or_8(volatile void* p, std::uint64_t v, int) {
  const std::uint32_t m = maskInterrupts();
  auto* q = static_cast<volatile std::uint64_t*>(p);
  const std::uint64_t old = *q;
  *q = old | v;
  restoreInterrupts(m);
  return old;
}
std::uint64_t __atomic_fetch_add_8(volatile void* p, std::uint64_t v, int) {
  const std::uint32_t m = maskInterrupts();
  auto* q = static_cast<volatile std::uint64_t*>(p);
  const std::uint64_t old = *q;
  *q = old + v;
  restoreInterrupts(m);
  return old;
}
}
