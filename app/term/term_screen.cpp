#include "app/term/term_screen.hpp"

namespace lattice::app {

TermScreen::TermScreen(const devices::Device& device, ByteSink* record)
    : emulator_(device.makeEmulator()), record_(record), answers_(device) {}

std::vector<std::uint8_t> TermScreen::receive(std::span<const std::uint8_t> bytes) {
  if (bytes.empty()) return {};
  if (record_) record_->write(bytes);
  emulator_->feed(bytes);
  bytes_ += bytes.size();
  return answers_.answer(bytes);
}

void TermScreen::finish() { emulator_->finish(); }

}  // namespace lattice::app
