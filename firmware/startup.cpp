// Reset and fault entry of the firmware on a Cortex-M3 (ARMv7-M): the vector
// table the core reads at address 0 (initial stack pointer, then handlers),
// and the reset handler that makes C++ possible: copy .data from flash, zero
// .bss, paint the stack for the high-water mark (firmware/memory_marks.hpp),
// run the static constructors, call firmwareMain (C++ forbids calling
// main), and exit through semihosting with its status. A fault ends the run with status 70 and a message on the
// host's stderr, never a silent hang.
#include <cstdint>
#include <cstring>

#include "firmware/firmware_main.hpp"
#include "firmware/memory_marks.hpp"
#include "firmware/semihosting.hpp"

extern "C" {
extern std::uint32_t __data_load, __data_start, __data_end, __bss_start, __bss_end, __stack_top;
extern void (*__preinit_array_start[])(), (*__preinit_array_end[])();
extern void (*__init_array_start[])(), (*__init_array_end[])();
void Reset_Handler();
void Fault_Handler();
void SysTick_Handler();
}

namespace {

using Vector = void (*)();
constexpr int kFaultStatus = 70;

}  // namespace

extern "C" void Reset_Handler() {
  std::memcpy(&__data_start, &__data_load,
              static_cast<std::size_t>(reinterpret_cast<char*>(&__data_end) - reinterpret_cast<char*>(&__data_start)));
  std::memset(&__bss_start, 0,
              static_cast<std::size_t>(reinterpret_cast<char*>(&__bss_end) - reinterpret_cast<char*>(&__bss_start)));
  lattice::firmware::paintStack();
  for (auto f = __preinit_array_start; f != __preinit_array_end; ++f) (*f)();
  for (auto f = __init_array_start; f != __init_array_end; ++f) (*f)();
  lattice::firmware::hostExit(lattice::firmware::firmwareMain());
}

extern "C" void Fault_Handler() {
  lattice::firmware::hostReport("firmware: CPU fault (hard fault, bus or usage fault); stopping\n");
  lattice::firmware::hostExit(kFaultStatus);
}

// ARMv7-M exception numbers 0..15: initial SP, reset, NMI, hard fault,
// memory management, bus and usage fault, four reserved, SVCall, debug
// monitor, reserved, PendSV, SysTick (firmware/virtual_clock.hpp).
__attribute__((section(".vectors"), used)) const Vector kVectors[] = {
    reinterpret_cast<Vector>(&__stack_top), Reset_Handler, Fault_Handler, Fault_Handler, Fault_Handler,
    Fault_Handler, Fault_Handler, nullptr, nullptr, nullptr, nullptr, Fault_Handler, Fault_Handler, nullptr,
    Fault_Handler, SysTick_Handler};
