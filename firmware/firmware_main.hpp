#pragma once
// The firmware's program (firmware/main.cpp), called by the reset handler
// (firmware/startup.cpp); its result is the exit status QEMU reports.
namespace lattice::firmware {

int firmwareMain();

}  // namespace lattice::firmware
