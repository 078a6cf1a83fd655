#include "lht/leaf/baked_lattice.hpp"

#include <fmt/format.h>

#include "foundation/error.hpp"
#include "lht/leaf/baked_lattice_union.hpp"
#include "lht/leaf/lattice_leaf.hpp"
#include "render/scene/scene_baker.hpp"

namespace lattice::lht {
namespace {

class BakedLatticeLeafDesc final : public LeafTemplate<BakedLatticeLeafDesc> {
 public:
  BakedLatticeLeafDesc(std::shared_ptr<const LhtFile> table, bool castsShadows, std::string name,
                       Bounds<double> objectBounds)
      : table_(std::move(table)), shadows_(castsShadows), name_(std::move(name)), bounds_(objectBounds) {}

  template <typename T>
  PrimitivePtr<T> buildAs(const Mat4d& toWorld, MaterialId material, const BuildOptions& options) const {
    if (options.fullRayTrace)
      throw Error(ErrorKind::Usage, fmt::format("{} is baked without its object: no full ray trace", describe()));
    return makeLatticeLeaf<T>(table_, toWorld, material, options.latticeShadows && shadows_);
  }
  Bounds<double> objectBounds() const override { return bounds_; }
  std::string describe() const override { return fmt::format("baked lattice '{}'", name_); }
#ifndef LATTICE_NO_BAKER  // the firmware renders a baked scene and never bakes one (render/scene/scene.hpp)
  std::string bake(SceneBaker& baker) const override {
    return bakeLatticeLeaf(baker, *table_, shadows_, name_, bounds_);
  }
  std::string bakeUnion(SceneBaker& baker, const NodeDesc& unionNode, const Mat4d& parentToWorld,
                        MaterialId inherited) const override {
    return bakeLatticeUnion(baker, name_, unionNode, parentToWorld, inherited);
  }
#endif

 private:
  std::shared_ptr<const LhtFile> table_;
  bool shadows_;
  std::string name_;
  Bounds<double> bounds_;
};

}  // namespace

LeafDescPtr makeBakedLatticeLeafDesc(std::shared_ptr<const LhtFile> table, bool castsShadows, std::string name,
                                     Bounds<double> objectBounds) {
  return std::make_shared<BakedLatticeLeafDesc>(std::move(table), castsShadows, std::move(name), objectBounds);
}

std::shared_ptr<const LhtFile> makeBakedLhtFile(std::uint32_t version, const LatticeBox& box, std::uint64_t objectHash,
                                                std::uint64_t pairs, std::uint64_t hits, LatticeHashTable table) {
  auto file = std::make_shared<LhtFile>();
  file->version = version;
  file->box = box;
  file->objectHash = objectHash;
  file->pairs = pairs;
  file->hits = hits;
  file->table = std::move(table);
  return file;
}

std::string bakeLatticeLeaf(SceneBaker& baker, const LhtFile& lht, bool castsShadows, const std::string& name,
                            const Bounds<double>& objectBounds) {
  const std::string file = bakedTableExpression(baker, lht, name);
  return fmt::format("lattice::lht::makeBakedLatticeLeafDesc({}, {}, \"{}\", lattice::Bounds<double>{{{}, {}}})",
                     file, castsShadows ? "true" : "false", name, baker.vec3(objectBounds.lo),
                     baker.vec3(objectBounds.hi));
}

std::string bakedTableExpression(SceneBaker& baker, const LhtFile& lht, const std::string& name) {
  baker.include("lht/leaf/baked_lattice.hpp");
  if (lht.form() != LhtForm::Hashed)
    throw Error(ErrorKind::Usage, fmt::format("lattice '{}': only the hashed table form can be baked for the firmware "
                                              "(docs/firmware.md); bake without a compressed or on-demand form",
                                              name));
  // One table in flash for every instance of the lattice.
  return baker.shared(&lht, [&] {
    const LatticeBox& box = lht.box;
    const LatticeHashTable& table = lht.hashed();
    const std::string slots = baker.flashBytes(table.slotView(), fmt::format("lattice '{}' table slots", name));
    return fmt::format(
        "lattice::lht::makeBakedLhtFile({}u, lattice::lht::LatticeBox({{{}, {}, {}}}, {}, {}, {}), {}ull, {}ull, {}ull, "
        "lattice::lht::LatticeHashTable::inPlace(static_cast<lattice::lht::LhtPrecision>({}), {}, {}ull, {}ull))",
        kLhtVersion, box.cells()[0], box.cells()[1], box.cells()[2], baker.number(box.lambda()),
        baker.number(box.oversample()), baker.vec3(box.origin()), lht.objectHash, lht.pairs, lht.hits,
        static_cast<int>(table.precision()), slots, table.capacity(), table.entryCount());
  });
}

}  // namespace lattice::lht
