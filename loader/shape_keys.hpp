#pragma once
// A shape's own keys in one [[objects]] table, as the shape's read(keys)
// asks for them (render/shapes/leaf_shape.hpp): typed values by key name and
// located failures, with no TOML in the shape's file.
//
// Method: a thin view of the table over ParseContext's checked accessors, so
// every message keeps the file, line and column; the value kinds a shape can
// ask for (a number, a list of points, a polynomial, a box) are the scene
// format's, not any one shape's. As pbrt-v4's shapes read a
// ParameterDictionary, the shape says what it needs and the format says how
// it is written.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "loader/scene_loader.hpp"
#include "render/shapes/quartic.hpp"

namespace lattice {

class ShapeKeys {
 public:
  ShapeKeys(const toml::table& table, ParseContext& context) : table_(table), context_(context) {}

  double positive(std::string_view key) const { return context_.positiveNumber(table_, key); }
  std::optional<double> number(std::string_view key) const { return context_.number(table_, key); }
  // The length of the array under `key`; 0 when it is missing or no array.
  std::size_t length(std::string_view key) const;
  // Every element of the array under `key` as [x, y, z]; `what` names one.
  std::vector<Vec3d> vec3List(std::string_view key, std::string_view what) const;
  // A table of x<i>y<j>z<k> monomials or the list of all 35 coefficients.
  QuarticPolynomial polynomial(std::string_view key) const;
  // `{ min = [x, y, z], max = [x, y, z] }`, or nothing when the key is absent.
  std::optional<Bounds<double>> box(std::string_view key) const;

  // At the key's value (at the table when the key is absent).
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;
  // At element `index` of the array under `key`.
  [[noreturn]] void failItem(std::string_view key, std::size_t index, const std::string& message) const;
  [[noreturn]] void failTable(const std::string& message) const { context_.fail(table_, message); }

 private:
  const toml::table& table_;
  ParseContext& context_;
};

}  // namespace lattice
