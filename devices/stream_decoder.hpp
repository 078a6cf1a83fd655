#pragma once
// An emulator is an ordinary decoder: feed it the bytes of a command stream
// in any chunking (one byte at a time too) and it keeps an indexed
// framebuffer and colour map, as the terminal's screen would. Any test can
// drive one; `lattice emulate` writes its image as PNG.
//
// Decoders never throw on stream content: unknown commands and garbage are
// skipped (resynchronising at the next command introducer) and counted in the
// report. They never read out of bounds or loop without consuming input.
#include <cstdint>
#include <map>
#include <span>
#include <string>

#include "foundation/indexed_image.hpp"

namespace lattice {

struct DecodeReport {
  std::uint64_t bytes = 0;            // bytes fed
  std::uint64_t commands = 0;         // commands recognised and executed
  std::uint64_t unknownCommands = 0;  // well-formed introducer, unknown name
  std::uint64_t malformed = 0;        // bad parameters, truncated commands, stray bytes
  std::map<std::string, std::uint64_t> unknownByName;  // name -> count, for --report
  // Drawing charged against kPixelWorkBudget (devices/work_budget.hpp); once
  // over it, nothing more is drawn.
  std::uint64_t pixelWork = 0;
  bool overBudget = false;
  std::string summary() const;                         // multi-line human-readable
};

class StreamDecoder {
 public:
  virtual ~StreamDecoder() = default;
  virtual void feed(std::span<const std::uint8_t> bytes) = 0;
  // End of stream: a command cut off by the end is counted as malformed.
  virtual void finish() = 0;
  virtual const IndexedImage& image() const = 0;
  virtual const DecodeReport& report() const = 0;
  // The alphanumeric text the stream wrote for the terminal's dialog area
  // (a 4100-series terminal's ANSI-mode and alpha-mode characters, with CR
  // and LF), its last kDialogKeepBytes; empty for a device without one.
  // `lattice term` shows its last lines below the picture.
  virtual const std::string& dialogText() const;
};

inline constexpr std::size_t kDialogKeepBytes = 4096;

// Appends `c` to a dialog area's text, keeping its last kDialogKeepBytes.
void appendDialogText(std::string& text, std::uint8_t c);

}  // namespace lattice
