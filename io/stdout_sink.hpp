#pragma once
// Writes a stream to standard output (`--stream -`), e.g. to pipe into a
// terminal emulator or `tee`.
#include "foundation/byte_sink.hpp"

namespace lattice::io {

class StdoutSink final : public ByteSink {
 public:
  using ByteSink::write;
  void write(std::span<const std::uint8_t> bytes) override;
  void flush() override;
  void close() override { flush(); }
  std::uint64_t bytesWritten() const override { return written_; }

 private:
  std::uint64_t written_ = 0;
};

}  // namespace lattice::io
