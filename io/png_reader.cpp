// Reading PNG files, bounded by the input (docs/limits.md).
//
// Method: libpng's low-level API reading from a FILE*, so the file is
// streamed (never read whole first). The 8-byte signature is checked by us,
// then png_read_info parses IHDR (ancillary chunks we do not use are skipped
// unread, the rest capped at kMaxChunkBytes); the header's width x height is checked against
// kMaxPngPixels before any pixel memory exists. Rows are then read one at a
// time (an interlaced file needs the whole RGBA picture, still under the cap).
//
// Samples are returned as written: no png_set_gamma / png_set_alpha_mode is
// ever called, so gAMA, sRGB, cHRM and iCCP change nothing. (libpng's
// simplified API converted a file with gAMA 1.0, as POV-Ray writes, to sRGB,
// so `lattice diff` compared converted samples.) Alpha is
// composited onto black on the stored values: out = round(c * a / 255).
//
// libpng reports errors by longjmp; each step that calls libpng sets its own
// jump point and holds no C++ object a longjmp would skip.
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <vector>

#include <fmt/format.h>
#include <png.h>

#include "io/png.hpp"
#include "foundation/error.hpp"

namespace lattice::io {
namespace {

struct PngReader {
  png_structp png = nullptr;
  png_infop info = nullptr;
  char message[256] = "";
  PngReader() = default;
  PngReader(const PngReader&) = delete;
  PngReader& operator=(const PngReader&) = delete;
  ~PngReader() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
};

void onError(png_structp png, png_const_charp message) {
  auto* reader = static_cast<PngReader*>(png_get_error_ptr(png));
  std::snprintf(reader->message, sizeof reader->message, "%s", message);
  png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) {}  // ancillary-chunk trouble: not ours to report

// Ancillary chunks we never use (tRNS is kept: it becomes alpha). libpng
// 1.6.39 allocates an eXIf chunk's declared length unchecked: a 173-byte file
// asked for 1 GiB (found by fuzz/, kept in fuzz/regressions/png/). Chunks
// marked "never" are skipped through a small buffer, nothing allocated.
constexpr png_byte kSkippedChunks[] = "bKGD\0cHRM\0eXIf\0gAMA\0hIST\0iCCP\0iTXt\0oFFs\0pCAL\0pHYs\0sBIT\0sCAL\0"
                                      "sPLT\0sRGB\0tEXt\0tIME\0zTXt";
constexpr int kSkippedChunkCount = 17;
// Every other chunk libpng buffers whole is capped at this (libpng's default
// cap is its build's choice).
constexpr png_alloc_size_t kMaxChunkBytes = 8u << 20;

bool readHeader(PngReader& r, std::FILE* in) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_init_io(r.png, in);
  png_set_keep_unknown_chunks(r.png, PNG_HANDLE_CHUNK_NEVER, kSkippedChunks, kSkippedChunkCount);
  png_set_chunk_malloc_max(r.png, kMaxChunkBytes);
  png_set_sig_bytes(r.png, 8);
  png_read_info(r.png, r.info);
  return true;
}

// To 8-bit RGBA whatever the colour type; returns the interlace pass count.
bool setTransforms(PngReader& r, int& passes) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_set_expand(r.png);  // palette -> RGB, grey < 8 bits -> 8, tRNS -> alpha
  png_set_scale_16(r.png);
  png_set_gray_to_rgb(r.png);
  png_set_filler(r.png, 0xFF, PNG_FILLER_AFTER);  // opaque alpha where there is none
  passes = png_set_interlace_handling(r.png);
  png_read_update_info(r.png, r.info);
  return true;
}

bool readRow(PngReader& r, png_bytep row) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_read_row(r.png, row, nullptr);
  return true;
}

bool readImage(PngReader& r, png_bytepp rows) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_read_image(r.png, rows);
  return true;
}

void composite(const std::uint8_t* rgba, std::uint8_t* rgb, std::size_t width) {
  for (std::size_t x = 0; x < width; ++x, rgba += 4, rgb += 3) {
    const unsigned a = rgba[3];
    for (int c = 0; c < 3; ++c) rgb[c] = static_cast<std::uint8_t>((rgba[c] * a + 127u) / 255u);
  }
}

}  // namespace

RgbImage readPng(std::FILE* in, const std::string& name) {
  auto fail = [&](const std::string& what) { return Error(ErrorKind::Input, fmt::format("{}: {}", name, what)); };
  png_byte signature[8];
  const std::size_t got = std::fread(signature, 1, sizeof signature, in);
  if (got < sizeof signature || png_sig_cmp(signature, 0, sizeof signature) != 0)
    throw fail("not a PNG file (it does not start with the 8-byte PNG signature)");
  PngReader r;
  r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r, onError, onWarning);
  if (r.png) r.info = png_create_info_struct(r.png);
  if (!r.png || !r.info) throw Error(ErrorKind::Input, fmt::format("{}: out of memory starting the PNG reader", name));
  if (!readHeader(r, in)) throw fail(fmt::format("not a readable PNG: {}", r.message));

  const png_uint_32 width = png_get_image_width(r.png, r.info), height = png_get_image_height(r.png, r.info);
  const std::uint64_t pixels = std::uint64_t(width) * height;
  if (width == 0 || height == 0 || pixels > kMaxPngPixels)
    throw fail(fmt::format("its header says {}x{} ({} pixels); this program reads PNGs of 1 to {} pixels "
                           "(kMaxPngPixels, docs/limits.md)",
                           width, height, pixels, kMaxPngPixels));
  int passes = 1;
  if (!setTransforms(r, passes)) throw fail(fmt::format("not a readable PNG: {}", r.message));
  if (png_get_rowbytes(r.png, r.info) != std::size_t(width) * 4)
    throw fail("unsupported PNG layout (could not convert it to 8-bit RGBA)");

  RgbImage out(static_cast<int>(width), static_cast<int>(height));
  const std::size_t rowBytes = std::size_t(width) * 4;
  auto decodingFailed = [&] { return fail(fmt::format("PNG decoding failed: {}", r.message)); };
  if (passes == 1) {
    std::vector<std::uint8_t> row(rowBytes);
    for (png_uint_32 y = 0; y < height; ++y) {
      if (!readRow(r, row.data())) throw decodingFailed();
      composite(row.data(), out.pixel(0, static_cast<int>(y)), width);
    }
  } else {  // interlaced: later passes fill in earlier rows, so keep them all
    std::vector<std::uint8_t> all(rowBytes * height);
    std::vector<png_bytep> rows(height);
    for (png_uint_32 y = 0; y < height; ++y) rows[y] = all.data() + rowBytes * y;
    if (!readImage(r, rows.data())) throw decodingFailed();
    for (png_uint_32 y = 0; y < height; ++y) composite(rows[y], out.pixel(0, static_cast<int>(y)), width);
  }
  return out;
}

RgbImage readPng(const std::filesystem::path& path) {
  std::FILE* in = std::fopen(path.c_str(), "rb");
  if (!in) throw Error(ErrorKind::Input, fmt::format("{}: cannot open: {}", path.string(), std::strerror(errno)));
  try {
    RgbImage image = readPng(in, path.string());
    std::fclose(in);
    return image;
  } catch (...) {
    std::fclose(in);
    throw;
  }
}

RgbImage readPngBytes(std::span<const std::uint8_t> bytes, const std::string& name) {
  if (bytes.empty()) throw Error(ErrorKind::Input, fmt::format("{}: not a PNG file (it is empty)", name));
  std::FILE* in = ::fmemopen(const_cast<std::uint8_t*>(bytes.data()), bytes.size(), "rb");
  if (!in) throw Error(ErrorKind::Input, fmt::format("{}: cannot open the bytes as a stream", name));
  try {
    RgbImage image = readPng(in, name);
    std::fclose(in);
    return image;
  } catch (...) {
    std::fclose(in);
    throw;
  }
}

}  // namespace lattice::io
