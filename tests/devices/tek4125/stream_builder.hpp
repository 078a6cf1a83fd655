#pragma once
// Building 4100-series streams byte by byte in tests, as a producer would
// write them, and decoding them whole.
#include <string_view>

#include "devices/tek4125/tek4100_decoder.hpp"
#include "devices/tek4125/tek_encoding.hpp"

namespace lattice::tektest {

struct Stream {
  tek::Bytes bytes;
  tek::XyEncoder xy;  // short forms: the registers the terminal keeps
  Stream& raw(std::string_view s) {
    for (char ch : s) bytes.push_back(static_cast<std::uint8_t>(ch));  // (insert trips a GCC 12 false warning)
    return *this;
  }
  Stream& cmd(std::string_view name) {
    tek::appendCommand(bytes, name);
    return *this;
  }
  Stream& i(int v) {
    tek::appendInt(bytes, v);
    return *this;
  }
  Stream& p(int x, int y) {  // short form
    xy.append(bytes, x, y);
    return *this;
  }
  Stream& full(int x, int y) {  // all five bytes, as GKS, zebra and RAL-CGM send them
    tek::XyEncoder fresh;
    fresh.append(bytes, x, y);
    return *this;
  }
};

inline Tek4100Decoder run(const tek::Bytes& b, Tek4125Profile profile = {}) {
  Tek4100Decoder d(profile);
  d.feed(b);
  d.finish();
  return d;
}

}  // namespace lattice::tektest
