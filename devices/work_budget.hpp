#pragma once
// Bounds on what an emulator does for its input (docs/limits.md), so that no
// stream, however hostile, costs more than a stated amount of time.
//
// Method and tunables:
//  - kPixelWorkBudget: the drawing work one stream may ask for, in pixel
//    units (a filled or cleared pixel, a vector step, a polygon edge crossing
//    a row). 2^30 is 819 full 1280x1024 screens, or 4,793 640x350 ones;
//    our own drivers' streams stay below a few screens. Drawing is charged
//    before it happens; once a stream has asked for more, nothing more is
//    drawn and the report says so (decoders still never throw on content),
//    and `lattice emulate` refuses the stream (exit 3).
//  - kMaxStreamBytes: the longest stream `lattice emulate` reads (256 MiB;
//    a full-screen 8-plane 4125 raster is under 2 MB), so an endless input
//    such as /dev/zero ends with a message instead of running forever.
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>

#include "devices/stream_decoder.hpp"

namespace lattice {

inline constexpr std::uint64_t kPixelWorkBudget = std::uint64_t(1) << 30;
inline constexpr std::uint64_t kMaxStreamBytes = std::uint64_t(256) << 20;

// Charges `units` of drawing to the stream's report. True: draw. False: the
// budget is spent (now or before); the caller draws nothing.
inline bool chargePixelWork(DecodeReport& report, std::uint64_t units) {
  if (report.overBudget || units > kPixelWorkBudget - report.pixelWork) {
    report.overBudget = true;
    return false;
  }
  report.pixelWork += units;
  return true;
}

// Error(Input) naming the stream when its drawing went over the budget.
void checkPixelWork(const DecodeReport& report, const std::string& name);

// Reads `in` to its end (at most kMaxStreamBytes, else Error(Input)) into the
// decoder, finishes it and checks the budget: what `lattice emulate` and a
// fuzzer call. `name` is used in messages.
void decodeStream(StreamDecoder& decoder, std::FILE* in, const std::string& name);
void decodeBytes(StreamDecoder& decoder, std::span<const std::uint8_t> bytes, const std::string& name);

}  // namespace lattice
