#include "firmware/virtual_clock.hpp"

namespace lattice::firmware {
namespace {

struct SysTick {
  volatile std::uint32_t csr, rvr, cvr, calib;
};
SysTick& systick() { return *reinterpret_cast<SysTick*>(std::uintptr_t{0xE000E010}); }
constexpr std::uint32_t kReload = 0xFFFFFF;
constexpr std::uint32_t kEnable = 1u << 0, kInterrupt = 1u << 1, kProcessorClock = 1u << 2;
volatile std::uint32_t wraps = 0;
std::uint64_t start = 0;

std::uint64_t rawTicks() {
  std::uint32_t before, value;
  do {  // a wrap between the two reads shows as a changed count: read again
    before = wraps;
    value = systick().cvr;
  } while (before != wraps);
  return std::uint64_t{before} * (kReload + 1) + (kReload - value);
}

}  // namespace

void countWrap() { wraps = wraps + 1; }

void startClock() {
  systick().rvr = kReload;
  systick().cvr = 0;
  systick().csr = kEnable | kInterrupt | kProcessorClock;
  // Writing CVR clears it; it holds 0 until the first tick reloads it, and
  // 0 would read as a whole period gone. Start counting after that tick.
  while (systick().cvr == 0) {
  }
  start = rawTicks();
}

std::uint64_t clockTicks() { return rawTicks() - start; }

}  // namespace lattice::firmware

extern "C" void SysTick_Handler() { lattice::firmware::countWrap(); }
