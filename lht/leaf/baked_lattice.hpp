#pragma once
// A lattice leaf of a baked scene (docs/firmware.md): the rasterized table
// comes ready-made (in the firmware, read in place from flash:
// LatticeHashTable::inPlace), so neither the lattice's object, the
// rasterizer nor a .lht file is needed where it is rendered. It renders like
// the loader's lattice leaf; the full ray trace (--full) needs the object
// and is refused.
#include <memory>
#include <string>

#include "lht/file/lht_file.hpp"
#include "render/scene/scene.hpp"

namespace lattice::lht {

LeafDescPtr makeBakedLatticeLeafDesc(std::shared_ptr<const LhtFile> table, bool castsShadows, std::string name,
                                     Bounds<double> objectBounds);

// The hashed-form table a baked scene rebuilds (its slots read in place).
std::shared_ptr<const LhtFile> makeBakedLhtFile(std::uint32_t version, const LatticeBox& box, std::uint64_t objectHash,
                                                std::uint64_t pairs, std::uint64_t hits, LatticeHashTable table);

// The C++ expression (render/scene/scene_baker.hpp) of such a leaf for `table`:
// its slots go to flash, the rest is written out as numbers.
std::string bakeLatticeLeaf(SceneBaker& baker, const LhtFile& table, bool castsShadows, const std::string& name,
                            const Bounds<double>& objectBounds);

// The expression of the shared std::shared_ptr<const LhtFile> of `table` in
// a baked scene (written once however many leaves use it); throws
// lattice::Error(Usage) for a form other than hashed.
std::string bakedTableExpression(SceneBaker& baker, const LhtFile& table, const std::string& name);

}  // namespace lattice::lht
