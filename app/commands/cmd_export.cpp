// `lattice export pov SCENE -o scene.pov`: writes a scene for POV-Ray 3.7
// (exporter/pov_export.hpp), the peer the benchmarks compare with.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <memory>
#include <string>

#include "app/commands/commands.hpp"
#include "app/cli/number_flags.hpp"
#include "exporter/pov_export.hpp"

namespace {

struct ExportOptions {
  std::string scene;
  std::string output;
  lattice::exporter::PovExportOptions pov;
  bool quiet = false;
};

void runExportPov(const ExportOptions& o) {
  const lattice::exporter::PovText text = lattice::exporter::exportPov(o.scene, o.output, o.pov);
  for (const std::string& note : text.notes) fmt::print(stderr, "lattice export pov: note: {}\n", note);
  if (!o.quiet)
    fmt::print("wrote {} ({} bytes); render it with\n  {}\n", o.output, text.text.size(),
               lattice::exporter::povrayCommand(o.output, "scene.png", text.width, text.height));
}

}  // namespace

namespace lattice::app {

void addExport(CLI::App& root) {
  auto* cmd = root.add_subcommand("export", "Write a scene for another renderer (today: POV-Ray 3.7)");
  cmd->require_subcommand(1);
  auto o = std::make_shared<ExportOptions>();
  auto* pov = cmd->add_subcommand(
      "pov",
      "Write SCENE in POV-Ray 3.7's language so that POV-Ray traces the same picture: quartics as POV's\n"
      "closed forms (plane, sphere, quadric, torus) or `quartic`, CSG as CSG, lattices as their exact\n"
      "spheres + cylinders, the same camera rays, lights with eq. 2.3's falloff, eq. 2.3 materials");
  pov->add_option("scene", o->scene, "Scene file (TOML)")->required();
  pov->add_option("-o,--output", o->output, "The .pov file to write (atomically)")->required();
  pov->add_option("--width", o->pov.width, "Image width the camera is written for (default: the scene's)")
      ->check(lattice::app::numberIn({1, 65535, true}));
  pov->add_option("--height", o->pov.height, "Image height the camera is written for (default: the scene's)")
      ->check(lattice::app::numberIn({1, 65535, true}));
  pov->add_flag("--sphere-sweep", o->pov.sphereSweep,
                "Polylines and capsules (lattice hair) as POV's sphere_sweep instead of spheres + cylinders");
  pov->add_flag("-q,--quiet", o->quiet, "Print nothing but notes and errors");
  pov->footer(
      "Render the file with the command it prints (and writes at its top): no antialiasing, shadows on,\n"
      "linear output (File_Gamma=1.0), so the PNG compares with `lattice render --full` by `lattice diff`.\n"
      "How each part is matched: docs/benchmarks.md, \"POV-Ray peer\". Example:\n"
      "  lattice export pov scenes/torus-floor.toml -o torus.pov\n"
      "  povray -D -A +Q4 +FN8 File_Gamma=1.0 +W320 +H240 +Itorus.pov +Otorus-pov.png\n"
      "  lattice render scenes/torus-floor.toml -o torus.png && lattice diff torus.png torus-pov.png");
  pov->callback([o] { runExportPov(*o); });
}

}  // namespace lattice::app
