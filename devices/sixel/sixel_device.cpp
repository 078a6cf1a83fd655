#include "devices/sixel/sixel_device.hpp"

#include <fmt/format.h>

#include "devices/sixel/sixel_decoder.hpp"
#include "devices/sixel/sixel_driver.hpp"
#include "devices/sixel/sixel_run_cost.hpp"
#include "devices/stream_shape.hpp"

namespace lattice::sixel {
namespace {

class StreamDriver final : public devices::Driver {
 public:
  StreamDriver(ByteSink& out, const SixelProfile& profile) : driver_(out, profile) {}
  IndexedSink& sink() override { return driver_; }
  devices::DriverStats stats() const override {
    const SixelStreamStats& s = driver_.stats();
    return {s.bytes, 0.0,
            fmt::format("{} registers defined of {}, {} bands, {} colour passes in {} segments on {} lines, {} runs",
                        s.registers, driver_.profile().registers, s.bands, s.band.passes, s.band.segments,
                        s.band.lines, s.band.runs)};
  }

 private:
  SixelDriver driver_;
};

}  // namespace

devices::Device makeDevice(const std::vector<std::string>& settings) {
  SixelProfile profile;
  applyOverrides(profile, settings);
  devices::Device d;
  d.name = "sixel";
  d.title = "DEC sixel terminal (VT340, xterm -ti vt340)";
  d.width = profile.width;
  d.height = profile.height;
  d.makeDriver = [profile](ByteSink& out) { return std::make_unique<StreamDriver>(out, profile); };
  d.makeEmulator = [profile] { return std::unique_ptr<StreamDecoder>(std::make_unique<SixelDecoder>(profile)); };
  // One band of indices, the encoder's three per-column arrays, the band's
  // bytes and a candidate layout's (at most about 4 a column a register
  // pass, usually far less), its runs (at most two a must column of a pass,
  // so 12 a column, 24 B each) and segments (fewer than runs, 64 B each).
  d.driverMemory = [](int w, int) { return static_cast<std::uint64_t>(w) * (6 + 3 + 2 * 64 + 12 * (24 + 64)) + 65536; };
  // The canvas, its cropped copy and the RGB copy for the PNG.
  d.emulatorMemory = 5 * static_cast<std::uint64_t>(profile.width) * static_cast<std::uint64_t>(profile.height);
  d.profileText = describe(profile);
  d.showsOnTerminal = true;
  // A sixel stream is 7-bit text (but for an 8-bit DCS and ST) with a
  // DCS ... q. Both are asked: the introducer alone (0x90 then `q`) turns up
  // in about one random 4 KiB in fourteen.
  d.recognise = [](std::span<const std::uint8_t> head) {
    return devices::mostlySevenBit(head) && devices::hasSixelIntroducer(head);
  };
  d.runCost = [](const IndexedImage& picture) { return sixelRunCost(picture); };
  return d;
}

}  // namespace lattice::sixel
