#pragma once
// The built-in leaves of a scene, as objects a program can make without the
// scene loader: a single quartic (thesis 3.2.1) and a capsule (a sphere is
// one of length 0; render/shapes/composite_shapes.hpp). The loader's node types
// (loader/node_types.cpp) and a baked scene (docs/firmware.md) both use these.
#include <string>

#include "render/scene/scene.hpp"
#include "render/shapes/quartic_presets.hpp"

namespace lattice {

LeafDescPtr makeQuarticLeafDesc(QuarticShape shape, std::string name);
LeafDescPtr makeCapsuleLeafDesc(double radius, double length, std::string name = "capsule");

}  // namespace lattice
