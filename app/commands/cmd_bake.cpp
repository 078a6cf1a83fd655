// `lattice bake SCENE.toml --size WxH -o scene_data.cpp`: a scene as C++ data
// for the firmware (app/scene_bake.hpp, docs/firmware.md). The flags match
// `lattice render`'s where they mean the same (--set, the quantizer's), so
// the host render that the firmware's stream is compared with takes the
// same words.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <memory>
#include <regex>
#include <string>
#include <vector>

#include "app/commands/commands.hpp"
#include "app/cli/pipeline_args.hpp"
#include "app/scene_bake.hpp"
#include "devices/device_table.hpp"
#include "foundation/system/atomic_file.hpp"
#include "foundation/error.hpp"

namespace lattice::app {
namespace {

struct BakeFlags {
  std::string scene;
  std::string size = "64x64";
  std::string output;
  std::vector<std::string> settings;
  PipelineArgs pipeline;
};

void parseSize(const std::string& text, int& width, int& height) {
  static const std::regex form(R"(([0-9]{1,5})x([0-9]{1,5}))");
  std::smatch m;
  if (!std::regex_match(text, m, form))
    throw Error(ErrorKind::Usage, fmt::format("--size {}: give WIDTHxHEIGHT in pixels, e.g. --size 64x64", text));
  width = std::stoi(m[1]);
  height = std::stoi(m[2]);
  if (width < 1 || height < 1 || width > 4096 || height > 4096)
    throw Error(ErrorKind::Usage, fmt::format("--size {}: each side must be 1..4096 pixels", text));
}

void runBake(const BakeFlags& f) {
  BakeRequest request;
  request.sceneFile = f.scene;
  parseSize(f.size, request.width, request.height);
  request.settings = f.settings;
  devices::makeDevice("tek4125", request.settings);  // a bad --set fails here, as in `lattice render`
  request.pipeline = toPipelineOptions(f.pipeline);
  lht::TableSettings tables;
  tables.progress = !f.pipeline.quiet;
  const lht::SceneWithLattices loaded = lht::loadSceneWithLattices(f.scene, tables);
  const BakeResult baked = bakeScene(loaded, request);
  writeFileAtomically(f.output, std::span(reinterpret_cast<const std::uint8_t*>(baked.source.data()),
                                          baked.source.size()));
  fmt::print(stderr, "lattice bake: {} -> {}: {}x{}, {} leaves, {} bytes of lattice tables (flash)\n", f.scene,
             f.output, request.width, request.height, baked.leaves, baked.flashBytes);
}

}  // namespace

void addBake(CLI::App& root) {
  auto* cmd = root.add_subcommand("bake", "Write a scene as C++ data for the firmware (no parser on the MCU)");
  cmd->footer(
      "Loads the scene (rasterizing its lattices, or reading their caches) and writes one C++ file that rebuilds\n"
      "it in code: camera, lights, materials, the CSG tree, lattice tables as constant arrays (flash). The\n"
      "firmware (docs/firmware.md) renders it with --arith fixed at --size and streams the Tek 4125 picture out\n"
      "of its UART; the same flags given to `lattice render ... --arith fixed --device tek4125` make the same\n"
      "bytes. The quantizer's histogram defaults to the small form here, the one that fits the MCU.\n"
      "Examples:\n"
      "  lattice bake scenes/sphere-hole.toml --size 64x64 -o scene_data.cpp\n"
      "  lattice bake scenes/hook.toml --size 64x64 --set planes=4 -o scene_data.cpp\n"
      "  scripts/firmware.sh scenes/hook.toml --size 64x64        # bake, build, run under QEMU, decode");
  auto flags = std::make_shared<BakeFlags>();
  flags->pipeline.initial.quantize.histogram = lattice::quantize::HistogramForm::Small;
  cmd->add_option("scene", flags->scene, "Scene file (TOML, see docs/scene-format.md)")->required();
  cmd->add_option("-o,--output", flags->output, "The C++ file to write (atomically)")->required();
  cmd->add_option("--size", flags->size, "Picture size WIDTHxHEIGHT in pixels")->capture_default_str();
  cmd->add_option("--set", flags->settings,
                  "Override a Tek 4125 profile assumption, key=value (repeatable; docs/tek4125.md)");
  addPipelineOptions(cmd, flags->pipeline);
  cmd->callback([flags] { runBake(*flags); });
}

}  // namespace lattice::app
