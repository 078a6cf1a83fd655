#pragma once
// What a sixel terminal shows after the bytes `lattice term` wrote to it:
// each picture (DCS ... ST) decoded by the project's sixel emulator and
// placed at the text row the CUP before it named (rows cellHeight pixels
// high), over a black screen. Tests play the host terminal with it.
#include <cstdint>
#include <string>
#include <vector>

#include "devices/sixel/sixel_decoder.hpp"
#include "foundation/rgb_image.hpp"

namespace lattice::testing {

struct SixelScreen {
  RgbImage image;
  int pictures = 0;         // DCS strings decoded
  std::vector<int> rows;    // the text row (1-based) each was drawn at
};

inline SixelScreen composeSixels(const std::string& bytes, int width, int height, int cellHeight) {
  SixelScreen screen;
  screen.image.width = width;
  screen.image.height = height;
  screen.image.rgb.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3, 0);
  // CSI row ; 1 H, then DCS ... ST (found by hand: std::regex recurses per character).
  for (std::size_t at = bytes.find("\x1b["); at != std::string::npos; at = bytes.find("\x1b[", at + 1)) {
    std::size_t end = at + 2;
    while (end < bytes.size() && bytes[end] >= '0' && bytes[end] <= '9') ++end;
    if (end == at + 2 || bytes.compare(end, 5, ";1H\x1bP") != 0) continue;
    const std::size_t stop = bytes.find("\x1b\\", end + 5);
    if (stop == std::string::npos) break;
    const int row = std::stoi(bytes.substr(at + 2, end - at - 2));
    const std::string dcs = bytes.substr(end + 3, stop + 2 - (end + 3));
    sixel::SixelProfile profile;
    profile.registers = 256;
    sixel::SixelDecoder decoder(profile);
    decoder.feed(std::span(reinterpret_cast<const std::uint8_t*>(dcs.data()), dcs.size()));
    decoder.finish();
    const IndexedImage& drawn = decoder.image();
    const int top = (row - 1) * cellHeight;
    for (int y = 0; y < drawn.height && top + y < height; ++y)
      for (int x = 0; x < drawn.width && x < width; ++x) {
        const Rgb8 c = drawn.colorAt(x, y);
        std::uint8_t* to = &screen.image.rgb[(static_cast<std::size_t>(top + y) * static_cast<std::size_t>(width) +
                                              static_cast<std::size_t>(x)) * 3];
        to[0] = c.r;
        to[1] = c.g;
        to[2] = c.b;
      }
    ++screen.pictures;
    screen.rows.push_back(row);
  }
  return screen;
}

}  // namespace lattice::testing
