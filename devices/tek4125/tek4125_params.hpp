#pragma once
// Terminal-side parsing of 4100-series parameters, one byte at a time, so a
// decoder never needs more of the stream than the byte in hand. The caller
// filters control characters (the terminal ignores them inside parameters)
// and ESC (which abandons the command); readers see only 0x20..0x7F.
#include <cstdint>

namespace lattice::tek4125 {

enum class ReadStatus { More, Done, Bad };

// An integer: Hi-I chars (0x40..0x7F) then the Lo-I char (0x20..0x3F) that
// ends it. A third Hi-I char cannot come from a 16-bit value: Bad.
class IntReader {
 public:
  ReadStatus feed(std::uint8_t c);
  int value() const { return value_; }
  bool started() const { return hiCount_ > 0; }
  void reset() { value_ = 0, hiCount_ = 0; }

 private:
  int value_ = 0;
  int hiCount_ = 0;
};

// The terminal's xy registers: they outlive a coordinate, because the short
// forms leave out bytes that did not change.
struct XyRegisters {
  int hiY = 0, extra = 0, loY = 0, hiX = 0, loX = 0;  // payload bits of each byte
  int x() const { return hiX << 7 | loX << 2 | (extra & 3); }
  int y() const { return hiY << 7 | loY << 2 | (extra >> 2 & 3); }
};

// One xy coordinate. Byte classes: 0x20..0x3F Hi-Y or Hi-X (Hi-X when a
// Lo-Y came before it in this coordinate), 0x60..0x7F Lo-Y or Extra (Extra
// when another such byte follows), 0x40..0x5F Lo-X, which ends it.
class XyReader {
 public:
  ReadStatus feed(std::uint8_t c, XyRegisters& regs);
  bool started() const { return started_; }
  void reset() { started_ = false, loYSeen_ = false, pendingLow_ = -1; }

 private:
  bool started_ = false;
  bool loYSeen_ = false;  // a Lo-Y was settled: the next high byte is Hi-X
  int pendingLow_ = -1;   // a 0x60..0x7F byte not yet known to be Lo-Y or Extra
};

}  // namespace lattice::tek4125
