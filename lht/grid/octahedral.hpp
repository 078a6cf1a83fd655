#pragma once
// Octahedral unit-vector encoding (Meyer, Sander, Rodrigues and Dachsbacher
// 2010; Cigolle, Donow, Evangelakos, Mara, McGuire and Meyer, "A Survey of
// Efficient Representations for Independent Unit Vectors", JCGT 3(2), 2014).
// A unit vector is projected onto the octahedron |x| + |y| + |z| = 1; the
// upper half (z >= 0) lies flat on the square |u| + |v| <= 1 and the lower
// half is folded out over the square's four corners, so two numbers in
// [-1, 1] cover the sphere with nearly even resolution - better use of the
// bits than three separate components (which waste codes on vectors that
// are not unit length).
//
// Here u and v are signed integers in [-m, m] (m = 127 for 8 bits, 32767
// for 16), so the axes and the fold (the equator, z = 0) are represented
// exactly, and decoding is pure integer arithmetic: the result is the
// vector's direction with |x| + |y| + |z| = m, to be normalized by the
// caller (in whatever arithmetic it renders in).
#include <array>
#include <cstdint>

#include "foundation/vec.hpp"

namespace lattice::lht {

struct OctahedralCode {
  std::int32_t u = 0;
  std::int32_t v = 0;
};

// `unit` need not be exactly unit length (it must not be zero). Of the (up to)
// four neighbouring codes around the exact projection, returns the one whose
// decoded direction is closest in angle ("precise" encoding in Cigolle et al.;
// plain rounding can be up to ~1.5 times worse).
OctahedralCode encodeOctahedral(const Vec3d& unit, std::int32_t maxValue);

// The direction a code stands for: |x| + |y| + |z| == maxValue, never zero.
// Codes outside [-maxValue, maxValue] (a corrupt file) are clamped first.
std::array<std::int32_t, 3> decodeOctahedral(OctahedralCode code, std::int32_t maxValue);

}  // namespace lattice::lht
