#pragma once
// A ByteSink that passes every byte on to another sink (or nowhere) and shows
// it to an observer first. `lattice render --device tek4125 -o pic.png` uses
// it to feed the emulator while the stream goes to a file or a serial line,
// so the PNG shows exactly the bytes that were sent.
#include <functional>

#include "foundation/byte_sink.hpp"

namespace lattice::io {

class TeeSink final : public ByteSink {
 public:
  using Observer = std::function<void(std::span<const std::uint8_t>)>;
  // downstream may be null: then bytes go only to the observer.
  TeeSink(ByteSink* downstream, Observer observer) : downstream_(downstream), observer_(std::move(observer)) {}

  using ByteSink::write;
  void write(std::span<const std::uint8_t> bytes) override {
    if (observer_) observer_(bytes);
    if (downstream_) downstream_->write(bytes);
    written_ += bytes.size();
  }
  void flush() override {
    if (downstream_) downstream_->flush();
  }
  void close() override {
    if (downstream_) downstream_->close();
  }
  std::uint64_t bytesWritten() const override { return written_; }

 private:
  ByteSink* downstream_;
  Observer observer_;
  std::uint64_t written_ = 0;
};

}  // namespace lattice::io
