#include "devices/tek4125/tek4125_device.hpp"

#include <fmt/format.h>

#include "devices/tek4125/tek4100_decoder.hpp"
#include "devices/tek4125/tek4125_driver.hpp"

namespace lattice::tek4125 {
namespace {

class StreamDriver final : public devices::Driver {
 public:
  StreamDriver(ByteSink& out, const Tek4125Profile& profile) : driver_(out, profile) {}
  IndexedSink& sink() override { return driver_; }
  devices::DriverStats stats() const override {
    const Tek4125StreamStats& s = driver_.stats();
    return {s.bytes, s.seconds,
            fmt::format("{} raster writes, {} rectangle fills, {} pixels left to the clear", s.rasterWrites,
                        s.rectangleFills, s.skippedPixels)};
  }

 private:
  Tek4125Driver driver_;
};

}  // namespace

devices::Device makeDevice(const std::vector<std::string>& settings) {
  Tek4125Profile profile;
  applyOverrides(profile, settings);
  devices::Device d;
  d.name = "tek4125";
  d.title = "Tektronix 4125";
  d.width = profile.width;
  d.height = profile.height;
  d.makeDriver = [profile](ByteSink& out) { return std::make_unique<StreamDriver>(out, profile); };
  d.makeEmulator = [profile] { return std::unique_ptr<StreamDecoder>(makeTek4100Decoder(profile)); };
  d.driverMemory = [](int, int) { return std::uint64_t{0}; };  // it streams: a row at a time
  // The screen a byte a pixel, and its RGB copy for the PNG.
  d.emulatorMemory = 3 * static_cast<std::uint64_t>(profile.width) * static_cast<std::uint64_t>(profile.height);
  d.line = profile.line();
  d.profileText = describe(profile);
  return d;
}

}  // namespace lattice::tek4125
