#include "devices/tek4014/tek4014_address.hpp"

namespace lattice::tek4014 {
namespace {

constexpr int kTagHigh = 0x20, kTagLoX = 0x40, kTagLoY = 0x60;

struct Bytes {
  int hiY, extra, loY, hiX, loX;
};

Bytes split(int x, int y) {
  return {kTagHigh | ((y >> 7) & 31), kTagLoY | ((y & 3) << 2) | (x & 3), kTagLoY | ((y >> 2) & 31),
          kTagHigh | ((x >> 7) & 31), kTagLoX | ((x >> 2) & 31)};
}

}  // namespace

int AddressEncoder::cost(int x, int y) const {
  const Bytes b = split(x, y);
  const bool hiY = !known_ || b.hiY != hiY_;
  const bool extra = twelveBit_ && (!known_ || b.extra != extra_);
  const bool hiX = !known_ || b.hiX != hiX_;
  const bool loY = !known_ || b.loY != loY_ || extra || hiX;
  return int(hiY) + int(extra) + int(loY) + int(hiX) + 1;
}

void AddressEncoder::encode(int x, int y, std::string& out) {
  const Bytes b = split(x, y);
  const bool hiY = !known_ || b.hiY != hiY_;
  const bool extra = twelveBit_ && (!known_ || b.extra != extra_);
  const bool hiX = !known_ || b.hiX != hiX_;
  const bool loY = !known_ || b.loY != loY_ || extra || hiX;
  if (hiY) out.push_back(static_cast<char>(b.hiY));
  if (extra) out.push_back(static_cast<char>(b.extra));
  if (loY) out.push_back(static_cast<char>(b.loY));
  if (hiX) out.push_back(static_cast<char>(b.hiX));
  out.push_back(static_cast<char>(b.loX));
  known_ = true;
  hiY_ = b.hiY;
  extra_ = b.extra;
  loY_ = b.loY;
  hiX_ = b.hiX;
}

void AddressAssembler::start() {
  px_ = x_;
  py_ = y_;
  loYSeen_ = false;
  pending_ = false;
}

bool AddressAssembler::add(std::uint8_t byte) {
  if (!pending_) start();
  pending_ = true;
  const int bits = byte & 31;
  if (byte < 0x40) {  // Hi Y before a Lo Y, Hi X after one
    if (loYSeen_) px_ = (px_ & ~(31 << 7)) | bits << 7;
    else py_ = (py_ & ~(31 << 7)) | bits << 7;
    return false;
  }
  if (byte < 0x60) {  // Lo X: the address is complete
    px_ = (px_ & ~(31 << 2)) | bits << 2;
    x_ = px_;
    y_ = py_;
    pending_ = false;
    return true;
  }
  // Lo Y; when one came before, that one was the extra byte (its low four
  // bits, already stored as Lo Y, move to the two lowest bits of x and y).
  // Bytes 0x80..0xFF land here too, their low five bits read as Lo Y.
  if (loYSeen_) {
    const int extra = (py_ >> 2) & 15;
    px_ = (px_ & ~3) | (extra & 3);
    py_ = (py_ & ~3) | (extra >> 2);
  }
  py_ = (py_ & ~(31 << 2)) | bits << 2;
  loYSeen_ = true;
  return false;
}

}  // namespace lattice::tek4014
