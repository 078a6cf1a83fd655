#pragma once
// `lattice emulate --at 10%,25%,50%` (or byte offsets, 4096,20000): the
// screen as it stands after the first N bytes of a stream, what a person at
// the terminal sees that many seconds in (bytes = seconds * baud / 10 at 8N1).
// Each point's screen is written beside the output: OUT.png gives
// OUT-at25pct.png and OUT-at4096B.png; the whole stream's screen goes to OUT.png.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "devices/stream_decoder.hpp"

namespace lattice::app {

struct StreamPoint {
  std::uint64_t offset = 0;  // bytes fed before the screen is taken
  std::string tag;           // "25pct", "4096B": names the file
};

// At most this many points: each is a full-screen PNG.
inline constexpr std::size_t kMaxStreamPoints = 32;

// "10%,25%" and/or "4096,20000" against a stream of `total` bytes, in
// stream order. Every item is read by the one number parser
// (foundation/number_text.hpp): a percentage 0..100, a byte offset a whole
// number within kMaxStreamBytes (past the stream's end it is the end).
// Error(Usage) names the bad item, the range and the forms allowed.
std::vector<StreamPoint> parseStreamPoints(const std::string& text, std::uint64_t total);

// The files the points of `text` will be written to (any stream length gives
// the same names) checked as -o is (app/output_check.hpp): called
// before the stream is read, so a bad --at costs nothing.
void checkStreamPointOutputs(const std::string& text, const std::string& output, bool force);

// OUT.png and "25pct" -> OUT-at25pct.png.
std::string pointPngPath(const std::string& output, const std::string& tag);

// Reads the stream (within kMaxStreamBytes), feeds it to the decoder,
// writing the screen at each point, then finishes it and checks its work
// budget as decodeStream does. Returns the paths written.
std::vector<std::string> decodeWithSnapshots(StreamDecoder& decoder, std::FILE* in, const std::string& name,
                                             const std::string& points, const std::string& output);

}  // namespace lattice::app
