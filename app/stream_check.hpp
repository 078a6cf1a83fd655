#pragma once
// `lattice emulate` checks what it was given before decoding it: the first
// bytes of the stream go to the device's recogniser (Device::recognise), and
// a stream it does not recognise is refused (Error(Input), exit 3) naming
// what the file looks like instead (a PNG, a scene, empty, another device's
// stream) and the fix. --raw skips the check.
//
// Method: CheckedDecoder sits in front of the emulator and holds back the
// first kRecogniseBytes (or the whole stream, if shorter) until it has seen
// them, so standard input works as well as a file and the emulator still
// sees every byte in order.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "devices/device.hpp"
#include "devices/stream_decoder.hpp"

namespace lattice::app {

// What a file's first bytes look like, in words: "an empty file", "a PNG
// image", "a scene file (TOML)", "a Tektronix 4125 stream" (from the device
// table's recognisers), ... Never empty.
std::string describeContent(std::span<const std::uint8_t> head);

class CheckedDecoder final : public StreamDecoder {
 public:
  // `name` (the file) is used in the message.
  CheckedDecoder(std::unique_ptr<StreamDecoder> inner, const devices::Device& device, std::string name);
  void feed(std::span<const std::uint8_t> bytes) override;
  void finish() override;
  const IndexedImage& image() const override { return inner_->image(); }
  const DecodeReport& report() const override { return inner_->report(); }

 private:
  void check();  // throws Error(Input) if the device does not recognise head_

  std::unique_ptr<StreamDecoder> inner_;
  const devices::Device& device_;
  std::string name_;
  std::vector<std::uint8_t> head_;
  bool checked_ = false;
};

}  // namespace lattice::app
