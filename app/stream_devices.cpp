#include "app/stream_devices.hpp"

#include <fmt/format.h>

#include "devices/tek4027/tek4027_decoder.hpp"
#include "devices/tek4027/tek4027_driver.hpp"
#include "devices/tek4027/tek4027_encoder.hpp"
#include "devices/tek4125/tek4100_decoder.hpp"
#include "devices/tek4125/tek4125_driver.hpp"
#include "util/error.hpp"

namespace lattice::app {
namespace {

class Tek4125StreamDriver final : public StreamDriver {
 public:
  Tek4125StreamDriver(ByteSink& out, const Tek4125Profile& profile) : driver_(out, profile) {}
  IndexedSink& sink() override { return driver_; }
  StreamStats stats() const override {
    const Tek4125StreamStats& s = driver_.stats();
    return {s.bytes, s.seconds,
            fmt::format("{} raster writes, {} rectangle fills, {} pixels left to the clear", s.rasterWrites,
                        s.rectangleFills, s.skippedPixels)};
  }

 private:
  Tek4125Driver driver_;
};

class Tek4027StreamDriver final : public StreamDriver {
 public:
  Tek4027StreamDriver(ByteSink& out, const Tek4027Profile& profile) : driver_(out, profile) {}
  IndexedSink& sink() override { return driver_; }
  StreamStats stats() const override {
    const Tek4027StreamStats& s = driver_.stats();
    return {s.bytes, s.seconds(),
            fmt::format("profile {}, strategy {} along {}, {} commands ({} colour changes, {} vector commands, {} report "
                        "requests), line {:.0f} s, drawing {:.0f} s",
                        driver_.profile().name, strategyName(s.strategy), orientationName(s.orientation), s.commands, s.colourSelects,
                        s.vectorCommands, s.reportRequests, s.lineSeconds, s.terminalSeconds)};
  }
  void answerOn(int fd, double timeoutSeconds) override {
    replies_ = std::make_unique<Tek4027FdReplies>(fd, timeoutSeconds);
    driver_.setReplies(replies_.get());
  }

 private:
  Tek4027Driver driver_;
  std::unique_ptr<Tek4027FdReplies> replies_;
};

StreamDevice tek4125(const std::vector<std::string>& overrides) {
  Tek4125Profile profile;
  applyOverrides(profile, overrides);
  StreamDevice d;
  d.name = "tek4125";
  d.title = "Tektronix 4125";
  d.width = profile.width;
  d.height = profile.height;
  d.line = profile.line();
  d.profileText = describe(profile);
  d.makeDriver = [profile](ByteSink& out) { return std::make_unique<Tek4125StreamDriver>(out, profile); };
  d.makeDecoder = [profile] { return std::unique_ptr<StreamDecoder>(makeTek4100Decoder(profile)); };
  return d;
}

StreamDevice tek4027(const std::vector<std::string>& overrides) {
  Tek4027Profile profile;
  applyOverrides(profile, overrides);
  StreamDevice d;
  d.name = "tek4027";
  d.title = "Tektronix 4027";
  d.width = profile.width;
  d.height = profile.height;
  d.line = profile.line;
  d.profileText = describe(profile);
  d.makeDriver = [profile](ByteSink& out) { return std::make_unique<Tek4027StreamDriver>(out, profile); };
  d.makeDecoder = [profile] { return std::unique_ptr<StreamDecoder>(std::make_unique<Tek4027Decoder>(profile)); };
  return d;
}

}  // namespace

std::vector<std::string> streamDeviceNames() { return {"tek4125", "tek4027"}; }

StreamDevice streamDevice(const std::string& name, const std::vector<std::string>& overrides) {
  if (name == "tek4125") return tek4125(overrides);
  if (name == "tek4027") return tek4027(overrides);
  throw Error(ErrorKind::Usage, fmt::format("unknown stream device '{}'; choose tek4125 or tek4027", name));
}

}  // namespace lattice::app
