// Quartic polynomials (eq. 3.1) and the quartic leaf: the ray is substituted
// exactly into f, giving a polynomial in t of degree <= 4 whose real roots are
// the surface crossings; inside/outside between roots comes from the sign of
// that polynomial, never from counting roots, so tangent rays (double roots)
// and rays that start inside come out right.
//
// Method and tunables: the general substitution expands f group by group
// (YZGroup). A quartic of the torus's form, a |p|^4 + b (x^2+y^2) + c z^2 + d
// (found from the coefficients; float and double only), is substituted
// through five dot products instead, and a ray whose line misses its object
// box (widened by 1e-6 of its size) is not solved at all: torus-floor's trace
// 0.58x, its pictures unchanged (docs/benchmarks.md, "The renderer against
// Embree"). Fixed point keeps the general path, whose range checks it needs.
#include "render/shapes/quartic.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <limits>
#include <optional>
#include <vector>

#include "render/shapes/quartic_arithmetic.hpp"
#include "render/shapes/quartic_arithmetic_fixed.hpp"
#include "render/solve/roots.hpp"
#include "foundation/transform_condition.hpp"
#include "foundation/error.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice {

int QuarticPolynomial::index(int i, int j, int k) {
  if (i < 0 || j < 0 || k < 0 || i + j + k > kMaxDegree)
    throw Error(ErrorKind::Internal, fmt::format("quartic monomial x^{} y^{} z^{} is not in eq. 3.1 (i+j+k <= 4)", i, j, k));
  // Monomials of lower total degree come first (d(d+1)(d+2)/6 of them); within
  // degree d they are ordered by m = j + k, then k.
  const int d = i + j + k, m = j + k;
  return d * (d + 1) * (d + 2) / 6 + m * (m + 1) / 2 + k;
}

std::array<int, 3> QuarticPolynomial::exponents(int idx) {
  for (int d = 0; d <= kMaxDegree; ++d)
    for (int m = 0; m <= d; ++m)
      for (int k = 0; k <= m; ++k)
        if (index(d - m, m - k, k) == idx) return {d - m, m - k, k};
  throw Error(ErrorKind::Internal, fmt::format("quartic coefficient index {} is out of range 0..34", idx));
}

QuarticPolynomial& QuarticPolynomial::addTerm(double c, int i, int j, int k) {
  a[static_cast<std::size_t>(index(i, j, k))] += c;
  return *this;
}

QuarticPolynomial QuarticPolynomial::constant(double c) { return QuarticPolynomial{}.addTerm(c, 0, 0, 0); }
QuarticPolynomial QuarticPolynomial::x() { return QuarticPolynomial{}.addTerm(1, 1, 0, 0); }
QuarticPolynomial QuarticPolynomial::y() { return QuarticPolynomial{}.addTerm(1, 0, 1, 0); }
QuarticPolynomial QuarticPolynomial::z() { return QuarticPolynomial{}.addTerm(1, 0, 0, 1); }

int QuarticPolynomial::degree() const {
  int deg = -1;
  for (int n = 0; n < kTerms; ++n)
    if (a[static_cast<std::size_t>(n)] != 0.0) {
      auto e = exponents(n);
      deg = std::max(deg, e[0] + e[1] + e[2]);
    }
  return deg;
}

namespace {

// The same evaluation serves double (set-up, tests) and the leaf's scalar T.
template <typename T>
struct Term {
  T c;
  int i, j, k;
};

template <typename T>
void powers(T v, T out[5]) {
  out[0] = T(1);
  for (int n = 1; n < 5; ++n) out[n] = out[n - 1] * v;
}

template <typename T>
T evalTerms(const std::vector<Term<T>>& terms, const Vec3<T>& p) {
  T px[5], py[5], pz[5];
  powers(p.x, px);
  powers(p.y, py);
  powers(p.z, pz);
  T sum(0);
  for (const Term<T>& t : terms) sum += t.c * px[t.i] * py[t.j] * pz[t.k];
  return sum;
}

template <typename T>
Vec3<T> gradientTerms(const std::vector<Term<T>>& terms, const Vec3<T>& p) {
  T px[5], py[5], pz[5];
  powers(p.x, px);
  powers(p.y, py);
  powers(p.z, pz);
  Vec3<T> g(0);
  for (const Term<T>& t : terms) {
    if (t.i > 0) g.x += t.c * T(t.i) * px[t.i - 1] * py[t.j] * pz[t.k];
    if (t.j > 0) g.y += t.c * T(t.j) * px[t.i] * py[t.j - 1] * pz[t.k];
    if (t.k > 0) g.z += t.c * T(t.k) * px[t.i] * py[t.j] * pz[t.k - 1];
  }
  return g;
}

template <typename T>
std::vector<Term<T>> nonZeroTerms(const QuarticPolynomial& f) {
  std::vector<Term<T>> terms;
  for (int n = 0; n < QuarticPolynomial::kTerms; ++n) {
    double c = f.a[static_cast<std::size_t>(n)];
    if (c == 0.0) continue;
    auto e = QuarticPolynomial::exponents(n);
    terms.push_back({static_cast<T>(c), e[0], e[1], e[2]});
  }
  return terms;
}

}  // namespace

double QuarticPolynomial::eval(const Vec3d& p) const { return evalTerms(nonZeroTerms<double>(*this), p); }
Vec3d QuarticPolynomial::gradient(const Vec3d& p) const { return gradientTerms(nonZeroTerms<double>(*this), p); }

QuarticPolynomial& QuarticPolynomial::operator+=(const QuarticPolynomial& o) {
  for (std::size_t n = 0; n < a.size(); ++n) a[n] += o.a[n];
  return *this;
}
QuarticPolynomial& QuarticPolynomial::operator-=(const QuarticPolynomial& o) {
  for (std::size_t n = 0; n < a.size(); ++n) a[n] -= o.a[n];
  return *this;
}
QuarticPolynomial& QuarticPolynomial::operator*=(double s) {
  for (double& c : a) c *= s;
  return *this;
}
QuarticPolynomial operator+(QuarticPolynomial l, const QuarticPolynomial& r) { return l += r; }
QuarticPolynomial operator-(QuarticPolynomial l, const QuarticPolynomial& r) { return l -= r; }
QuarticPolynomial operator-(QuarticPolynomial p) { return p *= -1.0; }
QuarticPolynomial operator*(QuarticPolynomial p, double s) { return p *= s; }
QuarticPolynomial operator*(double s, QuarticPolynomial p) { return p *= s; }

QuarticPolynomial operator*(const QuarticPolynomial& l, const QuarticPolynomial& r) {
  QuarticPolynomial out;
  for (int n = 0; n < QuarticPolynomial::kTerms; ++n) {
    double cl = l.a[static_cast<std::size_t>(n)];
    if (cl == 0.0) continue;
    auto el = QuarticPolynomial::exponents(n);
    for (int m = 0; m < QuarticPolynomial::kTerms; ++m) {
      double cr = r.a[static_cast<std::size_t>(m)];
      if (cr == 0.0) continue;
      auto er = QuarticPolynomial::exponents(m);
      int i = el[0] + er[0], j = el[1] + er[1], k = el[2] + er[2];
      if (i + j + k > QuarticPolynomial::kMaxDegree)
        throw Error(ErrorKind::Input,
                    fmt::format("product of quartic polynomials has degree {} (x^{} y^{} z^{}); eq. 3.1 allows at most 4: "
                                "simplify the shape or split it with CSG",
                                i + j + k, i, j, k));
      out.addTerm(cl * cr, i, j, k);
    }
  }
  return out;
}

namespace {

// Precomputed per leaf so that substituting a ray costs a few small
// polynomial products: f = sum over (j, k) of P_jk(x) y^j z^k, where P_jk
// collects the x-terms sharing y^j z^k.
template <typename T>
struct YZGroup {
  int j, k;
  T px[5];  // P_jk as a polynomial in x, lowest power first
  int degX;
};

// out[0..da+db] = a[0..da] * b[0..db], truncated at degree 4.
template <typename T>
void multiply(const T* a, int da, const T* b, int db, T* out) {
  for (int n = 0; n <= 4; ++n) out[n] = T(0);
  for (int p = 0; p <= da; ++p)
    for (int q = 0; q <= db && p + q <= 4; ++q) out[p + q] += a[p] * b[q];
}

// (o + u s)^p for p = 0..4 as polynomials in s.
template <typename T>
void linearPowers(T o, T u, T out[5][5]) {
  for (int p = 0; p < 5; ++p)
    for (int q = 0; q < 5; ++q) out[p][q] = T(0);
  out[0][0] = T(1);
  for (int p = 1; p <= 4; ++p)
    for (int q = 0; q <= p; ++q) out[p][q] = (q < p ? out[p - 1][q] * o : T(0)) + (q > 0 ? out[p - 1][q - 1] * u : T(0));
}

// f = a (x^2+y^2+z^2)^2 + b (x^2+y^2) + c z^2 + d, the form the torus preset
// gives: a ray substitutes into it through five dot products (closedForm)
// instead of the general expansion. Found from the coefficients exactly as
// given, so a quartic that is not of this form keeps the general path.
struct RevolutionForm {
  double a, b, c, d;
};
inline std::optional<RevolutionForm> revolutionForm(const QuarticPolynomial& f) {
  const auto at = [&](int i, int j, int k) { return f.a[static_cast<std::size_t>(QuarticPolynomial::index(i, j, k))]; };
  const RevolutionForm r{at(4, 0, 0), at(2, 0, 0), at(0, 0, 2), at(0, 0, 0)};
  if (r.a == 0.0) return std::nullopt;
  // The form rebuilt from a, b, c, d must be f, every one of the 35 terms.
  QuarticPolynomial form;
  form.addTerm(r.a, 4, 0, 0).addTerm(r.a, 0, 4, 0).addTerm(r.a, 0, 0, 4);
  form.addTerm(2 * r.a, 2, 2, 0).addTerm(2 * r.a, 2, 0, 2).addTerm(2 * r.a, 0, 2, 2);
  form.addTerm(r.b, 2, 0, 0).addTerm(r.b, 0, 2, 0).addTerm(r.c, 0, 0, 2).addTerm(r.d, 0, 0, 0);
  if (form.a != f.a) return std::nullopt;
  return r;
}

template <typename T>
class QuarticLeaf final : public Primitive<T> {
 public:
  QuarticLeaf(const QuarticPolynomial& f, const Bounds<double>& objectBounds, const Mat4d& objectToWorld,
              MaterialId material)
      : terms_(nonZeroTerms<T>(f)), material_(material) {
    checkLeafTransform<T>(objectToWorld, "quartic");
    glm::dmat3 linear(objectToWorld);
    const Mat4d worldToObject = glm::inverse(objectToWorld);
    arithmetic_ = QuarticArithmetic<T>(worldToObject);
    normalMatrix_ = Mat3<T>(glm::inverseTranspose(linear));
    linear_ = Mat3<T>(linear);

    // The point rays are re-based at: the middle of the object box (0 along
    // unbounded axes). Substituting a ray whose origin is far from the surface
    // makes the constant term a difference of huge numbers; re-basing near
    // the object keeps the coefficients of the order of the object's size.
    for (int ax = 0; ax < 3; ++ax) {
      double lo = objectBounds.lo[ax], hi = objectBounds.hi[ax];
      pivot_[ax] = (std::isfinite(lo) && std::isfinite(hi)) ? static_cast<T>(0.5 * (lo + hi)) : T(0);
    }

    for (const Term<T>& t : terms_) {
      auto it = std::find_if(groups_.begin(), groups_.end(), [&](const YZGroup<T>& g) { return g.j == t.j && g.k == t.k; });
      if (it == groups_.end()) {
        groups_.push_back({t.j, t.k, {}, 0});
        it = groups_.end() - 1;
      }
      it->px[t.i] += t.c;
      it->degX = std::max(it->degX, t.i);
    }

    if constexpr (kIsIeee<T>)
      if (const std::optional<RevolutionForm> r = revolutionForm(f))
        revolution_ = {true, static_cast<T>(r->a), static_cast<T>(r->b), static_cast<T>(r->c), static_cast<T>(r->d),
                       reachOf(objectBounds)};

    Bounds<double> world = transformBounds(objectBounds, objectToWorld);
    bounds_ = toScalarOutward(world);
  }

  const Bounds<T>& bounds() const override { return bounds_; }

  void spans(const Ray<T>& worldRay, T tmin, T tmax, SpanList<T>& out) const override {
    walk(worldRay, tmin, tmax, [&](const SpanAt& at) {
      out.push_back({at.enterHit(*this), at.leaveHit(*this)});
      return false;
    });
  }

  // The three queries the defaults derive from spans(), with the same
  // results bit for bit: the same spans in the same order, but a normal (a
  // gradient, a matrix product and a square root) only for the crossing
  // returned, none for a shadow ray.
  bool firstHit(const Ray<T>& worldRay, T tmin, T tmax, Hit<T>& hit) const override {
    bool found = false;
    walk(worldRay, tmin, tmax, [&](const SpanAt& at) {
      // firstCrossing's test on this span (render/shapes/primitive.hpp).
      if (at.enterT > tmin && at.enterT < tmax) hit = at.enterHit(*this), found = true;
      else if (at.leaveT > tmin && at.leaveT < tmax) hit = at.leaveHit(*this), found = true;
      return found;
    });
    return found;
  }

  bool firstEnter(const Ray<T>& worldRay, T tmin, T tmax, Hit<T>& hit, bool& inside) const override {
    bool found = false;
    walk(worldRay, tmin, tmax, [&](const SpanAt& at) {
      // Primitive::firstEnter's test on the first span.
      if (at.enterT <= tmin) inside = true;
      else if (at.enterT < tmax) hit = at.enterHit(*this), found = true;
      return true;
    });
    return found;
  }

  bool anyHit(const Ray<T>& worldRay, T tmin, T tmax) const override {
    bool found = false;
    walk(worldRay, tmin, tmax, [&](const SpanAt& at) {
      found = (at.enterT > tmin && at.enterT < tmax) || (at.leaveT > tmin && at.leaveT < tmax);
      return found;
    });
    return found;
  }

 private:
  // A span as walk() finds it: its ends' t, and what their hits need.
  struct SpanAt {
    const Vec3<T>& base;
    const Vec3<T>& u;
    T enterS, leaveS, enterT, leaveT;  // an infinite s has no normal (hitAt)
    Hit<T> enterHit(const QuarticLeaf& leaf) const { return leaf.hitAt(base, u, enterS, enterT, T(-1)); }
    Hit<T> leaveHit(const QuarticLeaf& leaf) const { return leaf.hitAt(base, u, leaveS, leaveT, T(1)); }
  };

  // Calls visit(SpanAt) for each span spans() gives, in order, until visit
  // returns true.
  template <typename Visit>
  void walk(const Ray<T>& worldRay, T tmin, T tmax, Visit&& visit) const {
    T c0, c1;
    if (!bounds_.clip(worldRay, tmin, tmax, c0, c1)) return;
    // The ray in object space as base + u s, u unit, re-based near the pivot.
    ObjectRay<T> ray;
    if (!arithmetic_.toObject(worldRay, pivot_, ray)) return;
    const Vec3<T>& base = ray.base;
    const Vec3<T>& u = ray.u;
    const T len = ray.len, t0 = ray.t0;
    if constexpr (kIsIeee<T>)
      if (revolution_.on) {
        // The object box in the ray's own s, (tmin, tmax) included: spans
        // outside it would be dropped by emit() anyway.
        T s0, s1;
        if (!revolution_.reach.clip(Ray<T>{base, u}, (tmin - t0) * len, (tmax - t0) * len, s0, s1)) return;
      }

    // The substituted coefficients and every intermediate of substitute() are
    // bounded by sum |a_ijk| Mx^i My^j Mz^k, M = |base| + 1 per axis (|u| <= 1
    // per component). In an arithmetic of limited range (fixed point) results
    // beyond it would be saturated garbage, so the ray misses this leaf
    // instead (docs/fixed-point.md, "Where fixed point cannot follow").
    if constexpr (QuarticArithmetic<T>::kChecksRange)
      if (!withinRange(base)) return;

    T coeff[5];
    substitute(base, u, coeff);
    int degree = 4;
    while (degree >= 0 && coeff[degree] == T(0)) --degree;
    if (degree < 0) return;  // the ray lies in the surface: no volume crossed
    if (degree == 0) {
      if (coeff[0] < T(0)) {
        const T inf = std::numeric_limits<T>::infinity();
        visit(SpanAt{base, u, -inf, inf, -inf, inf});
      }
      return;
    }

    T roots[4];
    int n = solvePolynomial<T>(std::span<const T>(coeff, static_cast<std::size_t>(degree) + 1), roots);
    n = std::clamp(n, 0, 4);
    // The solver promises ascending order; an insertion sort of <= 4 keeps
    // the sign walk below correct even if a polish step reorders near-equal roots.
    for (int a = 1; a < n; ++a)
      for (int b = a; b > 0 && roots[b] < roots[b - 1]; --b) std::swap(roots[b], roots[b - 1]);

    // Sign at -inf and +inf from the leading term; between roots from the
    // polynomial at the midpoint.
    const std::span<const T> poly(coeff, static_cast<std::size_t>(degree) + 1);
    bool inside = (degree % 2 == 0) ? coeff[degree] < T(0) : coeff[degree] > T(0);
    T enterS = -std::numeric_limits<T>::infinity();
    for (int r = 0; r < n; ++r) {
      // Crossing roots[r]: inside before it is `inside`, after it `next`.
      bool next = (r + 1 < n) ? evaluatePolynomial<T>(poly, (roots[r] + roots[r + 1]) * T(0.5)) < T(0)
                              : coeff[degree] < T(0);
      if (!inside && next) enterS = roots[r];
      if (inside && !next && emit(base, u, t0, len, enterS, roots[r], tmin, tmax, visit)) return;
      inside = next;
    }
    if (inside) emit(base, u, t0, len, enterS, std::numeric_limits<T>::infinity(), tmin, tmax, visit);
  }

  // Converts a double box to T, rounding outwards so it still contains the
  // solid (and saturating to +-inf instead of an undefined out-of-range cast).
  static Bounds<T> toScalarOutward(const Bounds<double>& b) {
    Bounds<T> out;
    if (b.empty()) return out;
    const double big = static_cast<double>(std::numeric_limits<T>::max());
    const T inf = std::numeric_limits<T>::infinity();
    for (int ax = 0; ax < 3; ++ax) {
      T lo = b.lo[ax] < -big ? -inf : b.lo[ax] > big ? std::numeric_limits<T>::max() : static_cast<T>(b.lo[ax]);
      T hi = b.hi[ax] > big ? inf : b.hi[ax] < -big ? std::numeric_limits<T>::lowest() : static_cast<T>(b.hi[ax]);
      if (static_cast<double>(lo) > b.lo[ax]) lo = nextToward(lo, -inf);
      if (static_cast<double>(hi) < b.hi[ax]) hi = nextToward(hi, inf);
      out.lo[ax] = lo;
      out.hi[ax] = hi;
    }
    return out;
  }

  bool withinRange(const Vec3<T>& base) const {
    T px[5], py[5], pz[5];
    powers(absolute(base.x) + T(1), px);
    powers(absolute(base.y) + T(1), py);
    powers(absolute(base.z) + T(1), pz);
    // Half the range: sums of in-range terms must not saturate either.
    const T limit = T(1 << 30);
    T bound(0);
    for (const Term<T>& t : terms_) {
      bound += absolute(t.c) * px[t.i] * py[t.j] * pz[t.k];
      if (bound >= limit) return false;
    }
    return true;
  }

  static T nextToward(T x, T to) { return QuarticArithmetic<T>::nextToward(x, to); }

  // f(base + u s) as c[0] + c[1] s + ... + c[4] s^4: exact symbolic expansion.
  void substitute(const Vec3<T>& base, const Vec3<T>& u, T c[5]) const {
    if constexpr (kIsIeee<T>)
      if (revolution_.on) return closedForm(base, u, c);
    T px[5][5], py[5][5], pz[5][5];
    linearPowers(base.x, u.x, px);
    linearPowers(base.y, u.y, py);
    linearPowers(base.z, u.z, pz);
    for (int n = 0; n < 5; ++n) c[n] = T(0);
    T xs[5], yz[5], prod[5];
    for (const YZGroup<T>& g : groups_) {
      // P_jk(x(s)) = sum_i px_i * (x0 + ux s)^i
      for (T& v : xs) v = T(0);
      for (int i = 0; i <= g.degX; ++i)
        if (g.px[i] != T(0))
          for (int q = 0; q <= i; ++q) xs[q] += g.px[i] * px[i][q];
      multiply(py[g.j], g.j, pz[g.k], g.k, yz);
      multiply(xs, g.degX, yz, g.j + g.k, prod);
      for (int n = 0; n < 5; ++n) c[n] += prod[n];
    }
  }

  // f(base + u s) for the revolution form: with q(s) = |p|^2, rho(s) =
  // x^2 + y^2 and z(s)^2 each a quadratic in s, f = a q^2 + b rho + c z^2 + d.
  void closedForm(const Vec3<T>& base, const Vec3<T>& u, T c[5]) const {
    const Revolution& r = revolution_;
    const T rho2 = u.x * u.x + u.y * u.y, rho1 = base.x * u.x + base.y * u.y, rho0 = base.x * base.x + base.y * base.y;
    const T z2 = u.z * u.z, z1 = base.z * u.z, z0 = base.z * base.z;
    const T q2 = rho2 + z2, q1 = rho1 + z1, q0 = rho0 + z0;
    c[4] = r.a * q2 * q2;
    c[3] = T(4) * r.a * q2 * q1;
    c[2] = r.a * (T(4) * q1 * q1 + T(2) * q2 * q0) + r.b * rho2 + r.c * z2;
    c[1] = T(4) * r.a * q1 * q0 + T(2) * (r.b * rho1 + r.c * z1);
    c[0] = r.a * q0 * q0 + r.b * rho0 + r.c * z0 + r.d;
  }

  T sToT(T s, T len) const { return arithmetic_.sToT(s, len); }

  // The t of a crossing at s (s itself when it is not finite).
  T tAt(T t0, T len, T s) const { return finite(s) ? t0 + sToT(s, len) : s; }

  // The hit at s whose t is tAt(s). `facing` is -1 for an enter and +1 for a
  // leave: the side a normal must face when the gradient vanishes.
  Hit<T> hitAt(const Vec3<T>& base, const Vec3<T>& u, T s, T t, T facing) const {
    Hit<T> h;
    h.material = material_;
    h.t = t;
    if (!finite(s)) return h;
    Vec3<T> g = gradientTerms(terms_, base + u * s);
    Vec3<T> n = normalMatrix_ * g;
    T nl = lattice::length(n);
    if (nl > T(0) && finite(nl)) {
      h.normal = n / nl;
    } else {
      // A vanishing gradient (a cone's apex) has no normal: face the ray.
      Vec3<T> along = linear_ * u;
      h.normal = along * (facing / lattice::length(along));
    }
    return h;
  }

  // The span (s0, s1) to visit() when spans() keeps it; true when visit()
  // asks to stop.
  template <typename Visit>
  bool emit(const Vec3<T>& base, const Vec3<T>& u, T t0, T len, T s0, T s1, T tmin, T tmax, Visit& visit) const {
    if (!(s1 > s0)) return false;  // a tangent touch encloses no volume
    const T enterT = tAt(t0, len, s0), leaveT = tAt(t0, len, s1);
    if (!(leaveT > tmin && enterT < tmax)) return false;
    if (!(leaveT > enterT)) return false;
    return visit(SpanAt{base, u, s0, s1, enterT, leaveT});
  }

  std::vector<Term<T>> terms_;
  std::vector<YZGroup<T>> groups_;
  struct Revolution {
    bool on = false;
    T a, b, c, d;
    // The object box, widened by a millionth of its size against the
    // rounding of base: a ray whose line misses it crosses no part of the
    // solid, which the box holds, and is not solved.
    Bounds<T> reach;
  } revolution_;  // on: substitute by closedForm

  static Bounds<T> reachOf(const Bounds<double>& box) {
    Bounds<T> out = Bounds<T>::infinite();
    for (int ax = 0; ax < 3; ++ax) {
      const double margin = 1e-6 * (box.hi[ax] - box.lo[ax]);
      if (!std::isfinite(margin)) continue;
      out.lo[ax] = static_cast<T>(box.lo[ax] - margin);
      out.hi[ax] = static_cast<T>(box.hi[ax] + margin);
    }
    return out;
  }
  QuarticArithmetic<T> arithmetic_;  // world -> object for rays
  Mat3<T> normalMatrix_{};
  Mat3<T> linear_{};  // object -> world for directions
  Vec3<T> pivot_{};
  Bounds<T> bounds_;
  MaterialId material_;
};

}  // namespace

template <typename T>
PrimitivePtr<T> makeQuarticLeaf(const QuarticPolynomial& original, const Bounds<double>& originalBounds,
                                const Mat4d& originalToWorld, MaterialId material) {
  const QuarticPlacement leaf = QuarticArithmetic<T>::prepare({original, originalBounds, originalToWorld});
  const QuarticPolynomial& f = leaf.f;
  const Mat4d& objectToWorld = leaf.objectToWorld;
  // Values are converted to T once here; one that T cannot hold would be an
  // undefined conversion, so it is refused with the fix.
  const char* hint = QuarticArithmetic<T>::kRangeHint;
  const double big = static_cast<double>(std::numeric_limits<T>::max());
  for (double c : f.a)
    if (!std::isfinite(c) || std::abs(c) > big)
      throw Error(ErrorKind::Input,
                  fmt::format("quartic has a coefficient that is not finite or too large for the renderer's number "
                              "type: check the shape's size and scale{}",
                              hint));
  Mat4d inverse = glm::inverse(objectToWorld);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (std::abs(objectToWorld[c][r]) > big || !(std::abs(inverse[c][r]) <= big))
        throw Error(ErrorKind::Input,
                    fmt::format("quartic transform is singular, not finite, or too large for the renderer's number "
                                "type: check the scene's scales and translations{}",
                                hint));
  return std::make_unique<QuarticLeaf<T>>(f, leaf.bounds, objectToWorld, material);
}

#define LATTICE_INSTANTIATE(T)                                                                                  \
  template PrimitivePtr<T> makeQuarticLeaf<T>(const QuarticPolynomial&, const Bounds<double>&, const Mat4d&, \
                                              MaterialId);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_INSTANTIATE)
#undef LATTICE_INSTANTIATE

}  // namespace lattice
