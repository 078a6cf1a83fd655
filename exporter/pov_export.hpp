#pragma once
// A scene written for POV-Ray 3.7 (`lattice export pov`), so that POV-Ray
// traces the same picture: the peer of docs/benchmarks.md.
//
// Method and tunables (the rules are docs/benchmarks.md's "POV-Ray peer"):
//  * camera: the rays of our Camera<double> written as POV's explicit
//    location, direction, right and up vectors (no look_at), so POV's ray
//    through pixel centre (x + 1/2, y + 1/2) is ours for the image size
//    written in the header (options.width/height, default the scene's);
//  * lights: eq. 2.3's I_inc / (D + K) as `fade_power 1` with
//    fade_distance K and colour I_inc / (2 K); K = 0 uses kZeroFadeDistance;
//  * materials: pigment k_diff, `ambient` k_amb / k_diff, `diffuse 1`,
//    `phong` k_spec, `phong_size` n_spec, `ambient_light` I_amb; POV-Ray's
//    phong has one value for all channels, so differing channels are
//    averaged and reported in `notes`;
//  * shapes: a quartic leaf as POV-Ray's closed form where it is one
//    (exporter/quartic_forms.hpp: plane, sphere, quadric, torus), else
//    `quartic { ... sturm }` (a finite leaf box as `bounded_by`); CSG as
//    union / intersection / difference;
//    each node's transform as one `matrix`; a lattice as its exact object
//    (spheres + capped cylinders, or `sphere_sweep` with options.sphereSweep),
//    declared once per lattice and material and placed per instance.
// Errors: lattice::Error(Input) naming the scene file and the object's line
// for what POV-Ray cannot express (a leaf type that does not describe
// itself, K < 0).
#include <filesystem>
#include <string>
#include <vector>

#include "render/scene/scene.hpp"

namespace lattice::exporter {

struct PovExportOptions {
  int width = 0;  // 0: the scene's [options] size
  int height = 0;
  bool sphereSweep = false;  // polylines and capsules as sphere_sweep instead of spheres + cylinders
};

struct PovText {
  std::string text;
  std::vector<std::string> notes;  // approximations made (e.g. per-channel specular averaged)
  int width = 0;
  int height = 0;
};

// With K = 0 (no softening), fade_distance 1e-4: a relative error of 1e-4 / D.
inline constexpr double kZeroFadeDistance = 1e-4;

PovText povText(const SceneDesc& scene, const PovExportOptions& options = {});

// Loads a scene file (lattices included; no table is rasterized) and writes
// its POV-Ray text to `output` atomically.
PovText exportPov(const std::filesystem::path& sceneFile, const std::filesystem::path& output,
                  const PovExportOptions& options = {});

// The povray command line that renders an exported file as Lattice would
// (no antialiasing, shadows, linear output): docs/benchmarks.md.
std::string povrayCommand(const std::filesystem::path& pov, const std::filesystem::path& png, int width, int height,
                          int threads = 1);

}  // namespace lattice::exporter
