#include "devices/tek4125/tek4125_params.hpp"

namespace lattice::tek4125 {

ReadStatus IntReader::feed(std::uint8_t c) {
  if (c >= 0x40 && c <= 0x7F) {
    if (hiCount_ == 2) return ReadStatus::Bad;
    value_ = value_ << 6 | (c & 63);
    ++hiCount_;
    return ReadStatus::More;
  }
  if (c >= 0x20 && c <= 0x3F) {
    value_ = value_ << 4 | (c & 15);
    if ((c & 0x10) == 0) value_ = -value_;
    return ReadStatus::Done;
  }
  return ReadStatus::Bad;
}

ReadStatus XyReader::feed(std::uint8_t c, XyRegisters& regs) {
  started_ = true;
  if (c >= 0x60 && c <= 0x7F) {
    if (pendingLow_ >= 0) regs.extra = pendingLow_ & 15;  // two in a row: the first was Extra
    pendingLow_ = c & 31;
    return ReadStatus::More;
  }
  if (pendingLow_ >= 0) {  // a lone low byte before a high or Lo-X byte is Lo-Y
    regs.loY = pendingLow_;
    pendingLow_ = -1;
    loYSeen_ = true;
  }
  if (c >= 0x20 && c <= 0x3F) {
    (loYSeen_ ? regs.hiX : regs.hiY) = c & 31;
    return ReadStatus::More;
  }
  if (c >= 0x40 && c <= 0x5F) {
    regs.loX = c & 31;
    return ReadStatus::Done;
  }
  return ReadStatus::Bad;
}

}  // namespace lattice::tek4125
