// `lattice render SCENE.toml`: the flags of app/render_job.hpp's renderScene,
// one call, and the closing line. The device is png (truecolour) or any entry
// of the device table; its stream goes to a file (--stream), standard output
// (--stream -) or a serial line (--port), and/or its emulator's picture (-o).
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "app/commands/commands.hpp"
#include "app/commands/send_file.hpp"
#include "app/cli/number_flags.hpp"
#include "app/cli/pipeline_args.hpp"
#include "app/cli/setting_flags.hpp"
#include "app/render_job.hpp"
#include "app/cli/serial_args.hpp"
#include "app/cli/wire_args.hpp"
#include "app/terminal_stream.hpp"
#include "devices/device_table.hpp"
#include "foundation/arithmetics.hpp"
#include "foundation/error.hpp"
#include "foundation/system/output_transaction.hpp"
#include "foundation/system/resident_memory.hpp"
#include "io/serial_settings.hpp"
#include "lht/leaf/lookup_stats.hpp"
#include "loader/table_settings.hpp"

namespace lattice::app {
namespace {

struct RenderFlags {
  RenderJob job;
  std::string device = "png";
  bool noLatticeShadows = false;
  bool lhtStats = false;
  std::string memoryBudget;  // as typed
  PipelineArgs pipeline;
  io::SerialOptions serial;
  WireArgs wire;
};

constexpr const char* kOutputGroup = "Output";
constexpr const char* kPictureGroup = "Picture";
constexpr const char* kLatticeGroup = "Lattices";

// --baud's default as it behaves: each device's own line rate.
std::string profileBaudText() {
  std::vector<std::string> rates;
  for (const devices::DeviceEntry& entry : devices::deviceTable()) {
    const devices::Device device = entry.make({});
    if (device.line) rates.push_back(fmt::format("{} {}", entry.name, device.line->baud));
  }
  return fmt::format("the device profile's rate: {}", fmt::join(rates, ", "));
}

bool isVirtualPort(const std::string& port) { return port.rfind("virtual:", 0) == 0; }

// Where `render --port` records the stream without --stream: beside the
// picture (-o), else the scene's name in the current folder, with the
// device's name as the extension (fuzzy.png -> fuzzy.tek4125).
std::string recordingPath(const RenderJob& job, const std::string& device) {
  std::filesystem::path path = job.output.picture.empty() ? std::filesystem::path(job.scene).filename() : std::filesystem::path(job.output.picture);
  path.replace_extension(device);
  return path.string();
}

// After the render: the recorded stream to the port (app/commands/send_file.hpp).
void sendRecording(const RenderFlags& f, const CLI::App& cmd, const RenderJob& job, const RenderResult& result) {
  SendArgs send;
  send.stream = job.output.stream;
  send.device = f.device;
  send.settings = job.output.settings;
  if (result.wire) send.settings.insert(send.settings.end(), result.wire->settings.begin(), result.wire->settings.end());
  send.serial = f.serial;
  send.baudGiven = cmd.count("--baud") > 0;
  if (!send.baudGiven && !isVirtualPort(f.serial.port)) {
    // One rate: a real line runs at the profile's rate unless --baud says otherwise.
    if (const devices::Device device = devices::makeDevice(f.device, send.settings); device.line)
      send.serial.baud = device.line->baud, send.baudGiven = true;
  }
  send.screen = f.job.output.picture;
  send.screenGiven = isVirtualPort(f.serial.port) && !f.job.output.picture.empty();
  send.force = true;  // -o was checked with render's flags
  send.who = "lattice render";
  OutputTransaction::commitOpen();  // the recording lands before a byte goes out
  fmt::print(stderr, "lattice render: the stream is recorded in {}; sending it to {}\n", job.output.stream, f.serial.port);
  runSend(send);
}

// A flag that would do nothing in this combination is refused with the reason.
void refuseUnless(const CLI::App& cmd, std::initializer_list<const char*> flags, bool applies, const std::string& why) {
  if (applies) return;
  for (const char* flag : flags)
    if (cmd.count(flag) > 0) throw Error(ErrorKind::Usage, fmt::format("{} {}", flag, why));
}

void defineFlags(CLI::App& cmd, RenderFlags& f) {
  RenderJob& j = f.job;
  std::vector<std::string> devices = {"png"};
  for (const std::string& name : devices::deviceNames()) devices.push_back(name);
  cmd.add_option("scene", j.scene, "Scene file (TOML, see docs/scene-format.md)")->required();
  // Help groups follow docs/cli.md's list for `lattice render`; a flag added
  // without a group is listed under "Options".
  cmd.add_option("-o,--output", j.output.picture,
                 "PNG to write (atomically): the truecolour picture, or the device emulator's view of the stream")
      ->group(kOutputGroup);
  cmd.add_option("--device", f.device, fmt::format("png (truecolour) or a device: {}", fmt::join(devices, ", ")))
      ->check(CLI::IsMember(devices))
      ->capture_default_str()
      ->group(kOutputGroup);
  cmd.add_option("--stream", j.output.stream,
                 "Devices: write the command stream to this file, or - for stdout (sixel: stdout when it is a "
                 "terminal and no other destination is named)")
      ->group(kOutputGroup);
  cmd.add_option("--set", j.output.settings,
                 "Devices: override a profile assumption, key=value (repeatable), e.g. --set planes=4; "
                 "docs/tek4125.md, docs/tek4027.md and docs/tek4014.md list the keys")
      ->group(kOutputGroup);
  cmd.add_option("--width", j.render.width, "Image width in pixels (default: the scene's, fitted to the device)")
      ->check(numberIn({1, 16384, true}))
      ->group(kPictureGroup);
  cmd.add_option("--height", j.render.height, "Image height in pixels (default: the scene's, fitted to the device)")
      ->check(numberIn({1, 16384, true}))
      ->group(kPictureGroup);
  cmd.add_option("--threads", j.render.threads, "Threads for rendering and rasterizing (default: all cores): fewer leave cores to other work; the "
                 "image is the same")
      ->check(numberIn({1, 256, true}))
      ->group(kPictureGroup);
  cmd.add_option("--arith", j.arithmetic,
                 fmt::format("Arithmetic of the whole per-pixel path: {} (fixed: Q31.32 integers, no FPU: the "
                             "picture a firmware build computes, bit for bit, on the host; docs/fixed-point.md)",
                             arithmeticNames()))
      ->check([](const std::string& name) { return isArithmeticName(name) ? "" : "choose " + arithmeticNames(); })
      ->capture_default_str()
      ->group(kPictureGroup);
  cmd.add_flag("--full", j.render.build.fullRayTrace, "Full ray trace: every lattice replaced by its exact CSG object, the reference a lattice render is "
               "compared with")->group(kLatticeGroup);
  cmd.add_flag("--no-lattice-shadows", f.noLatticeShadows, "Lattices cast no shadows, as particles (thesis plate 3)")
      ->group(kLatticeGroup);
  // The lattice tables' flags write j.tables as they are read (loader/table_settings.hpp).
  addSettingFlagsInto(&cmd, lht::tableSettings(), j.tables, settableKeys(lht::tableSettings()), kLatticeGroup);
  cmd.add_flag("--lht-stats", f.lhtStats,
               "After rendering, print per lattice: look-ups, hits, misses, distinct (p_i, p_o) asked, entries "
               "referenced (share of N_iz) and look-ups per entry: how much of a table a render uses, to choose "
               "its form (docs/lattices.md); off, nothing is counted")
      ->group(kLatticeGroup);
  cmd.add_option("--memory-budget", f.memoryBudget,
                 "Keep peak resident memory within SIZE (8MiB, 8192K, 8388608): picks the quantizer mode and the "
                 "entry form of lattices rasterized now, or exits 8 saying why not; a lattice too large to "
                 "rasterize within it exits 3 before any work (default: half the physical memory, which only "
                 "refuses; docs/memory.md)")
      ->type_name("SIZE")
      ->check(settingFlagCheck({SettingKind::Bytes, {}, {}, {}}))  // sizes as every SIZE flag
      ->group("Memory");
  addPipelineOptions(&cmd, f.pipeline, "Quantizer (devices)", kRenderPipelineKeys);
  addSerialOptions(&cmd, f.serial, /*portRequired=*/false, profileBaudText());
  addWireOptions(&cmd, f.wire);
}

// The parsed flags as a job; bad combinations fail here, before the scene.
RenderJob jobFrom(RenderFlags& f, const CLI::App& cmd) {
  const bool png = f.device == "png";
  const std::string deviceChoices = fmt::format("{}", fmt::join(devices::deviceNames(), ", "));
  refuseUnless(cmd, {"--stream", "--port"}, !png,
               fmt::format("takes a device's command stream, and a truecolour render has none: add --device ({})",
                           deviceChoices));
  for (std::string_view key : kRenderPipelineKeys)  // the quantizer's flags, from its schema
    refuseUnless(cmd, {fmt::format("--{}", key).c_str()}, !png,
                 fmt::format("sets the quantizer of a device's colours, and a truecolour PNG is not quantized: add "
                             "--device ({}), or quantize the PNG afterwards with `lattice quantize`",
                             deviceChoices));
  refuseUnless(cmd, {"--set"}, !png,
               fmt::format("overrides a device profile, and none was chosen: add --device ({})", deviceChoices));
  for (std::string_view key : settableKeys(io::serialSettings()))  // the line's flags, from its schema
    if (key != "baud")
      refuseUnless(cmd, {fmt::format("--{}", key).c_str()}, cmd.count("--port") > 0,
                   "sets the serial line of --port, and none was given: add --port PORT, or drop it");
  // --wire-seconds counts at --baud too (a device without a serial line, sixel, has no other rate).
  refuseUnless(cmd, {"--baud"}, cmd.count("--port") > 0 || cmd.count("--wire-seconds") > 0,
               "sets the serial line of --port, and none was given: add --port PORT (or --wire-seconds S to "
               "count a budget at that rate), or drop it");
  RenderJob job = f.job;
  if (f.device != "png") job.output.device = f.device;
  job.render.build.latticeShadows = !f.noLatticeShadows;
  if (f.lhtStats) job.tables.stats = std::make_shared<lht::LookupStatsBook>();
  if (cmd.count("--lht-cache") > 0 && job.tables.form != lht::LhtForm::OnDemand)
    fmt::print(stderr,
               "lattice render: warning: --lht-cache bounds only tables built on demand; it applies to no lattice "
               "unless --lht-form on-demand is given or the scene sets form = \"on-demand\"\n");
  if (!f.memoryBudget.empty()) job.memory.budget = parseByteCount(f.memoryBudget, "--memory-budget");
  job.memory.modeChosenByUser = cmd.count("--mode") > 0 || cmd.count("--sample") > 0;
  job.memory.histogramChosenByUser = cmd.count("--histogram") > 0;
  job.pipeline = toPipelineOptions(f.pipeline);
  job.quiet = f.pipeline.quiet;
  // With --port the stream is recorded (--stream, or a file beside the
  // picture) and then sent from the file, so a send that stops resumes.
  if (cmd.count("--port") > 0) {
    if (job.output.stream == "-")
      throw Error(ErrorKind::Usage, "--stream - and --port: the stream sent to --port is recorded in a file; give "
                                    "--stream FILE, or drop --stream for a file beside the picture");
    if (job.output.stream.empty()) job.output.stream = recordingPath(job, f.device);
    // A virtual terminal's screen is the -o picture; render's own emulator is not needed.
    if (isVirtualPort(f.serial.port)) job.output.picture.clear();
  }
  // One baud: --baud becomes the profile's rate too, so the wire budget, the
  // timing line and the port all count at it. A device without a serial line
  // (sixel) has no `baud` key in its settings table and takes it for the
  // budget alone.
  const auto hasBaudKey = [&] {
    const std::vector<SettingInfo> keys = devices::deviceEntry(f.device).settings();
    return std::any_of(keys.begin(), keys.end(), [](const SettingInfo& s) { return s.key == "baud"; });
  };
  if (cmd.count("--baud") > 0 && f.device != "png" && hasBaudKey()) {
    for (const std::string& setting : job.output.settings)
      if (setting.rfind("baud=", 0) == 0 && setting != fmt::format("baud={}", f.serial.baud))
        throw Error(ErrorKind::Usage, fmt::format("--baud {} and --set {} name two line rates; give one", f.serial.baud,
                                                  setting));
    job.output.settings.push_back(fmt::format("baud={}", f.serial.baud));
  }
  applyWireArgs(f.wire, cmd, f.serial.baud, job);
  streamToTerminalByDefault(job);  // sixel on a terminal: the picture goes there
  return job;  // renderScene checks it first thing (checkRenderJob), before anything is made
}

// What the render says on stderr as it goes (app/render_events.hpp).
// Each phase's wall time in parentheses of its own, so a script greps one,
// e.g. "(trace S s)" (bench/peers.sh, bench/scaling.sh), then their CPU
// times and the process's since it started; quantize only for a device.
std::string phaseTimes(const RenderPhases& p) {
  const bool device = p.quantize.wall > 0;
  return fmt::format(" (set-up {:.4f} s) (trace {:.4f} s){} (output {:.4f} s) (CPU set-up {:.4f} s, trace {:.4f} s{}, "
                     "output {:.4f} s, process {:.4f} s)",
                     p.setup.wall, p.trace.wall,
                     device ? fmt::format(" (quantize {:.4f} s)", p.quantize.wall) : std::string(), p.output.wall,
                     p.setup.cpu, p.trace.cpu, device ? fmt::format(", quantize {:.4f} s", p.quantize.cpu) : std::string(),
                     p.output.cpu, PhaseTimer::cpuNow());
}

void sayRenderEvent(const RenderEvent& event) {
  std::visit(
      [](const auto& e) {
        using E = std::decay_t<decltype(e)>;
        if constexpr (std::is_same_v<E, SizeFitted>) {
          fmt::print(stderr, "lattice render: the scene's {}x{} is larger than the device's {}x{}: rendering {}x{}\n",
                     e.sceneWidth, e.sceneHeight, e.deviceWidth, e.deviceHeight, e.width, e.height);
        } else if constexpr (std::is_same_v<E, TableRepacked>) {
          fmt::print(stderr, "lattice render: memory plan: lattice '{}' packed as {} ({}) instead of {} to fit the "
                             "budget; not written to its cache\n",
                     e.lattice, lht::lhtPrecisionName(e.packed), formatBytes(e.packedBytes),
                     lht::lhtPrecisionName(e.requested));
        } else if constexpr (std::is_same_v<E, MemoryPlanned>) {
          fmt::print(stderr, "lattice render: memory plan: {}\n", e.summary);
        } else if constexpr (std::is_same_v<E, PeakMeasured>) {
          fmt::print(stderr, "lattice render: peak resident memory {} of the {} budget\n", formatBytes(e.peak),
                     formatBytes(e.budget));
        } else if constexpr (std::is_same_v<E, StreamSent>) {
          if (e.baud)
            fmt::print(stderr, "lattice render: {} stream {} bytes -> {}; {:.1f} s on a {} at {} baud ({})\n", e.device,
                       e.stats.bytes, e.where, e.stats.seconds, e.title, *e.baud, e.stats.detail);
          else
            fmt::print(stderr, "lattice render: {} stream {} bytes -> {} ({}, {})\n", e.device, e.stats.bytes, e.where,
                       e.title, e.stats.detail);
        } else if constexpr (std::is_same_v<E, WireChosen>) {
          fmt::print(stderr, "lattice render: wire budget: {}\n", e.description);
        } else {
          static_assert(std::is_same_v<E, LookupsCounted>);
          if (e.lattices.empty()) fmt::print(stderr, "lattice render: lht-stats: no lattice was looked up\n");
          for (const lht::LookupSummary& s : e.lattices)
            fmt::print(stderr, "lattice render: lht-stats: {}\n", lht::describeLookups(s));
        }
      },
      event);
}

}  // namespace

void addRender(CLI::App& root) {
  auto* cmd = root.add_subcommand("render", "Ray trace a scene into a PNG, or a device's command stream");
  cmd->footer(
      "Traces one ray per pixel through the scene's camera, intersects the CSG tree (quartics and lattices), and\n"
      "lights hits with the thesis's eq. 2.3 (ambient, diffuse, Phong specular, shadow rays). For a device the\n"
      "18-bit picture is quantized by median cut to the device's colours first.\n"
      "Examples:\n"
      "  lattice render scenes/torus-floor.toml -o torus.png\n"
      "  lattice render scenes/fuzzy-sphere-1000.toml --device tek4125 --stream fuzzy.tek -o fuzzy-tek.png\n"
      "  lattice render scenes/sphere-hole.toml --device tek4027 --port auto --baud 4800\n"
      "  lattice render scenes/fuzzy-sphere-1000.toml --device tek4125 --port virtual:tek4125 --baud 9600 "
      "--wire-seconds 60 -o screen.png\n"
      "    (the best picture a minute at 9600 baud allows, its size chosen; the stream recorded in "
      "screen.tek4125)\n"
      "  lattice render scenes/thistle.toml --device apollo --set profile=dn660-4 -o thistle.png\n"
      "  lattice render scenes/fuzzy-sphere-1000.toml --device sixel --set registers=256   (in xterm -ti vt340)");
  auto flags = std::make_shared<RenderFlags>();
  defineFlags(*cmd, *flags);
  cmd->callback([flags, cmd] {
    RenderJob job = jobFrom(*flags, *cmd);
    job.events = sayRenderEvent;
    const RenderResult r = renderScene(job);
    fmt::print(stderr, "lattice render: {}: {}x{}, {:.2f} s{}, {} rays ({} arithmetic, {} thread{}){}\n", job.scene,
               r.width, r.height, r.seconds, phaseTimes(r.phases), r.rays, job.arithmetic, r.threads,
               r.threads == 1 ? "" : "s", job.output.picture.empty() ? "" : fmt::format(", picture {}", job.output.picture));
    if (cmd->count("--port") > 0) sendRecording(*flags, *cmd, job, r);
  });
}

}  // namespace lattice::app
