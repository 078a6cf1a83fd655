#pragma once
// Numbers, vectors and matrices in POV-Ray's syntax, shared by the exporter's
// files. Numbers are the shortest text that reads back as the same double.
#include <fmt/format.h>

#include <iterator>
#include <string>

#include "foundation/vec.hpp"

namespace lattice::exporter {

inline std::string povNumber(double v) { return fmt::format("{}", v == 0.0 ? 0.0 : v); }  // no "-0"

inline std::string povVector(const Vec3d& v) {
  return fmt::format("<{}, {}, {}>", povNumber(v.x), povNumber(v.y), povNumber(v.z));
}

// POV-Ray applies `matrix <a..l>` to row vectors: its rows are the images of
// x, y and z, then the translation; glm's columns are the same four vectors.
inline std::string povMatrix(const Mat4d& m) {
  std::string s = "matrix <";
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) fmt::format_to(std::back_inserter(s), "{}{}", povNumber(m[c][r]), c == 3 && r == 2 ? ">" : ", ");
  return s;
}

inline bool isIdentity(const Mat4d& m) { return m == Mat4d(1.0); }

}  // namespace lattice::exporter
