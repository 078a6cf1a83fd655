#pragma once
// A PNG encoder that compresses bands of rows on every thread (what
// io/png.cpp writes with).
//
// Method: each row is filtered with one fixed PNG filter (W3C PNG, section 9:
// None, Sub, Up or Paeth); the filtered rows are cut into bands of a fixed
// size (kPngBandBytes, never a function of the thread count, so the bytes
// are the same on any number of threads) and each band is deflated on its
// own by zlib as raw deflate, primed with the whole rows of at least 8 KiB
// before it (deflateSetDictionary) so the ratio hardly suffers, and ended with a
// sync flush (the last band: finish), a row at a time, so a worker holds its
// deflate state and a few rows. Raw deflate streams ended so join into
// one (RFC 1951: a sync flush ends on a byte boundary with no final block),
// and the zlib wrapper's Adler-32 of the whole is combined from the bands'
// (adler32_combine; each band's own by io/adler32.hpp); this is how pigz
// compresses in parallel. The bands go out as IDAT chunks, each with its
// CRC-32, straight to the file.
//
// Why: libpng compresses on one thread, and its simplified API
// (png_image_write_to_memory) compresses the whole picture twice, once only
// to learn the size; at 2048 x 2048 that was most of everything a render
// does besides tracing. bench/png-encoder.sh measures the level, strategy
// and filter chosen below against the others and against libpng and libspng.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "foundation/byte_sink.hpp"
#include "foundation/scanline.hpp"

namespace lattice::io {

enum class PngFilter : std::uint8_t { None = 0, Sub = 1, Up = 2, Paeth = 4 };  // the filter-type byte

// The defaults won bench/png-encoder.sh on Plate 7, Plate 6 and torus-floor
// at 2048 x 2048: the least CPU time of the settings measured, with files
// about the size libpng's defaults write (bench/results/2026-12-04-tail.md).
struct PngEncoding {
  int level = 1;           // zlib's level, 0..9
  bool runLength = false;  // zlib's Z_RLE strategy: matches at distance one only
  PngFilter filter = PngFilter::None;  // a render's flat runs repeat whole pixels, which filtering breaks up
  unsigned threads = 0;    // 0: every core; the bytes do not depend on it
};

// A picture as PNG wants it: rows of 8-bit samples, 3 a pixel (RGB) or 1 (an
// index into `palette`, at most 256 entries).
struct PngPixels {
  int width = 0;
  int height = 0;
  std::span<const std::uint8_t> samples;  // width * channels * height
  std::span<const Rgb8> palette;          // empty: RGB
};

// Raw filtered rows are deflated in bands of about this many bytes.
inline constexpr std::size_t kPngBandBytes = std::size_t(256) << 10;

// The whole PNG file onto `out` (not closed), each band's deflated bytes
// freed once written. Throws Error(Internal) if zlib fails (it cannot on
// memory it was given, short of running out), and what `out` throws.
void encodePng(const PngPixels& pixels, const PngEncoding& encoding, ByteSink& out);
// The same into memory.
std::vector<std::uint8_t> encodePng(const PngPixels& pixels, const PngEncoding& encoding);

// What one worker holds besides the bands' deflated bytes: zlib's state, the
// rows that prime a band's dictionary, a row (what a memory plan counts).
std::size_t pngEncoderWorkerBytes(int width, bool indexed);

}  // namespace lattice::io
