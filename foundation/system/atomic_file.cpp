#include "foundation/system/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "foundation/error.hpp"
#include "foundation/system/output_transaction.hpp"
#include "foundation/system/temp_file_registry.hpp"

namespace lattice {
namespace {

std::atomic<unsigned> tempCounter{0};
constexpr std::size_t kBufferSize = 1 << 16;

[[noreturn]] void failOutput(const std::filesystem::path& path, const std::string& what) {
  throw Error(ErrorKind::Output, fmt::format("{}: cannot {}: {}", path.string(), what, std::strerror(errno)));
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target, Landing landing) : target_(std::move(target)), landing_(landing) {
  temp_ = target_;
  temp_ += fmt::format(".tmp-{}-{}", ::getpid(), tempCounter.fetch_add(1));
  registrySlot_ = TempFileRegistry::add(temp_.c_str());  // before the file exists: a signal never misses it
  fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    const int saved = errno;
    TempFileRegistry::remove(registrySlot_);
    errno = saved;
    failOutput(target_, "create (is the directory there and writable?)");
  }
  buffer_.reserve(kBufferSize);
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) {
    ::close(fd_);
    ::unlink(temp_.c_str());
  }
  TempFileRegistry::remove(registrySlot_);
}

void AtomicFile::write(std::span<const std::uint8_t> bytes) {
  if (fd_ < 0) throw Error(ErrorKind::Internal, "AtomicFile: write after close");
  buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
  written_ += bytes.size();
  if (buffer_.size() >= kBufferSize) flushBuffer();
}

void AtomicFile::flushBuffer() {
  const std::uint8_t* p = buffer_.data();
  std::size_t left = buffer_.size();
  while (left > 0) {
    ssize_t n = ::write(fd_, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      failOutput(target_, "write");
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  buffer_.clear();
}

void AtomicFile::flush() {
  if (fd_ >= 0) flushBuffer();
}

void AtomicFile::close() {
  if (fd_ < 0) return;
  flushBuffer();
  if (::fsync(fd_) != 0 && errno != EINVAL) failOutput(target_, "sync");
  if (::close(fd_) != 0) {
    fd_ = -1;
    const int saved = errno;
    ::unlink(temp_.c_str());
    errno = saved;
    failOutput(target_, "close");  // the destructor releases the registry slot
  }
  fd_ = -1;
  if (landing_ == Landing::WithCommand && OutputTransaction::keep(temp_, target_, registrySlot_)) {
    registrySlot_ = -1;  // the transaction renames or unlinks it, and releases the slot
    return;
  }
  const int renamed = ::rename(temp_.c_str(), target_.c_str());
  const int saved = errno;
  if (renamed != 0) ::unlink(temp_.c_str());
  TempFileRegistry::remove(registrySlot_);
  registrySlot_ = -1;
  errno = saved;
  if (renamed != 0) failOutput(target_, "rename the finished file into place");
}

void writeFileAtomically(const std::filesystem::path& target, std::span<const std::uint8_t> bytes,
                         AtomicFile::Landing landing) {
  AtomicFile file(target, landing);
  file.write(bytes);
  file.close();
}

std::vector<std::uint8_t> readWholeFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorKind::Input, fmt::format("{}: cannot open: {}", path.string(), std::strerror(errno)));
  std::vector<std::uint8_t> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw Error(ErrorKind::Input, fmt::format("{}: read error", path.string()));
  return data;
}

std::vector<std::uint8_t> readFileUpTo(const std::filesystem::path& path, std::uint64_t maxBytes,
                                       const std::string& what) {
  const auto tooLarge = [&](const std::string& size) {
    return Error(ErrorKind::Input, fmt::format("{}: {}more than the {}-byte limit for {} (docs/limits.md)",
                                               path.string(), size, maxBytes, what));
  };
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec)) {
    const std::uint64_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > maxBytes) throw tooLarge(fmt::format("{} bytes, ", size));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorKind::Input, fmt::format("{}: cannot open: {}", path.string(), std::strerror(errno)));
  std::vector<std::uint8_t> data;
  std::vector<char> chunk(1 << 16);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    if (data.size() + got > maxBytes) throw tooLarge("");
    data.insert(data.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(got));
  }
  if (in.bad()) throw Error(ErrorKind::Input, fmt::format("{}: read error", path.string()));
  return data;
}

}  // namespace lattice
