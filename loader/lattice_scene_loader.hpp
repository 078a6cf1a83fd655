#pragma once
// Lattices in scene files (docs/lattices.md):
//
//   [[lattices]]                 # a lattice definition (thesis ch. 2)
//   name = "hair"
//   spacing = 0.05               # lambda, object units
//   oversample = 1               # f_lat
//   cache = "hair.lht"           # optional; relative to the scene file
//   shadows = true               # false: casts no shadows, like particles (plate 3)
//   precision = "thesis"         # LHT entry: thesis (14 B), wide (16 B), compact (13 B)
//   form = "hashed"              # LHT form: hashed (the thesis's), compressed (no key)
//   lookup = "thesis"            # look-up: thesis (nearest points) or blend (16 pairs)
//   object = { type = "union", children = [ ... ] }   # any CSG subtree
//
//   [[objects]]
//   type = "lattice"             # one instance, placed by the usual keys
//   lattice = "hair"
//
//   [[objects]]
//   type = "lattice_scatter"     # N instances almost uniformly on a sphere
//   lattice = "hair"
//   count = 1000
//   radius = 1.0                 # each instance's object z axis along the normal
//   seed = 1                     # random twist about that normal
//
// (`type = "polyline"`, spheres joined by cylinders, is a built-in shape:
// render/shapes/polyline_shape.hpp.)
//
// Every instance shares one rasterized table (loader/lattice_tables.hpp), built
// under the TableSettings the scene was loaded or rebound with. With
// BuildOptions.fullRayTrace an instance is built as its exact object instead
// (the thesis's "full ray trace"); with latticeShadows off, lattices cast no
// shadows (plate 3).
//
// Method: the loader (loader/scene_loader.hpp) is handed the built-in format
// plus the lattice section and types, whose parsers keep the definitions of
// this one load; the load returns the scene and those definitions together.
#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

#include "loader/lattice_definition.hpp"
#include "render/scene/scene.hpp"

namespace lattice::lht {

// A loaded scene, its [[lattices]] definitions (in file order), and the
// settings its lattice leaves build their tables under.
struct SceneWithLattices {
  SceneDesc scene;
  std::vector<LatticeDefinitionPtr> lattices;
  TableSettings tables;
};

SceneWithLattices loadSceneWithLattices(const std::filesystem::path& sceneFile, const TableSettings& tables = {});
SceneWithLattices parseSceneWithLattices(std::string_view text, const std::filesystem::path& fileName,
                                         const TableSettings& tables = {});

// The same scene with its lattice leaves building their tables under
// `tables` instead (for settings that depend on the loaded scene, such as a
// memory budget's packing). Shares everything else with `loaded`.
SceneWithLattices withTableSettings(const SceneWithLattices& loaded, const TableSettings& tables);

// Almost uniformly spaced unit vectors: the Fibonacci (golden-angle) spiral.
std::vector<Vec3d> fibonacciSphere(int count);

// The most instances one lattice_scatter places (docs/limits.md). Placement
// is linear (the Fibonacci spiral) and the union's BVH O(n log n), but each
// instance holds about 850 bytes and every ray passes more of them; the
// limit keeps a scene's load and render within the figures docs/limits.md
// gives (measured by bench/scatter-scaling.sh).
inline constexpr long long kMaxScatterCount = 100000;

}  // namespace lattice::lht
