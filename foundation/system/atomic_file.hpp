#pragma once
// Files are written atomically: into "<path>.tmp-<pid>-<n>" beside the target,
// fsync'd, then renamed over it. A crash or an error leaves either the old file
// or the new one, never half of one; SIGINT, SIGTERM and SIGHUP unlink the
// temporary before the process dies (foundation/system/temp_file_registry.hpp).
// While a command's OutputTransaction is open, close() leaves the rename to
// it, so all of a command's outputs land together (output_transaction.hpp).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "foundation/byte_sink.hpp"

namespace lattice {

class AtomicFile final : public ByteSink {
 public:
  // WithCommand: renamed with the command's other outputs when it succeeds;
  // Now: renamed at close() (a cache that is worth keeping whatever follows).
  enum class Landing { WithCommand, Now };
  explicit AtomicFile(std::filesystem::path target, Landing landing = Landing::WithCommand);
  ~AtomicFile() override;  // discards the temporary if close() was not reached
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  using ByteSink::write;
  void write(std::span<const std::uint8_t> bytes) override;
  void flush() override;
  void close() override;  // fsync + rename; throws lattice::Error(Output) on failure
  std::uint64_t bytesWritten() const override { return written_; }
  const std::filesystem::path& target() const { return target_; }

 private:
  void flushBuffer();

  std::filesystem::path target_;
  std::filesystem::path temp_;
  int fd_ = -1;
  Landing landing_;
  int registrySlot_ = -1;
  std::uint64_t written_ = 0;
  std::vector<std::uint8_t> buffer_;
};

// Whole-file helpers.
void writeFileAtomically(const std::filesystem::path& target, std::span<const std::uint8_t> bytes,
                         AtomicFile::Landing landing = AtomicFile::Landing::WithCommand);
std::vector<std::uint8_t> readWholeFile(const std::filesystem::path& path);  // Error(Input) if unreadable
// The same for a file from outside, refused (Error(Input), naming `what` and
// docs/limits.md) when it holds more than maxBytes: a regular file by its
// size before anything is read, anything else (a pipe, /dev/zero) once
// maxBytes + 1 bytes have arrived.
std::vector<std::uint8_t> readFileUpTo(const std::filesystem::path& path, std::uint64_t maxBytes,
                                       const std::string& what);

}  // namespace lattice
