// The banded PNG encoder (method and reasons in png_encoder.hpp).
#include "io/png_encoder.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>

#include "foundation/error.hpp"
#include "foundation/threads.hpp"

namespace lattice::io {
namespace {

constexpr std::size_t kWindowBytes = 32768;  // deflate's window (RFC 1951): the most a dictionary can reach back

int paeth(int a, int b, int c) {  // W3C PNG 9.4: the neighbour nearest a + b - c
  const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  if (pa <= pb && pa <= pc) return a;
  return pb <= pc ? b : c;
}

// One row as PNG stores it: the filter byte, then the filtered samples.
// `above` is the previous row unfiltered, or null for the first row.
void filterRow(PngFilter filter, std::size_t bpp, const std::uint8_t* row, const std::uint8_t* above,
               std::size_t rowBytes, std::uint8_t* out) {
  *out++ = static_cast<std::uint8_t>(filter);
  switch (filter) {
    case PngFilter::None: std::memcpy(out, row, rowBytes); return;
    case PngFilter::Sub:
      for (std::size_t i = 0; i < rowBytes; ++i) out[i] = static_cast<std::uint8_t>(row[i] - (i >= bpp ? row[i - bpp] : 0));
      return;
    case PngFilter::Up:
      for (std::size_t i = 0; i < rowBytes; ++i) out[i] = static_cast<std::uint8_t>(row[i] - (above ? above[i] : 0));
      return;
    case PngFilter::Paeth:
      for (std::size_t i = 0; i < rowBytes; ++i) {
        const int a = i >= bpp ? row[i - bpp] : 0, b = above ? above[i] : 0;
        const int c = above && i >= bpp ? above[i - bpp] : 0;
        out[i] = static_cast<std::uint8_t>(row[i] - paeth(a, b, c));
      }
      return;
  }
}

void appendBigEndian(std::vector<std::uint8_t>& out, std::uint32_t v) {
  out.insert(out.end(), {std::uint8_t(v >> 24), std::uint8_t(v >> 16), std::uint8_t(v >> 8), std::uint8_t(v)});
}

// A chunk (W3C PNG 5.3): length, type, data, CRC-32 of type and data.
void appendChunk(std::vector<std::uint8_t>& out, const char* type, std::span<const std::uint8_t> head,
                 std::span<const std::uint8_t> data = {}, std::span<const std::uint8_t> tail = {}) {
  appendBigEndian(out, static_cast<std::uint32_t>(head.size() + data.size() + tail.size()));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), head.begin(), head.end());
  out.insert(out.end(), data.begin(), data.end());
  out.insert(out.end(), tail.begin(), tail.end());
  uLong crc = crc32(0, nullptr, 0);
  crc = crc32_z(crc, out.data() + start, out.size() - start);
  appendBigEndian(out, static_cast<std::uint32_t>(crc));
}

struct Band {
  std::vector<std::uint8_t> deflated;
  uLong adler = 1;
  std::size_t filteredBytes = 0;
};

struct Layout {
  std::size_t bpp, rowBytes, rowsPerBand, bands, rowsBefore;  // rowsBefore: rows that fill the dictionary
};

// Filters rows [first - rowsBefore, last) of the picture into `scratch` and
// deflates the band's own rows, primed with what precedes them.
void deflateBand(const PngPixels& px, const PngEncoding& encoding, const Layout& layout, std::size_t band,
                 std::vector<std::uint8_t>& scratch, Band& out) {
  const std::size_t first = band * layout.rowsPerBand;
  const std::size_t last = std::min<std::size_t>(first + layout.rowsPerBand, std::size_t(px.height));
  const std::size_t from = first - std::min(first, layout.rowsBefore);
  const std::size_t stride = layout.rowBytes + 1;
  scratch.resize((last - from) * stride);
  for (std::size_t y = from; y < last; ++y) {
    const std::uint8_t* row = px.samples.data() + y * layout.rowBytes;
    filterRow(encoding.filter, layout.bpp, row, y > 0 ? row - layout.rowBytes : nullptr, layout.rowBytes,
              scratch.data() + (y - from) * stride);
  }
  const std::size_t ownStart = (first - from) * stride;
  const std::size_t own = scratch.size() - ownStart;
  const std::size_t dictionary = std::min(ownStart, kWindowBytes);

  z_stream z{};
  if (deflateInit2(&z, encoding.level, Z_DEFLATED, -15, 8, encoding.runLength ? Z_RLE : Z_DEFAULT_STRATEGY) != Z_OK)
    throw Error(ErrorKind::Internal, "PNG encoding: zlib's deflateInit2 failed");
  if (dictionary > 0)
    deflateSetDictionary(&z, scratch.data() + ownStart - dictionary, static_cast<uInt>(dictionary));
  out.deflated.resize(deflateBound(&z, own) + 16);  // + the sync flush's empty stored block
  z.next_in = scratch.data() + ownStart;
  z.avail_in = static_cast<uInt>(own);
  z.next_out = out.deflated.data();
  z.avail_out = static_cast<uInt>(out.deflated.size());
  const bool lastBand = last == std::size_t(px.height);
  const int status = deflate(&z, lastBand ? Z_FINISH : Z_SYNC_FLUSH);
  const bool complete = lastBand ? status == Z_STREAM_END : (status == Z_OK && z.avail_in == 0 && z.avail_out > 0);
  out.deflated.resize(out.deflated.size() - z.avail_out);
  deflateEnd(&z);
  if (!complete) throw Error(ErrorKind::Internal, fmt::format("PNG encoding: zlib's deflate stopped ({})", status));
  out.adler = adler32_z(adler32(0, nullptr, 0), scratch.data() + ownStart, own);
  out.filteredBytes = own;
}

}  // namespace

std::vector<std::uint8_t> encodePng(const PngPixels& px, const PngEncoding& encoding) {
  const bool indexed = !px.palette.empty();
  Layout layout{};
  layout.bpp = indexed ? 1 : 3;
  layout.rowBytes = std::size_t(px.width) * layout.bpp;
  layout.rowsPerBand = std::max<std::size_t>(1, kPngBandBytes / (layout.rowBytes + 1));
  layout.bands = (std::size_t(px.height) + layout.rowsPerBand - 1) / layout.rowsPerBand;
  layout.rowsBefore = (kWindowBytes + layout.rowBytes) / (layout.rowBytes + 1);

  std::vector<Band> bands(layout.bands);
  std::atomic<std::size_t> next{0};
  const unsigned threads = encoding.threads > 0 ? encoding.threads : hardwareThreads();
  const unsigned workers = static_cast<unsigned>(std::min<std::size_t>(threads, layout.bands));
  runWorkers(
      workers,
      [&](unsigned) {
        std::vector<std::uint8_t> scratch;
        for (std::size_t b; (b = next.fetch_add(1)) < layout.bands;) deflateBand(px, encoding, layout, b, scratch, bands[b]);
      },
      [&] { next = layout.bands; });

  std::vector<std::uint8_t> file = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<std::uint8_t> header;
  appendBigEndian(header, static_cast<std::uint32_t>(px.width));
  appendBigEndian(header, static_cast<std::uint32_t>(px.height));
  header.insert(header.end(), {8, std::uint8_t(indexed ? 3 : 2), 0, 0, 0});  // depth, colour type, methods
  appendChunk(file, "IHDR", header);
  const std::uint8_t perceptual = 0;  // what libpng's simplified API wrote, so viewers show the same
  appendChunk(file, "sRGB", std::span(&perceptual, 1));
  if (indexed) {
    std::vector<std::uint8_t> plte;
    for (const Rgb8& c : px.palette) plte.insert(plte.end(), {c.r, c.g, c.b});
    appendChunk(file, "PLTE", plte);
  }
  // The zlib wrapper (RFC 1950): CMF 0x78 (deflate, 32 KiB window), FLG with
  // the level class and the check bits making CMF * 256 + FLG a multiple of 31.
  const int levelClass = encoding.level <= 1 ? 0 : encoding.level <= 5 ? 1 : encoding.level == 6 ? 2 : 3;
  const unsigned cmfFlg = 0x7800u | unsigned(levelClass << 6);
  const std::uint8_t zlibHeader[2] = {0x78, std::uint8_t((cmfFlg + (31 - cmfFlg % 31) % 31) & 0xff)};
  uLong adler = adler32(0, nullptr, 0);
  for (const Band& band : bands) adler = adler32_combine(adler, band.adler, static_cast<z_off_t>(band.filteredBytes));
  std::vector<std::uint8_t> trailer;
  appendBigEndian(trailer, static_cast<std::uint32_t>(adler));
  for (std::size_t b = 0; b < bands.size(); ++b)
    appendChunk(file, "IDAT", b == 0 ? std::span<const std::uint8_t>(zlibHeader) : std::span<const std::uint8_t>(),
                bands[b].deflated, b + 1 == bands.size() ? std::span<const std::uint8_t>(trailer)
                                                           : std::span<const std::uint8_t>());
  appendChunk(file, "IEND", {});
  return file;
}

}  // namespace lattice::io
