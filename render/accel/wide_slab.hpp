#pragma once
// The slab test of one ray against four boxes at once, in float, rounded so
// that it can only widen each box's interval: a box the exact test reaches is
// never culled (render/accel/wide_bvh.hpp relies on it to lose no hit of the
// double-precision traversal it replaced).
//
// Method and tunables:
//  * Boxes are stored in float rounded outwards (lo down, hi up: floatBelow,
//    floatAbove). The ray's origin is rounded per axis and per plane the way
//    that can only move that plane's t outwards: for the near plane the
//    origin is rounded towards the box's far side, for the far plane the
//    other way. Near and far planes are chosen once per ray by the sign of
//    the reciprocal direction (signbit, so a direction of -0 takes the side
//    its -inf reciprocal needs).
//  * What is left is the rounding of (plane - origin) * inverse: the
//    subtraction, the reciprocal (double division, then float) and the
//    product, four roundings of relative size u = 2^-24 at most, so each
//    computed t is the exact one times (1 + theta), |theta| <= gamma(4) =
//    4u / (1 - 4u) (Higham, Accuracy and Stability of Numerical Algorithms,
//    2nd ed., lemma 3.1). pbrt-v4 bounds its float box test the same way and
//    scales tFar by 1 + 2 gamma(3) (src/pbrt/util/vecmath.h,
//    Bounds3::IntersectP). Here rays may start anywhere and t may be
//    negative, so both ends are widened by their magnitude: entry - k|entry|
//    - m and exit + k|exit| + m, with k = kRelativeMargin = 2 gamma(4) (one
//    gamma for the product, one to cover the rounding of the widening
//    itself) and m = kAbsoluteMargin = FLT_MIN for products that underflow.
//    |t| is capped at FLT_MAX in the widening so that an infinite t (a zero
//    direction component with the origin outside that slab) stays infinite
//    instead of turning into inf - inf = NaN, which would keep the box.
//  * A direction component below 2^-126 in magnitude has a reciprocal
//    beyond float range and acts as a zero one: a box is then culled only
//    where its exact entry lies beyond (gap to the slab) * 2^126.
//  * The segment ends are rounded outwards too (tmin down, limit up).
//  * NaN (0 * inf: an origin exactly on the plane of a zero direction
//    component, or inf - inf after an overflow) never culls: the max/min
//    keep the running bound and the final test is !(entry > exit).
//  * The entry returned per box is a lower bound of the exact entry (at least
//    tmin), so a caller may skip a box whose entry is at or beyond its best
//    hit so far.
// The SSE path (x86-64, behind __SSE2__), the 8-lane AVX path
// (render/accel/wide_slab8.hpp) and the scalar path (the Cortex-M3 firmware)
// do the same float operations in the same order, lane by lane, so they cull
// the same boxes; tests/render/wide_bvh_test.cpp and wide_bvh8_test.cpp check that.
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "foundation/ray.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace lattice {

namespace wide_slab_detail {
// The next float below a finite or +inf f (the callers never pass -inf).
inline float nextDown(float f) {
  if (f == 0.0f) return -std::numeric_limits<float>::denorm_min();
  std::uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  bits = f > 0.0f ? bits - 1 : bits + 1;
  std::memcpy(&f, &bits, sizeof bits);
  return f;
}
inline float nextUp(float f) { return -nextDown(-f); }
}  // namespace wide_slab_detail

// The largest float <= v, and the smallest float >= v (NaN stays NaN).
// A double beyond float range converts to +-inf (IEEE 754 overflow), and
// the step back gives +-FLT_MAX where that is the bound asked for.
inline float floatBelow(double v) {
  const float f = static_cast<float>(v);
  return double(f) > v ? wide_slab_detail::nextDown(f) : f;
}
inline float floatAbove(double v) {
  const float f = static_cast<float>(v);
  return double(f) < v ? wide_slab_detail::nextUp(f) : f;
}
inline float floatBelow(float v) { return v; }
inline float floatAbove(float v) { return v; }

// 2 gamma(4), u = 2^-24; and the smallest normal float.
inline constexpr float kRelativeMargin = float(2.0 * (4.0 / 16777216.0) / (1.0 - 4.0 / 16777216.0));
inline constexpr float kAbsoluteMargin = FLT_MIN;

// Four boxes, one lane each: box[0] the lo corners, box[1] the hi corners,
// [axis][lane]. Aligned for the SSE loads.
struct alignas(16) BoxLanes {
  float box[2][3][4];
};

// A ray set up once for many box tests.
struct WideRay {
  float originNear[3], originFar[3], inverse[3];
  int nearSide[3];  // 0: the near plane is lo (direction >= +0); 1: hi

  WideRay() = default;  // filled by wideRayAvx2 (render/accel/wide_slab8.hpp)
  template <typename T>
  [[gnu::always_inline]] explicit WideRay(const Ray<T>& ray) {
    for (int a = 0; a < 3; ++a) {
      const double d = double(ray.direction[a]);
      inverse[a] = static_cast<float>(1.0 / d);
      nearSide[a] = std::signbit(inverse[a]) ? 1 : 0;
      const float down = floatBelow(ray.origin[a]), up = floatAbove(ray.origin[a]);
      // lo - origin must not grow and hi - origin must not shrink.
      originNear[a] = nearSide[a] == 0 ? up : down;
      originFar[a] = nearSide[a] == 0 ? down : up;
    }
  }
};

// Lane by lane, as the SSE and AVX paths do: bit n of the result set when box
// n of W may meet the segment, entry[n] a lower bound of where it does.
template <int W>
inline unsigned slabTestScalar(const float (&box)[2][3][W], const WideRay& r, float tmin, float limit,
                               float entry[W]) {
  unsigned mask = 0;
  for (int lane = 0; lane < W; ++lane) {
    float c = tmin, e = limit;
    for (int a = 0; a < 3; ++a) {
      const float tn = (box[r.nearSide[a]][a][lane] - r.originNear[a]) * r.inverse[a];
      const float tf = (box[1 - r.nearSide[a]][a][lane] - r.originFar[a]) * r.inverse[a];
      c = tn > c ? tn : c;  // NaN keeps the running bound
      e = tf < e ? tf : e;
    }
    const float ac = std::fabs(c), ae = std::fabs(e);
    const float lo = c - (kRelativeMargin * (ac < FLT_MAX ? ac : FLT_MAX) + kAbsoluteMargin);
    const float hi = e + (kRelativeMargin * (ae < FLT_MAX ? ae : FLT_MAX) + kAbsoluteMargin);
    if (!(lo > hi)) mask |= 1u << lane;
    entry[lane] = lo > tmin ? lo : tmin;
  }
  return mask;
}
inline unsigned slabTest4Scalar(const BoxLanes& b, const WideRay& r, float tmin, float limit, float entry[4]) {
  return slabTestScalar<4>(b.box, r, tmin, limit, entry);
}

#if defined(__SSE2__)
// Always inlined (as slabTest4 and WideRay's constructor): in the walks that
// also call a leaf cull, GCC otherwise made them calls of their own.
[[gnu::always_inline]] inline unsigned slabTest4Sse(const BoxLanes& b, const WideRay& r, float tmin, float limit,
                                                    float entry[4]) {
  const __m128 sign = _mm_set1_ps(-0.0f), k = _mm_set1_ps(kRelativeMargin), m = _mm_set1_ps(kAbsoluteMargin),
               big = _mm_set1_ps(FLT_MAX);
  const __m128 tmin4 = _mm_set1_ps(tmin);
  __m128 c = tmin4, e = _mm_set1_ps(limit);
  for (int a = 0; a < 3; ++a) {
    const __m128 inv = _mm_set1_ps(r.inverse[a]);
    const __m128 tn = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(b.box[r.nearSide[a]][a]), _mm_set1_ps(r.originNear[a])), inv);
    const __m128 tf =
        _mm_mul_ps(_mm_sub_ps(_mm_load_ps(b.box[1 - r.nearSide[a]][a]), _mm_set1_ps(r.originFar[a])), inv);
    c = _mm_max_ps(tn, c);  // maxps returns its second operand when either is NaN
    e = _mm_min_ps(tf, e);
  }
  const __m128 lo = _mm_sub_ps(c, _mm_add_ps(_mm_mul_ps(k, _mm_min_ps(_mm_andnot_ps(sign, c), big)), m));
  const __m128 hi = _mm_add_ps(e, _mm_add_ps(_mm_mul_ps(k, _mm_min_ps(_mm_andnot_ps(sign, e), big)), m));
  _mm_storeu_ps(entry, _mm_max_ps(lo, tmin4));
  return static_cast<unsigned>(_mm_movemask_ps(_mm_cmpngt_ps(lo, hi)));
}
#endif

[[gnu::always_inline]] inline unsigned slabTest4(const BoxLanes& b, const WideRay& r, float tmin, float limit,
                                                 float entry[4]) {
#if defined(__SSE2__)
  return slabTest4Sse(b, r, tmin, limit, entry);
#else
  return slabTest4Scalar(b, r, tmin, limit, entry);
#endif
}

// The walks of render/accel/wide_bvh.hpp name the ray's set-up and the test
// by the lanes' type.
template <typename T>
[[gnu::always_inline]] inline WideRay wideRayFor(const BoxLanes&, const Ray<T>& ray) {
  return WideRay(ray);
}
[[gnu::always_inline]] inline unsigned slabTestLanes(const BoxLanes& b, const WideRay& r, float tmin, float limit,
                                                     float entry[4]) {
  return slabTest4(b, r, tmin, limit, entry);
}

}  // namespace lattice
