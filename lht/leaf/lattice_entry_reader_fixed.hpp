#pragma once
// The lattice leaf's fixed-point entry reader (Fixed32): the specialisation
// of lht/leaf/lattice_entry_reader.hpp for --arith fixed (docs/fixed-point.md).
//
// Method and tunables:
// * Entries are decoded to integers (decodePayloadIntegers, the same decoder
//   find() uses before its conversion to double): s is a fraction of
//   integers, the normal an integer direction normalized in Q31.32.
// * The integer direction (components up to normalDirectionMax: 127, or
//   32767 for the wide entry) is multiplied by the normal matrix scaled by a
//   power of two, so the product stays as small as with the thesis's 127
//   (Q31.32 saturates at 2^31); for the thesis the factor is exactly 1.
// * kSmallestCell = 1e-6 world units: a ray's box entry and exit are
//   t = (face - origin) / direction in lattice units, and a direction of
//   1 / (world size of a cell) leaves 1 / direction few bits; normals,
//   multiplied by entries of 1 / cell, saturate. Measured on a sphere
//   lattice: cells of 2.5e-7 still meet the lattice's own 1.5-cell bound,
//   cells of 2.5e-8 do not (normals 0.65 off unit length), 2.5e-9 give
//   garbage (docs/stability.md). Smaller cells are refused.
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>

#include "foundation/error.hpp"
#include "foundation/fixed.hpp"
#include "foundation/transform_condition.hpp"
#include "lht/table/entry_codec.hpp"
#include "lht/leaf/lattice_entry_reader.hpp"

namespace lattice::lht {

template <>
class EntryReader<Fixed32> {
 public:
  static constexpr double kSmallestCell = 1e-6;

  EntryReader(const LhtLookup& table, const Mat4d& latticeToWorld, const Mat4d& worldToLattice)
      : table_(table), precision_(table.precision()) {
    const double cell = singularValueRange(latticeToWorld).smallest;
    if (!(cell >= kSmallestCell))
      throw Error(ErrorKind::Input,
                  fmt::format("lattice: a cell of this lattice is {:.3g} world units across, below the 1e-6 that "
                              "--arith fixed resolves (its resolution is 2^-32 = 2.3e-10); use --arith double, "
                              "or scale the whole scene up",
                              cell));
    const Mat3<double> normalToWorld = glm::transpose(Mat3<double>(worldToLattice));
    const int bits = static_cast<int>(std::bit_width(static_cast<unsigned>(normalDirectionMax(precision_))));
    const int extraBits = std::max(0, bits - 7);
    directionToWorld_ = Mat3<Fixed32>(normalToWorld * std::ldexp(1.0, -extraBits));
  }

  // With the map normalMap() of a reader built as above (a baked placement).
  EntryReader(const LhtLookup& table, const Mat3<Fixed32>& normalMap)
      : table_(table), precision_(table.precision()), directionToWorld_(normalMap) {}
  const Mat3<Fixed32>& normalMap() const { return directionToWorld_; }

  const std::uint8_t* find(const LatticePoint& from, const LatticePoint& to) const { return table_.payload(from, to); }
  Fixed32 s(const std::uint8_t* entry) const {
    const EntryFraction f = decodePayloadFraction(entry, precision_);
    return fixed(f.numerator) / fixed(f.denominator);
  }
  Vec3<Fixed32> normal(const std::uint8_t* entry) const {
    const EntryIntegers e = decodePayloadIntegers(entry, precision_);
    return lattice::normalize(directionToWorld_ * Vec3<Fixed32>(fixed(e.normal[0]), fixed(e.normal[1]), fixed(e.normal[2])));
  }

  bool read(const LatticePoint& from, const LatticePoint& to, Fixed32& sOut, Vec3<Fixed32>& worldNormal) const {
    const std::uint8_t* entry = find(from, to);
    if (!entry) return false;
    sOut = s(entry);
    worldNormal = normal(entry);
    return true;
  }

 private:
  // int: std::int32_t is long on 32-bit ARM, and Fixed is built from int.
  static Fixed32 fixed(std::int32_t v) { return Fixed32(static_cast<int>(v)); }

  LhtLookup table_;
  LhtPrecision precision_;
  Mat3<Fixed32> directionToWorld_{Fixed32(1)};
};

}  // namespace lattice::lht
