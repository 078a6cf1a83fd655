#include "app/term/term_answers.hpp"

namespace lattice::app {

namespace {
constexpr std::uint8_t kEsc = 0x1b;
constexpr std::uint8_t kSub = 0x1a;
}  // namespace

TermAnswers::TermAnswers(const devices::Device& device)
    : replies_(device.replies), gin_(device.name != "tek4027") {}

std::vector<std::uint8_t> ginReport(std::uint8_t key, int x, int y) {
  return {key,
          static_cast<std::uint8_t>(0x20 | ((y >> 5) & 0x1f)),
          static_cast<std::uint8_t>(0x60 | (y & 0x1f)),
          static_cast<std::uint8_t>(0x20 | ((x >> 5) & 0x1f)),
          static_cast<std::uint8_t>(0x40 | (x & 0x1f)),
          '\r'};
}

std::vector<std::uint8_t> TermAnswers::answer(std::span<const std::uint8_t> received) {
  std::vector<std::uint8_t> out;
  for (std::uint8_t c : received) {
    if (gin_ && escape_ && c == kSub) {
      const std::vector<std::uint8_t> report = ginReport(' ', 512, 390);  // the middle of the 4010's screen
      out.insert(out.end(), report.begin(), report.end());
      ++answered_;
    }
    escape_ = c == kEsc;
  }
  if (!replies_) return out;
  pending_.insert(pending_.end(), received.begin(), received.end());
  const std::vector<std::size_t> points = replies_->points(pending_);
  for (std::size_t i = 0; i < points.size(); ++i) out.push_back('\r');
  answered_ += points.size();
  if (!points.empty())
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(points.back()));
  else if (pending_.size() > kKeepBytes)
    pending_.erase(pending_.begin(), pending_.end() - static_cast<std::ptrdiff_t>(kKeepBytes / 2));
  return out;
}

}  // namespace lattice::app
