#pragma once
// Tektronix 4010/4014 graphic addresses, both ways: the encoder the driver
// uses and the assembler the emulator uses. docs/tek4014-sources.md cites
// every rule here.
//
// Method: an address is up to five bytes, told apart by their two tag bits
// (bits 6 and 5): Hi Y and Hi X 01 (0x20..0x3F, the five high bits),
// Lo Y 11 (0x60..0x7F, the next five), Lo X 10 (0x40..0x5F, the next five,
// and it completes the address); in 12-bit mode an extra byte, also tagged
// 11, goes before Lo Y and holds the two lowest bits of y (bits 3..2) and
// of x (bits 1..0). A terminal keeps each byte's bits until replaced, so
// only what changed is sent, with these rules:
//  - Hi Y when it changed;
//  - the extra byte when it changed, and then Lo Y too (a tag-11 byte is
//    only an extra byte when another tag-11 byte follows it);
//  - Lo Y when it changed, and whenever Hi X is sent (a tag-01 byte before
//    Lo Y is Hi Y, after it Hi X);
//  - Hi X when it changed;
//  - Lo X always.
// Coordinates here are 12-bit (0..4095), the unit every byte is decoded
// into; a 10-bit stream is a 12-bit one whose two low bits never change.
#include <cstdint>
#include <string>

namespace lattice::tek4014 {

// Bytes the driver sends; the parser recognises the same ones.
inline constexpr char kEsc = 0x1B;
inline constexpr char kFormFeed = 0x0C;  // ESC FF: erase the screen (PAGE)
inline constexpr char kPointPlot = 0x1C;  // FS: each address is one dot
inline constexpr char kGraph = 0x1D;      // GS: the first address moves, the next ones draw vectors
inline constexpr char kIncremental = 0x1E;  // RS: one-unit steps
inline constexpr char kAlpha = 0x1F;      // US: text

class AddressEncoder {
 public:
  explicit AddressEncoder(bool twelveBit) : twelveBit_(twelveBit) {}
  // Appends the bytes that take the terminal from the last address to (x, y).
  void encode(int x, int y, std::string& out);
  // Bytes encode() would append, without changing anything.
  int cost(int x, int y) const;

 private:
  bool twelveBit_;
  bool known_ = false;  // nothing sent yet: the terminal's registers are unknown
  int hiY_ = 0, extra_ = 0, loY_ = 0, hiX_ = 0;
};

// Collects an address byte by byte, as xterm's Tek window does: partial
// bytes are held aside, and only Lo X commits them to the position.
class AddressAssembler {
 public:
  // Resets the bytes of an address in progress (a control byte abandons it).
  void start();
  // One byte 0x20..0xFF of an address; true when it completed one (Lo X):
  // then x() and y() are the new position.
  bool add(std::uint8_t byte);
  int x() const { return x_; }
  int y() const { return y_; }
  bool inProgress() const { return pending_; }

 private:
  int x_ = 0, y_ = 0;    // committed
  int px_ = 0, py_ = 0;  // being assembled
  bool loYSeen_ = false;
  bool pending_ = false;
};

}  // namespace lattice::tek4014
