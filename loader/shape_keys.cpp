// A shape's keys read from its TOML table (loader/shape_keys.hpp).
//
// Method: each value kind is parsed here once, for whichever shape asks: a
// polynomial in either spelling (monomial table or the 35-number list), a
// box, a list of points; failures go through ParseContext, so they carry the
// file, line and column of the value at fault.
#include "loader/shape_keys.hpp"

#include <fmt/format.h>

#include <cctype>

namespace lattice {

namespace {

// "x2y1z0" -> (2, 1, 0); every letter present once, in order.
bool parseMonomial(std::string_view key, int& i, int& j, int& k) {
  if (key.size() != 6 || key[0] != 'x' || key[2] != 'y' || key[4] != 'z') return false;
  for (std::size_t p : {1u, 3u, 5u})
    if (!std::isdigit(static_cast<unsigned char>(key[p]))) return false;
  i = key[1] - '0';
  j = key[3] - '0';
  k = key[5] - '0';
  return i + j + k <= QuarticPolynomial::kMaxDegree;
}

}  // namespace

std::size_t ShapeKeys::length(std::string_view key) const {
  const toml::node* node = table_.get(key);
  const toml::array* list = node ? node->as_array() : nullptr;
  return list ? list->size() : 0;
}

std::vector<Vec3d> ShapeKeys::vec3List(std::string_view key, std::string_view what) const {
  std::vector<Vec3d> points;
  const toml::node* node = table_.get(key);
  if (const toml::array* list = node ? node->as_array() : nullptr)
    for (const toml::node& p : *list) points.push_back(context_.toVec3(p, what));
  return points;
}

QuarticPolynomial ShapeKeys::polynomial(std::string_view key) const {
  const toml::node* c = table_.get(key);
  if (!c)
    context_.fail(table_, fmt::format("missing key '{}' (a table like {{ x2y0z0 = 1, x0y0z0 = -1 }} or a list of 35 "
                                      "numbers)",
                                      key));
  QuarticPolynomial f;
  if (const toml::table* terms = c->as_table()) {
    for (auto&& [monomial, value] : *terms) {
      int i = 0, j = 0, k = 0;
      if (!parseMonomial(monomial.str(), i, j, k))
        context_.fail(value, fmt::format("coefficient key '{}' is not of the form x<i>y<j>z<k> with i + j + k <= 4 "
                                         "(e.g. x2y0z0 for x^2, x0y0z0 for the constant)",
                                         monomial.str()));
      f.addTerm(context_.toNumber(value, monomial.str()), i, j, k);
    }
  } else if (const toml::array* list = c->as_array()) {
    if (list->size() != QuarticPolynomial::kTerms)
      context_.fail(*c, fmt::format("'{}' as a list must have {} numbers (got {}), ordered by total degree: "
                                    "1, x, y, z, x^2, xy, xz, y^2, yz, z^2, x^3, ...",
                                    key, QuarticPolynomial::kTerms, list->size()));
    for (int n = 0; n < QuarticPolynomial::kTerms; ++n)
      f.a[static_cast<std::size_t>(n)] = context_.toNumber((*list)[static_cast<std::size_t>(n)], key);
  } else {
    context_.fail(*c, fmt::format("'{}' must be a table of x<i>y<j>z<k> keys or a list of 35 numbers", key));
  }
  return f;
}

std::optional<Bounds<double>> ShapeKeys::box(std::string_view key) const {
  const toml::node* b = table_.get(key);
  if (!b) return std::nullopt;
  const toml::table* bt = b->as_table();
  if (!bt)
    context_.fail(*b, fmt::format("'{}' must be a table {{ min = [x, y, z], max = [x, y, z] }} containing the solid",
                                  key));
  context_.checkKeys(*bt, {"min", "max"});
  const Bounds<double> bounds{context_.requiredVec3(*bt, "min"), context_.requiredVec3(*bt, "max")};
  if (bounds.empty()) context_.fail(*b, fmt::format("'{}' min must be <= max in every coordinate", key));
  return bounds;
}

void ShapeKeys::fail(std::string_view key, const std::string& message) const {
  if (const toml::node* node = table_.get(key)) context_.fail(*node, message);
  context_.fail(table_, message);
}

void ShapeKeys::failItem(std::string_view key, std::size_t index, const std::string& message) const {
  const toml::node* node = table_.get(key);
  const toml::array* list = node ? node->as_array() : nullptr;
  if (list && index < list->size()) context_.fail((*list)[index], message);
  fail(key, message);
}

}  // namespace lattice
