#include "devices/tek4027/tek4027_pacing.hpp"

#include <fmt/format.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>

#include "foundation/error.hpp"

namespace lattice::tek4027 {

void Tek4027FdReplies::awaitReply() {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration<double>(timeoutSeconds_);
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0)
      throw Error(ErrorKind::Stalled,
                  fmt::format("tek4027: no answer to report request {} within {:.0f} s; is the terminal on line and "
                              "set to answer reports? (--set pacing=none sends without waiting)",
                              seen_ + 1, timeoutSeconds_));
    pollfd entry{fd_, POLLIN, 0};
    const int ready = ::poll(&entry, 1, static_cast<int>(left));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    if ((entry.revents & (POLLHUP | POLLERR)) != 0 && (entry.revents & POLLIN) == 0)
      throw Error(ErrorKind::HangUp, fmt::format("tek4027: the line hung up while waiting for report {}", seen_ + 1));
    char byte = 0;
    const ssize_t n = ::read(fd_, &byte, 1);
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) continue;
    if (n <= 0)
      throw Error(ErrorKind::HangUp, fmt::format("tek4027: the line closed while waiting for report {}", seen_ + 1));
    if (byte == '\r') {
      ++seen_;
      return;
    }
  }
}

namespace {

bool paced(const std::string& text, const Tek4027Profile& profile) {
  switch (profile.pacing) {
    case Tek4027Pacing::None: return false;
    case Tek4027Pacing::Report: return true;
    case Tek4027Pacing::Auto: return text.size() > static_cast<std::size_t>(profile.recordBytes);
  }
  return false;
}

}  // namespace

namespace {
std::string requestText(const Tek4027Profile& profile) { return std::string(1, profile.commandChar) + "REP 00\r"; }
}  // namespace

std::vector<std::size_t> reportRecordEnds(const std::string& paced, const Tek4027Profile& profile) {
  // The command character never appears inside a command, so each request
  // is found exactly where it was put.
  const std::string request = requestText(profile);
  std::vector<std::size_t> ends;
  for (std::size_t at = paced.find(request); at != std::string::npos; at = paced.find(request, at + 1))
    ends.push_back(at + request.size());
  return ends;
}

std::vector<std::size_t> recordCuts(const std::string& text, const Tek4027Profile& profile) {
  std::vector<std::size_t> cuts;
  if (!paced(text, profile)) return cuts;
  const std::size_t budget = static_cast<std::size_t>(profile.recordBytes) - requestText(profile).size();
  // The stream's own final terminator belongs to its last command; the last
  // request's CR takes its place.
  std::size_t end = text.size();
  if (end > 0 && text.back() == profile.terminator) --end;
  std::size_t recordStart = 0;
  for (std::size_t at = 0; at < end;) {
    std::size_t next = text.find(profile.commandChar, at + 1);
    if (next == std::string::npos || next > end) next = end;
    // Close the record before a command that would overflow it (never empty).
    if (next - recordStart > budget && at > recordStart) {
      cuts.push_back(at);
      recordStart = at;
    }
    at = next;
  }
  if (recordStart < end) cuts.push_back(end);
  return cuts;
}

std::size_t pacedSize(const std::string& text, const std::vector<std::size_t>& cuts, const Tek4027Profile& profile) {
  if (cuts.empty()) return text.size();
  return cuts.back() + cuts.size() * requestText(profile).size();
}

std::string paceWithReports(std::string text, const Tek4027Profile& profile) {
  const std::vector<std::size_t> cuts = recordCuts(text, profile);
  if (cuts.empty()) return text;
  const std::string request = requestText(profile);
  std::string out;
  out.reserve(pacedSize(text, cuts, profile));
  std::size_t from = 0;
  for (std::size_t cut : cuts) {
    out.append(text, from, cut - from);
    out += request;  // its CR also ends the command before it
    from = cut;
  }
  return out;
}

}  // namespace lattice::tek4027
