#pragma once
// Elapsed time of a firmware run as the board's clock sees it: the Cortex-M3
// SysTick (ARMv7-M architecture reference, B3.3: CSR 0xE000E010, RVR
// 0xE000E014, CVR 0xE000E018), counting down from 2^24 - 1 on the processor
// clock, its wraps counted by the SysTick interrupt. Under QEMU the clock
// is virtual: with `-icount shift=0` each guest instruction advances it by
// exactly 1 ns (QEMU's -icount documentation), so ticks times the tick's
// length in ns is the number of instructions executed - the count
// bench/firmware.sh reports. The processor clock is the board's
// (firmware/boards/BOARD/board.tsv, LATTICE_BOARD_HZ): QEMU's mps2-an385 runs at 25 MHz
// (hw/arm/mps2.c, SYSCLK_FRQ; 40 ns a tick), its netduinoplus2 at 168 MHz
// (hw/arm/netduinoplus2.c; 5.95 ns a tick, so the count is good to 6).
#include <cstdint>

namespace lattice::firmware {

inline constexpr std::uint64_t kClockHz = LATTICE_BOARD_HZ;
// Ticks to ns, exact for whole-ns ticks (good to 2^64 / 10^9 ticks, 584 years at 1 GHz).
constexpr std::uint64_t tickNanoseconds(std::uint64_t ticks) { return ticks * 1000000000u / kClockHz; }

void startClock();
std::uint64_t clockTicks();
void countWrap();  // the SysTick interrupt

}  // namespace lattice::firmware
