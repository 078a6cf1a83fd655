#include "devices/apollo_sim/apollo_driver.hpp"

#include "devices/apollo_sim/gpr_display.hpp"

#include <fmt/format.h>

#include "foundation/error.hpp"

namespace lattice::apollo {

ApolloDriver::ApolloDriver(GprCalls& display) : display_(display) {}

int ApolloDriver::maxColors() const { return display_.inqDispCharacteristics().colorMapEntries; }

void ApolloDriver::begin(const FrameInfo& frame) {
  GprDisplayCharacteristics screen = display_.inqDispCharacteristics();
  if (frame.width < 1 || frame.height < 1 || frame.width > screen.xVisibleSize || frame.height > screen.yVisibleSize)
    throw Error(ErrorKind::Usage,
                fmt::format("a {}x{} picture does not fit the {} screen ({}x{}): render at most {}x{}", frame.width,
                            frame.height, screen.model, screen.xVisibleSize, screen.yVisibleSize,
                            screen.xVisibleSize, screen.yVisibleSize));
  if (frame.palette.size() > static_cast<std::size_t>(screen.colorMapEntries))
    throw Error(ErrorKind::Internal, fmt::format("ApolloDriver: {} palette entries for a {}-entry colour map",
                                                 frame.palette.size(), screen.colorMapEntries));
  frame_ = frame;
  originX_ = (screen.xVisibleSize - frame.width) / 2;
  originY_ = (screen.yVisibleSize - frame.height) / 2;
  rowValues_.assign(static_cast<std::size_t>(frame.width), 0);

  std::vector<std::uint32_t> map;
  map.reserve(frame.palette.size() + 1);
  for (Rgb8 c : frame.palette) map.push_back(packRgb(c));
  std::uint32_t background = 0;
  if (map.size() < static_cast<std::size_t>(screen.colorMapEntries)) {
    background = static_cast<std::uint32_t>(map.size());
    map.push_back(0x000000);
  } else {
    int best = 1 << 30;
    for (std::size_t i = 0; i < frame.palette.size(); ++i) {
      Rgb8 c = frame.palette[i];
      int d = c.r * c.r + c.g * c.g + c.b * c.b;
      if (d < best) {
        best = d;
        background = static_cast<std::uint32_t>(i);
      }
    }
  }
  display_.acquireDisplay();
  display_.setColorMap(0, map);
  display_.clear(background);
}

void ApolloDriver::row(int y, std::span<const PaletteIndex> indices) {
  if (y < 0 || y >= frame_.height || indices.size() != rowValues_.size())
    throw Error(ErrorKind::Internal, fmt::format("ApolloDriver: row {} of {} pixels for a {}x{} picture", y,
                                                 indices.size(), frame_.width, frame_.height));
  for (std::size_t x = 0; x < indices.size(); ++x) {
    if (indices[x] >= frame_.palette.size())
      throw Error(ErrorKind::Internal, fmt::format("ApolloDriver: index {} beyond the {}-entry palette", indices[x],
                                                   frame_.palette.size()));
    rowValues_[x] = indices[x];
  }
  display_.writePixels(rowValues_, GprWindow{originX_, originY_ + y, frame_.width, 1});
}

void ApolloDriver::end() { display_.releaseDisplay(); }

}  // namespace lattice::apollo
