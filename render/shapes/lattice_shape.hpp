#pragma once
// The lattice shape: a lattice (thesis ch. 2) answers with the exact object it
// was rasterized from, so a writer for another renderer places that object
// where the lattice is. One alternative of LeafShape
// (render/shapes/leaf_shape.hpp).
//
// Method: the lattice leaf itself is built by lht/ from its table
// (loader/lattice_scene_loader.cpp), so this shape has no reader or build of
// its own: the lattice module adds its `type` to the scene format and
// returns this from its leaves. The object is shared by all instances.
#include <optional>
#include <string>
#include <string_view>

#include "render/shapes/ball_chain.hpp"

namespace lattice {

struct NodeDesc;

struct LatticeShape {
  static constexpr std::string_view kName = "lattice";
  // Names the [[lattices]] entry `example` (tests/lht/shape_table_test.cpp defines it).
  static constexpr std::string_view kExample = "lattice = \"example\"";

  const NodeDesc* object = nullptr;  // owned by the definition, which outlives the scene
  std::string name;                  // the definition's name
  bool castsShadows = true;          // false for `shadows = false` (thesis plate 3)

  std::optional<BallChain> balls() const { return std::nullopt; }  // its box is the definition's
};

}  // namespace lattice
