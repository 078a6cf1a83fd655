#pragma once
// What the terminal says back to the program or line, as the real terminal
// would, so that programs which wait for an answer go on:
//  * the 4027's `!REP` report request (UGS ends every record with one and
//    sends the next record only after the answer; `lattice send` to a 4027
//    paces against it): answered with a CR once the request has arrived,
//    found by the device's own reply pacing (devices/device.hpp), so the
//    sender and the terminal agree on what a request is;
//  * the 4010-series GIN request ESC SUB (crosshair on; the terminal sends
//    the key struck and the cursor's position): answered at once with a
//    space and the centre of the screen in the 4010's four address bytes
//    and CR, the terminal's default GIN terminator. docs/tek-sources.md
//    cites each answer.
// Requests are looked for in the bytes since the last one answered, kept
// here (trimmed to kKeepBytes when none comes, so memory stays bounded).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "devices/device.hpp"

namespace lattice::app {

class TermAnswers {
 public:
  static constexpr std::size_t kKeepBytes = 4096;

  explicit TermAnswers(const devices::Device& device);
  // The answers owed for `received` (the bytes that just arrived, in order).
  std::vector<std::uint8_t> answer(std::span<const std::uint8_t> received);
  std::uint64_t answered() const { return answered_; }

 private:
  std::optional<devices::Device::ReplyPacing> replies_;
  std::vector<std::uint8_t> pending_;  // bytes since the last request answered
  bool gin_;                           // a 4010-compatible terminal (not the 4027)
  bool escape_ = false;                // the last byte seen was ESC
  std::uint64_t answered_ = 0;
};

// The 4010's GIN report: the key, the four address bytes of (x, y) in
// 1024 x 1024 terminal space (high y, low y, high x, low x), then CR.
std::vector<std::uint8_t> ginReport(std::uint8_t key, int x, int y);

}  // namespace lattice::app
