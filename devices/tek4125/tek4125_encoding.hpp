#pragma once
// Host-side encoding of Tektronix 4100-series command parameters. Every
// function appends to a byte buffer, so a driver can assemble a command and
// hand it to its ByteSink in one write.
//
// Encodings (4106/4107/4109/CX programmer's manual, as also implemented by
// gnuplot's tek410x terminal and PGPLOT's TK4100 driver); docs/tek4125.md
// restates them:
//   integer  up to two Hi-I chars (0x40 | 6 bits, most significant first,
//            leading zeros dropped) and one Lo-I char (0x20 | 4 bits, plus
//            0x10 when the value is >= 0). Magnitude 0..65535.
//   array    an integer count, then the integers.
//   real     two integers: mantissa and exponent, value = m * 2^e.
//   string   an integer count, then the raw characters.
//   xy       12-bit x and y in up to five bytes; bytes that did not change
//            since the previous xy may be left out (XyEncoder keeps the
//            terminal's idea of the previous one).
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace lattice::tek4125 {

using Bytes = std::vector<std::uint8_t>;

constexpr std::uint8_t kEsc = 0x1B;
constexpr int kMaxIntMagnitude = 65535;  // 2 Hi-I chars (12 bits) + Lo-I (4 bits)
constexpr int kMaxCoordinate = 4095;     // 12-bit xy

// ESC followed by the two-letter command name ("TG", "RP", ...).
void appendCommand(Bytes& out, std::string_view name);
// Throws lattice::Error(Internal) when |value| > kMaxIntMagnitude: a driver
// bug, never user input.
void appendInt(Bytes& out, int value);
// How many bytes appendInt would write (1..3), for size estimates.
int intLength(int value);
void appendIntArray(Bytes& out, std::span<const int> values);
void appendReal(Bytes& out, int mantissa, int exponent);
// Nearest m * 2^e with |m| <= 65535 (largest such mantissa, so the most precise).
void appendReal(Bytes& out, double value);
void appendString(Bytes& out, std::string_view text);

// The five xy bytes of one coordinate pair.
struct XyBytes {
  std::uint8_t hiY = 0, extra = 0, loY = 0, hiX = 0, loX = 0;
  friend bool operator==(const XyBytes&, const XyBytes&) = default;
};
XyBytes xyBytes(int x, int y);  // x, y in 0..4095 (Error(Internal) otherwise)

// Short-form xy encoder. Hi-Y is sent when it changed, Extra when it
// changed, Lo-Y when it changed or Extra or Hi-X is sent (a decoder tells
// Hi-X from Hi-Y only by a Lo-Y byte before it), Hi-X when it changed, Lo-X
// always (it ends the coordinate). One encoder must follow the whole stream,
// because the terminal keeps its registers across commands.
class XyEncoder {
 public:
  void append(Bytes& out, int x, int y);
  // Bytes append() would write now, without changing the registers.
  int length(int x, int y) const;
  // OpenVnmrJ's form (tek_coord0): Hi-Y and Hi-X left out when unchanged,
  // Extra, Lo-Y and Lo-X always sent (3 to 5 bytes; a decoder tells Hi-X from
  // Hi-Y by the Lo-Y always before it).
  void appendHighShort(Bytes& out, int x, int y);
  int highShortLength(int x, int y) const;
  // Forget the previous coordinate: the next one is sent in full.
  void reset() { known_ = false; }

 private:
  XyBytes last_;
  bool known_ = false;
};

}  // namespace lattice::tek4125
