#pragma once
// FNV-1a, 64 bit (Fowler, Noll, Vo): the hash that ties a .lht file to its
// object (the object's canonical text) and the file's checksum.
//
// Method: xor each byte into the state, then multiply by the FNV prime; the
// seed is the offset basis, or a previous result to hash on from there.
// Tunables: none (the offset basis and prime are FNV's 64-bit constants).
#include <cstdint>
#include <span>
#include <string_view>

namespace lattice {

inline std::uint64_t fnv1a64(std::span<const std::uint8_t> bytes, std::uint64_t seed = 0xcbf29ce484222325ull) {
  std::uint64_t h = seed;
  for (std::uint8_t b : bytes) {
    h ^= b;
    h *= 0x100000001b3ull;
  }
  return h;
}

inline std::uint64_t fnv1a64(std::string_view text) {
  return fnv1a64(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

}  // namespace lattice
