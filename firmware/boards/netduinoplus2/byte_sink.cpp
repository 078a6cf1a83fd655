// The byte sink of the netduinoplus2 board (firmware/boards/netduinoplus2/): USART1 of
// an STM32F405/F407, polled. QEMU 7.2's stm32f405_soc wires its first serial
// chardev (-serial) to USART1 at 0x40011000 (hw/arm/stm32f405_soc.c lists
// the USARTs from 0x40011000; `info mtree` shows stm32f2xx-usart there).
//
// Method: registers from ST's RM0090 (STM32F405/415/407/417/427/437/429/439
// reference manual): memory map (section 2.3, table 1): RCC 0x40023800,
// GPIOA 0x40020000, USART1 0x40011000 on APB2; RCC_AHB1ENR +0x30 bit 0
// GPIOAEN, RCC_APB2ENR +0x44 bit 4 USART1EN (section 7.3); GPIOx_MODER +0x00
// (two bits a pin, 0b10 alternate function), GPIOx_AFRH +0x24 (four bits a
// pin from PA8) (section 8.4); USART_SR +0x00 (bit 7 TXE, bit 6 TC),
// USART_DR +0x04, USART_BRR +0x08, USART_CR1 +0x0C (bit 13 UE, bit 3 TE,
// bit 2 RE) (section 30.6). PA9 is USART1_TX and PA10 USART1_RX on
// alternate function 7 (ST's STM32F405xx/407xx datasheet, DS8626, table 9).
// On QEMU the RCC and GPIO blocks are unimplemented and ignore the writes;
// on a real part they are what makes the pins carry the line.
//
// Tunables: kBrr. After reset the part runs on its 16 MHz HSI oscillator and
// APB2 is undivided (RM0090 section 6.2), so BRR = 16e6 / (16 x 115200) =
// 8.68: mantissa 8, fraction round(0.68 x 16) = 11, 0x8B, 115,108 baud
// (0.08 % from 115,200). The firmware never raises the clock, so this holds.
#include <cstdint>

#include "firmware/uart_sink.hpp"

namespace lattice::firmware {
namespace {

struct Stm32Usart {
  volatile std::uint32_t sr, dr, brr, cr1, cr2, cr3, gtpr;
};
constexpr std::uintptr_t kRcc = 0x40023800, kGpioA = 0x40020000, kUsart1 = 0x40011000;
constexpr std::uint32_t kAhb1enrGpioA = 1u << 0, kApb2enrUsart1 = 1u << 4;
constexpr std::uint32_t kSrTxe = 1u << 7, kSrTc = 1u << 6;
constexpr std::uint32_t kCr1Ue = 1u << 13, kCr1Te = 1u << 3, kCr1Re = 1u << 2;
constexpr std::uint32_t kBrr = 0x8B;
constexpr int kTxPin = 9, kRxPin = 10, kAlternateUsart1 = 7;

volatile std::uint32_t& reg(std::uintptr_t base, std::uint32_t offset) {
  return *reinterpret_cast<volatile std::uint32_t*>(base + offset);
}
Stm32Usart& usart() { return *reinterpret_cast<Stm32Usart*>(kUsart1); }

void routePin(int pin) {
  const auto mode = static_cast<std::uint32_t>(2 * pin), af = static_cast<std::uint32_t>(4 * (pin - 8));
  reg(kGpioA, 0x00) = (reg(kGpioA, 0x00) & ~(3u << mode)) | (2u << mode);
  reg(kGpioA, 0x24) = (reg(kGpioA, 0x24) & ~(15u << af)) | (static_cast<std::uint32_t>(kAlternateUsart1) << af);
}

}  // namespace

UartSink::UartSink() {
  reg(kRcc, 0x30) = reg(kRcc, 0x30) | kAhb1enrGpioA;
  reg(kRcc, 0x44) = reg(kRcc, 0x44) | kApb2enrUsart1;
  routePin(kTxPin);
  routePin(kRxPin);
  usart().brr = kBrr;
  usart().cr1 = kCr1Ue | kCr1Te | kCr1Re;
}

void UartSink::write(std::span<const std::uint8_t> bytes) {
  for (std::uint8_t b : bytes) {
    while (!(usart().sr & kSrTxe)) {
    }
    usart().dr = b;
  }
  written_ += bytes.size();
}

void UartSink::close() {
  while (!(usart().sr & kSrTc)) {
  }
}

}  // namespace lattice::firmware
