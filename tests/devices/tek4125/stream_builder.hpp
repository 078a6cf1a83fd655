#pragma once
// Building 4100-series streams byte by byte in tests, as a producer would
// write them, and decoding them whole.
#include <string_view>

#include "devices/tek4125/tek4125_decoder.hpp"
#include "devices/tek4125/tek4125_encoding.hpp"

#include "tests/devices/tek4125/readings_keys.hpp"

namespace lattice::tek4125::test {

struct Stream {
  tek4125::Bytes bytes;
  tek4125::XyEncoder xy;  // short forms: the registers the terminal keeps
  Stream& raw(std::string_view s) {
    for (char ch : s) bytes.push_back(static_cast<std::uint8_t>(ch));  // (insert trips a GCC 12 false warning)
    return *this;
  }
  Stream& cmd(std::string_view name) {
    tek4125::appendCommand(bytes, name);
    return *this;
  }
  Stream& i(int v) {
    tek4125::appendInt(bytes, v);
    return *this;
  }
  Stream& p(int x, int y) {  // short form
    xy.append(bytes, x, y);
    return *this;
  }
  Stream& full(int x, int y) {  // all five bytes, as GKS, zebra and RAL-CGM send them
    tek4125::XyEncoder fresh;
    fresh.append(bytes, x, y);
    return *this;
  }
};

// The stream decoded under `profile` and the readings given as key=value
// (readings_keys.hpp).
inline Tek4125Decoder run(const tek4125::Bytes& b, const Tek4125Profile& profile = {},
                          const std::vector<std::string>& readings = {}) {
  Tek4125Decoder d(profile, readingsOf(readings));
  d.feed(b);
  d.finish();
  return d;
}

}  // namespace lattice::tek4125::test
