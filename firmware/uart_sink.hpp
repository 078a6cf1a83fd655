#pragma once
// The byte sink of the firmware, one implementation per board
// (firmware/boards/BOARD/byte_sink.cpp): this file's notes are the
// mps2-an385's, whose byte_sink.cpp drives the CMSDK APB UART0 of the MPS2 AN385
// (base 0x40004000, qemu hw/arm/mps2.c; register layout from Arm's CMSDK
// technical reference, DDI 0479: DATA at +0, STATE at +4 with bit 0 "TX
// buffer full", CTRL at +8 with bit 0 "TX enable", BAUDDIV at +0x10). It is
// the same foundation ByteSink the host's file and serial transports
// implement, so the Tek 4125 driver writes to it unchanged.
//
// Tunables: kBaudDivisor (the board's 25 MHz clock / 16 is the least the
// CMSDK UART accepts; QEMU does not pace the line, a real board would want
// 25e6 / 38400).
#include <cstdint>
#include <span>

#include "foundation/byte_sink.hpp"

namespace lattice::firmware {

class UartSink final : public ByteSink {
 public:
  UartSink();
  using ByteSink::write;
  void write(std::span<const std::uint8_t> bytes) override;
  void close() override;  // returns once the last byte has left the shift register
  std::uint64_t bytesWritten() const override { return written_; }

 private:
  std::uint64_t written_ = 0;
};

}  // namespace lattice::firmware
