#include "app/render_job.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <utility>

#include "app/output_check.hpp"
#include "app/render_budget.hpp"
#include "app/wire_size.hpp"
#include "devices/device_table.hpp"
#include "foundation/arithmetics.hpp"
#include "foundation/system/atomic_file.hpp"
#include "foundation/error.hpp"
#include "foundation/progress.hpp"
#include "foundation/threads.hpp"
#include "io/png.hpp"
#include "io/serial_sink.hpp"
#include "io/stdout_sink.hpp"
#include "io/tee_sink.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "lht/leaf/lookup_stats.hpp"
#include "quantize/rate_distortion_runs.hpp"
#include "render/renderer.hpp"

namespace lattice::app {
namespace {

// The picture size: what the job asks for, else the scene's own, shrunk
// (keeping its shape) to fit the device's screen (a SizeFitted event).
RenderSettings renderSettings(const RenderJob& job, const SceneDesc& scene, int deviceWidth, int deviceHeight) {
  RenderSettings s = job.render;
  // The scene's tree is built on the render's threads (render/scene/scene.cpp).
  s.build.threads = job.render.threads > 0 ? unsigned(job.render.threads) : hardwareThreads();
  if (s.width <= 0) s.width = scene.options.width;
  if (s.height <= 0) s.height = scene.options.height;
  if (deviceWidth > 0 && (s.width > deviceWidth || s.height > deviceHeight)) {
    if (job.render.width > 0 || job.render.height > 0)
      throw Error(ErrorKind::Usage,
                  fmt::format("{}x{} does not fit the device's {}x{} drawable area; choose a smaller --width/--height "
                              "or change the profile with --set width=... --set height=...",
                              s.width, s.height, deviceWidth, deviceHeight));
    const double scale = std::min(double(deviceWidth) / s.width, double(deviceHeight) / s.height);
    const int w = std::max(1, int(s.width * scale)), h = std::max(1, int(s.height * scale));
    // A wire budget's size search says the size it chose instead (app/wire_size.hpp).
    if (!job.wire) raise(job.events, SizeFitted{s.width, s.height, deviceWidth, deviceHeight, w, h});
    s.width = w;
    s.height = h;
  }
  return s;
}

// The trace (what bench/peers.sh compares with a peer's own trace timer: no
// set-up, no PNG), with a progress bar, timed as the trace phase.
template <typename T>
RgbImage tracedImage(Renderer<T>& renderer, const RenderJob& job, RenderPhases& phases) {
  Progress progress("render", static_cast<std::uint64_t>(renderer.height()), "rows");
  progress.setEnabled(progress.enabled() && !job.quiet);
  const PhaseTimer trace;
  RgbImage image = renderImage(renderer, &progress);
  trace.addTo(phases.trace);
  progress.finish();
  return image;
}

// The trace, then the PNG.
template <typename T>
void renderTruecolour(Renderer<T>& renderer, const RenderJob& job, RenderPhases& phases) {
  const RgbImage image = tracedImage(renderer, job, phases);
  const PhaseTimer output;
  io::writePng(job.output.picture, image, renderer.threads());
  output.addTo(phases.output);
}

// The transport the job names, and where it goes in words; none when only
// the emulator's picture is wanted. A serial line also gives the descriptor
// the terminal answers on (replyFd), for drivers that wait for answers.
std::unique_ptr<ByteSink> openTransport(const RenderJob& job, const devices::Device& device, std::string& where,
                                        int& replyFd) {
  replyFd = -1;
  if (job.output.port) {
    io::SerialOptions serial = *job.output.port;
    if (job.output.baudFromProfile && device.line) serial.baud = device.line->baud;
    auto sink = io::openSerialSink(serial);
    where = serial.port;
    replyFd = sink->fd();
    return sink;
  }
  if (job.output.stream == "-") {
    where = "standard output";
    return std::make_unique<io::StdoutSink>();
  }
  if (!job.output.stream.empty()) {
    where = job.output.stream;
    return std::make_unique<AtomicFile>(job.output.stream);
  }
  where = "the emulator only";
  return nullptr;
}

// Renders into the device's driver row by row; the bytes go to the transport
// and, when a picture is asked for, through the emulator on their way.
// The source's time goes to phases.quantize, the emulator's picture to phases.output.
devices::DriverStats renderToDevice(const std::function<void(IndexedSink&)>& source, const RenderJob& job,
                                    const devices::Device& device, std::string& where, RenderPhases& phases) {
  const PhaseTimer pipeline;
  int replyFd = -1;
  std::unique_ptr<ByteSink> transport = openTransport(job, device, where, replyFd);
  std::unique_ptr<StreamDecoder> emulator;
  if (!job.output.picture.empty()) emulator = device.makeEmulator();
  io::TeeSink tee(transport.get(), [&emulator](std::span<const std::uint8_t> bytes) {
    if (emulator) emulator->feed(bytes);
  });
  auto driver = device.makeDriver(tee);
  if (replyFd >= 0) driver->answerOn(replyFd, job.output.port->stallTimeoutSeconds);
  if (job.rdLambda > 0 && !device.runCost)
    throw Error(ErrorKind::Usage, fmt::format("rate-distortion runs: {} has no run costs; they apply to devices "
                                              "that send runs (tek4125, tek4027, sixel)",
                                              device.name));
  if (job.rdLambda > 0 && !job.wire) {
    quantize::RateDistortionSink runs(driver->sink(), device.runCost, job.rdLambda);
    source(runs);
  } else {
    source(driver->sink());
  }
  pipeline.addTo(phases.quantize);
  const PhaseTimer output;
  tee.close();  // renames the stream file into place, or drains the serial line
  const devices::DriverStats stats = driver->stats();
  raise(job.events, StreamSent{device.name, device.title,
                                device.line ? std::optional<int>(device.line->baud) : std::nullopt, where, stats});
  if (emulator) {
    emulator->finish();
    io::writePng(job.output.picture, emulator->image(), static_cast<unsigned>(job.render.threads));
    const DecodeReport& report = emulator->report();
    if (report.unknownCommands + report.malformed > 0)
      throw Error(ErrorKind::Internal,
                  fmt::format("the emulator found {} unknown and {} malformed commands in our own stream:\n{}",
                              report.unknownCommands, report.malformed, report.summary()));
  }
  output.addTo(phases.output);
  return stats;
}

// The truecolour picture once, then the search of app/wire_budget.hpp; with
// the size free (no --width/--height), the size search of
// app/wire_size.hpp, which renders each size it tries from `scene`.
template <typename T>
WireSearch renderWithinWireBudget(Renderer<T>& renderer, const SceneDesc& scene, const RenderSettings& settings,
                                  const RenderJob& job, const devices::Device& device,
                                  const quantize::PipelineOptions& pipeline, const std::vector<std::string>& added,
                                  RenderPhases& phases) {
  WireSearch search;
  const PhaseTimer whole;
  if (job.render.width == 0 && job.render.height == 0) {
    const SizeArea area = sizeAreaFor(scene.options.width, scene.options.height, device.width, device.height);
    const RenderAt renderAt = [&](int width, int height) {
      const PhaseTimer trace;  // each size's render is trace; the rest of the search, quantize
      RgbImage image;
      if (width == renderer.width() && height == renderer.height()) {
        image = renderImage(renderer);
      } else {
        RenderSettings at = settings;
        at.width = width, at.height = height;
        Renderer<T> sized(scene, at);
        image = renderImage(sized);
      }
      trace.addTo(phases.trace);
      return image;
    };
    WireSizeSearch sized = searchWireSize(renderAt, area, job.wire->quality, device, *job.wire, pipeline.quantize,
                                          !job.quiet);
    search = std::move(sized.search);
    search.settings = added;
    raise(job.events, WireChosen{describeWireSize(sized, area)});
  } else {
    search = searchWireBudget(tracedImage(renderer, job, phases), device, *job.wire, pipeline.quantize, !job.quiet);
    search.settings = added;
  }
  PhaseSeconds searching;  // the whole, less the renders
  whole.addTo(searching);
  phases.quantize.wall += searching.wall - phases.trace.wall;
  phases.quantize.cpu += searching.cpu - phases.trace.cpu;
  raise(job.events, WireChosen{describeWireChoice(search)});
  return search;
}

// Takes the loaded scene: its node tree is released once the renderer holds
// its own. `room`: the budget its lattices are rasterized under (null: none).
// `start`: started when the scene began loading (set-up runs until the renderer is built).
template <typename T>
RenderResult renderWith(lht::SceneWithLattices loaded, const RenderJob& job, const std::shared_ptr<RasterRoom>& room,
                        const PhaseTimer& start) {
  quantize::PipelineOptions pipeline = job.pipeline;
  // A kept frame is counted and mapped on every thread; under a chosen memory
  // budget on one, so the plan (and with it the picture) never depends on the count.
  if (!job.memory.budget) pipeline.threads = job.render.threads > 0 ? unsigned(job.render.threads) : hardwareThreads();
  std::optional<devices::Device> device;
  std::vector<std::string> wireAdded;  // profile settings the wire budget turned on
  if (!job.output.device.empty()) {
    device = devices::makeDevice(job.output.device, job.output.settings);
    if (job.wire) {
      wireAdded = wireSettingsToAdd(*device, job.output.settings);
      if (!wireAdded.empty()) {
        std::vector<std::string> all = job.output.settings;
        all.insert(all.end(), wireAdded.begin(), wireAdded.end());
        device = devices::makeDevice(job.output.device, all);
      }
    }
  }
  const RenderSettings settings =
      renderSettings(job, loaded.scene, device ? device->width : 0, device ? device->height : 0);
  std::optional<MemoryPlanRequest> budget;
  std::optional<lht::SceneWithLattices> bound;  // the scene with its tables packed to fit the budget
  if (room) {
    // The default budget checks the job's mode and histogram; only a chosen
    // one picks them, so a picture never depends on the machine's memory.
    budget = renderBudgetRequest(room->budget, settings.width, settings.height, pipeline,
                                 job.memory.modeChosenByUser || !room->chosen, device ? &*device : nullptr,
                                 job.output.picture.empty() ? 0u : job.render.threads > 0 ? unsigned(job.render.threads) : hardwareThreads());
    budget->histogramChosenByUser = job.memory.histogramChosenByUser || !room->chosen;
    room->leastOutput = leastOutputBytes(*budget);  // before the renderer rasterizes the lattices
  }
  if (job.memory.budget) {
    lht::TableSettings tables = loaded.tables;
    tables.packing = tablePackingWithin(*budget, job.events);
    bound = lht::withTableSettings(loaded, tables);
  }
  // The renderer takes the node tree, releasing each set operation's
  // descriptions (a scatter's are 262 B an instance) once its operands are
  // built, before its BVH's build and the output's buffers (docs/memory.md);
  // a wire budget's size search renders the scene again at other sizes, so
  // then the renderer copies it.
  const bool sizeSearch = device && job.wire && job.render.width == 0 && job.render.height == 0;
  SceneDesc& scene = bound ? bound->scene : loaded.scene;
  Renderer<T> renderer = sizeSearch ? Renderer<T>(scene, settings) : Renderer<T>(std::move(scene), settings);
  if (!sizeSearch) loaded.scene.root = NodeDesc{};  // under a budget its copy was built: the loaded tree goes too
  if (job.memory.budget) {
    const MemoryPlan plan = planBuiltRender(*budget, job.events);
    pipeline.mode = plan.mode;
    pipeline.quantize.histogram = plan.histogram;
  } else if (budget && residentMemory()) {
    planBuiltRender(*budget);  // the default budget: a check, said only when it refuses
  }

  RenderResult result;
  start.addTo(result.phases.setup);
  if (device && job.wire) {
    WireSearch search = renderWithinWireBudget(renderer, bound ? bound->scene : loaded.scene, settings, job, *device,
                                               pipeline, wireAdded, result.phases);
    result.stream = renderToDevice([&](IndexedSink& s) { sendPicture(search.picture, s); }, job, *device,
                                   result.destination, result.phases);
    search.picture = {};
    result.wire = std::move(search);
  } else if (device) {
    TimedRowSource rows(renderer, result.phases.trace);
    result.stream = renderToDevice([&](IndexedSink& s) { quantize::runPipeline(rows, s, pipeline); }, job, *device,
                                   result.destination, result.phases);
    result.phases.quantize.wall -= result.phases.trace.wall;  // the pipeline's time less the waits for rows
    result.phases.quantize.cpu -= result.phases.trace.cpu;
  } else
    renderTruecolour(renderer, job, result.phases);
  PhaseSeconds whole;
  start.addTo(whole);
  result.seconds = whole.wall;
  result.width = result.wire ? result.wire->choice.width : renderer.width();
  result.height = result.wire ? result.wire->choice.height : renderer.height();
  result.rays = renderer.raysTraced();
  result.threads = renderer.threads();
  if (job.memory.budget) checkPeakAgainst(budget->budget, job.events);
  if (result.wire && !result.wire->choice.fits)
    throw Error(ErrorKind::Budget,
                fmt::format("no setting fits {} bytes: the smallest stream is {} bytes ({:.1f} s at {} baud), written; "
                            "{}",
                            result.wire->limit, result.wire->choice.bytes, result.wire->choice.seconds,
                            result.wire->baud,
                            job.wire->shrink ? "allow more time (--wire-shrink already made the picture as small as "
                                               "it goes)"
                                             : "allow more time, or add --wire-shrink to send a smaller picture"),
                Outputs::Keep);
  return result;
}

}  // namespace

void checkRenderJob(const RenderJob& job) {
  if (!isArithmeticName(job.arithmetic)) throwUnknownArithmetic(job.arithmetic);
  if (job.output.device.empty()) {
    if (job.wire || job.rdLambda > 0)
      throw Error(ErrorKind::Usage, "--wire-seconds and --wire-bytes shape a device's stream; choose one with "
                                    "--device");
    if (job.output.picture.empty()) throw Error(ErrorKind::Usage, "a truecolour render writes a PNG: give -o OUT.png");
    if (!job.output.stream.empty() || job.output.port)
      throw Error(ErrorKind::Usage,
                  fmt::format("--stream and --port take a device's command stream; choose one with --device ({})",
                              fmt::join(devices::deviceNames(), ", ")));
    if (!job.output.settings.empty())
      throw Error(ErrorKind::Usage, "--set overrides a device profile; use it with --device");
  } else {
    devices::deviceEntry(job.output.device);  // an unknown name fails now
    if (job.wire && !job.wire->bytes && !job.wire->seconds)
      throw Error(ErrorKind::Usage, "a wire budget needs --wire-seconds S or --wire-bytes N");
    if (job.output.picture.empty() && job.output.stream.empty() && !job.output.port)
      throw Error(ErrorKind::Usage,
                  fmt::format("--device {} needs somewhere to send the stream: --stream FILE, --stream -, --port "
                              "PORT, and/or -o OUT.png for the emulated picture",
                              job.output.device));
    if (!job.output.stream.empty() && job.output.port)
      throw Error(ErrorKind::Usage, "give either --stream or --port, not both (record a stream with --stream, then "
                                    "`lattice send` it)");
  }
  // Read-only files were refused (or allowed by --force) with the flags.
  checkOutputPath(job.output.picture, "-o", /*force=*/true);
  checkOutputPath(job.output.stream, "--stream", /*force=*/true);
}

RenderResult renderScene(const RenderJob& job) {
  const PhaseTimer start;
  checkRenderJob(job);
  if (job.memory.budget) shareOneAllocatorArena();  // before the rasterizer's threads
  // Scenes may hold [[lattices]]; their tables are built when the renderer
  // is, under these settings.
  lht::TableSettings tables = job.tables;
  tables.threads = static_cast<unsigned>(job.render.threads);  // one thread means one thread throughout
  // Every render has a budget, the one given or the default; the lattices
  // the renderer rasterizes are admitted against it before any work.
  std::shared_ptr<RasterRoom> room;
  if (const auto budget = job.memory.budget ? job.memory.budget : defaultMemoryBudget()) {
    room = std::make_shared<RasterRoom>();
    room->budget = *budget;
    room->chosen = job.memory.budget.has_value();
    tables.admission = rasterizingWithin(room);
  }
  lht::SceneWithLattices loaded = lht::loadSceneWithLattices(job.scene, tables);
  RenderResult result = withArithmetic(job.arithmetic, [&](auto type) {
    return renderWith<typename decltype(type)::type>(std::move(loaded), job, room, start);
  });
  if (tables.stats) raise(job.events, LookupsCounted{tables.stats->summaries()});
  return result;
}

}  // namespace lattice::app
