#pragma once
// The byte transport under every device driver (u8g2's "byte callback"):
// a driver formats commands, a ByteSink delivers them to a file, stdout or a
// serial line. Drivers never know which.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace lattice {

class ByteSink {
 public:
  virtual ~ByteSink() = default;
  // Deliver all bytes, in order, or throw lattice::Error saying how many went out.
  virtual void write(std::span<const std::uint8_t> bytes) = 0;
  // Push buffered bytes to the device (not necessarily out of the UART).
  virtual void flush() {}
  // Finish: a file is renamed into place, a serial port drained. After close()
  // the sink takes no more bytes. A sink destroyed without close() discards
  // a partial file rather than leave a truncated one behind.
  virtual void close() {}
  // Bytes accepted so far.
  virtual std::uint64_t bytesWritten() const = 0;

  void write(std::string_view text) {
    write(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
  }
};

// Keeps everything in memory: tests, and emulating a stream without a file.
class MemorySink final : public ByteSink {
 public:
  using ByteSink::write;
  void write(std::span<const std::uint8_t> bytes) override { data_.insert(data_.end(), bytes.begin(), bytes.end()); }
  std::uint64_t bytesWritten() const override { return data_.size(); }
  const std::vector<std::uint8_t>& data() const { return data_; }

 private:
  std::vector<std::uint8_t> data_;
};

// Keeps nothing and counts: what a stream would weigh, without holding it
// (the 4125 driver sizes its candidate streams this way).
class CountingSink final : public ByteSink {
 public:
  using ByteSink::write;
  void write(std::span<const std::uint8_t> bytes) override { count_ += bytes.size(); }
  std::uint64_t bytesWritten() const override { return count_; }

 private:
  std::uint64_t count_ = 0;
};

}  // namespace lattice
