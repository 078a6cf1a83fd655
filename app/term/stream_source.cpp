#include "app/term/stream_source.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "devices/work_budget.hpp"
#include "foundation/system/atomic_file.hpp"

namespace lattice::app {

StreamSource::StreamSource(const std::string& path, double charactersPerSecond)
    : path_(path),
      bytes_(readFileUpTo(path, kMaxStreamBytes, "a stream to play")),
      rate_(charactersPerSecond),
      start_(std::chrono::steady_clock::now()) {}

std::size_t StreamSource::owed() const {
  if (rate_ <= 0) return std::min(bytes_.size(), played_ + kUnpacedChunk);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return std::min(bytes_.size(), static_cast<std::size_t>(seconds * rate_));
}

bool StreamSource::read(std::vector<std::uint8_t>& out) {
  const std::size_t until = owed();
  if (until > played_) {
    out.insert(out.end(), bytes_.begin() + static_cast<std::ptrdiff_t>(played_),
               bytes_.begin() + static_cast<std::ptrdiff_t>(until));
    played_ = until;
  }
  return played_ < bytes_.size();
}

int StreamSource::timeoutMs() const {
  if (played_ >= bytes_.size() || rate_ <= 0) return 0;
  // When the next character is due, but no sooner than a slice from now.
  const double due = static_cast<double>(played_ + 1) / rate_;
  const double now = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return std::max(kSliceMs, static_cast<int>(std::ceil((due - now) * 1000)));
}

std::string StreamSource::endReason() const {
  return fmt::format("{}: the stream has been played ({} bytes)", path_, bytes_.size());
}

}  // namespace lattice::app
