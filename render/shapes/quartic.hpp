#pragma once
// Quartic primitives (thesis section 3.2.1, eq. 3.1): the solid where
// f(x, y, z) = sum a_ijk x^i y^j z^k < 0, i + j + k <= 4. f > 0 is outside,
// and grad f is the outward surface normal.
//
// Scene set-up builds polynomials in double; a leaf converts them once to the
// ray tracer's scalar T, so nothing on the per-ray path uses double when
// T = float or Fixed32.
#include <array>

#include "render/shapes/primitive.hpp"
#include "foundation/vec.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice {

struct QuarticPolynomial {
  static constexpr int kMaxDegree = 4;
  static constexpr int kTerms = 35;  // monomials x^i y^j z^k with i + j + k <= 4

  // a[index(i, j, k)] is the coefficient a_ijk.
  std::array<double, kTerms> a{};

  // Position of a_ijk in `a`; monomials are grouped by total degree.
  // Throws lattice::Error (Internal) for i, j, k < 0 or i + j + k > 4.
  static int index(int i, int j, int k);
  // The exponents of the monomial at `index` (inverse of index()).
  static std::array<int, 3> exponents(int index);

  double coefficient(int i, int j, int k) const { return a[static_cast<std::size_t>(index(i, j, k))]; }

  // Building blocks for presets: f += c x^i y^j z^k, and the polynomials
  // 1, x, y, z, so that a sphere is x*x + y*y + z*z - r*r.
  QuarticPolynomial& addTerm(double c, int i, int j, int k);
  static QuarticPolynomial constant(double c);
  static QuarticPolynomial x();
  static QuarticPolynomial y();
  static QuarticPolynomial z();

  // Highest total degree with a non-zero coefficient (-1 for f == 0).
  int degree() const;

  double eval(const Vec3d& p) const;
  Vec3d gradient(const Vec3d& p) const;

  QuarticPolynomial& operator+=(const QuarticPolynomial& o);
  QuarticPolynomial& operator-=(const QuarticPolynomial& o);
  QuarticPolynomial& operator*=(double s);
};

QuarticPolynomial operator+(QuarticPolynomial l, const QuarticPolynomial& r);
QuarticPolynomial operator-(QuarticPolynomial l, const QuarticPolynomial& r);
QuarticPolynomial operator-(QuarticPolynomial p);
QuarticPolynomial operator*(QuarticPolynomial p, double s);
QuarticPolynomial operator*(double s, QuarticPolynomial p);
// Product of polynomials; throws lattice::Error (Input) if the degree would exceed 4.
QuarticPolynomial operator*(const QuarticPolynomial& l, const QuarticPolynomial& r);

// The leaf for f < 0 placed in the world by objectToWorld (transforms are kept
// at leaves, thesis 3.1). objectBounds must contain the solid (it may be
// infinite); rays that miss its world box skip the root solving entirely.
// Throws lattice::Error (Input) if objectToWorld is singular or not finite.
template <typename T>
PrimitivePtr<T> makeQuarticLeaf(const QuarticPolynomial& f, const Bounds<double>& objectBounds,
                                const Mat4d& objectToWorld, MaterialId material);

#define LATTICE_DECLARE(T)                                                                                        \
  extern template PrimitivePtr<T> makeQuarticLeaf<T>(const QuarticPolynomial&, const Bounds<double>&, const Mat4d&, \
                                                     MaterialId);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_DECLARE)
#undef LATTICE_DECLARE

}  // namespace lattice
