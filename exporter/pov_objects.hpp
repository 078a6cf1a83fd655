#pragma once
// The CSG tree of a scene as POV-Ray objects (the shapes half of
// exporter/pov_export.hpp). Every leaf gets its resolved material's
// texture, `Material<id>`, which the frame declares; a lattice's exact object
// is declared once per lattice and material (`Lattice<n>`) and each instance
// is an `object` with its own matrix.
#include <fmt/format.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "exporter/pov_export.hpp"

namespace lattice::exporter {

class PovObjectWriter {
 public:
  PovObjectWriter(const std::filesystem::path& source, const PovExportOptions& options)
      : source_(source), options_(options) {}
  // Appends the subtree (its own transform included) to the objects text.
  void write(const NodeDesc& node, MaterialId inherited);
  const std::string& declarations() const { return declarations_; }
  const std::string& objects() const { return objects_; }
  const std::vector<std::string>& notes() const { return notes_; }

 private:
  // `parentOrigin`: where the parent was defined, a node's own when it has none.
  void node(std::string& out, const NodeDesc& node, MaterialId inherited, int depth,
            const std::string& parentOrigin = {});
  void leaf(std::string& out, const NodeDesc& node, MaterialId material, int depth, const std::string& origin);
  void quartic(std::string& out, const QuarticShape& shape, const std::string& modifiers, int depth);
  void tube(std::string& out, const std::vector<Vec3d>& points, double radius, const std::string& modifiers,
            int depth);
  const std::string& latticeName(const LatticeShape& lattice, MaterialId material, const std::string& where);

  std::filesystem::path source_;
  PovExportOptions options_;
  std::string declarations_;
  std::string objects_;
  std::vector<std::string> notes_;
  std::map<std::pair<const NodeDesc*, MaterialId>, std::string> lattices_;
};

inline std::string povMaterialName(MaterialId id) { return fmt::format("Material{}", id); }

}  // namespace lattice::exporter
