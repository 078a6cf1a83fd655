#pragma once
// What the terminal says back to the program or line, as the real terminal
// would, so that programs which wait for an answer go on:
//  * the 4027's `!REP` report request (UGS ends every record with one and
//    sends the next record only after the answer; `lattice send` to a 4027
//    paces against it): answered with a CR once the request has arrived,
//    found by the device's own reply pacing (devices/device.hpp), so the
//    sender and the terminal agree on what a request is;
//  * GIN (the crosshair: the terminal sends the key struck and where the
//    cursor is), answered at once with a space and the centre of the
//    screen, then CR, the default GIN terminator, as the RAL GKS drivers
//    read it (docs/tek-sources.md, "Answers"):
//    - the 4010's ESC SUB (GK0TCS: key, Hi-X, Lo-X, Hi-Y, Lo-Y, five bits
//      each plus 32, 1024 points a side), on the 4014 and the 4125;
//    - the 4100 series' ENABLE-GIN, ESC I E and two integers (GK1TCS on a
//      4107: key, Hi-Y, Extra, Lo-Y, Hi-X, Lo-X, five bits each plus 32,
//      4096 points a side, the Extra byte's low bits X's and the next Y's),
//      on the 4125.
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
  bool gin4010_;                       // a 4010-compatible terminal (not the 4027)
  bool gin4100_;                       // a 4100-series terminal
  // Where the scan stands in ESC I E int int: 0 ground, 1 after ESC, 2 after
  // ESC I, 3 and 4 inside the first and second integer.
  int enableGin_ = 0;
  std::uint64_t answered_ = 0;
};

// The 4010's GIN report of (x, y), 0..1023: key, Hi-X, Lo-X, Hi-Y, Lo-Y, CR.
std::vector<std::uint8_t> ginReport4010(std::uint8_t key, int x, int y);
// The 4100 series' GIN report of (x, y), 0..4095: key, Hi-Y, Extra, Lo-Y, Hi-X, Lo-X, CR.
std::vector<std::uint8_t> ginReport4100(std::uint8_t key, int x, int y);

}  // namespace lattice::app
