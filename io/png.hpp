#pragma once
// PNG files. Writes go through io/png_encoder.hpp (bands of rows deflated on
// `threads` threads, 0: every core; the bytes do not depend on the count) and
// are atomic (see atomic_file.hpp). Reads (io/png_reader.cpp, libpng) stream
// the file, check the signature and the header's size against kMaxPngPixels
// before allocating, and return the samples as written: no gamma, sRGB or
// ICC conversion.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "foundation/indexed_image.hpp"
#include "foundation/system/atomic_file.hpp"
#include "foundation/rgb_image.hpp"

namespace lattice::io {

// `landing`: with the command's other outputs (the default), or at once
// (a terminal's snapshot, rewritten while the session goes on).
void writePng(const std::filesystem::path& path, const RgbImage& image, unsigned threads = 0,
              AtomicFile::Landing landing = AtomicFile::Landing::WithCommand);
// Writes a palette PNG (colour type 3) when the map has <= 256 entries.
void writePng(const std::filesystem::path& path, const IndexedImage& image, unsigned threads = 0,
              AtomicFile::Landing landing = AtomicFile::Landing::WithCommand);
// The largest picture a PNG read accepts (docs/limits.md): 2^26 pixels,
// e.g. 8192 x 8192, 192 MiB as 8-bit RGB. Larger headers are refused (exit 3)
// before any pixel memory is allocated.
inline constexpr std::uint64_t kMaxPngPixels = std::uint64_t(1) << 26;

// Any PNG as 8-bit RGB: palette and grey expanded, 16-bit samples rounded to
// 8, alpha composited onto black; gAMA, sRGB, cHRM and iCCP are ignored so
// pictures compare as their samples were written. Error(Input) naming the file.
RgbImage readPng(const std::filesystem::path& path);
// The same from an open stream (read from its current position; `name` is
// used in messages) and from bytes in memory: what a fuzzer drives.
RgbImage readPng(std::FILE* stream, const std::string& name);
RgbImage readPngBytes(std::span<const std::uint8_t> bytes, const std::string& name);

}  // namespace lattice::io
