#pragma once
// Little-endian integers in byte buffers: the byte order of every file and
// stream field Lattice writes (.lht files, baked scenes), whatever the host.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lattice {

// Appends the low `bytes` bytes of `value`, least significant first.
inline void appendLittleEndian(std::vector<std::uint8_t>& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

// Reads `bytes` bytes at `p`, least significant first (the caller checked the bounds).
inline std::uint64_t readLittleEndian(const std::uint8_t* p, int bytes) {
  std::uint64_t value = 0;
  for (int i = 0; i < bytes; ++i) value |= std::uint64_t(p[i]) << (8 * i);
  return value;
}

}  // namespace lattice
