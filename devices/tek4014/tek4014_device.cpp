#include "devices/tek4014/tek4014_device.hpp"

#include <fmt/format.h>

#include "devices/tek4014/tek4014_decoder.hpp"
#include "devices/tek4014/tek4014_driver.hpp"
#include "devices/tek4014/tek4014_screen.hpp"
#include "devices/stream_shape.hpp"

namespace lattice::tek4014 {
namespace {

class StreamDriver final : public devices::Driver {
 public:
  StreamDriver(ByteSink& out, const Tek4014Profile& profile) : driver_(out, profile) {}
  IndexedSink& sink() override { return driver_; }
  devices::DriverStats stats() const override {
    const Tek4014Stats& s = driver_.stats();
    const Tek4014Profile& p = driver_.profile();
    return {s.bytes, transmitSeconds(s.bytes, p.line),
            fmt::format("{}-bit addresses, {} dither, {} dots lit; {} rows as point plots, {} as {} short vectors",
                        p.addressBits, ditherName(p.dither), s.dots, s.pointRows, s.vectorRows, s.vectors)};
  }

 private:
  Tek4014Driver driver_;
};

}  // namespace

devices::Device makeDevice(const std::vector<std::string>& settings) {
  Tek4014Profile profile;
  applyOverrides(profile, settings);
  devices::Device d;
  d.name = "tek4014";
  d.title = "Tektronix 4014";
  d.width = profile.width();
  d.height = profile.height();
  d.makeDriver = [profile](ByteSink& out) { return std::make_unique<StreamDriver>(out, profile); };
  d.makeEmulator = [profile] { return std::unique_ptr<StreamDecoder>(std::make_unique<Tek4014Decoder>(profile)); };
  // A row at a time: the dots of a row, two rows of dither error (4 B a
  // pixel each) and the row's two candidate encodings (at most 6 B a dot
  // each in 12-bit mode, 5 in 10-bit).
  d.driverMemory = [](int w, int) { return 24 * static_cast<std::uint64_t>(w) + 4096; };
  // The screen's two bitmaps, the picture made of them (a byte a pixel) and
  // its RGB copy for the PNG.
  d.emulatorMemory = Tek4014Screen::bitmapBytes(profile.width(), profile.height()) +
                     4 * static_cast<std::uint64_t>(profile.width()) * static_cast<std::uint64_t>(profile.height());
  d.line = profile.line;
  d.profileText = describe(profile);
  // 7-bit bytes with the 4014's graph modes (GS: vectors, FS: point plots) or
  // its erase (ESC FF); a scene, a text or an image has none of them. A 4100
  // command (ESC and a capital or `%`) says the stream is a 4125's instead.
  d.recognise = [](std::span<const std::uint8_t> head) {
    if (!devices::mostlySevenBit(head)) return false;
    for (std::size_t i = 0; i + 1 < head.size(); ++i)
      if (head[i] == 0x1B && ((head[i + 1] >= 'A' && head[i + 1] <= 'Z') || head[i + 1] == '%')) return false;
    for (std::size_t i = 0; i < head.size(); ++i) {
      if (head[i] == 0x1D || head[i] == 0x1C) return true;
      if (head[i] == 0x1B && i + 1 < head.size() && head[i + 1] == 0x0C) return true;
    }
    return false;
  };
  return d;
}

}  // namespace lattice::tek4014
