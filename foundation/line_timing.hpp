#pragma once
// How long bytes take on an asynchronous serial line: each character costs a
// start bit, its data bits, an optional parity bit and its stop bits
// (10 bit times for 8N1). Drivers report a stream's transmit time with this.
#include <cstdint>

namespace lattice {

struct LineFormat {
  int baud = 9600;
  int dataBits = 8;
  bool parity = false;
  int stopBits = 1;
  int bitsPerCharacter() const { return 1 + dataBits + (parity ? 1 : 0) + stopBits; }
};

inline double transmitSeconds(std::uint64_t bytes, const LineFormat& line) {
  return static_cast<double>(bytes) * line.bitsPerCharacter() / static_cast<double>(line.baud);
}

}  // namespace lattice
