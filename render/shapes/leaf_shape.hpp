#pragma once
// The table of shapes: what a scene leaf can be made of, as a closed set.
// Code that writes the scene for another renderer (exporter/: POV-Ray;
// bench/peers/: Embree), the rasterizer's cover (lht/raster/object_cover.cpp),
// the instance bounds (render/scene/instance_node.cpp) and the scene loader
// (loader/node_types.cpp) ask a leaf for its LeafShape; the tracer never asks,
// it builds through LeafDesc::build.
//
// Method: a std::variant of one small struct per shape, each holding only its
// own fields, as pbrt-v4's Shape is a closed tagged set of its shapes
// (src/pbrt/base/shape.h). A shape's struct lives in its own file,
// render/shapes/<shape>_shape.hpp, and gives:
//   kName                  its scene-file `type` and its name here, unique
//   kExample               the keys of one valid object of it (read back by
//                          tests/lht/shape_table_test.cpp)
//   balls()                balls swept along centres that contain it, or none
//                          (then its box serves)
// and, when the tracer builds it from a scene file (all but the lattice,
// which lht/ builds from its table):
//   kKeys, read(keys)      its keys and how it reads them (the loader's
//                          loader/shape_keys.hpp; format-neutral, as pbrt's
//                          Shape::Create reads a ParameterDictionary)
//   objectBounds(), describe(), build<T>(toWorld, material), bake(baker, name)
// The loader's types, the leaf (render/scene/shape_leaf.hpp) and the visitors
// follow this list. Visitors that must handle every shape name each
// alternative with Overloaded (foundation/overloaded.hpp) and no catch-all, so
// a shape added here without its case does not compile.
#include <cstddef>
#include <optional>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

#include "render/shapes/capsule_shape.hpp"
#include "render/shapes/lattice_shape.hpp"
#include "render/shapes/polyline_shape.hpp"
#include "render/shapes/quartic_shape.hpp"

namespace lattice {

// One row per shape.
using LeafShape = std::variant<  //
    QuarticShape,                //
    CapsuleShape,                //
    PolylineShape,               //
    LatticeShape>;

// Calls visit.template operator()<Shape>() for every row, in order.
template <typename Visit>
void forEachShape(Visit&& visit) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (visit.template operator()<std::variant_alternative_t<I, LeafShape>>(), ...);
  }(std::make_index_sequence<std::variant_size_v<LeafShape>>{});
}

inline std::string_view shapeName(const LeafShape& shape) {
  return std::visit([](const auto& s) { return std::remove_cvref_t<decltype(s)>::kName; }, shape);
}

inline std::optional<BallChain> ballsOf(const LeafShape& shape) {
  return std::visit([](const auto& s) { return s.balls(); }, shape);
}

}  // namespace lattice
