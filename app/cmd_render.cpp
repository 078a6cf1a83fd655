// `lattice render SCENE.toml -o OUT.png`: ray traces a scene file into a PNG.
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "app/command_registry.hpp"
#include "io/png.hpp"
#include "render/renderer.hpp"
#include "render/scene_loader.hpp"
#include "util/error.hpp"
#include "util/progress.hpp"

namespace {

struct RenderCommandOptions {
  std::string scene;
  std::string output;
  int width = 0;
  int height = 0;
  int threads = 0;
  std::string arith = "double";
};

// All of the command's flags in one place (more output options will join them).
void defineRenderOptions(CLI::App& cmd, RenderCommandOptions& o) {
  cmd.add_option("scene", o.scene, "Scene file (TOML, see docs/scene-format.md)")->required();
  cmd.add_option("-o,--output", o.output, "PNG file to write (written atomically)")->required();
  cmd.add_option("--width", o.width, "Image width in pixels (default: the scene's [options] width)")
      ->check(CLI::Range(1, 16384));
  cmd.add_option("--height", o.height, "Image height in pixels (default: the scene's [options] height)")
      ->check(CLI::Range(1, 16384));
  cmd.add_option("--threads", o.threads, "Worker threads (default: all cores); the image does not depend on it")
      ->check(CLI::Range(1, 256));
  cmd.add_option("--arith", o.arith, "Scalar type of the ray tracer: float or double (default double)")
      ->check(CLI::IsMember({"float", "double"}));
}

template <typename T>
void renderTo(const lattice::SceneDesc& scene, const RenderCommandOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  lattice::RenderSettings settings;
  settings.width = o.width;
  settings.height = o.height;
  settings.threads = o.threads;
  lattice::Renderer<T> renderer(scene, settings);
  lattice::RgbImage image;
  {
    lattice::Progress progress("render", static_cast<std::uint64_t>(renderer.height()), "rows");
    image = lattice::renderImage(renderer, &progress);
    progress.finish();
  }
  lattice::writePng(o.output, image);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  fmt::print(stderr, "lattice render: {} -> {}: {}x{}, {:.2f} s, {} rays ({} arithmetic, {} threads)\n", o.scene,
             o.output, image.width, image.height, seconds, renderer.raysTraced(), o.arith, renderer.threads());
}

void runRender(const RenderCommandOptions& o) {
  // Refuse an unwritable destination before a long render, not after it.
  const std::filesystem::path parent = std::filesystem::absolute(o.output).parent_path();
  std::error_code ec;
  if (!std::filesystem::is_directory(parent, ec))
    throw lattice::Error(lattice::ErrorKind::Output,
                         fmt::format("{}: the directory {} does not exist; create it or choose another -o path",
                                     o.output, parent.string()));
  const lattice::SceneDesc scene = lattice::loadScene(o.scene);
  if (o.arith == "float")
    renderTo<float>(scene, o);
  else
    renderTo<double>(scene, o);
}

void addRender(CLI::App& root) {
  auto* cmd = root.add_subcommand("render", "Ray trace a scene file into a PNG image");
  cmd->footer(
      "Traces one ray per pixel through the scene's camera, intersects the CSG tree, and lights hits with\n"
      "the thesis's eq. 2.3 (ambient, diffuse, Phong specular, shadow rays). Colours are linear and\n"
      "clamped to [0, 1]. Example:\n"
      "  lattice render scenes/torus-floor.toml -o torus.png --width 320 --height 240");
  auto options = std::make_shared<RenderCommandOptions>();
  defineRenderOptions(*cmd, *options);
  cmd->callback([options] { runRender(*options); });
}

}  // namespace

LATTICE_COMMAND(addRender);
