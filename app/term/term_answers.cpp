#include "app/term/term_answers.hpp"

namespace lattice::app {

namespace {
constexpr std::uint8_t kEsc = 0x1b;
constexpr std::uint8_t kSub = 0x1a;
}  // namespace

TermAnswers::TermAnswers(const devices::Device& device)
    : replies_(device.replies), gin4010_(device.name != "tek4027"), gin4100_(device.name == "tek4125") {}

std::vector<std::uint8_t> ginReport4010(std::uint8_t key, int x, int y) {
  auto five = [](int v) { return static_cast<std::uint8_t>(0x20 | (v & 0x1f)); };
  return {key, five(x >> 5), five(x), five(y >> 5), five(y), '\r'};
}

std::vector<std::uint8_t> ginReport4100(std::uint8_t key, int x, int y) {
  auto five = [](int v) { return static_cast<std::uint8_t>(0x20 | (v & 0x1f)); };
  return {key, five(y >> 7), five(((y & 3) << 2) | (x & 3)), five(y >> 2), five(x >> 7), five(x >> 2), '\r'};
}

std::vector<std::uint8_t> TermAnswers::answer(std::span<const std::uint8_t> received) {
  std::vector<std::uint8_t> out;
  auto send = [&](const std::vector<std::uint8_t>& report) {
    out.insert(out.end(), report.begin(), report.end());
    ++answered_;
  };
  for (std::uint8_t c : received) {
    // A 4100 integer ends with its low byte, 0x20..0x3F; its high bytes are 0x40..0x7F.
    const bool intEnds = c >= 0x20 && c < 0x40;
    const bool afterEsc = enableGin_ == 1;
    switch (enableGin_) {
      case 1: enableGin_ = c == 'I' ? 2 : 0; break;
      case 2: enableGin_ = c == 'E' ? 3 : 0; break;
      case 3: enableGin_ = intEnds ? 4 : (c >= 0x40 && c < 0x80 ? 3 : 0); break;
      case 4:
        if (intEnds) {
          if (gin4100_) send(ginReport4100(' ', 2048, 1536));  // the middle of the 4096 x 3072 space
          enableGin_ = 0;
        } else if (!(c >= 0x40 && c < 0x80)) {
          enableGin_ = 0;
        }
        break;
      default: break;
    }
    if (gin4010_ && afterEsc && c == kSub) send(ginReport4010(' ', 512, 390));  // the middle of the 4010's screen
    if (c == kEsc) enableGin_ = 1;  // an ESC starts over, even inside a command
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
