#include "devices/tek4125/tek4125_device.hpp"

#include <fmt/format.h>

#include "devices/stream_shape.hpp"
#include "devices/tek4125/tek4125_decoder.hpp"
#include "devices/tek4125/tek4125_driver.hpp"
#include "devices/tek4125/tek4125_run_cost.hpp"
#include "devices/tek4125/tek4125_writer.hpp"

namespace lattice::tek4125 {
namespace {

class StreamDriver final : public devices::Driver {
 public:
  StreamDriver(ByteSink& out, const Tek4125Profile& profile) : driver_(out, profile), forms_(profile.forms) {}
  IndexedSink& sink() override { return driver_; }
  devices::DriverStats stats() const override {
    const Tek4125StreamStats& s = driver_.stats();
    return {s.bytes, s.seconds,
            fmt::format("profile {}, {} bits a pixel, {} raster writes, {} run-length writes, {} rectangle fills, "
                        "{} background pixels skipped ({})",
                        forms_, s.rasterBits, s.rasterWrites, s.runLengthWrites, s.rectangleFills, s.skippedPixels,
                        s.candidate)};
  }

 private:
  Tek4125Driver driver_;
  std::string forms_;
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
  d.makeEmulator = [profile] { return std::unique_ptr<StreamDecoder>(makeTek4125Decoder(profile)); };
  // The driver keeps the frame (a byte a pixel); its candidate streams are
  // counted, not held, and the writer hands bytes on every 16 KiB
  // (tek4125_writer.hpp): two spill buffers, escaped and not. Per column the
  // row planner's runs, ways, open rectangles and the row itself, under
  // 128 bytes. Measured against this bound in docs/memory.md ("Calibration").
  // progressive=on adds what the screen shows (an int a pixel), the draft
  // rows (a byte a pixel) and the covers (at most a rectangle a column of
  // each 16- and 8-row band, 3/16 of the pixels, 20 bytes each).
  d.driverMemory = [progressive = profile.progressive](int w, int h) {
    const auto width = static_cast<std::uint64_t>(w), area = width * static_cast<std::uint64_t>(h);
    const std::uint64_t plan = progressive ? (sizeof(int) + 1) * area + 20 * 3 * area / 16 : 0;
    return area + 128 * width + 4 * Tek4125Writer::kSpillBytes + plan;
  };
  // The screen a byte a pixel, and its RGB copy for the PNG.
  d.emulatorMemory = 3 * static_cast<std::uint64_t>(profile.width) * static_cast<std::uint64_t>(profile.height);
  d.line = profile.line();
  d.profileText = describe(profile);
  // 7-bit bytes with a 4100-series command (ESC and a letter: `ESC L F`,
  // `ESC % ! 0`) or the 4010 graph mode (GS) that gnuplot's and PGPLOT's
  // streams use; a scene, a text or an image has neither (nor a sixel
  // picture, whose DCS is ESC and a letter too).
  d.recognise = [](std::span<const std::uint8_t> head) {
    if (!devices::mostlySevenBit(head) || devices::hasSixelIntroducer(head)) return false;
    for (std::size_t i = 0; i < head.size(); ++i) {
      if (head[i] == 0x1D) return true;
      if (head[i] == 0x1B && i + 1 < head.size() && ((head[i + 1] >= 'A' && head[i + 1] <= 'Z') || head[i + 1] == '%'))
        return true;
    }
    return false;
  };
  d.runCost = [profile](const IndexedImage& picture) { return tek4125RunCost(profile, picture); };
  // Forms that draw the same screen in fewer bytes, off by default, as the
  // settings that turn them on.
  Tek4125Profile wire = profile;
  if (profile.formSet().fullXy) wire.xyShort = true;  // compact's short xy goes further
  if (profile.formSet().fittedDepth) wire.ruBitsFit = true;
  d.wireSettings = settingsChanged(tek4125Settings(), profile, wire);
  return d;
}

}  // namespace lattice::tek4125
