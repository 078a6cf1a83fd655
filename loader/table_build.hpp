#pragma once
// Building a lattice's table, the one call `lattice rasterize`, scene loads
// and benchmarks share: the lattice box around the object, rasterization
// (lht/raster/rasterize.hpp), the entry form, the hash tying the file to its object,
// the hash table (lht/table/hash_table.hpp).
//
// Method: the object comes from a [[lattices]] entry (its exact CSG subtree,
// hashed with its spacing, oversampling and entry form) or from a built-in
// shape of `lattice rasterize --shape` (hashed by its own description, in
// units of lambda = 1). Nothing is read from or written to a cache here;
// loader/lattice_tables.hpp does that for scenes.
#include <filesystem>
#include <optional>
#include <string>

#include "loader/lattice_definition.hpp"
#include "lht/file/lht_file.hpp"
#include "lht/raster/rasterize.hpp"

namespace lattice::lht {

struct BuiltTable {
  LhtFile lht;
  RasterStats stats;
};

// A [[lattices]] entry's table, rasterized now. Errors name the entry.
BuiltTable buildLatticeTable(const LatticeDefinition& lattice, const TableSettings& settings);

// What `lattice rasterize` builds: a [[lattices]] entry of a scene file
// (scene + name) or a shape (shape + radius, length).
struct TableRequest {
  std::filesystem::path scene;
  std::string name;
  std::string shape;  // "sphere" (centred) or "capsule" (axis along z from 0 to length)
  double radius = 0.5, length = 10.0;  // in lambda
  std::optional<double> oversample;    // overrides the entry's; shapes: 1
  TableSettings settings;              // precision unset: the entry's, or the thesis's for shapes
};

// Throws lattice::Error(Usage) when the request names neither or both, or an
// unknown shape; Error(Input) for a scene without that entry.
BuiltTable buildLatticeTable(const TableRequest& request);

}  // namespace lattice::lht
