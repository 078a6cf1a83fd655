#pragma once
// The table of built-in object types of scene files (loader/node_types.cpp).
// builtinSceneFormat() is made from it. A set operation or a preset is one
// entry there; a shape's type follows its row of render/shapes/leaf_shape.hpp.
#include <map>
#include <string>

#include "loader/scene_loader.hpp"

namespace lattice {

std::map<std::string, NodeParser> builtinNodeTypes();

}  // namespace lattice
