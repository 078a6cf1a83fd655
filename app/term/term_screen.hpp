#pragma once
// The terminal's screen: what becomes of each piece of bytes as it arrives.
// The piece is recorded (the exact bytes received, for `lattice emulate` and
// golden tests), fed to the device's emulator, and searched for requests the
// terminal answers. The emulators take bytes in any chunking, so after every
// piece the screen is what `lattice emulate --at` draws for the bytes so far
// (tests/app/term_screen_test.cpp checks this with random splits).
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "app/term/term_answers.hpp"
#include "devices/device.hpp"
#include "foundation/byte_sink.hpp"

namespace lattice::app {

class TermScreen {
 public:
  // `record`: where received bytes are kept, or nullptr.
  TermScreen(const devices::Device& device, ByteSink* record);
  // Returns the answers the terminal owes the far side for these bytes.
  std::vector<std::uint8_t> receive(std::span<const std::uint8_t> bytes);
  // The end of the bytes: a command cut off is counted as malformed.
  void finish();
  const IndexedImage& image() const { return emulator_->image(); }
  const DecodeReport& report() const { return emulator_->report(); }
  const std::string& dialogText() const { return emulator_->dialogText(); }
  std::uint64_t bytes() const { return bytes_; }
  std::uint64_t answers() const { return answers_.answered(); }

 private:
  std::unique_ptr<StreamDecoder> emulator_;
  ByteSink* record_;
  TermAnswers answers_;
  std::uint64_t bytes_ = 0;
};

}  // namespace lattice::app
