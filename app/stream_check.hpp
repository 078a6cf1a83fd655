#pragma once
// What a stream is, checked before a command acts on it: `lattice emulate`
// before decoding, `lattice send` before a byte goes on the line, `lattice
// show` before decoding and to choose the emulator. The first bytes of the
// file go to the devices' recognisers (Device::recognise); a file no
// recogniser takes is refused (Error(Input), exit 3) naming what it looks
// like instead (a PNG, a scene, empty, another device's stream) and the fix.
// Each command's --raw skips the check.
//
// Method: the recognisers judge at most kRecogniseBytes from the start of the
// file, so a large file is judged without reading it (readStreamHead).
// CheckedDecoder sits in front of an emulator and holds back that head until
// it has seen it, so standard input works as well as a file and the emulator
// still sees every byte in order.
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

// The device whose stream `head` is, by the recognisers; empty when none
// takes it. Where one terminal reads another's language the narrower answer
// wins: a 4014 stream passes the 4125's recogniser too (the 4125 reads
// 4010-series graphics), but names the 4014.
std::string recogniseDevice(std::span<const std::uint8_t> head);

// The first kRecogniseBytes of the file (all of it when shorter): what the
// recognisers judge. Error(Input) when it cannot be opened or read.
std::vector<std::uint8_t> readStreamHead(const std::string& path);

// The command a refusal advises for: how it names a device, and what its
// --raw does.
enum class StreamUse {
  Emulate,      // emulate --device DEVICE
  Send,         // send --port PORT [--device DEVICE]
  SendVirtual,  // send --port virtual:DEVICE
  Show,         // show --as DEVICE
};

// Returns when `device` recognises `head` (or has no recogniser); else throws
// Error(Input): "NAME: this is a PNG image, not a Tektronix 4125 stream; FIX
// (--raw ... anyway)". `name` is the file, as the user gave it.
void requireStream(std::span<const std::uint8_t> head, const devices::Device& device, const std::string& name,
                   StreamUse use);

// Returns when some device recognises `head` (a send to a port without
// --device: any terminal's stream may be meant); else throws as above.
void requireAnyStream(std::span<const std::uint8_t> head, const std::string& name, StreamUse use);

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
