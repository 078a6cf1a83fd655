#pragma once
// The slab test of one ray against eight boxes at once: the four-box test of
// render/accel/wide_slab.hpp (its rounding argument, its NaN rules, its
// margins) in one 256-bit AVX pass, for the 8-wide nodes of
// render/accel/wide_bvh.hpp on CPUs with AVX2; and the ray's set-up for it
// (WideRay) with the three axes in lanes.
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
// WideRay's constructor for the three axes at once: the same double division,
// the same conversions to float (round to nearest) and the same one-step
// outward rounding of the origin (floatBelow, floatAbove), so every field is
// bit for bit the scalar constructor's (tests/render/wide_bvh8_test.cpp). Each
// walk sets a ray up once per union, and the scalar form's twelve compares
// and conversions were a tenth of the walk where a union holds a few children.
template <typename T>
__attribute__((target("avx2"), always_inline)) inline WideRay wideRayAvx2(const Ray<T>& ray) {
  const __m256d o = _mm256_set_pd(0.0, double(ray.origin.z), double(ray.origin.y), double(ray.origin.x));
  const __m256d d = _mm256_set_pd(1.0, double(ray.direction.z), double(ray.direction.y), double(ray.direction.x));
  const __m128 inverse = _mm256_cvtpd_ps(_mm256_div_pd(_mm256_set1_pd(1.0), d));
  const __m128 f = _mm256_cvtpd_ps(o);
  const __m256d back = _mm256_cvtps_pd(f);
  // The doubles' compare masks, packed to one 32-bit lane each (no lambda:
  // it would not carry the target).
  const __m256i pack = _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7);
  const __m128i over = _mm256_castsi256_si128(  // f above the origin: step down
      _mm256_permutevar8x32_epi32(_mm256_castpd_si256(_mm256_cmp_pd(back, o, _CMP_GT_OQ)), pack));
  const __m128i under = _mm256_castsi256_si128(  // f below it: step up
      _mm256_permutevar8x32_epi32(_mm256_castpd_si256(_mm256_cmp_pd(back, o, _CMP_LT_OQ)), pack));
  const __m128i bits = _mm_castps_si128(f), one = _mm_set1_epi32(1);
  const __m128i positive = _mm_castps_si128(_mm_cmpgt_ps(f, _mm_setzero_ps()));
  const __m128i zero = _mm_castps_si128(_mm_cmpeq_ps(f, _mm_setzero_ps()));
  // One float step towards -inf (nextDown) and towards +inf (nextUp), as
  // wide_slab_detail's: from zero to -/+ the smallest subnormal.
  const __m128i stepDown = _mm_blendv_epi8(_mm_blendv_epi8(_mm_add_epi32(bits, one), _mm_sub_epi32(bits, one), positive),
                                           _mm_set1_epi32(std::int32_t(0x80000001u)), zero);
  const __m128i stepUp = _mm_blendv_epi8(_mm_blendv_epi8(_mm_sub_epi32(bits, one), _mm_add_epi32(bits, one), positive),
                                         one, zero);
  const __m128i down = _mm_blendv_epi8(bits, stepDown, over), up = _mm_blendv_epi8(bits, stepUp, under);
  const __m128i far = _mm_srai_epi32(_mm_castps_si128(inverse), 31);  // sign set: the near plane is hi
  alignas(16) float inv[4], near[4], farOrigin[4];
  _mm_store_ps(inv, inverse);
  _mm_store_ps(near, _mm_castsi128_ps(_mm_blendv_epi8(up, down, far)));
  _mm_store_ps(farOrigin, _mm_castsi128_ps(_mm_blendv_epi8(down, up, far)));
  const int signs = _mm_movemask_ps(inverse);
  WideRay r;
  for (int a = 0; a < 3; ++a) {
    r.inverse[a] = inv[a];
    r.originNear[a] = near[a];
    r.originFar[a] = farOrigin[a];
    r.nearSide[a] = signs >> a & 1;
  }
  return r;
}

// The walks of render/accel/wide_bvh.hpp name the ray's set-up and the test
// by the lanes' type.
template <typename T>
__attribute__((target("avx2"))) inline WideRay wideRayFor(const BoxLanes8&, const Ray<T>& ray) {
  return wideRayAvx2(ray);
}
// Not always_inline: GCC refuses that where a caller lacks the target (the
// walk's own body), and inlines it once the walk sits in its AVX2 caller.
__attribute__((target("avx2"))) inline unsigned slabTestLanes(const BoxLanes8& b, const WideRay& r, float tmin,
                                                               float limit, float entry[8]) {
  return slabTest8Avx2(b, r, tmin, limit, entry);
}
#endif

}  // namespace lattice
