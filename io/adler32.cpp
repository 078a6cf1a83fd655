// Adler-32 by blocks (method and reasons in adler32.hpp).
#include "io/adler32.hpp"

#include <zlib.h>

#include <atomic>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace lattice::io {
namespace {

constexpr std::uint32_t kAdlerModulus = 65521;  // the largest prime below 2^16 (RFC 1950)
// 173 blocks of 32: zlib's NMAX (5552) rounded down to whole blocks, the most
// bytes whose sums cannot pass 2^32 from a reduced start.
constexpr std::size_t kAdlerChunkBytes = 5536;

std::atomic<AdlerPath> forcedAdler{AdlerPath::Auto};

#if defined(__x86_64__)
bool cpuHasAvx2ForAdler() {
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
}

__attribute__((target("avx2"))) std::uint32_t sumLanes(__m256i v) {
  const __m128i s = _mm_add_epi32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
  const __m128i t = _mm_add_epi32(s, _mm_shuffle_epi32(s, 0x4e));  // lanes 2,3 onto 0,1
  return static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_add_epi32(t, _mm_shuffle_epi32(t, 0xb1))));
}

__attribute__((target("avx2"))) std::uint32_t adler32Avx2(std::uint32_t adler, const std::uint8_t* p,
                                                          std::size_t size) {
  std::uint64_t a = adler & 0xffff, b = adler >> 16;
  const __m256i weights = _mm256_setr_epi8(32, 31, 30, 29, 28, 27, 26, 25, 24, 23, 22, 21, 20, 19, 18, 17, 16, 15,
                                           14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1);
  const __m256i ones = _mm256_set1_epi16(1), zero = _mm256_setzero_si256();
  while (size >= 32) {
    const std::size_t blocks = std::min(size, kAdlerChunkBytes) / 32;
    __m256i plain = zero, before = zero, weighted = zero;
    for (std::size_t k = 0; k < blocks; ++k, p += 32) {
      const __m256i x = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
      before = _mm256_add_epi32(before, plain);  // every earlier block's bytes, once per block after it
      plain = _mm256_add_epi32(plain, _mm256_sad_epu8(x, zero));
      weighted = _mm256_add_epi32(weighted, _mm256_madd_epi16(_mm256_maddubs_epi16(x, weights), ones));
    }
    const std::uint64_t n = blocks * 32;
    b = (b + n * a + 32 * std::uint64_t(sumLanes(before)) + sumLanes(weighted)) % kAdlerModulus;
    a = (a + sumLanes(plain)) % kAdlerModulus;
    size -= n;
  }
  for (; size > 0; --size) {  // the last 31 bytes or fewer, one at a time
    a += *p++;
    b += a;
  }
  return static_cast<std::uint32_t>((b % kAdlerModulus) << 16 | (a % kAdlerModulus));
}
#endif

}  // namespace

void forceAdlerPath(AdlerPath path) { forcedAdler.store(path); }

std::uint32_t adler32Update(std::uint32_t adler, const std::uint8_t* data, std::size_t size) {
#if defined(__x86_64__)
  if (forcedAdler.load(std::memory_order_relaxed) == AdlerPath::Auto && cpuHasAvx2ForAdler())
    return adler32Avx2(adler, data, size);
#endif
  return static_cast<std::uint32_t>(adler32_z(adler, data, size));
}

}  // namespace lattice::io
