#include "devices/tek4027/tek4027_device.hpp"

#include <fmt/format.h>

#include "devices/stream_shape.hpp"
#include "devices/tek4027/tek4027_decoder.hpp"
#include "devices/tek4027/tek4027_driver.hpp"
#include "devices/tek4027/tek4027_encoder.hpp"
#include "devices/tek4027/tek4027_pacing.hpp"
#include "devices/tek4027/tek4027_run_cost.hpp"

namespace lattice::tek4027 {
namespace {

class StreamDriver final : public devices::Driver {
 public:
  StreamDriver(ByteSink& out, const Tek4027Profile& profile) : driver_(out, profile) {}
  IndexedSink& sink() override { return driver_; }
  devices::DriverStats stats() const override {
    const Tek4027StreamStats& s = driver_.stats();
    return {s.bytes, s.seconds(),
            fmt::format("profile {}, strategy {} along {}, {} commands ({} colour changes, {} vector commands, "
                        "{} report requests), line {:.0f} s, drawing {:.0f} s",
                        driver_.profile().name, strategyName(s.strategy), orientationName(s.orientation), s.commands,
                        s.colourSelects, s.vectorCommands, s.reportRequests, s.lineSeconds, s.terminalSeconds)};
  }
  void answerOn(int fd, double timeoutSeconds) override {
    replies_ = std::make_unique<Tek4027FdReplies>(fd, timeoutSeconds);
    driver_.setReplies(replies_.get());
  }

 private:
  Tek4027Driver driver_;
  std::unique_ptr<Tek4027FdReplies> replies_;
};

std::uint64_t pixels(int w, int h) { return static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h); }

}  // namespace

devices::Device makeDevice(const std::vector<std::string>& settings) {
  Tek4027Profile profile;
  applyOverrides(profile, settings);
  devices::Device d;
  d.name = "tek4027";
  d.title = "Tektronix 4027";
  d.width = profile.width;
  d.height = profile.height;
  d.makeDriver = [profile](ByteSink& out) { return std::make_unique<StreamDriver>(out, profile); };
  d.makeEmulator = [profile] { return std::unique_ptr<StreamDecoder>(std::make_unique<Tek4027Decoder>(profile)); };
  // The driver keeps the frame and its pot map, then encodes its stream
  // orders one after another, holding the shortest so far beside the next
  // (strings that grow by doubling): measured up to 16.3 B a pixel of working
  // set on the example scenes (docs/memory.md, "Calibration"), before the
  // orientations added a turned copy of the frame (1 B a pixel); the paced
  // copy of the winner takes the place of the candidate, so pacing adds none.
  // 20 B a pixel left the 5000-hair sphere 195 KiB above its prediction once
  // the closed-form leaves and the static C++ runtime moved what is
  // resident before the driver starts (bench/memory-calibration.sh, 2026-12-02).
  d.driverMemory = [](int w, int h) { return 22 * pixels(w, h); };
  d.emulatorMemory = 3 * pixels(profile.width, profile.height);  // the screen, and its RGB copy for the PNG
  d.line = profile.line;
  d.profileText = describe(profile);
  // 7-bit text with a command: the command character `!` and a three-letter
  // name (`!WOR`, `!GRA`, `!MAP`); no escape sequences, which are the 4100
  // series' (the 4027 takes ESC only as an ordinary control character).
  d.recognise = [](std::span<const std::uint8_t> head) {
    if (!devices::mostlySevenBit(head)) return false;
    bool command = false;
    for (std::size_t i = 0; i < head.size(); ++i) {
      if (head[i] == 0x1B) return false;
      const auto upper = [&](std::size_t at) { return at < head.size() && head[at] >= 'A' && head[at] <= 'Z'; };
      command = command || (head[i] == '!' && upper(i + 1) && upper(i + 2) && upper(i + 3));
    }
    return command;
  };
  d.runCost = [](const IndexedImage& picture) { return tek4027RunCost(picture); };
  // `lattice send --device tek4027` waits where the stream asks (the same
  // requests the driver waits on over a live line).
  d.replies = devices::Device::ReplyPacing{
      [profile](std::span<const std::uint8_t> stream) {
        return reportRecordEnds(std::string(reinterpret_cast<const char*>(stream.data()), stream.size()), profile);
      },
      [](int fd, double timeoutSeconds) { Tek4027FdReplies(fd, timeoutSeconds).awaitReply(); }};
  return d;
}

}  // namespace lattice::tek4027
