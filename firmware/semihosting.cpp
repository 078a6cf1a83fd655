#include "firmware/semihosting.hpp"

#include <cstdint>

namespace lattice::firmware {
namespace {

// Operation numbers of the semihosting specification.
constexpr std::uint32_t kSysOpen = 0x01, kSysWrite = 0x05, kSysExitExtended = 0x20;
constexpr std::uint32_t kApplicationExit = 0x20026;  // ADP_Stopped_ApplicationExit
constexpr std::uint32_t kModeAppend = 8;              // ":tt" opened in mode "a" is stderr

std::uint32_t call(std::uint32_t operation, const void* argument) {
  register std::uint32_t r0 __asm__("r0") = operation;
  register const void* r1 __asm__("r1") = argument;
  __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return r0;
}

int stderrHandle() {
  static int handle = -1;
  if (handle < 0) {
    static const char name[] = ":tt";
    const std::uint32_t block[3] = {reinterpret_cast<std::uint32_t>(name), kModeAppend, sizeof(name) - 1};
    handle = static_cast<int>(call(kSysOpen, block));
  }
  return handle;
}

}  // namespace

void hostReport(std::string_view text) {
  const std::uint32_t block[3] = {static_cast<std::uint32_t>(stderrHandle()),
                                  reinterpret_cast<std::uint32_t>(text.data()), text.size()};
  call(kSysWrite, block);
}

void hostExit(int status) {
  const std::uint32_t block[2] = {kApplicationExit, static_cast<std::uint32_t>(status)};
  for (;;) call(kSysExitExtended, block);
}

}  // namespace lattice::firmware
