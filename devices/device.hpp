#pragma once
// What a device is to the rest of Lattice: one entry of the device table
// (device_table.hpp), made from the device's profile. Like gnuplot's terminal
// table (term_api.h) it has required entries every device fills and optional
// ones a device may leave empty; like u8g2, a driver writes bytes to a
// ByteSink and never learns whether they go to a file, a serial line, or
// straight into the emulator.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "devices/stream_decoder.hpp"
#include "foundation/byte_sink.hpp"
#include "foundation/line_timing.hpp"
#include "foundation/scanline.hpp"
#include "quantize/rate_distortion_runs.hpp"

namespace lattice::devices {

// What a driver reports once its stream is finished.
struct DriverStats {
  std::uint64_t bytes = 0;
  double seconds = 0;  // the time the real device takes: line rate, or drawing rate if slower
  std::string detail;  // device-specific, one line
};

// A device driver: quantized rows in (sink()), the device's bytes out.
class Driver {
 public:
  virtual ~Driver() = default;
  virtual IndexedSink& sink() = 0;
  virtual DriverStats stats() const = 0;  // after sink().end()
  // A serial line the terminal answers on (its descriptor), for drivers that
  // wait for answers (the 4027's `!REP` pacing); the others ignore it.
  virtual void answerOn(int /*fd*/, double /*timeoutSeconds*/) {}
};

struct Device {
  // Required.
  std::string name;   // as the CLI names it: "tek4125"
  std::string title;  // "Tektronix 4125"
  int width = 0;      // the screen (drawable area), pixels
  int height = 0;
  std::function<std::unique_ptr<Driver>(ByteSink&)> makeDriver;
  std::function<std::unique_ptr<StreamDecoder>()> makeEmulator;
  // Memory the driver holds for a width x height picture beyond a row, and
  // what its emulator holds to decode a stream and save the screen as a PNG
  // (docs/memory.md, "Calibration", measured these).
  std::function<std::uint64_t(int width, int height)> driverMemory;
  std::uint64_t emulatorMemory = 0;

  // Optional.
  std::optional<LineFormat> line;  // the serial line it expects; none for a workstation display
  std::string profileText;         // its profile, one key=value per line
  // Its stream draws on the terminal the user types in (sixel): `lattice
  // render` sends it to standard output when that is a terminal and no
  // other destination is named.
  bool showsOnTerminal = false;

  // Optional: how a sender of a stored stream keeps pace with a terminal that
  // answers requests (the 4027's `!REP` pacing). `points` gives the offsets
  // just past each request in a stream; `await` blocks on the line's
  // descriptor until one answer has come, throwing Error(Stalled or HangUp).
  struct ReplyPacing {
    std::function<std::vector<std::size_t>(std::span<const std::uint8_t> stream)> points;
    std::function<void(int fd, double timeoutSeconds)> await;
  };
  std::optional<ReplyPacing> replies;

  // Optional: whether a stream's first bytes (at most kRecogniseBytes, fewer
  // when the stream is shorter, never empty) look like this device's stream.
  // `lattice emulate` checks it before decoding, so that a PNG or a scene
  // file is named for what it is instead of decoded into noise. It should
  // accept streams of other programs the emulator reads too (gnuplot's,
  // PGPLOT's), so it judges the shape of the bytes, not our driver's habits.
  // A device without one accepts any stream.
  std::function<bool(std::span<const std::uint8_t> head)> recognise;
  // Optional: what a run of one colour costs in this device's encoding, for
  // rate-distortion runs (quantize/rate_distortion_runs.hpp); a device without
  // one cannot take --rd-lambda or a wire budget's lambda.
  quantize::RunCostFactory runCost;
  // Optional: profile settings ("key=value") a wire budget turns on unless
  // the user set the key: forms that draw the same screen in fewer bytes but
  // stay off by default, so the default stream does not change (the 4125's
  // xy-short=on, docs/wire.md).
  std::vector<std::string> wireSettings;
};

// How much of a stream Device::recognise is shown.
inline constexpr std::size_t kRecogniseBytes = 4096;

}  // namespace lattice::devices
