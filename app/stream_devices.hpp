#pragma once
// The devices that take a byte stream (Tektronix 4125 and 4027), by the name
// the CLI uses. One table serves `render --device`, `emulate --device` and the
// tests, so adding a terminal touches one place. The Apollo simulator is not
// here: it draws into a framebuffer, not a byte stream.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "devices/stream_decoder.hpp"
#include "io/byte_sink.hpp"
#include "io/line_timing.hpp"
#include "pipeline/scanline.hpp"

namespace lattice::app {

// What a driver reports once its stream is finished.
struct StreamStats {
  std::uint64_t bytes = 0;
  double seconds = 0;  // the time a real terminal takes: line rate, or drawing rate if slower
  std::string detail;  // device-specific, one line
};

class StreamDriver {
 public:
  virtual ~StreamDriver() = default;
  virtual IndexedSink& sink() = 0;
  virtual StreamStats stats() const = 0;  // after sink().end()
  // A serial line the terminal answers on (its descriptor), for drivers that
  // wait for answers (the 4027's `!REP` pacing). Ignored by the others.
  virtual void answerOn(int /*fd*/, double /*timeoutSeconds*/) {}
};

struct StreamDevice {
  std::string name;       // "tek4125"
  std::string title;      // "Tektronix 4125"
  int width = 0;          // drawable area in pixels
  int height = 0;
  LineFormat line;
  std::string profileText;  // the profile, one key=value per line
  std::function<std::unique_ptr<StreamDriver>(ByteSink&)> makeDriver;
  std::function<std::unique_ptr<StreamDecoder>()> makeDecoder;
};

// `overrides` are the profile's key=value settings (--set). Throws
// lattice::Error(Usage) for an unknown device or a bad setting.
StreamDevice streamDevice(const std::string& name, const std::vector<std::string>& overrides = {});
std::vector<std::string> streamDeviceNames();

}  // namespace lattice::app
