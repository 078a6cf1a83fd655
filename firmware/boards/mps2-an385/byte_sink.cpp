#include "firmware/uart_sink.hpp"

namespace lattice::firmware {
namespace {

struct CmsdkUart {
  volatile std::uint32_t data;
  volatile std::uint32_t state;
  volatile std::uint32_t ctrl;
  volatile std::uint32_t intStatus;
  volatile std::uint32_t bauddiv;
};
constexpr std::uintptr_t kUart0 = 0x40004000;
constexpr std::uint32_t kTxFull = 1u << 0;
constexpr std::uint32_t kTxEnable = 1u << 0;
constexpr std::uint32_t kBaudDivisor = 16;

CmsdkUart& uart() { return *reinterpret_cast<CmsdkUart*>(kUart0); }

}  // namespace

UartSink::UartSink() {
  uart().bauddiv = kBaudDivisor;
  uart().ctrl = kTxEnable;
}

void UartSink::write(std::span<const std::uint8_t> bytes) {
  for (std::uint8_t b : bytes) {
    while (uart().state & kTxFull) {
    }
    uart().data = b;
  }
  written_ += bytes.size();
}

// The CMSDK UART has no "transmission complete" flag: TX not full is the end.
void UartSink::close() {
  while (uart().state & kTxFull) {
  }
}

}  // namespace lattice::firmware
