#pragma once
// The table of built-in object types of scene files (loader/node_types.cpp).
// builtinSceneFormat() is made from it; adding a primitive to the format
// means adding one entry there.
#include <map>
#include <string>

#include "loader/scene_loader.hpp"

namespace lattice {

std::map<std::string, NodeParser> builtinNodeTypes();

}  // namespace lattice
