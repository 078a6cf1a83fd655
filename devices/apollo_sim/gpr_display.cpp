#include "devices/apollo_sim/gpr_display.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "foundation/error.hpp"

namespace lattice::apollo {
namespace {

[[noreturn]] void misuse(const std::string& message) {
  throw Error(ErrorKind::Internal, "Apollo GPR simulator: " + message);
}

}  // namespace

void GprDisplay::init(GprDisplayMode mode, const ApolloProfile& profile) {
  if (initialized_) misuse("gpr_$init called twice without gpr_$terminate");
  if (profile.width < 1 || profile.height < 1 || profile.planes < 1 || profile.planes > 8)
    misuse(fmt::format("profile '{}' is {}x{} with {} planes; the simulator supports 1..8 planes", profile.name,
                       profile.width, profile.height, profile.planes));
  profile_ = profile;
  mode_ = mode;
  framebuffer_.assign(static_cast<std::size_t>(profile.width) * static_cast<std::size_t>(profile.height), 0);
  // Power-on colour map: the simulator starts every entry black, so anything
  // drawn before gpr_$set_color_map is visibly wrong rather than plausible.
  colorMap_.assign(static_cast<std::size_t>(profile.colorMapEntries()), 0);
  initialized_ = true;
  acquired_ = false;
}

GprDisplayCharacteristics GprDisplay::inqDispCharacteristics() const {
  if (!initialized_) misuse("gpr_$inq_disp_characteristics before gpr_$init");
  return characteristicsOf(profile_);
}

GprDisplayCharacteristics characteristicsOf(const ApolloProfile& profile) {
  return GprDisplayCharacteristics{profile.model, profile.width, profile.height, profile.planes, profile.gunBits,
                                   profile.colorMapEntries()};
}

void GprDisplay::acquireDisplay() {
  if (!initialized_) misuse("gpr_$acquire_display before gpr_$init");
  if (acquired_) misuse("gpr_$acquire_display while the display is already acquired");
  acquired_ = true;
}

void GprDisplay::releaseDisplay() {
  if (!acquired_) misuse("gpr_$release_display without gpr_$acquire_display");
  acquired_ = false;
}

void GprDisplay::requireDrawable(const char* call) const {
  if (!initialized_) misuse(fmt::format("{} before gpr_$init", call));
  bool shared = mode_ == GprDisplayMode::Borrow || mode_ == GprDisplayMode::Direct;
  if (shared && !acquired_) misuse(fmt::format("{} without gpr_$acquire_display", call));
}

void GprDisplay::setColorMap(int start, std::span<const std::uint32_t> values) {
  requireDrawable("gpr_$set_color_map");
  long end = long(start) + long(values.size());
  if (start < 0 || end > long(colorMap_.size()))
    misuse(fmt::format("gpr_$set_color_map entries {}..{} outside the {}-entry colour map", start, end - 1,
                       colorMap_.size()));
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i] > 0xFFFFFFu) misuse(fmt::format("gpr_$set_color_map value {:#x} is not 0xRRGGBB", values[i]));
    colorMap_[static_cast<std::size_t>(start) + i] = values[i];
  }
}

void GprDisplay::writePixels(std::span<const std::uint32_t> values, const GprWindow& window) {
  requireDrawable("gpr_$write_pixels");
  if (window.width < 0 || window.height < 0 || window.x < 0 || window.y < 0 ||
      long(window.x) + window.width > profile_.width || long(window.y) + window.height > profile_.height)
    misuse(fmt::format("gpr_$write_pixels window {}x{} at ({}, {}) is outside the {}x{} screen", window.width,
                       window.height, window.x, window.y, profile_.width, profile_.height));
  if (values.size() != static_cast<std::size_t>(window.width) * static_cast<std::size_t>(window.height))
    misuse(fmt::format("gpr_$write_pixels got {} values for a {}x{} window", values.size(), window.width,
                       window.height));
  const std::uint32_t mask = (1u << profile_.planes) - 1u;
  for (int row = 0; row < window.height; ++row) {
    auto target = framebuffer_.begin() +
                  static_cast<std::ptrdiff_t>(window.y + row) * profile_.width + window.x;
    auto source = values.subspan(static_cast<std::size_t>(row) * static_cast<std::size_t>(window.width),
                                 static_cast<std::size_t>(window.width));
    std::transform(source.begin(), source.end(), target,
                   [mask](std::uint32_t v) { return static_cast<std::uint8_t>(v & mask); });
  }
}

void GprDisplay::clear(std::uint32_t index) {
  requireDrawable("gpr_$clear");
  std::fill(framebuffer_.begin(), framebuffer_.end(),
            static_cast<std::uint8_t>(index & ((1u << profile_.planes) - 1u)));
}

void GprDisplay::terminate() {
  if (!initialized_) misuse("gpr_$terminate before gpr_$init");
  initialized_ = false;
  acquired_ = false;
}

std::uint32_t GprDisplay::pixel(int x, int y) const {
  if (framebuffer_.empty() || x < 0 || y < 0 || x >= profile_.width || y >= profile_.height)
    misuse(fmt::format("pixel ({}, {}) is outside the screen", x, y));
  return framebuffer_[static_cast<std::size_t>(y) * static_cast<std::size_t>(profile_.width) +
                      static_cast<std::size_t>(x)];
}

std::uint32_t GprDisplay::colorMapEntry(int index) const {
  if (index < 0 || static_cast<std::size_t>(index) >= colorMap_.size())
    misuse(fmt::format("colour map entry {} does not exist", index));
  return colorMap_[static_cast<std::size_t>(index)];
}

IndexedImage GprDisplay::snapshot() const {
  if (framebuffer_.empty()) misuse("snapshot before gpr_$init");
  IndexedImage image(profile_.width, profile_.height, 0);
  image.pixels = framebuffer_;
  image.colormap.reserve(colorMap_.size());
  for (std::uint32_t v : colorMap_) image.colormap.push_back(unpackRgb(v));
  return image;
}

}  // namespace lattice::apollo
