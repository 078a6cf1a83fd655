// `lattice show FILE`: any PNG, or any recorded stream of a device Lattice
// emulates (tek4125, tek4027, tek4014, sixel), drawn on the sixel terminal in
// front of the user. The device is told by the stream's first bytes
// (app/stream_check.hpp). A stream is decoded by our emulator; the picture
// (scaled down to the terminal's largest sixel picture if it is bigger,
// nearest pixel) keeps its own colours when they fit in the terminal's colour
// registers (quantize/exact_palette.hpp), else goes through the median cut,
// and then through the sixel driver, to standard output or a file. A decoded
// stream that fits as it is goes from its indices straight to the driver (no
// RGB picture between: the same palette and bytes, for less work).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/commands/commands.hpp"
#include "app/stream_check.hpp"
#include "app/wire_budget.hpp"
#include "devices/device_table.hpp"
#include "devices/sixel/sixel_driver.hpp"
#include "devices/work_budget.hpp"
#include "foundation/system/atomic_file.hpp"
#include "foundation/error.hpp"
#include "foundation/rgb_image_source.hpp"
#include "io/png.hpp"
#include "io/stdout_sink.hpp"
#include "quantize/exact_palette.hpp"
#include "quantize/run_pipeline.hpp"

namespace lattice::app {
namespace {

struct ShowOptions {
  std::string input;
  std::string as;      // the input's device; empty: told by its first bytes
  std::string stream;  // empty or "-": standard output
  std::vector<std::string> settings;
  bool raw = false;    // decode as --as even bytes that do not look like its stream
};

// Reads the file once (it may be a pipe, as with <(...)), handing its first
// kRecogniseBytes (all of it, if shorter) to `judge` before the rest is
// read, so a file judged wrong is refused without being read to its end.
std::vector<std::uint8_t> readInput(const std::string& path,
                                    const std::function<void(std::span<const std::uint8_t>)>& judge) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorKind::Input, fmt::format("{}: cannot open it to show", path));
  std::vector<std::uint8_t> bytes(devices::kRecogniseBytes);
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  judge(bytes);
  char buffer[65536];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    bytes.insert(bytes.end(), buffer, buffer + in.gcount());
    if (bytes.size() > kMaxStreamBytes)
      throw Error(ErrorKind::Input, fmt::format("{}: longer than the {} MiB a stream may be (docs/limits.md)", path,
                                                kMaxStreamBytes >> 20));
  }
  return bytes;
}

bool isPng(std::span<const std::uint8_t> b) {
  static const std::uint8_t magic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  return b.size() >= 8 && std::equal(magic, magic + 8, b.begin());
}

// Nearest-pixel reduction to fit width x height, keeping the aspect.
// The picture itself when it fits (moved, not copied).
RgbImage fitWithin(RgbImage image, int width, int height) {
  if (image.width <= width && image.height <= height) return image;
  const double scale = std::min(double(width) / image.width, double(height) / image.height);
  RgbImage out(std::max(1, int(image.width * scale)), std::max(1, int(image.height * scale)));
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const int sx = std::min(image.width - 1, int((x + 0.5) / scale));
      const int sy = std::min(image.height - 1, int((y + 0.5) / scale));
      std::copy_n(image.pixel(sx, sy), 3, out.pixel(x, y));
    }
  return out;
}

void runShow(const ShowOptions& o) {
  sixel::SixelProfile profile;
  sixel::applyOverrides(profile, o.settings);
  // What the file is, told by the recognisers from its first bytes, or
  // checked against --as: a scene or noise is refused, not decoded into a
  // screen of nothing.
  bool png = false;
  std::string device = o.as;
  const std::vector<std::uint8_t> bytes = readInput(o.input, [&](std::span<const std::uint8_t> head) {
    png = o.as.empty() && isPng(head);
    if (png) return;
    if (device.empty()) {
      requireAnyStream(head, o.input, StreamUse::Show);
      device = recogniseDevice(head);
    } else if (!o.raw) {
      requireStream(head, devices::makeDevice(device), o.input, StreamUse::Show);
    }
  });
  RgbImage picture;
  std::string what;
  // A decoded stream that fits the terminal and its registers as it is: its
  // indices go to the driver without the RGB round trip (the same palette
  // and indices exactPalette gives the RGB picture, so the same bytes).
  std::optional<IndexedImage> direct;
  int width = 0, height = 0;
  if (png) {
    picture = io::readPngBytes(bytes, o.input);
    what = "PNG";
  } else {
    // A sixel stream is read with the most registers any of ours uses, so none wraps around.
    const std::vector<std::string> readAs = device == "sixel" ? std::vector<std::string>{"registers=256"}
                                                               : std::vector<std::string>{};
    std::unique_ptr<StreamDecoder> decoder = devices::makeDevice(device, readAs).makeEmulator();
    decodeBytes(*decoder, bytes, o.input);
    const DecodeReport& report = decoder->report();
    if (report.unknownCommands + report.malformed > 0)
      fmt::print(stderr, "lattice show: {}: skipped {} unknown and {} malformed commands\n", o.input,
                 report.unknownCommands, report.malformed);
    const IndexedImage& decoded = decoder->image();
    if (decoded.width <= profile.width && decoded.height <= profile.height)
      direct = quantize::exactPalette(decoded, profile.registers);
    if (!direct) picture = toRgbImage(decoded);
    width = decoded.width, height = decoded.height;
    what = device + " stream";
  }
  if (!direct) width = picture.width, height = picture.height;
  std::unique_ptr<ByteSink> out;
  if (o.stream.empty() || o.stream == "-") out = std::make_unique<io::StdoutSink>();
  else out = std::make_unique<AtomicFile>(o.stream);
  sixel::SixelDriver driver(*out, profile);
  int shownWidth = width, shownHeight = height;
  if (direct) {
    sendPicture(*direct, driver);
  } else {
    const RgbImage fitted = fitWithin(std::move(picture), profile.width, profile.height);
    shownWidth = fitted.width, shownHeight = fitted.height;
    // A picture with no more colours than the registers (a quantized PNG)
    // is sent with its own colours; only a richer one is cut.
    if (const auto exact = quantize::exactPalette(fitted, profile.registers)) {
      sendPicture(*exact, driver);
    } else {
      RgbImageSource source(fitted);
      quantize::PipelineOptions options;
      options.progress = false;  // standard error is most likely the terminal being drawn on
      quantize::runPipeline(source, driver, options);
    }
  }
  out->close();
  fmt::print(stderr, "lattice show: {} ({}, {}x{}{}): {} bytes of sixel, {} registers, to {}\n", o.input, what, width,
             height, shownWidth != width ? fmt::format(" shown at {}x{}", shownWidth, shownHeight) : "",
             driver.stats().bytes, driver.stats().registers,
             o.stream.empty() || o.stream == "-" ? "standard output" : o.stream);
}

}  // namespace

void addShow(CLI::App& root) {
  auto o = std::make_shared<ShowOptions>();
  auto* cmd = root.add_subcommand("show", "Show a PNG, or a recorded tek4125, tek4027, tek4014 or sixel stream, on a "
                                          "sixel terminal (xterm -ti vt340, mlterm, foot, WezTerm)");
  cmd->add_option("file", o->input, "A PNG, or a stream file lattice render --stream wrote")->required();
  CLI::Option* as =
      cmd->add_option("--as", o->as,
                      "The stream's device (tek4125, tek4027, tek4014, sixel, apollo) instead of the one its first "
                      "bytes tell; a stream that does not look like that device's is refused (exit 3) unless --raw")
          ->check(CLI::IsMember(devices::deviceNames()));
  cmd->add_flag("--raw", o->raw, "With --as: decode the file as that device's stream even if it does not look like one")
      ->needs(as);
  cmd->add_option("--set", o->settings,
                  "The sixel terminal's profile, key=value (repeatable): registers (16; 256 for xterm with "
                  "numColorRegisters: 256), width, height (largest picture, 1000x1000), p1, p2 (docs/sixel.md)");
  cmd->add_option("--stream", o->stream, "Write the sixel stream to this file (atomically) instead of standard output");
  cmd->footer(
      "A stream's device is told by its first bytes, as `lattice emulate` checks them: a file that is neither a PNG\n"
      "nor a stream of a device Lattice emulates (a scene, noise) is refused with exit 3 saying what it is. The\n"
      "stream is decoded by Lattice's own emulator of its device, then re-encoded as sixel; a picture larger than\n"
      "the terminal's largest sixel picture is scaled down (nearest pixel). Examples:\n"
      "  lattice show torus.png\n"
      "  lattice show fuzzy.tek --set registers=256        (xterm -ti vt340 -xrm 'XTerm*numColorRegisters: 256')\n"
      "  lattice show hole.tek                                (a Tek 4014 stream, told by its bytes)\n"
      "  lattice show odd.tek --as tek4125 --raw");
  cmd->callback([o] { runShow(*o); });
}

}  // namespace lattice::app
