#pragma once
// Adler-32 (RFC 1950, section 8.2), the check the PNG encoder's zlib
// wrapper ends with.
//
// Method: a = 1 + the sum of the bytes, b = the sum of a after each byte,
// both modulo 65521. Over a block of n bytes x_0..x_{n-1} that is
// a' = a + sum x_p and b' = b + n a + sum (n - p) x_p, so a block's sums
// can be taken with no dependence from byte to byte: where the CPU has
// AVX2 (__builtin_cpu_supports, once), 32 bytes at a time, their plain sum
// by _mm256_sad_epu8 and their weighted sum by _mm256_maddubs_epi16 with
// the weights 32..1; the blocks before each one add 32 times their plain
// sum. The sums are reduced modulo 65521 every kAdlerChunkBytes, before a
// 32-bit lane can overflow. Elsewhere it is zlib's adler32_z.
//
// Why: zlib's own Adler-32 takes a byte at a time; at 2048 x 2048 the
// check of 12.6 MB of filtered rows cost more CPU than anything in the
// process besides the trace and deflate (bench/results/2026-12-05-lead.md).
#include <cstddef>
#include <cstdint>

namespace lattice::io {

// `adler` carried on over `size` more bytes; start from 1 (what zlib's
// adler32(0, nullptr, 0) returns). Equal to zlib's adler32_z on every input.
std::uint32_t adler32Update(std::uint32_t adler, const std::uint8_t* data, std::size_t size);

// Which way adler32Update takes: for tests that run both.
enum class AdlerPath : std::uint8_t { Auto, Portable };
void forceAdlerPath(AdlerPath path);

}  // namespace lattice::io
