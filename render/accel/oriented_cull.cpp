// The oriented-box cull of a BVH leaf's items (method and why:
// render/accel/oriented_cull.hpp): the scalar reference, the lanes (AVX2 for
// double, SSE2 for float), and the choice between them.
#include "render/accel/oriented_cull.hpp"

#include <atomic>
#include <limits>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace lattice {

namespace {

std::atomic<CullPath> forcedPath{CullPath::Auto};

bool cpuHasAvx2() {
#if defined(__x86_64__)
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
#else
  return false;
#endif
}

#if defined(__x86_64__)
// Four positions from `first`: the scalar reference's operations lane by lane
// (no fused multiply-add: "fma" is not among the targets).
__attribute__((target("avx2"))) unsigned keep4Avx2(const double* data, std::size_t stride, std::uint32_t first,
                                                    const Ray<double>& ray, double tmin, double tmax,
                                                    LaneChords<double>* chords) {
  const double* base = data + first;
#define LATTICE_ROW(r) _mm256_loadu_pd(base + std::size_t(r) * stride)  // a lambda would need the target too
  const __m256d ox = _mm256_set1_pd(ray.origin.x), oy = _mm256_set1_pd(ray.origin.y),
                oz = _mm256_set1_pd(ray.origin.z);
  const __m256d dx = _mm256_set1_pd(ray.direction.x), dy = _mm256_set1_pd(ray.direction.y),
                dz = _mm256_set1_pd(ray.direction.z);
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
  __m256d t0 = _mm256_set1_pd(-std::numeric_limits<double>::infinity());
  __m256d t1 = _mm256_set1_pd(std::numeric_limits<double>::infinity());
  __m256d reject = zero;
  for (int a = 0; a < 3; ++a) {
    const __m256d c0 = LATTICE_ROW(a), c1 = LATTICE_ROW(3 + a), c2 = LATTICE_ROW(6 + a), c3 = LATTICE_ROW(9 + a),
                  extent = LATTICE_ROW(12 + a);
    const __m256d o = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(c0, ox), _mm256_mul_pd(c1, oy)),
                                    _mm256_add_pd(_mm256_mul_pd(c2, oz), c3));
    const __m256d d = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(c0, dx), _mm256_mul_pd(c1, dy)), _mm256_mul_pd(c2, dz));
    if (chords) {
      _mm256_storeu_pd(chords->origin[a], o);
      _mm256_storeu_pd(chords->direction[a], d);
    }
    const __m256d flat = _mm256_cmp_pd(d, zero, _CMP_EQ_OQ);
    const __m256d outside = _mm256_or_pd(_mm256_cmp_pd(o, zero, _CMP_LT_OQ), _mm256_cmp_pd(o, extent, _CMP_GT_OQ));
    reject = _mm256_or_pd(reject, _mm256_and_pd(flat, outside));
    const __m256d inv = _mm256_div_pd(one, d);
    const __m256d toLow = _mm256_mul_pd(_mm256_sub_pd(zero, o), inv);
    const __m256d toHigh = _mm256_mul_pd(_mm256_sub_pd(extent, o), inv);
    const __m256d swap = _mm256_cmp_pd(toLow, toHigh, _CMP_GT_OQ);
    const __m256d ta = _mm256_blendv_pd(toLow, toHigh, swap), tb = _mm256_blendv_pd(toHigh, toLow, swap);
    // A flat axis leaves the interval as it is (the scalar clip skips it).
    t0 = _mm256_blendv_pd(t0, ta, _mm256_andnot_pd(flat, _mm256_cmp_pd(ta, t0, _CMP_GT_OQ)));
    t1 = _mm256_blendv_pd(t1, tb, _mm256_andnot_pd(flat, _mm256_cmp_pd(tb, t1, _CMP_LT_OQ)));
  }
#undef LATTICE_ROW
  // The leaf's chord test: t1 > t0, not ending by tmin, not starting at tmax.
  const __m256d chord = _mm256_cmp_pd(t1, t0, _CMP_GT_OQ);
  const __m256d before = _mm256_cmp_pd(t1, _mm256_set1_pd(tmin), _CMP_LE_OQ);
  const __m256d after = _mm256_cmp_pd(t0, _mm256_set1_pd(tmax), _CMP_GE_OQ);
  const __m256d dropped = _mm256_or_pd(_mm256_or_pd(reject, before), after);
  if (chords) {
    _mm256_storeu_pd(chords->t0, t0);
    _mm256_storeu_pd(chords->t1, t1);
  }
  return static_cast<unsigned>(_mm256_movemask_pd(_mm256_andnot_pd(dropped, chord)));
}

// The same four lanes in float, SSE2 (every x86-64 has it): blends as and/or.
unsigned keep4Sse(const float* data, std::size_t stride, std::uint32_t first, const Ray<float>& ray, float tmin,
                  float tmax, LaneChords<float>* chords) {
  const float* base = data + first;
  const auto row = [&](int r) { return _mm_loadu_ps(base + std::size_t(r) * stride); };
  const auto pick = [](__m128 mask, __m128 a, __m128 b) { return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b)); };
  const __m128 ox = _mm_set1_ps(ray.origin.x), oy = _mm_set1_ps(ray.origin.y), oz = _mm_set1_ps(ray.origin.z);
  const __m128 dx = _mm_set1_ps(ray.direction.x), dy = _mm_set1_ps(ray.direction.y), dz = _mm_set1_ps(ray.direction.z);
  const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
  __m128 t0 = _mm_set1_ps(-std::numeric_limits<float>::infinity());
  __m128 t1 = _mm_set1_ps(std::numeric_limits<float>::infinity());
  __m128 reject = zero;
  for (int a = 0; a < 3; ++a) {
    const __m128 c0 = row(a), c1 = row(3 + a), c2 = row(6 + a), c3 = row(9 + a), extent = row(12 + a);
    const __m128 o = _mm_add_ps(_mm_add_ps(_mm_mul_ps(c0, ox), _mm_mul_ps(c1, oy)), _mm_add_ps(_mm_mul_ps(c2, oz), c3));
    const __m128 d = _mm_add_ps(_mm_add_ps(_mm_mul_ps(c0, dx), _mm_mul_ps(c1, dy)), _mm_mul_ps(c2, dz));
    if (chords) {
      _mm_storeu_ps(chords->origin[a], o);
      _mm_storeu_ps(chords->direction[a], d);
    }
    const __m128 flat = _mm_cmpeq_ps(d, zero);
    const __m128 outside = _mm_or_ps(_mm_cmplt_ps(o, zero), _mm_cmpgt_ps(o, extent));
    reject = _mm_or_ps(reject, _mm_and_ps(flat, outside));
    const __m128 inv = _mm_div_ps(one, d);
    const __m128 toLow = _mm_mul_ps(_mm_sub_ps(zero, o), inv);
    const __m128 toHigh = _mm_mul_ps(_mm_sub_ps(extent, o), inv);
    const __m128 swap = _mm_cmpgt_ps(toLow, toHigh);
    const __m128 ta = pick(swap, toHigh, toLow), tb = pick(swap, toLow, toHigh);
    t0 = pick(_mm_andnot_ps(flat, _mm_cmpgt_ps(ta, t0)), ta, t0);
    t1 = pick(_mm_andnot_ps(flat, _mm_cmplt_ps(tb, t1)), tb, t1);
  }
  const __m128 chord = _mm_cmpgt_ps(t1, t0);
  const __m128 before = _mm_cmple_ps(t1, _mm_set1_ps(tmin));
  const __m128 after = _mm_cmpge_ps(t0, _mm_set1_ps(tmax));
  const __m128 dropped = _mm_or_ps(_mm_or_ps(reject, before), after);
  if (chords) {
    _mm_storeu_ps(chords->t0, t0);
    _mm_storeu_ps(chords->t1, t1);
  }
  return static_cast<unsigned>(_mm_movemask_ps(_mm_andnot_ps(dropped, chord)));
}
#endif

}  // namespace

void setCullPath(CullPath path) { forcedPath.store(path, std::memory_order_relaxed); }

bool doubleLanesRun() { return cpuHasAvx2(); }

CullPath activeCullPath() {
  const CullPath forced = forcedPath.load(std::memory_order_relaxed);
  if (forced == CullPath::Portable || forced == CullPath::None) return forced;
#if defined(__x86_64__)
  return CullPath::Lanes;
#else
  return CullPath::None;
#endif
}

template <typename T>
OrientedCull<T>::OrientedCull(std::uint32_t positions, const BoxAt& boxAt)
    : positions_(positions), stride_(std::size_t(positions) + 4),
      data_(std::size_t(kRows) * (std::size_t(positions) + 4), T(0)), has_(std::size_t(positions) + 4, 0),
      path_(activeCullPath()) {
  OrientedBox<T> box;
  for (std::uint32_t p = 0; p < positions; ++p) {
    if (!boxAt(p, box)) continue;
    has_[p] = 1;
    for (int c = 0; c < 4; ++c)
      for (int a = 0; a < 3; ++a) data_[std::size_t(3 * c + a) * stride_ + p] = box.column[c][a];
    for (int a = 0; a < 3; ++a) data_[std::size_t(12 + a) * stride_ + p] = box.extent[a];
  }
}

template <typename T>
OrientedCull<T>::OrientedCull(const std::vector<OrientedBox<T>>& boxes, const std::vector<bool>& has)
    : OrientedCull(static_cast<std::uint32_t>(boxes.size()), [&](std::uint32_t p, OrientedBox<T>& box) {
        box = boxes[p];
        return bool(has[p]);
      }) {}

template <typename T>
bool OrientedCull<T>::keepOne(std::uint32_t p, const Ray<T>& ray, T tmin, T tmax, LocalChord<T>* chord) const {
  if (!has_[p]) return true;
  T o[3], d[3];
  for (int a = 0; a < 3; ++a) {
    const T c0 = row(a)[p], c1 = row(3 + a)[p], c2 = row(6 + a)[p], c3 = row(9 + a)[p];
    o[a] = (c0 * ray.origin.x + c1 * ray.origin.y) + (c2 * ray.origin.z + c3);
    d[a] = (c0 * ray.direction.x + c1 * ray.direction.y) + c2 * ray.direction.z;
  }
  T t0 = -std::numeric_limits<T>::infinity(), t1 = std::numeric_limits<T>::infinity();
  for (int a = 0; a < 3; ++a) {
    const T extent = row(12 + a)[p];
    if (d[a] == T(0)) {
      if (o[a] < T(0) || o[a] > extent) return false;
      continue;
    }
    const T inv = T(1) / d[a];
    const T toLow = (T(0) - o[a]) * inv, toHigh = (extent - o[a]) * inv;
    const bool swap = toLow > toHigh;
    const T ta = swap ? toHigh : toLow, tb = swap ? toLow : toHigh;
    t0 = ta > t0 ? ta : t0;
    t1 = tb < t1 ? tb : t1;
    if (t0 > t1) return false;
  }
  if (!(t1 > t0)) return false;
  if (t1 <= tmin || t0 >= tmax) return false;
  if (chord) *chord = {{{o[0], o[1], o[2]}, {d[0], d[1], d[2]}}, t0, t1};
  return true;
}

template <typename T>
unsigned OrientedCull<T>::keepEach(std::uint32_t first, std::uint32_t count, const Ray<T>& ray, T tmin, T tmax,
                                   LaneChords<T>* chords) const {
  unsigned mask = 0;
  LocalChord<T> chord;
  for (std::uint32_t k = 0; k < count; ++k) {
    if (!keepOne(first + k, ray, tmin, tmax, &chord)) continue;
    mask |= 1u << k;
    if (!chords || !has_[first + k]) continue;
    for (int a = 0; a < 3; ++a) {
      chords->origin[a][k] = chord.local.origin[a];
      chords->direction[a][k] = chord.local.direction[a];
    }
    chords->t0[k] = chord.t0;
    chords->t1[k] = chord.t1;
    chords->written |= 1u << k;
  }
  return mask;
}

template <typename T>
unsigned OrientedCull<T>::keepLanes(std::uint32_t first, std::uint32_t count, const Ray<T>& ray, T tmin, T tmax,
                                    LaneChords<T>* chords) const {
  const unsigned all = (1u << count) - 1u;
#if defined(__x86_64__)
  unsigned boxless = 0;  // positions without a box are always kept
  for (std::uint32_t k = 0; k < count; ++k)
    if (!has_[first + k]) boxless |= 1u << k;
  unsigned kept = all;
  if constexpr (std::is_same_v<T, double>) {
    if (!cpuHasAvx2()) return all;
    kept = (keep4Avx2(data_.data(), stride_, first, ray, tmin, tmax, chords) | boxless) & all;
  } else {
    kept = (keep4Sse(data_.data(), stride_, first, ray, tmin, tmax, chords) | boxless) & all;
  }
  if (chords) chords->written = kept & ~boxless;
  return kept;
#endif
  (void)first, (void)ray, (void)tmin, (void)tmax, (void)chords;
  return all;
}

template class OrientedCull<float>;
template class OrientedCull<double>;

}  // namespace lattice
