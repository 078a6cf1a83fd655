// The frame of an exported POV-Ray file: header, global settings, camera,
// lights and materials (exporter/pov_export.hpp says how each is matched);
// the objects come from exporter/pov_objects.cpp.
#include "exporter/pov_export.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "exporter/pov_format.hpp"
#include "exporter/pov_objects.hpp"
#include "foundation/system/atomic_file.hpp"
#include "foundation/error.hpp"
#include "loader/lattice_scene_loader.hpp"

namespace lattice::exporter {

namespace {

// Our camera's rays as POV's vectors. Ours: corner + x step_x + y step_y
// through pixel (x, y); POV's: direction + ((x + 1/2) / W - 1/2) right +
// (1/2 - (y + 1/2) / H) up. They agree for right = W step_x, up = -H step_y,
// direction = corner + (W - 1) / 2 step_x + (H - 1) / 2 step_y.
std::string camera(const CameraDesc& desc, int width, int height) {
  const Camera<double> cam(desc, width, height);
  const Vec3d corner = cam.primaryRay(0, 0).direction;
  const Vec3d stepX = cam.primaryRay(1, 0).direction - corner, stepY = cam.primaryRay(0, 1).direction - corner;
  const Vec3d direction = corner + stepX * ((width - 1) / 2.0) + stepY * ((height - 1) / 2.0);
  return fmt::format(
      "// the camera as explicit vectors (no look_at): POV's ray through each pixel centre is Lattice's\n"
      "camera {{\n  perspective\n  location {}\n  direction {}\n  right {}\n  up {}\n}}\n\n",
      povVector(cam.observer()), povVector(direction), povVector(stepX * double(width)),
      povVector(stepY * -double(height)));
}

std::string lights(const SceneDesc& scene) {
  const double K = scene.options.attenuationK;
  if (!(K >= 0) || !std::isfinite(K))
    throw Error(ErrorKind::Input, fmt::format("{}: [options] K = {}: POV-Ray's light fading needs K >= 0 "
                                              "(fade_distance K); use a K of 0 or more to export this scene",
                                              scene.source.string(), K));
  const double fade = K > 0 ? K : kZeroFadeDistance;
  std::string s = fmt::format("// eq. 2.3's I_inc / (D + K) as fade_power 1: colour I_inc / (2 fd), fade_distance "
                              "fd = {}\n",
                              K > 0 ? "K" : fmt::format("{} (K = 0)", povNumber(kZeroFadeDistance)));
  for (const PointLight<double>& light : scene.lights)
    s += fmt::format("light_source {{ {} rgb {} fade_distance {} fade_power 1{} }}\n", povVector(light.position),
                     povVector(light.intensity / (2.0 * fade)), povNumber(fade),
                     scene.options.shadows ? "" : " shadowless");
  return s + "\n";
}

// A channel of k_diff of 0 cannot carry k_amb as pigment x ambient; this
// small pigment keeps the ambient term exact and the diffuse term 1e-9 or less.
constexpr double kSmallestPigment = 1e-9;

std::string material(const NamedMaterial& named, MaterialId id, std::vector<std::string>& notes) {
  const Material<double>& m = named.material;
  Vec3d pigment, ambient;
  for (int c = 0; c < 3; ++c) {
    pigment[c] = std::max(m.diffuse[c], kSmallestPigment);
    ambient[c] = m.ambient[c] / pigment[c];
  }
  const double phong = (m.specular.x + m.specular.y + m.specular.z) / 3.0;
  const double size = (m.shininess.x + m.shininess.y + m.shininess.z) / 3.0;
  if (m.specular.x != m.specular.y || m.specular.y != m.specular.z || m.shininess.x != m.shininess.y ||
      m.shininess.y != m.shininess.z)
    notes.push_back(fmt::format("material '{}': specular and shininess differ by channel; POV-Ray's phong is one "
                                "value, so their means are written ({}, {})",
                                named.name, phong, size));
  return fmt::format("#declare {} = texture {{ // '{}'\n  pigment {{ rgb {} }}\n  finish {{ ambient rgb {} diffuse 1 "
                     "phong {} phong_size {} }}\n}}\n",
                     povMaterialName(id), named.name, povVector(pigment), povVector(ambient), povNumber(phong),
                     povNumber(size));
}

}  // namespace

std::string povrayCommand(const std::filesystem::path& pov, const std::filesystem::path& png, int width, int height,
                          int threads) {
  return fmt::format("povray -D -A +Q4 +FN8 File_Gamma=1.0 +W{} +H{} +WT{} '+I{}' '+O{}'", width, height, threads,
                     pov.string(), png.string());
}

PovText povText(const SceneDesc& scene, const PovExportOptions& options) {
  PovText out;
  out.width = options.width > 0 ? options.width : scene.options.width;
  out.height = options.height > 0 ? options.height : scene.options.height;
  const std::string source = scene.source.empty() ? std::string("a scene built in code") : scene.source.string();
  PovObjectWriter objects(scene.source, options);
  objects.write(scene.root, 0);

  std::string& s = out.text;
  s += fmt::format("// {} for POV-Ray 3.7, written by `lattice export pov` (docs/benchmarks.md, POV-Ray peer).\n"
                   "// The camera's vectors are for {}x{} pixels; render with\n//   {}\n"
                   "// (no antialiasing, shadows, linear samples: both programs write round(255 v)).\n",
                   source, out.width, out.height,
                   povrayCommand("scene.pov", "scene.png", out.width, out.height));
  s += "#version 3.7;\n";
  s += fmt::format("global_settings {{ assumed_gamma 1.0 ambient_light rgb {} max_trace_level 1 }}\n",
                   povVector(scene.options.ambient));
  s += fmt::format("background {{ rgb {} }}\n\n", povVector(scene.options.background));
  s += camera(scene.camera, out.width, out.height);
  s += lights(scene);
  s += "// eq. 2.3 materials: pigment k_diff, ambient k_amb / k_diff (times ambient_light I_amb), phong k_spec\n";
  for (std::size_t id = 0; id < scene.materials.size(); ++id)
    s += material(scene.materials[id], static_cast<MaterialId>(id), out.notes);
  s += "\n" + objects.declarations() + objects.objects();
  out.notes.insert(out.notes.end(), objects.notes().begin(), objects.notes().end());
  return out;
}

PovText exportPov(const std::filesystem::path& sceneFile, const std::filesystem::path& output,
                  const PovExportOptions& options) {
  const lht::SceneWithLattices loaded = lht::loadSceneWithLattices(sceneFile);
  PovText text = povText(loaded.scene, options);
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(text.text.data());
  writeFileAtomically(output, std::span<const std::uint8_t>(bytes, text.text.size()));
  return text;
}

}  // namespace lattice::exporter
