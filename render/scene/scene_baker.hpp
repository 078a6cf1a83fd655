#pragma once
// Baking a scene into C++ for the firmware (docs/firmware.md): the firmware
// has no scene parser, so `lattice bake` writes the loaded SceneDesc as C++
// that rebuilds it, with large tables as constant data in flash. Each leaf
// writes its own construction (LeafDesc::bake) through this interface; the
// writer of the file lives in app/ (app/scene_bake.cpp).
//
// Numbers are written as C++ hexadecimal floating literals, so every double
// the firmware sees has the host's exact bits, and the fixed-point picture
// can be byte-identical to the host's.
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>

#include "foundation/vec.hpp"

namespace lattice {

struct NodeDesc;

class SceneBaker {
 public:
  virtual ~SceneBaker() = default;
  // An exact C++ literal of v.
  virtual std::string number(double v) const = 0;
  std::string vec3(const Vec3d& v) const {
    return "lattice::Vec3d(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")";
  }
  std::string mat4(const Mat4d& m) const;
  // A C++ expression of type NodeDesc rebuilding `node` (a subtree a leaf
  // owns, such as a lattice's object).
  virtual std::string node(const NodeDesc& node) = 0;
  // Defines a constant array holding `bytes` in flash and returns the
  // expression of a std::span<const std::uint8_t> over it.
  virtual std::string flashBytes(std::span<const std::uint8_t> bytes, std::string_view what) = 0;
  // A value several leaves share (a lattice's table: one copy in flash for
  // all its instances): `expression` is written once, into a variable, the
  // first time `identity` is seen; every call returns the variable's name.
  virtual std::string shared(const void* identity, const std::function<std::string()>& expression) = 0;
  // A header the generated file must include ("render/scene/builtin_leaves.hpp").
  virtual void include(std::string_view header) = 0;
  // Definitions of constant data (constexpr arrays) written before every
  // use, counted as `bytes` of flash.
  virtual void constantData(std::string definitions, std::size_t bytes) = 0;
  // A name no other definition of the file has: prefix + a number.
  virtual std::string freshName(std::string_view prefix) = 0;
  // True the first time `key` is asked: helpers to define once per file.
  virtual bool defineOnce(std::string_view key) = 0;
};

}  // namespace lattice
