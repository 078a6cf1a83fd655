// `lattice render SCENE.toml`: ray traces a scene and sends the picture down
// the output chain the user picks:
//   --device png      truecolour PNG (-o)
//   --device apollo   the simulated Apollo display, written as PNG (-o)
//   --device tek4125 | tek4027
//                     a command stream to a file (--stream), standard output
//                     (--stream -) or a serial line (--port), and/or the
//                     emulator's picture of that very stream (-o)
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/command_registry.hpp"
#include "app/render_budget.hpp"
#include "app/pipeline_args.hpp"
#include "app/serial_options.hpp"
#include "app/stream_devices.hpp"
#include "devices/apollo_sim/apollo_output.hpp"
#include "devices/apollo_sim/apollo_profile.hpp"
#include "foundation/atomic_file.hpp"
#include "io/png.hpp"
#include "io/serial_sink.hpp"
#include "io/stdout_sink.hpp"
#include "io/tee_sink.hpp"
#include "lht/lattice_scene.hpp"
#include "quantize/run_pipeline.hpp"
#include "render/renderer.hpp"
#include "foundation/error.hpp"
#include "foundation/progress.hpp"

namespace {

using lattice::Error;
using lattice::ErrorKind;

struct RenderCommandOptions {
  std::string scene;
  std::string output;  // PNG: truecolour, Apollo screen, or the emulated stream
  std::string device = "png";
  std::string stream;  // file or "-" for standard output
  int width = 0;
  int height = 0;
  int threads = 0;
  std::string arith = "double";
  bool full = false;
  bool noLatticeShadows = false;
  std::string lhtPrecision;  // empty: each lattice's own `precision`
  std::string apolloProfile = "dn660";
  std::vector<std::string> settings;  // device profile key=value overrides
  std::string memoryBudget;            // --memory-budget, as typed
  lattice::app::PipelineArgs pipeline;
  lattice::SerialOptions serial;
};

// All of the command's flags in one place.
void defineRenderOptions(CLI::App& cmd, RenderCommandOptions& o) {
  cmd.add_option("scene", o.scene, "Scene file (TOML, see docs/scene-format.md)")->required();
  cmd.add_option("-o,--output", o.output,
                 "PNG to write (atomically): the truecolour picture, the Apollo screen, or the emulator's view of "
                 "the Tek stream");
  cmd.add_option("--device", o.device,
                 "png (truecolour), apollo (simulated DN660/DN580), tek4125 or tek4027 (command streams)")
      ->check(CLI::IsMember({"png", "apollo", "tek4125", "tek4027"}))
      ->capture_default_str();
  cmd.add_option("--stream", o.stream, "Tek devices: write the command stream to this file, or - for stdout");
  cmd.add_option("--set", o.settings,
                 "Tek devices: override a profile assumption, key=value (repeatable), e.g. --set planes=4; "
                 "docs/tek4125.md and docs/tek4027.md list the keys");
  cmd.add_option("--apollo-profile", o.apolloProfile, "apollo: dn660 (8 planes), dn660-4 (4 planes) or dn580")
      ->check(CLI::IsMember(lattice::apolloProfileNames()))
      ->capture_default_str();
  cmd.add_option("--width", o.width, "Image width in pixels (default: the scene's, fitted to the device)")
      ->check(CLI::Range(1, 16384));
  cmd.add_option("--height", o.height, "Image height in pixels (default: the scene's, fitted to the device)")
      ->check(CLI::Range(1, 16384));
  cmd.add_option("--threads", o.threads,
                 "Worker threads for rendering and rasterizing lattices (default: all cores); the image does not "
                 "depend on it")
      ->check(CLI::Range(1, 256));
  cmd.add_option("--arith", o.arith,
                 "Arithmetic of the whole per-pixel path: float, double, or fixed (Q31.32 integers, no FPU; "
                 "docs/fixed-point.md)")
      ->check(CLI::IsMember({"float", "double", "fixed"}))
      ->capture_default_str();
  cmd.add_flag("--full", o.full,
               "Full ray trace: replace every lattice by its exact CSG object (the thesis's reference column)");
  cmd.add_flag("--no-lattice-shadows", o.noLatticeShadows,
               "Lattices cast no shadows, as particles would not (thesis plate 3; plate 4 is the default)");
  cmd.add_option("--lht-precision", o.lhtPrecision,
                 fmt::format("LHT entry precision of every lattice, overriding the scene's `precision`: {} "
                             "(docs/lattices.md, \"Entry precision\")",
                             lattice::lht::lhtPrecisionChoices()));
  cmd.add_option("--memory-budget", o.memoryBudget,
                 "Keep peak resident memory within SIZE (e.g. 8MiB, 8192K, 8388608): chooses the quantizer's mode "
                 "and the entry form of lattices rasterized now to fit, or exits 8 saying why it cannot "
                 "(docs/memory.md)");
  lattice::app::addPipelineOptions(&cmd, o.pipeline);
  lattice::app::addSerialOptions(&cmd, o.serial, /*portRequired=*/false);
}

bool isStreamDevice(const std::string& device) { return device == "tek4125" || device == "tek4027"; }

void requireDirectoryFor(const std::string& path, const char* flag) {
  const std::filesystem::path parent = std::filesystem::absolute(path).parent_path();
  std::error_code ec;
  if (!std::filesystem::is_directory(parent, ec))
    throw Error(ErrorKind::Output, fmt::format("{} {}: the directory {} does not exist; create it or choose another "
                                               "path",
                                               flag, path, parent.string()));
}

// Refuse contradictory or missing outputs before a long render, not after it.
void checkOutputs(const RenderCommandOptions& o, const CLI::App& cmd) {
  const bool port = cmd.count("--port") > 0;
  if (!isStreamDevice(o.device)) {
    if (o.output.empty())
      throw Error(ErrorKind::Usage, fmt::format("--device {} writes a PNG: give -o OUT.png", o.device));
    if (!o.stream.empty() || port)
      throw Error(ErrorKind::Usage,
                  fmt::format("--stream and --port take a Tek command stream; use --device tek4125 or tek4027 "
                              "(--device {} only writes -o)",
                              o.device));
    if (!o.settings.empty())
      throw Error(ErrorKind::Usage, "--set overrides a Tek profile; use it with --device tek4125 or tek4027");
  } else {
    if (o.output.empty() && o.stream.empty() && !port)
      throw Error(ErrorKind::Usage,
                  fmt::format("--device {} needs somewhere to send the stream: --stream FILE, --stream -, --port "
                              "PORT, and/or -o OUT.png for the emulated picture",
                              o.device));
    if (!o.stream.empty() && port)
      throw Error(ErrorKind::Usage, "give either --stream or --port, not both (record a stream with --stream, then "
                                    "`lattice send` it)");
  }
  if (!o.memoryBudget.empty()) lattice::parseByteCount(o.memoryBudget, "--memory-budget");  // a typo fails now
  if (!o.output.empty()) requireDirectoryFor(o.output, "-o");
  if (!o.stream.empty() && o.stream != "-") requireDirectoryFor(o.stream, "--stream");
}

// The picture size: what the user asked for, else the scene's own, shrunk
// (keeping its shape) to fit the device's drawable area.
lattice::RenderSettings renderSettings(const RenderCommandOptions& o, const lattice::SceneDesc& scene,
                                       int deviceWidth, int deviceHeight) {
  lattice::RenderSettings s;
  s.threads = o.threads;
  s.build.fullRayTrace = o.full;
  s.build.latticeShadows = !o.noLatticeShadows;
  s.width = o.width > 0 ? o.width : scene.options.width;
  s.height = o.height > 0 ? o.height : scene.options.height;
  if (deviceWidth > 0 && (s.width > deviceWidth || s.height > deviceHeight)) {
    if (o.width > 0 || o.height > 0)
      throw Error(ErrorKind::Usage,
                  fmt::format("{}x{} does not fit the device's {}x{} drawable area; choose a smaller --width/--height "
                              "or change the profile with --set width=... --set height=...",
                              s.width, s.height, deviceWidth, deviceHeight));
    const double scale = std::min(double(deviceWidth) / s.width, double(deviceHeight) / s.height);
    const int w = std::max(1, int(s.width * scale)), h = std::max(1, int(s.height * scale));
    fmt::print(stderr, "lattice render: the scene's {}x{} is larger than the device's {}x{}: rendering {}x{}\n",
               s.width, s.height, deviceWidth, deviceHeight, w, h);
    s.width = w;
    s.height = h;
  }
  return s;
}

template <typename T>
void renderTruecolour(lattice::Renderer<T>& renderer, const RenderCommandOptions& o) {
  lattice::RgbImage image;
  {
    lattice::Progress progress("render", static_cast<std::uint64_t>(renderer.height()), "rows");
    progress.setEnabled(progress.enabled() && !o.pipeline.quiet);
    image = lattice::renderImage(renderer, &progress);
    progress.finish();
  }
  lattice::writePng(o.output, image);
}

// Renders into the driver row by row; the bytes go to the chosen transport and,
// when -o is given, through the emulator on their way.
template <typename T>
void renderStream(lattice::Renderer<T>& renderer, const RenderCommandOptions& o,
                  const lattice::app::StreamDevice& device, const lattice::PipelineOptions& pipeline,
                  bool toPort) {
  std::unique_ptr<lattice::ByteSink> transport;
  std::string destination;
  if (toPort) {
    lattice::SerialOptions serial = o.serial;
    transport = lattice::openSerialSink(serial);
    destination = serial.port;
  } else if (o.stream == "-") {
    transport = std::make_unique<lattice::StdoutSink>();
    destination = "standard output";
  } else if (!o.stream.empty()) {
    transport = std::make_unique<lattice::AtomicFile>(o.stream);
    destination = o.stream;
  }
  std::unique_ptr<lattice::StreamDecoder> emulator;
  if (!o.output.empty()) emulator = device.makeDecoder();
  lattice::TeeSink tee(transport.get(), [&emulator](std::span<const std::uint8_t> bytes) {
    if (emulator) emulator->feed(bytes);
  });
  auto driver = device.makeDriver(tee);
  lattice::runPipeline(renderer, driver->sink(), pipeline);
  tee.close();  // renames the stream file into place, or drains the serial line
  const lattice::app::StreamStats stats = driver->stats();
  fmt::print(stderr, "lattice render: {} stream {} bytes -> {}; {:.1f} s on a {} at {} baud ({})\n", device.name,
             stats.bytes, destination.empty() ? "the emulator only" : destination, stats.seconds, device.title,
             device.line.baud, stats.detail);
  if (emulator) {
    emulator->finish();
    lattice::writePng(o.output, emulator->image());
    const lattice::DecodeReport& report = emulator->report();
    if (report.unknownCommands + report.malformed > 0)
      throw Error(ErrorKind::Internal,
                  fmt::format("the emulator found {} unknown and {} malformed commands in our own stream:\n{}",
                              report.unknownCommands, report.malformed, report.summary()));
  }
}

template <typename T>
void renderWith(const lattice::lht::SceneWithLattices& loaded, const RenderCommandOptions& o, const CLI::App& cmd) {
  const lattice::SceneDesc& scene = loaded.scene;
  const auto start = std::chrono::steady_clock::now();
  lattice::PipelineOptions pipeline = lattice::app::toPipelineOptions(o.pipeline, cmd);
  const bool toPort = cmd.count("--port") > 0;
  std::optional<lattice::app::StreamDevice> device;
  int deviceWidth = 0, deviceHeight = 0;
  std::optional<lattice::ApolloProfile> apollo;
  if (isStreamDevice(o.device)) {
    device = lattice::app::streamDevice(o.device, o.settings);
    deviceWidth = device->width;
    deviceHeight = device->height;
  } else if (o.device == "apollo") {
    apollo = lattice::apolloProfileByName(o.apolloProfile);
    deviceWidth = apollo->width;
    deviceHeight = apollo->height;
  }
  const lattice::RenderSettings settings = renderSettings(o, scene, deviceWidth, deviceHeight);
  std::optional<lattice::app::MemoryPlanRequest> budget;
  std::optional<lattice::lht::SceneWithLattices> bound;  // the scene with tables packed to fit the budget
  if (!o.memoryBudget.empty()) {
    budget = lattice::app::renderBudgetRequest(
        lattice::parseByteCount(o.memoryBudget, "--memory-budget"), settings.width, settings.height, pipeline,
        cmd.count("--mode") > 0 || cmd.count("--sample") > 0, {o.device, !o.output.empty(), deviceWidth, deviceHeight});
    lattice::lht::TableSettings tables = loaded.tables;
    tables.packing = lattice::app::tablePackingWithin(*budget);
    bound = lattice::lht::withTableSettings(loaded, tables);
  }
  lattice::Renderer<T> renderer(bound ? bound->scene : scene, settings);
  if (budget) pipeline.mode = lattice::app::planBuiltRender(*budget).mode;

  if (device) {
    RenderCommandOptions adjusted = o;
    if (toPort && cmd.count("--baud") == 0) adjusted.serial.baud = device->line.baud;  // the profile's rate
    renderStream(renderer, adjusted, *device, pipeline, toPort);
  } else if (apollo) {
    const lattice::ApolloScreen result = lattice::renderToApollo(renderer, *apollo, pipeline);
    lattice::writePng(o.output, result.screen);
    fmt::print(stderr, "lattice render: {} palette entries on the simulated {}\n", result.report.paletteSize,
               apollo->model);
  } else {
    renderTruecolour(renderer, o);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  fmt::print(stderr, "lattice render: {}: {}x{}, {:.2f} s, {} rays ({} arithmetic, {} threads){}\n", o.scene,
             renderer.width(), renderer.height(), seconds, renderer.raysTraced(), o.arith, renderer.threads(),
             o.output.empty() ? "" : fmt::format(", picture {}", o.output));
  if (budget) lattice::app::checkPeakAgainst(budget->budget);
}

void runRender(const RenderCommandOptions& o, const CLI::App& cmd) {
  checkOutputs(o, cmd);
  // Before the scene: a bad flag should not wait for a parse.
  std::optional<lattice::lht::LhtPrecision> precision;
  if (!o.lhtPrecision.empty()) precision = lattice::lht::parseLhtPrecision(o.lhtPrecision, "--lht-precision");
  // Scenes may hold [[lattices]]; their tables are built when the renderer
  // is, under these settings.
  lattice::lht::TableSettings tables;
  tables.precision = precision;
  tables.threads = static_cast<unsigned>(o.threads);  // --threads 1 means one thread throughout
  const lattice::lht::SceneWithLattices loaded = lattice::lht::loadSceneWithLattices(o.scene, tables);
  if (o.arith == "float")
    renderWith<float>(loaded, o, cmd);
  else if (o.arith == "fixed")
    renderWith<lattice::Fixed32>(loaded, o, cmd);
  else
    renderWith<double>(loaded, o, cmd);
}

void addRender(CLI::App& root) {
  auto* cmd = root.add_subcommand("render", "Ray trace a scene into a PNG, an Apollo screen or a Tek command stream");
  cmd->footer(
      "Traces one ray per pixel through the scene's camera, intersects the CSG tree (quartics and lattices), and\n"
      "lights hits with the thesis's eq. 2.3 (ambient, diffuse, Phong specular, shadow rays). For the Apollo and\n"
      "Tek devices the 18-bit picture is quantized by median cut to the device's colours first.\n"
      "Examples:\n"
      "  lattice render scenes/torus-floor.toml -o torus.png\n"
      "  lattice render scenes/fuzzy-sphere-1000.toml --device tek4125 --stream fuzzy.tek -o fuzzy-tek.png\n"
      "  lattice render scenes/sphere-hole.toml --device tek4027 --port auto --baud 4800\n"
      "  lattice render scenes/thistle.toml --device apollo --apollo-profile dn660-4 -o thistle.png");
  auto options = std::make_shared<RenderCommandOptions>();
  defineRenderOptions(*cmd, *options);
  cmd->callback([options, cmd] { runRender(*options, *cmd); });
}

}  // namespace

LATTICE_COMMAND(addRender);
