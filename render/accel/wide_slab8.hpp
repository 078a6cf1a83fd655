#pragma once
// The slab test of one ray against eight boxes at once: the four-box test of
// render/accel/wide_slab.hpp (its rounding argument, its NaN rules, its
// margins) in one 256-bit AVX pass, for the 8-wide nodes of
// render/accel/wide_bvh.hpp on CPUs with AVX2.
//
// Method: the same float operations in the same order as slabTestScalar<8>,
// lane by lane (sub, mul, max, min; no fused multiply-add, as "fma" is not
// among the targets), so a box is culled by the AVX pass exactly when the
// scalar reference culls it; tests/render/wide_bvh8_test.cpp checks it bit for
// bit. The function carries target("avx2") so the rest of the binary stays
// runnable on any x86-64; the walks that call it carry the same target and
// are chosen at run time (__builtin_cpu_supports).
#include "render/accel/wide_slab.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#define LATTICE_WIDE8 1  // the 8-wide nodes exist only where AVX2 may run
#else
#define LATTICE_WIDE8 0
#endif

namespace lattice {

// Eight boxes, one lane each: box[0] the lo corners, box[1] the hi corners,
// [axis][lane]. Aligned for the 256-bit loads.
struct alignas(32) BoxLanes8 {
  float box[2][3][8];
};

#if defined(__x86_64__)
__attribute__((target("avx2"), always_inline)) inline unsigned slabTest8Avx2(const BoxLanes8& b, const WideRay& r, float tmin,
                                                               float limit, float entry[8]) {
  const __m256 sign = _mm256_set1_ps(-0.0f), k = _mm256_set1_ps(kRelativeMargin), m = _mm256_set1_ps(kAbsoluteMargin),
               big = _mm256_set1_ps(FLT_MAX);
  const __m256 tmin8 = _mm256_set1_ps(tmin);
  __m256 c = tmin8, e = _mm256_set1_ps(limit);
  for (int a = 0; a < 3; ++a) {
    const __m256 inv = _mm256_set1_ps(r.inverse[a]);
    const __m256 tn =
        _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b.box[r.nearSide[a]][a]), _mm256_set1_ps(r.originNear[a])), inv);
    const __m256 tf =
        _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b.box[1 - r.nearSide[a]][a]), _mm256_set1_ps(r.originFar[a])), inv);
    c = _mm256_max_ps(tn, c);  // as maxps: the second operand when either is NaN
    e = _mm256_min_ps(tf, e);
  }
  const __m256 lo =
      _mm256_sub_ps(c, _mm256_add_ps(_mm256_mul_ps(k, _mm256_min_ps(_mm256_andnot_ps(sign, c), big)), m));
  const __m256 hi =
      _mm256_add_ps(e, _mm256_add_ps(_mm256_mul_ps(k, _mm256_min_ps(_mm256_andnot_ps(sign, e), big)), m));
  _mm256_storeu_ps(entry, _mm256_max_ps(lo, tmin8));
  return static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(lo, hi, _CMP_NGT_UQ)));
}
// The walks of render/accel/wide_bvh.hpp name the test by the lanes' type.
// Not always_inline: GCC refuses that where a caller lacks the target (the
// walk's own body), and inlines it once the walk sits in its AVX2 caller.
__attribute__((target("avx2"))) inline unsigned slabTestLanes(const BoxLanes8& b, const WideRay& r, float tmin,
                                                               float limit, float entry[8]) {
  return slabTest8Avx2(b, r, tmin, limit, entry);
}
#endif

}  // namespace lattice
