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
//   [[objects]]                  # spheres joined by cylinders (hook, hair)
//   type = "polyline"
//   points = [[0, 0, 0], [0, 0, 1], [0.2, 0, 2]]
//   radius = 0.5
//
// Every instance shares one rasterized table. With BuildOptions.fullRayTrace
// an instance is built as its exact object instead (the thesis's "full ray
// trace"); with latticeShadows off, lattices cast no shadows (plate 3).
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lht/lht_file.hpp"
#include "render/scene.hpp"

namespace lattice::lht {

// The most instances one lattice_scatter places (docs/limits.md). Placement
// is linear (the Fibonacci spiral) and the union's BVH O(n log n), but each
// instance holds about 850 bytes and every ray passes more of them: measured
// by bench/scatter-scaling.sh, 100,000 hairs load in 0.36 s and 86 MiB and
// render 64x64 in 0.62 s; 10^6 take 2.5 s and 837 MiB before the first ray
// and 8.3 s for 64x64 (minutes for 512x512).
inline constexpr long long kMaxScatterCount = 100000;

class LatticeDefinition {
 public:
  std::string name;
  double lambda = 1.0;
  double oversample = 1.0;
  NodeDesc object;
  std::string objectText;  // canonical text of the object table (lht/canonical_toml.hpp)
  std::optional<std::filesystem::path> cache;
  bool shadows = true;     // false: this lattice casts no shadows (thesis plate 3)
  // The table's entry form. A plain field: `lattice render --lht-precision`
  // (or a memory budget) may set it any time before table() first runs.
  LhtPrecision precision = LhtPrecision::Thesis;

  // Under a memory budget: the entry form to pack a freshly rasterized table
  // in, given its entry count and the bytes its hit list holds meanwhile
  // (unset: `precision`). A cache is read as named whatever this says; a
  // table packed in another form than `precision` is not written to it.
  std::function<LhtPrecision(std::uint64_t entries, std::uint64_t hitListBytes)> packing;
  unsigned rasterThreads = 0;  // threads rasterizing the table; 0: all cores
  std::string origin;      // "scene.toml:12:1"

  // Hash of everything that decides the table's contents (precision
  // included, so a cache of another precision is stale).
  std::uint64_t hash() const { return hashFor(precision); }
  std::uint64_t hashFor(LhtPrecision form) const;
  // The rasterized table: read from the cache when it matches, else
  // rasterized (and written to the cache if one is named). Thread-safe; done once.
  std::shared_ptr<const LhtFile> table(bool progress = true) const;
  // The object's box in its own coordinates (computed once).
  const Bounds<double>& objectBounds() const;
  // Rasterizes now, ignoring any cache.
  LhtFile rasterizeNow(bool progress, RasterStats* stats = nullptr, unsigned threads = 0) const;

 private:
  mutable std::once_flag once_, boundsOnce_;
  mutable Bounds<double> bounds_;
  mutable std::shared_ptr<const LhtFile> table_;
};

using LatticeDefinitionPtr = std::shared_ptr<LatticeDefinition>;

// Adds the "lattices" section and the "lattice" / "lattice_scatter" node
// types to the scene loader. Idempotent; call before loadScene().
void registerLatticeSceneTypes();

// The [[lattices]] definitions of a scene file (for `lattice rasterize --scene`).
std::vector<LatticeDefinitionPtr> loadLatticeDefinitions(const std::filesystem::path& sceneFile);

// A loaded scene and its [[lattices]] definitions, which the scene's
// lattice leaves share: changing a definition (its precision, say) before
// the scene is rendered changes what the render builds.
struct SceneWithLattices {
  SceneDesc scene;
  std::vector<LatticeDefinitionPtr> lattices;
};
SceneWithLattices loadSceneWithLattices(const std::filesystem::path& sceneFile);
SceneWithLattices parseSceneWithLattices(std::string_view text, const std::filesystem::path& fileName);
std::vector<LatticeDefinitionPtr> parseLatticeDefinitions(std::string_view text, const std::filesystem::path& fileName);

// Almost uniformly spaced unit vectors: the Fibonacci (golden-angle) spiral.
std::vector<Vec3d> fibonacciSphere(int count);

// A leaf standing for one lattice instance.
LeafDescPtr makeLatticeLeafDesc(LatticeDefinitionPtr definition);

}  // namespace lattice::lht
