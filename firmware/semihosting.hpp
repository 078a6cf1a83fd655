#pragma once
// ARM semihosting: the debugger (here QEMU's -semihosting) carries out a
// request the program makes with `bkpt 0xAB` (ARM's "Semihosting for
// AArch32 and AArch64" specification: operation number in r0, argument block
// in r1). The firmware uses three: open ":tt" for the host's stderr, write
// to it (the run's report, kept off the UART so the Tek stream stays the
// host's byte for byte), and exit with a status (SYS_EXIT_EXTENDED).
// On a real board with no debugger attached `bkpt` faults; docs/firmware.md
// says what to change there.
#include <cstddef>
#include <string_view>

namespace lattice::firmware {

// Writes text to the host's stderr.
void hostReport(std::string_view text);
// Ends the run; QEMU exits with `status`.
[[noreturn]] void hostExit(int status);

}  // namespace lattice::firmware
