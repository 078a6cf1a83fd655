#pragma once
// Elapsed time of a firmware run as the board's clock sees it: the Cortex-M3
// SysTick (ARMv7-M architecture reference, B3.3: CSR 0xE000E010, RVR
// 0xE000E014, CVR 0xE000E018), counting down from 2^24 - 1 on the processor
// clock, its wraps counted by the SysTick interrupt. Under QEMU the clock
// is virtual: with `-icount shift=0` each guest instruction advances it by
// exactly 1 ns (QEMU's -icount documentation), so ticks times the tick's
// length in ns is the number of instructions executed - the count
// bench/firmware.sh reports. QEMU's mps2-an385 clocks the CPU at 25 MHz
// (hw/arm/mps2.c, SYSCLK_FRQ), 40 ns a tick.
#include <cstdint>

namespace lattice::firmware {

inline constexpr std::uint64_t kTickNanoseconds = 40;

void startClock();
std::uint64_t clockTicks();
void countWrap();  // the SysTick interrupt

}  // namespace lattice::firmware
